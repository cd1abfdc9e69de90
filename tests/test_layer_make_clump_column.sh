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
#    width, the bound 16, "lower --n to 115" / "61" and "--width-rm 19.2" /
#    "13.5" or more, no --out file (`--width-rm 6 --n 300`, 77 times: a box
#    of 5 R_m is now refused first, narrower than the longest clump lies flat
#    in: test_layer_make_clump_wedge);
#  2 an existing sample at --out is left as it was (byte for byte);
#  3 Python's layer_make(clumps=True, width_rm=8, n=600) raises
#    GranwaveValueError in its keywords (n, width_rm), nothing written;
#  4 the n and the width the messages name pass the check: short runs
#    (t-max 0.01) exit 0 and write their samples; one clump more than the n
#    named is refused (the n is the largest that passes);
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

msg() { # msg N W NFIT WFIT: the refusal's line as a pattern
    echo "^granwave layer-make --n: $1 clumps in a box of --width-rm $2 start in rows .* m high .*, .* times as high as the box is wide, above 16: .* lower --n to $3, or widen the box to --width-rm $4 or more\$"
}

# --- 1 the fault's commands refused before any work, nothing written ---
refused "layer-make --clumps --width-rm 8 --n 600 (rows 86 times the width)" "$(msg 600 8 115 '19\.2')" \
    layer-make --clumps --width-rm 8 --n 600 --out "$tmp/o"
refused "layer-make --clumps --width-rm 6 --n 300 (rows 77 times the width)" "$(msg 300 6 61 '13\.5')" \
    layer-make --clumps --width-rm 6 --n 300 --out "$tmp/o"

# --- 2 an existing sample at --out left as it was ---
make_sample keep.txt --n 10 --width-rm 8 --t-max 0.05
cp keep.txt keep.orig
if exits_refused "layer-make --clumps over an existing sample" "$(msg 600 8 115 '19\.2')" 60 \
    "$GW" layer-make --clumps --width-rm 8 --n 600 --out keep.txt; then
    if cmp -s keep.txt keep.orig; then ok "layer-make --clumps over an existing sample: refused, the sample unchanged"
    else ko "layer-make --clumps over an existing sample: the sample changed"; fi
fi

# --- 3 Python refuses it in its keywords ---
py_checks 2 <<'PYEOF'
import os
refused("layer_make(clumps=True, width_rm=8, n=600)", ["n: 600 clumps in a box of width_rm 8", "above 16",
        "lower n to 115", "width_rm 19.2"], granwave.layer_make, clumps=True, width_rm=8, n=600, out="py.txt")
check(not os.path.exists("py.txt"), "layer_make(clumps=True, width_rm=8, n=600): nothing written")
PYEOF

# --- 4 the n and the width the messages name pass; one clump more does not ---
for args in "--n 115 --width-rm 8" "--n 600 --width-rm 19.2" "--n 61 --width-rm 6" "--n 300 --width-rm 13.5"; do
    rm -f s4.txt
    # shellcheck disable=SC2086
    if timeout -s KILL 60 "$GW" layer-make --clumps $args --t-max 0.01 --quiet --out s4.txt >/dev/null 2>"$tmp/s4.err" &&
        [ -s s4.txt ]; then
        ok "layer-make --clumps $args (the message's suggestion): runs"
    else
        ko "layer-make --clumps $args (the message's suggestion): $(head -c 300 "$tmp/s4.err")"
    fi
done
refused "layer-make --clumps --width-rm 8 --n 116 (one clump above the n named)" "$(msg 116 8 115 '[0-9.]+')" \
    layer-make --clumps --width-rm 8 --n 116 --out "$tmp/o"

# --- 5 within the bound: a valid settled clump pile in a narrow box ---
if timeout -s KILL 300 "$GW" layer-make --clumps --n 30 --width-rm 6 --seed 1 --json --quiet --out n30.txt \
    >n30.json 2>n30.err; then
    /usr/bin/python3 - n30.txt n30.json <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[2]))
width, n, rows = None, None, []
for line in open(sys.argv[1]):
    f = line.split()
    if not f or line.startswith("#"):
        continue
    if f[0] == "width":
        width = float(f[1])
    elif f[0] == "n":
        n = int(f[1])
    elif f[0] == "springs":
        break
    elif n is not None and len(f) >= 3 and len(rows) < n:
        rows.append(tuple(map(float, f[:3])))
out = [i for i, (x, y, r) in enumerate(rows) if x - r < -0.02 * r or x + r > width + 0.02 * r or y - r < -0.02 * r]
ok = d["converged"] is True and len(rows) == n and d["n_bodies"] == 30 and not out and 0.6 <= d["floor_load"] <= 1.4
print(("PASS" if ok else "FAIL") + ": --clumps --n 30 --width-rm 6: converged %s, %d bodies, %d discs, %d outside "
      "the box, floor load %g" % (d["converged"], d["n_bodies"], len(rows), len(out), d["floor_load"]))
PYEOF
else
    echo "FAIL: --clumps --n 30 --width-rm 6: $(head -c 300 n30.err)"
fi >n30.out
if grep -q "^PASS" n30.out; then ok "$(cut -c7- n30.out)"; else ko "$(cat n30.out)"; fi

test_summary test_layer_make_clump_column
