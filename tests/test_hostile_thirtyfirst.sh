#!/bin/bash
# test_hostile_thirtyfirst.sh GRANWAVE SRCDIR: what the thirty-first hostile
# pass found, fixed at its root and asserted here.
#  1 A drop refused only after the whole drop had run. The drop runs the
#    column's fall and bounces over t-max, then its first collision again by
#    the chain's own code, whose plan bounds its work before it runs (a light
#    bead ringing between heavy ones, chain_ring_check; its sampling and
#    steps). That plan was made only when the first collision came: drop --n 3
#    --radii 4e-3,1e-6,4e-3 ran the drop for about 23 s (progress lines on
#    stderr), then exited 2 naming --radii. The bounds of the first
#    collision's plan that hold whatever t-max it is cut at are now checked
#    before the drop runs (chain_collide_drop_check): exit 2, one line naming
#    --radii, nothing written, and in Python the progress callback is never
#    called. A drop within the bounds (a 3e-5 m bead between two of 4e-3 m)
#    still runs.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
SRC=$(cd "$SRC" && pwd)
cd "$tmp" || exit 1
export LC_ALL=C
export LSAN_OPTIONS="suppressions=$SRC/tests/lsan.supp:print_suppressions=0"

# --- 1 the drop's first collision planned before the drop ---
# (the time limit only guards against a hang: before, the refusal came after
# the drop, with its progress lines)
REFUSE_TIMEOUT=300 refused "drop --radii 4e-3,1e-6,4e-3: refused before the drop runs (one line, nothing written)" \
    "^granwave drop --radii: bead 2 \(.* kg\) is .* times lighter than bead 1" \
    drop --n 3 --radii 4e-3,1e-6,4e-3 --out o
if runs_json "drop, a 3e-5 m bead between two of 4e-3 m" d.json drop --n 3 --radii 4e-3,3e-5,4e-3 --height 1e-5 \
    --t-max 1e-3 --quiet; then
    [ "$(jq_py d.json "d['n']")" = 3 ] && ok "drop within the ring bound still runs (exit 0)" || ko "drop within the bound: $(head -c 200 d.json)"
fi
py_checks <<'EOF'
import granwave
calls = []
try:
    granwave.drop(n=3, radii=[4e-3, 1e-6, 4e-3], progress=lambda done, total: calls.append(done))
    print("FAIL: Python drop with radii 4e-3, 1e-6, 4e-3 ran")
except granwave.GranwaveValueError as e:
    print(("PASS: " if "radii" in str(e) else "FAIL: ") + "Python drop: GranwaveValueError naming radii")
print(("PASS: " if not calls else "FAIL: ") + "Python drop: refused before the drop ran (the progress callback "
      "called %d times)" % len(calls))
EOF

test_summary test_hostile_thirtyfirst
