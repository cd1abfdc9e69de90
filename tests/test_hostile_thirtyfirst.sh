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
#  2 A sensor body's steps underestimated. The plan took cvode's steps over a
#    sensor body's oscillation as 2 a radian of sqrt(k_s/M): measured, 7 to
#    37 at the default tolerance 1e-12, and a heavy bead's contact stiffens
#    the body further. chain --n 3 --radius 1 --sensor-mass 1e-7
#    --sensor-stiffness 1e9 passed the plan (5.5e6 steps estimated), ran 2e8
#    steps (438 s on an idle machine) into the run's own bound and exited 1
#    ("... or use cvode", which it was using). The estimate now takes the
#    contact's stiffness into the body's frequency and 20 steps a radian at
#    1e-12 (fewer at looser tolerances): refused at once, exit 2 naming
#    --sensor-stiffness, nothing written. A body within the bound still runs.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

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

# --- 2 a sensor body's steps: its contact's stiffness, 20 a radian at 1e-12 ---
# (60 s only guards against the run of the code before, which took minutes)
REFUSE_TIMEOUT=60 refused "chain --radius 1 --sensor-mass 1e-7 --sensor-stiffness 1e9: refused before the run" \
    "^granwave chain --sensor-stiffness: a sensor body oscillating at .* rad/s .* needs about .* steps over the collision" \
    chain --n 3 --radius 1 --sensor-mass 1e-7 --sensor-stiffness 1e9 --out o
if runs_json "chain, a sensor body within the bound" s.json chain --n 3 --sensor-mass 1e-3 --sensor-stiffness 1e9; then
    jcheck_ok=$(jq_py s.json "d['f_max'] > 0 and d['converged']")
    [ "$jcheck_ok" = True ] && ok "chain --sensor-mass 1e-3 --sensor-stiffness 1e9 still runs (exit 0, converged)" ||
        ko "chain with a sensor body within the bound: $(head -c 200 s.json)"
fi

test_summary test_hostile_thirtyfirst
