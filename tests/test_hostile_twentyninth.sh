#!/bin/bash
# test_hostile_twentyninth.sh GRANWAVE SRCDIR: what the twenty-ninth hostile
# pass (the files the program reads, the library's C interface) found, fixed
# at its root and asserted here.
#  1 One option under two spellings in a sweep config. The options take '_'
#    for '-' (t_max is t-max), but the config reader compared keys as
#    written: 'wall-material = steel, glass, pmma' in [grid] and
#    'wall_material = rigid' in [params] both went through, the later one
#    setting every case (three equal rows, exit 0), and 't-max' beside
#    't_max' in [params] the same. Keys are now read under the option's one
#    spelling ('-'), so the second is a duplicate key (exit 2 naming the
#    config and the line, nothing written), and the table's header and
#    '# grid' lines give that spelling.
#  2 layer-stats read a table keyed rb_rm and height_rm (a sweep given those
#    spellings wrote them so) as grid keys like any other: no diagram, and the
#    binary table put every row under the default R_b/R_m = 1 (exit 0). Its
#    grid keys and params are matched with '_' and '-' as one now: the table
#    gives the diagram and the binary rows of its rb-rm twin; a header with a
#    key under both spellings is refused as a column given twice.
#  3 dispersion --wisdom took a file that began with FFTW wisdom and went on
#    (notes after it, a second wisdom appended, a NUL byte and more): FFTW
#    read the first wisdom, the export at the end replaced the file, and what
#    followed was lost (exit 0; the recorded hash stopped at the NUL). Such a
#    file is refused now, left as it is; wisdom alone is still read.
#  4 A sample of fine grains at the default skin (0.1 m, in metres: about a
#    thousand 1 mm grains within it) grew its contact list until the
#    allocation failed: 20000 such grains listed 2e8 pairs, about 40 GB with
#    their state (exit 1 under a 2 GB ulimit, the kernel's OOM killer without
#    one), before the impact's bound on its work could name the skin. The
#    list now stops at 8 pairs a particle (at least 1e7) and the run is
#    refused naming the skin (exit 2, nothing written); a small skin runs.
# Also: a journal an earlier granwave wrote in a key's '_' spelling is named
# as such on a resume, and a comment longer than the config reader's line is
# named as a comment (its hint was about ranges and lists).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

# --- 1 one option under two spellings ---
printf '[sweep]\nmodel = chain\n[grid]\nwall-material = steel, glass, pmma\n[params]\nsolver = rk4\nwall_material = rigid\nn = 3\n' >a.ini
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nt-max = 1e-3\nt_max = 2e-3\n' >b.ini
printf '[sweep]\nmodel = chain\n[grid]\ndt_out = 1e-6, 2e-6\ndt-out = 3e-6\nn = 2\n' >c.ini
for c in a:7:wall_material b:7:t_max c:5:dt-out; do
    f=${c%%:*}.ini; rest=${c#*:}; line=${rest%%:*}; key=${rest#*:}
    rm -rf o
    if exits_refused "$f" "^granwave sweep: $f:$line: duplicate key '$key'" 30 "$GW" sweep "$f" --out o --jobs 1; then
        ok "$f: '$key' beside its other spelling refused, naming line $line"
    fi
    [ -e o ] && ko "$f: wrote o" || ok "$f: nothing written"
    if exits_refused "$f --check" "^granwave sweep: $f:$line: duplicate key" 30 "$GW" sweep "$f" --out o --check; then
        ok "$f: sweep --check refuses it as the run does"
    fi
done
# a config in '_' spelling runs as its '-' twin and writes the '-' spelling
printf '[sweep]\nmodel = chain\n[grid]\nwall_material = steel, pmma\n[params]\nsolver = rk4\nn = 3\n' >u.ini
printf '[sweep]\nmodel = chain\n[grid]\nwall-material = steel, pmma\n[params]\nsolver = rk4\nn = 3\n' >d.ini
rm -rf ou od
if "$GW" sweep u.ini --out ou --jobs 1 >/dev/null 2>&1 && "$GW" sweep d.ini --out od --jobs 1 >/dev/null 2>&1 &&
    cmp -s ou/results.csv od/results.csv && grep -q '^case,wall-material,f_max' ou/results.csv; then
    ok "wall_material in [grid]: the table of wall-material byte for byte (header and '# grid' in the '-' spelling)"
else
    ko "wall_material in [grid]: its table differs from wall-material's ($(grep '^case' ou/results.csv 2>/dev/null | cut -c1-40))"
fi
# a journal of a granwave that kept the '_' spelling (its head hashed over it):
# named as such on a resume, the journal left as it is
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\ndt_out = 1e-6, 2e-6\n[params]\nsolver = rk4\n' >j.ini
rm -rf oj
"$GW" sweep j.ini --out oj --jobs 1 >/dev/null 2>&1 || ko "j.ini did not run"
sed -i '1s/journal [0-9a-f]*,/journal 0123456789abcdef,/; s/^# grid dt-out =/# grid dt_out =/' oj/journal.csv
cp oj/journal.csv j.before
rm -f oj/results.csv
if exits_refused "a journal in the '_' spelling" "^granwave sweep: oj: this directory holds another sweep: its journal has \[grid\] dt_out, an earlier granwave's spelling of dt-out" 30 \
    "$GW" sweep j.ini --out oj --jobs 1; then ok "a journal of the '_' spelling: the resume names the spelling"; fi
cmp -s oj/journal.csv j.before && [ ! -e oj/results.csv ] && ok "that journal left as it is, no table" ||
    ko "that journal changed or a table written"
# the grid does act: two materials, two forces
if $PY - od/results.csv <<'EOF'
import sys
rows = [l.split(",") for l in open(sys.argv[1]) if l[0].isdigit()]
sys.exit(0 if len(rows) == 2 and rows[0][2] != rows[1][2] else 1)
EOF
then ok "the two wall materials give two forces"; else ko "the wall-material grid gave equal rows"; fi

# a comment longer than the reader's line: named as a comment (the hint was
# "give integers as a range A:B"), nothing written
{ printf '[sweep]\nmodel = chain\n; '; head -c 300 /dev/zero | tr '\0' x; printf '\n[grid]\nn = 1:2\n'; } >lc.ini
rm -rf o
if exits_refused "a long comment" "^granwave sweep: lc.ini:3: a comment of 302 characters, above the 198" 30 \
    "$GW" sweep lc.ini --out o --jobs 1; then ok "a comment of 302 characters named as a comment"; fi

# --- 2 layer-stats over a table keyed rb_rm, height_rm ---
$PY -c "import sys; sys.path.insert(0, '$SRC/tests'); import synthetic_tables as s; s.write_bouncing_diagram('dash.csv')" ||
    ko "synthetic table not written"
sed '/^case,/s/rb-rm/rb_rm/; /^case,/s/height-rm/height_rm/' dash.csv >under.csv
if "$GW" layer-stats dash.csv --json >dash.json 2>/dev/null && "$GW" layer-stats under.csv --json >under.json 2>/dev/null; then
    if $PY - <<'EOF'
import json, sys
a, b = json.load(open("dash.json")), json.load(open("under.json"))
bad = []
if len(b["diagrams"]) != len(a["diagrams"]) or not a["diagrams"]:
    bad.append("diagrams %d against %d" % (len(b["diagrams"]), len(a["diagrams"])))
else:
    for k in ("rb_rm", "height_rm", "share", "r_crit"):
        if k in a["diagrams"][0] and a["diagrams"][0][k] != b["diagrams"][0].get(k):
            bad.append("diagram " + k)
if a["binary"] != b["binary"]:
    bad.append("binary rows: %s" % [r["rb_rm"] for r in b["binary"]])
bad and print("; ".join(bad))
sys.exit(1 if bad else 0)
EOF
    then ok "a table keyed rb_rm, height_rm: the diagram and binary rows of its rb-rm twin"
    else ko "a table keyed rb_rm, height_rm is read otherwise than its rb-rm twin"; fi
else
    ko "layer-stats over the synthetic tables failed"
fi
sed '/^case,/s/,point,/,rb_rm,point,/; /^[0-9]/s/^\([0-9]*,[^,]*,[^,]*,\)/\11,/' dash.csv >both.csv
if exits_refused "rb-rm and rb_rm" "both.csv:[0-9]+: header column 'rb_rm' appears twice" 30 "$GW" layer-stats both.csv --json; then
    ok "a header with rb-rm and rb_rm refused as one column given twice"
fi
# the rows of R_b/R_m = 0.5 without their rb-rm column, which two params then give
{ echo "# param rb_rm = 2"; echo "# param rb-rm = 3"; grep -v '^#' dash.csv | grep -E '^(case|[0-9]+,0.5,)' |
    sed 's/^\([a-z0-9]*\),[^,]*,/\1,/'; } >params.csv
if exits_refused "# param rb_rm and rb-rm" "params.csv:2: param rb-rm given twice" 30 "$GW" layer-stats params.csv --json; then
    ok "'# param rb_rm' and '# param rb-rm' refused as one param given twice"
fi

# --- 3 a wisdom file that holds more than wisdom ---
"$GW" dispersion --n 16 --wisdom good.w --json >/dev/null 2>&1 || ko "dispersion did not write its wisdom"
{ cat good.w; printf 'my notes on this machine\n'; } >notes.w
{ cat good.w; printf '\0'; cat good.w; } >nul.w
{ cat good.w; cat good.w; } >two.w
for w in notes nul two; do
    cp $w.w $w.before
    rm -rf o
    if exits_refused "--wisdom $w.w" "^granwave dispersion --wisdom: '$w.w' holds more than FFTW wisdom" 60 \
        "$GW" dispersion --n 16 --wisdom $w.w --out o; then ok "--wisdom $w.w: refused, naming it"; fi
    cmp -s $w.w $w.before && [ ! -e o ] && ok "--wisdom $w.w: the file unchanged, nothing written" ||
        ko "--wisdom $w.w: the file changed or o written"
done
cp good.w g2.w
if "$GW" dispersion --n 16 --wisdom g2.w --json >g2.json 2>/dev/null &&
    [ "$($PY -c "
import json
h = 14695981039346656037
for c in open('good.w', 'rb').read():
    h = ((h ^ c) * 1099511628211) % 2**64
d = json.load(open('g2.json'))
print(d['settings']['spectrum']['fftw_wisdom_fnv1a64'] == '%016x' % h)")" = True ]; then
    ok "wisdom alone is read, its recorded hash that of the file's bytes"
else
    ko "wisdom alone: refused, or its recorded hash is not the file's"
fi

# --- 4 a sample of fine grains at the default skin ---
# 20000 discs of radius 0.5 mm in a square lattice (touching, 200 a row)
$PY - <<'EOF'
n, nx, r = 20000, 200, 0.0005
with open("fine.txt", "w") as f:
    f.write("granwave-layer-sample 1\nwidth %.17g\nrm %.17g\nvolume_ratio 1\nseed 0\nmass_law disc\nn %d\n" % (nx * 2 * r, r, n))
    for i in range(n):
        f.write("%.17g %.17g %.17g\n" % ((i % nx) * 2 * r + r, (i // nx) * 2 * r + r, r))
EOF
rm -rf o
lim="" # the sanitizer build reserves terabytes of shadow memory: no ulimit -v there
sanitizer_build || lim="ulimit -v 2000000;"
bash -c "$lim exec timeout -s KILL 120 \"$GW\" layer-impact --sample fine.txt --t-max 1e-4 --until verdict --out o" \
    >stdout 2>stderr </dev/null
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <stderr)" -eq 1 ] && grep -q "^granwave layer-impact --skin: 0.1 m lists more than 10000000 pairs of the 20001 particles" stderr; then
    ok "fine grains at the default skin: exit 2 naming the skin, before the list took the memory"
else
    ko "fine grains at the default skin: exit $rc ($(head -c 200 stderr))"
fi
[ -e o ] && ko "fine grains: wrote o" || ok "fine grains at the default skin: nothing written"
if bash -c "$lim exec timeout -s KILL 120 \"$GW\" layer-impact --sample fine.txt --t-max 1e-4 --until verdict --skin 1e-4 --json" \
    >fine.json 2>stderr </dev/null && [ "$($PY -c "import json; print(json.load(open('fine.json'))['v_ni'])")" = 20 ]; then
    ok "fine grains with a skin of their size run"
else
    ko "fine grains with --skin 1e-4 did not run ($(head -c 200 stderr))"
fi

test_summary test_hostile_twentyninth
