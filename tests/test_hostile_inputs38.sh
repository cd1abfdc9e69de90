#!/bin/bash
# test_hostile_inputs38.sh GRANWAVE SRCDIR: what the thirty-eighth hostile
# pass (over the input files and the physics) found, fixed at its root and
# asserted here.
#  1 A sweep config file cut inside its last line ran. A config given as text
#    (Python's sweep, gw_sweep_run_text) legitimately ends without a newline,
#    and the config file was read by the same rule: '[grid] vi = 10, 0.25'
#    cut to 'vi = 10, 0.2' ran another grid (case 1 at 0.2 m/s) with exit 0,
#    and sweep --check said it was valid. A config FILE whose last line
#    holding a value has no newline after it (LF, or the CR of a CR LF) is
#    now refused as the end of a cut file, naming the file, the line and the
#    value (sweep, sweep --check); a last comment line without its newline
#    changes nothing read and still runs, and so does config text without a
#    final newline given to the library.
#  2 A layer sweep table cut inside its last row was read. A table with the
#    hash columns is refused by its last hash cut short, but one without them
#    (written before them, or made by hand) read its last penetration cut in
#    its digits into the statistics with exit 0. A table file whose last row
#    has no newline is now refused naming the file and the line (layer-stats
#    and Python's layer_stats); the whole table, and one ending in a comment
#    line without its newline, are read.
#  3 FFTW wisdom cut short (checked, no fault): its closing parenthesis goes
#    first, and dispersion --wisdom refuses it as not FFTW wisdom (it is
#    overwritten at the end of a run) without touching it.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

make_sample s.txt --n 40 --seed 2

# --- 1 a sweep config file cut inside its last line ---
head='[sweep]\nmodel = layer\nout = o\n[params]\nsample = s.txt\nt-max = 0.002\n[grid]\n'
printf "${head}vi = 10, 0.25\n" >whole.ini
printf "${head}vi = 10, 0.25" >cut0.ini          # the newline alone gone
printf "${head}vi = 10, 0.2" >cut1.ini           # the last digit and the newline
printf "${head}vi = 10, 0.25\r" >crlf.ini        # a CR LF file without its last LF: whole
printf "${head}vi = 10, 0.25\n; the end" >com.ini # a comment ends the file
printf "${head}vi = 10,\n    0.25" >cont.ini     # a continued list cut after its last value
CUTC="the file ends inside this line \\(no newline after it\\): cut short\\?"
refused "sweep over a config cut inside its last value: refused naming the file, the line and the value" \
    "^granwave sweep: cut1.ini:8: $CUTC 'vi = 10, 0.2' may hold a value cut short" sweep cut1.ini --quiet
refused "sweep --check over that config: refused alike" \
    "^granwave sweep: cut1.ini:8: $CUTC" sweep cut1.ini --check
refused "sweep over a config whose last value line lacks only its newline: refused" \
    "^granwave sweep: cut0.ini:8: $CUTC 'vi = 10, 0.25'" sweep cut0.ini --check
refused "sweep over a config cut after a continued list's last value: refused naming that line" \
    "^granwave sweep: cont.ini:9: $CUTC '0.25'" sweep cont.ini --check
# the whole config runs, and its cases are the grid written (vi 10 and 0.25)
checks_run() { # checks_run WHAT CONFIG: sweep CONFIG --check exits 0 with 2 cases
    if timeout -s KILL 60 "$GW" sweep "$2" --check >"$tmp/stdout" 2>&1 </dev/null; then
        grep -q "2 cases" "$tmp/stdout" && ok "$1" || ko "$1: $(head -c 300 "$tmp/stdout")"
    else
        ko "$1: exit $? ($(head -c 300 "$tmp/stdout"))"
    fi
}
checks_run "sweep --check over the whole config (LF): valid, 2 cases" whole.ini
checks_run "sweep --check over a CR LF config without its last LF: valid" crlf.ini
checks_run "sweep --check over a config ending in a comment without its newline: valid" com.ini
rm -rf o
if timeout -s KILL 120 "$GW" sweep whole.ini --quiet >/dev/null 2>"$tmp/stderr" </dev/null; then
    vs=$(grep -v '^#' o/results.csv | $PY -c "import csv, sys; print(sorted(float(r['vi']) for r in csv.DictReader(sys.stdin)))")
    [ "$vs" = "[0.25, 10.0]" ] && ok "sweep over the whole config: its cases at vi 10 and 0.25 m/s" ||
        ko "sweep over the whole config: vi $vs"
else
    ko "sweep over the whole config: exit $? ($(head -c 300 "$tmp/stderr"))"
fi
mv o/results.csv table.csv
rm -rf o
# config text without a final newline, given to the library: runs, its last value whole
py_checks 1 <<'EOF'
import ctypes
from granwave import _lib
text = b"[sweep]\nmodel = layer\n[params]\nsample = s.txt\nt-max = 0.002\n[grid]\nvi = 10, 0.25"
values, n, m, err = _lib.c_double_p(), ctypes.c_long(), ctypes.POINTER(_lib.GwSweepModel)(), _lib.GwErr()
rc = _lib.lib.gw_sweep_run_text(text, b"text", 1, _lib.PROGRESS(), None, ctypes.byref(values), ctypes.byref(n),
                                ctypes.byref(m), ctypes.byref(err))
check(rc == 0 and n.value == 2, "config text without a final newline, given to the library: runs its 2 cases "
      "(rc %d, %d cases, %s)" % (rc, n.value, bytes(err.msg).split(b"\0")[0][:200]))
if rc == 0:
    _lib.lib.gw_free(values)
EOF

# --- 2 a layer sweep table cut inside its last row ---
# the table without its hash columns (as written before them), penetration last
$PY - <<'EOF' || ko "making the tables"
import csv
lines = open("table.csv").read().splitlines(True)
com = [l for l in lines if l.startswith("#")]
data = list(csv.reader([l for l in lines if not l.startswith("#")]))
h = data[0]
keep = [i for i, c in enumerate(h) if c not in ("case_config_fnv1a64", "sample_fnv1a64", "penetration")]
keep.append(h.index("penetration"))
with open("t.csv", "w") as f:
    f.write("".join(l for l in com if not l.startswith("# build")))
    for r in data:
        f.write(",".join(r[i] for i in keep) + "\n")
EOF
stats_runs() { # stats_runs WHAT TABLE: layer-stats exits 0
    rm -rf "$tmp/st"
    timeout -s KILL 60 "$GW" layer-stats "$2" --out "$tmp/st" >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$1" || ko "$1: exit $? ($(head -c 300 "$tmp/stderr"))"
}
stats_runs "layer-stats over the table without hashes, whole: read" t.csv
printf '# the end' >>t.csv.com && cat t.csv t.csv.com >tc.csv
stats_runs "layer-stats over that table ending in a comment without its newline: read" tc.csv
sed 's/$/\r/' t.csv | head -c -1 >tcr.csv
stats_runs "layer-stats over that table in CR LF without its last LF: read" tcr.csv
CUTT="the file ends inside this line \\(no newline after it\\): cut short\\?"
last=$(grep -c '' t.csv)
for k in 1 19; do
    head -c -$((k + 1)) t.csv >t$k.csv           # k digits of the last penetration and the newline gone (19: 0.00041 m read as 0.0)
    refused "layer-stats over the table cut $k digits into its last penetration: refused naming the file and line" \
        "^granwave layer-stats: t$k.csv:$last: $CUTT" layer-stats t$k.csv --out o
done
head -c -1 t.csv >tn.csv
refused "layer-stats over the table without its last newline: refused" \
    "^granwave layer-stats: tn.csv:$last: $CUTT" layer-stats tn.csv --out o
head -c -8 table.csv >th.csv                     # the sweep's own table, its last hash cut
refused "layer-stats over the sweep's table cut in its last hash: refused naming the line" \
    "^granwave layer-stats: th.csv:[0-9]+: " layer-stats th.csv --out o
py_checks 1 <<'EOF'
refused("Python layer_stats on the table cut in its last penetration", ["t19.csv", "the file ends inside this line"],
        granwave.layer_stats, "t19.csv")
EOF

# --- 3 FFTW wisdom cut short: refused as not wisdom, left as it is ---
if timeout -s KILL 60 "$GW" dispersion --wisdom w.txt --quiet >/dev/null 2>&1 </dev/null && [ -s w.txt ]; then
    for k in 2 20; do
        head -c -$k w.txt >w$k.txt
        cp w$k.txt w$k.before
        refused "dispersion --wisdom cut $k bytes short: refused as not FFTW wisdom" \
            "^granwave dispersion --wisdom: 'w$k.txt' is not FFTW wisdom; refusing to overwrite it" \
            dispersion --wisdom w$k.txt --out o
        cmp -s w$k.txt w$k.before && ok "the cut wisdom left as it was" || ko "the cut wisdom was changed"
    done
else
    ko "dispersion --wisdom w.txt: no wisdom written"
fi

test_summary test_hostile_inputs38
