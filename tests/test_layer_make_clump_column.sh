#!/bin/bash
# test_layer_make_clump_column.sh GRANWAVE SRCDIR: a clump pile far taller than
# its box is wide. `layer-make --clumps --width-rm 8 --n 600` starts its 600
# clumps in rows of their bounding boxes 223 m high, 86 times the 2.6 m box's
# width (its top falls longer than t-max); the clumps wedge between the walls
# and it ended (exit 1) "particle outside the box" after many minutes (a
# member disc more than 2 % of its radius into a wall); `--width-rm 5 --n 300`
# (108 times) ran on past 400 s. The disc lattice's rule (COLUMN_ASPECT_MAX)
# did not apply: clumps start from their own rows. gw_layer_make (the program
# and Python alike) now refuses rows more than 16 times as high as the box is
# wide before any work, exit 2, naming --n, --width-rm, the bound, an n and a
# width that pass; nothing is written. Checks:
#  1 the fault's commands are refused: exit 2, one line naming --n, the
#    width, the bound 16, "lower --n to 115" / "61" and "--width-rm 19.1" /
#    "13.4" with the range of widths checked to pass ("from 19.1 to 23.8",
#    "13.4 to 16.7"), no --out file; the message said "--width-rm 19.2 or
#    more", but the rows' top is not monotonic in the width (`--width-rm 6
#    --n 300`, 77 times: a box of 5 R_m is now refused first, narrower than
#    the longest clump lies flat in: test_layer_make_clump_wedge);
#  2 an existing sample at --out is left as it was (byte for byte);
#  3 Python's layer_make(clumps=True, width_rm=8, n=600) raises
#    GranwaveValueError in its keywords (n, width_rm), nothing written;
#  4 the n and the width the messages name pass the check: short runs
#    (t-max 0.01) exit 0 and write their samples; one clump more than the n
#    named is refused (the n is the largest that passes); every width of
#    three digits in the range named for n 600 (19.1 to 23.8) is not refused
#    by the rule (t-max 1e-4: 48 short runs), and 19.0, below it, is; the
#    rule is not monotonic in the width: n 1500 passes at 30.7, is refused
#    at 30.8 (named: 30.9 to 35.9) and passes at 30.9;
#  5 within the bound a narrow clump pile settles valid: --n 30 at
#    --width-rm 6 (rows 8 times as high as wide) is converged, every member
#    disc inside the box to 0.02 r (read from the file), and the floor carries
#    0.6 to 1.4 of the weight (the JSON).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
REFUSE_TIMEOUT=60 # (only a guard: the code before ran these for minutes)
PY_TIMEOUT=120

msg() { # msg N W NFIT WFIT WHI: the refusal's line as a pattern
    echo "^granwave layer-make --n: $1 clumps in a box of --width-rm $2 start in rows .* m high .*, .* times as high as the box is wide, above 16: .* lower --n to $3, or widen the box to --width-rm $4 \\(each width of three digits from $4 to $5 passes; the rows repack as the width changes: one below or above may not\\)\$"
}

# --- 1 the fault's commands refused before any work, nothing written ---
refused "layer-make --clumps --width-rm 8 --n 600 (rows 86 times the width)" "$(msg 600 8 115 '19\.1' '23\.8')" \
    layer-make --clumps --width-rm 8 --n 600 --out "$tmp/o"
refused "layer-make --clumps --width-rm 6 --n 300 (rows 77 times the width)" "$(msg 300 6 61 '13\.4' '16\.7')" \
    layer-make --clumps --width-rm 6 --n 300 --out "$tmp/o"

# --- 2 an existing sample at --out left as it was ---
make_sample keep.txt --n 10 --width-rm 8 --t-max 0.05
cp keep.txt keep.orig
if exits_refused "layer-make --clumps over an existing sample" "$(msg 600 8 115 '19\.1' '23\.8')" 60 \
    "$GW" layer-make --clumps --width-rm 8 --n 600 --out keep.txt; then
    if cmp -s keep.txt keep.orig; then ok "layer-make --clumps over an existing sample: refused, the sample unchanged"
    else ko "layer-make --clumps over an existing sample: the sample changed"; fi
fi

# --- 3 Python refuses it in its keywords ---
py_checks 2 <<'PYEOF'
import os
refused("layer_make(clumps=True, width_rm=8, n=600)", ["n: 600 clumps in a box of width_rm 8", "above 16",
        "lower n to 115", "width_rm 19.1 (each width of three digits from 19.1 to 23.8 passes"], granwave.layer_make, clumps=True, width_rm=8, n=600, out="py.txt")
check(not os.path.exists("py.txt"), "layer_make(clumps=True, width_rm=8, n=600): nothing written")
PYEOF

# --- 4 the n and the width the messages name pass; one clump more does not ---
for args in "--n 115 --width-rm 8" "--n 600 --width-rm 19.1" "--n 61 --width-rm 6" "--n 300 --width-rm 13.4"; do
    rm -f s4.txt
    # shellcheck disable=SC2086
    if timeout -s KILL 60 "$GW" layer-make --clumps $args --t-max 0.01 --quiet --out s4.txt >/dev/null 2>"$tmp/s4.err" &&
        [ -s s4.txt ]; then
        ok "layer-make --clumps $args (the message's suggestion): runs"
    else
        ko "layer-make --clumps $args (the message's suggestion): $(head -c 300 "$tmp/s4.err")"
    fi
done
refused "layer-make --clumps --width-rm 8 --n 116 (one clump above the n named)" "$(msg 116 8 115 '[0-9.]+' '[0-9.]+')" \
    layer-make --clumps --width-rm 8 --n 116 --out "$tmp/o"

# every width of three digits in the range named passes the rule, the one below it not
bad=""
for w in $(seq 19.0 0.1 23.8); do
    timeout -s KILL 60 "$GW" layer-make --clumps --n 600 --width-rm "$w" --t-max 1e-4 --quiet --out s4.txt \
        >/dev/null 2>"$tmp/w.err"
    rc=$?
    if [ "$w" = 19.0 ]; then [ $rc = 2 ] && grep -q "clumps in a box of --width-rm 19 start" "$tmp/w.err" || bad="$bad $w:$rc"
    elif [ $rc != 0 ]; then bad="$bad $w:$rc"; fi
done
if [ -z "$bad" ]; then ok "--clumps --n 600: --width-rm 19.0 refused, every width of three digits from 19.1 to 23.8 runs"
else ko "--clumps --n 600: widths against the range named (width:exit):$bad"; fi
# the rule is not monotonic in the width (why no width is named "or more")
r1=$("$GW" layer-make --clumps --n 1500 --width-rm 30.7 --t-max 1e-4 --quiet --out s4.txt >/dev/null 2>&1; echo $?)
r2=$("$GW" layer-make --clumps --n 1500 --width-rm 30.8 --t-max 1e-4 --quiet --out s4.txt 2>&1 >/dev/null |
    grep -c "from 30\.9 to 35\.9 passes")
r3=$("$GW" layer-make --clumps --n 1500 --width-rm 30.9 --t-max 1e-4 --quiet --out s4.txt >/dev/null 2>&1; echo $?)
if [ "$r1$r2$r3" = 010 ]; then ok "--clumps --n 1500: width-rm 30.7 runs, 30.8 refused naming 30.9 to 35.9, 30.9 runs"
else ko "--clumps --n 1500: width-rm 30.7 exit $r1, 30.8 refusals naming 30.9 to 35.9 $r2, 30.9 exit $r3"; fi

# --- 5 within the bound: a valid settled clump pile in a narrow box ---
if timeout -s KILL 300 "$GW" layer-make --clumps --n 30 --width-rm 6 --seed 1 --json --quiet --out n30.txt \
    >n30.json 2>n30.err; then
    /usr/bin/python3 - n30.json $(discs_outside n30.txt) <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
n, rows, out = map(int, sys.argv[2:5])
ok = d["converged"] is True and rows == n and d["n_bodies"] == 30 and not out and 0.6 <= d["floor_load"] <= 1.4
print(("PASS" if ok else "FAIL") + ": --clumps --n 30 --width-rm 6: converged %s, %d bodies, %d discs, %d outside "
      "the box, floor load %g" % (d["converged"], d["n_bodies"], rows, out, d["floor_load"]))
PYEOF
else
    echo "FAIL: --clumps --n 30 --width-rm 6: $(head -c 300 n30.err)"
fi >n30.out
if grep -q "^PASS" n30.out; then ok "$(cut -c7- n30.out)"; else ko "$(cat n30.out)"; fi

test_summary test_layer_make_clump_column
