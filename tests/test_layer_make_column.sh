#!/bin/bash
# test_layer_make_column.sh GRANWAVE SRCDIR: a pile far taller than its box is
# wide. `layer-make --width-rm 5 --t-max 12` (300 discs) starts as one column
# 300 rows high (the box holds one lattice column: 1.625 m against a pitch of
# 0.977 m); its discs fall up to 290 m, wedge between the walls and lock in
# forces many times the pile's weight, and after 40 s of work it ended (exit 1)
# "did not settle into a valid sample (particle outside the box)": a disc
# 3.3 % of its radius into a wall, about 19 MN against a pile of 2.7 MN.
# layer-make (the library's gw_layer_make: the program and Python alike) now
# refuses a lattice more than 100 times as high as the box is wide before any
# work, exit 2, naming --n and --width-rm, the bound, the n and the width that
# pass; nothing is written. Checks:
#  1 the fault's command is refused: exit 2, one line naming --n, --width-rm 5,
#    the bound 100, "lower --n to 166" and "--width-rm 6.01028", no --out file;
#  2 an existing sample at --out is left as it was (byte for byte);
#  3 Python's layer_make(width_rm=5, t_max=12) raises GranwaveValueError in
#    its keywords (n, width_rm), nothing written;
#  4 the n the message names (166) and the width (for 300 discs) pass the
#    check: short runs (t-max 0.01) exit 0 and write their samples; the
#    width's "or more" holds (the lattice's aspect never rises with the
#    width, unlike the clumps' rows): 6.01 is refused, 6.5, 9, 12.1 and 60
#    run;
#  5 within the bound the narrow box makes a valid settled pile: --n 20 at
#    --width-rm 5 is converged, every disc inside the box to 0.02 r (read from
#    the file), and the floor carries 0.5 to 1.5 of the weight (the JSON).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

msg="^granwave layer-make --n: 300 particles in a box of --width-rm 5 start as a lattice 300 rows high and 1 column wide .* above 100: .* lower --n to 166, or widen the box to --width-rm 6\\.01028 or more\$"

# --- 1 the fault's command refused before any work, nothing written ---
refused "layer-make --width-rm 5 --t-max 12 (a column 300 rows high)" "$msg" \
    layer-make --width-rm 5 --t-max 12 --out "$tmp/o"

# --- 2 an existing sample at --out left as it was ---
make_sample keep.txt --n 10 --width-rm 8 --t-max 0.05
cp keep.txt keep.orig
if exits_refused "layer-make over an existing sample" "$msg" 20 \
    "$GW" layer-make --width-rm 5 --t-max 12 --out keep.txt; then
    if cmp -s keep.txt keep.orig; then ok "layer-make over an existing sample: refused, the sample unchanged"
    else ko "layer-make over an existing sample: the sample changed"; fi
fi

# --- 3 Python refuses it in its keywords ---
py_checks 2 <<'PYEOF'
import os
refused("layer_make(width_rm=5, t_max=12)", ["n: 300 particles in a box of width_rm 5", "above 100",
        "lower n to 166", "width_rm 6.01028"], granwave.layer_make, width_rm=5, t_max=12, out="py.txt")
check(not os.path.exists("py.txt"), "layer_make(width_rm=5, t_max=12): nothing written")
PYEOF

# --- 4 the n and the width the message names pass ---
for args in "--n 166 --width-rm 5" "--n 300 --width-rm 6.01028"; do
    rm -f s4.txt
    # shellcheck disable=SC2086
    if "$GW" layer-make $args --t-max 0.01 --quiet --out s4.txt >/dev/null 2>"$tmp/s4.err" && [ -s s4.txt ]; then
        ok "layer-make $args (the message's suggestion): runs"
    else
        ko "layer-make $args (the message's suggestion): $(head -c 300 "$tmp/s4.err")"
    fi
done

bad=""
for w in 6.01 6.5 9 12.1 60; do
    "$GW" layer-make --width-rm "$w" --t-max 0.01 --quiet --out s4.txt >/dev/null 2>"$tmp/w.err"
    rc=$?
    if [ "$w" = 6.01 ]; then [ $rc = 2 ] && grep -q "start as a lattice 300 rows high" "$tmp/w.err" || bad="$bad $w:$rc"
    elif [ $rc != 0 ]; then bad="$bad $w:$rc"; fi
done
if [ -z "$bad" ]; then ok "300 discs: --width-rm 6.01 refused, 6.5, 9, 12.1 and 60 (wider than 6.01028) run"
else ko "300 discs: widths against '6.01028 or more' (width:exit):$bad"; fi

# --- 5 within the bound: a valid settled pile in the narrow box ---
if "$GW" layer-make --n 20 --width-rm 5 --seed 1 --json --out n20.txt >n20.json 2>n20.err; then
    /usr/bin/python3 - n20.json $(discs_outside n20.txt) <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
n, rows, out = map(int, sys.argv[2:5])
ok = d["converged"] is True and rows == 20 and not out and 0.5 <= d["floor_load"] <= 1.5
print(("PASS" if ok else "FAIL") + ": --n 20 --width-rm 5: converged %s, %d discs, %d outside the box, floor load %g"
      % (d["converged"], rows, out, d["floor_load"]))
EOF
else
    echo "FAIL: --n 20 --width-rm 5: $(head -c 300 n20.err)"
fi >n20.out
if grep -q "^PASS" n20.out; then ok "$(cut -c7- n20.out)"; else ko "$(cat n20.out)"; fi

test_summary test_layer_make_column
