#!/bin/bash
# test_sensor_ring_explicit.sh GRANWAVE SRCDIR: the explicit methods (cvode
# adams, arkode erk) on a sensor body that rings far faster than the
# collision (issue 18). Their step is held to the ring by their stability,
# whatever the tolerance (1e-7 kg on 1e13 N/m, n = 3: erk 2.11 million steps
# at 1e-12, 2.08 at 1e-8), and their errors stay undamped in the ring: at
# 1e14 N/m erk took 8.2 million steps (33 s) and adams 9.5 million (44 s),
# F_max 7.2e-5 and 3.9e-6 N above arkode dirk's (10,393 steps, 0.6 s), where
# the converged ring is 3.8e-7 N; at 1e13 erk's F_max was 2.4e-5 N above RK4's
# at 5e-12 s (0.235 N at 1e-8), bdf's and dirk's 2.1e-6 N below (the ring they
# step over). Beyond 5e5 radians of the ring over the collision, for a ring
# more than 1e3 times the beads' shortest contact's pi/tau, they are now
# refused before the run, naming --sensor-stiffness, the estimated steps and
# bdf, by chain, falcon, drop, sweeps and Python; below (1e12 N/m: 3.5e5
# radians, erk within 3.8e-6 N of RK4, the implicit methods 1.2e-5) and
# without a body they run as before.
# The timeouts (20 s) only stop the runs of the code before.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

PAT="^granwave (chain|falcon|drop|sweep)[^:]*(: [^:]*: case 0)?:? ?(--)?sensor-stiffness: a sensor body ringing at .* rad/s .* times the beads' shortest contact's pi/tau, turns .* radians over .* above 5e\+05: (arkode erk|cvode adams) \(explicit\) holds its step to it at any tolerance, about .* steps.*use cvode bdf or arkode dirk"
B14="--n 3 --sensor-mass 1e-7 --sensor-stiffness 1e14"
B13="--n 3 --sensor-mass 1e-7 --sensor-stiffness 1e13"
# shellcheck disable=SC2086
refused "chain on 1e-7 kg, 1e14 N/m under arkode erk (8.2 million steps, F_max 7.2e-5 N high before)" "$PAT" \
    chain $B14 --solver arkode --out o
# shellcheck disable=SC2086
refused "chain on 1e-7 kg, 1e14 N/m under cvode adams (9.5 million steps before)" "$PAT" \
    chain $B14 --solver cvode --method adams --out o
# shellcheck disable=SC2086
refused "chain on 1e-7 kg, 1e13 N/m under arkode erk at rtol 1e-8 (F_max 0.235 N high before)" "$PAT" \
    chain $B13 --solver arkode --rtol 1e-8 --atol 1e-8 --out o
refused "falcon --n 1:3 on 1e-7 kg, 1e14 N/m under arkode erk" "$PAT" \
    falcon --n 1:3 --heights none --sensor-mass 1e-7 --sensor-stiffness 1e14 --solver arkode --out o
# the drop's ring over its t-max: 1e9 rad/s over 1 ms, within the body's general step bound (2e7 steps)
refused "drop on 1e-7 kg, 1e11 N/m to 1 ms under arkode erk" "$PAT" \
    drop --n 3 --sensor-mass 1e-7 --sensor-stiffness 1e11 --t-max 1e-3 --solver arkode --out o
printf '[sweep]\nmodel = chain\n[grid]\nn = 2:3\n[params]\nsensor_mass = 1e-7\nsensor_stiffness = 1e14\nsolver = arkode\n' >ring.ini
refused "sweep --check of chain cases on 1e-7 kg, 1e14 N/m under arkode erk" "$PAT" sweep ring.ini --out o --check
refused "sweep of chain cases on 1e-7 kg, 1e14 N/m under arkode erk" "$PAT" sweep ring.ini --out o --quiet

# --- what still runs: the implicit methods on that body, the explicit ones without one or on a slow one ---
# shellcheck disable=SC2086
if runs_json "chain on 1e-7 kg, 1e14 N/m under arkode dirk" dirk.json chain $B14 --solver arkode --method dirk --quiet; then
    [ "$(jq_py dirk.json "d['steps'] < 1e5")" = True ] && ok "  dirk steps over the ring ($(jq_py dirk.json "d['steps']") steps)" ||
        ko "  dirk: $(jq_py dirk.json "d['steps']") steps"
fi
runs_json "chain --n 3 under arkode erk (no sensor body)" erk.json chain --n 3 --solver arkode --quiet &&
    ok "chain --n 3 under arkode erk runs"
# 1e-3 kg on 1e9 N/m: about 1e6 rad/s, a few hundred radians over the collision
if runs_json "chain on 1e-3 kg, 1e9 N/m under arkode erk" e9.json chain --n 3 --sensor-mass 1e-3 --sensor-stiffness 1e9 --solver arkode --quiet &&
    runs_json "chain on 1e-3 kg, 1e9 N/m under cvode bdf" b9.json chain --n 3 --sensor-mass 1e-3 --sensor-stiffness 1e9 --quiet; then
    [ "$(jq_py e9.json "abs(d['f_max'] / $(jq_py b9.json "d['f_max']") - 1) < 1e-7")" = True ] &&
        ok "  erk on a slow sensor body runs, F_max within 1e-7 of bdf's" ||
        ko "  erk on a slow sensor body: F_max $(jq_py e9.json "d['f_max']") against bdf's $(jq_py b9.json "d['f_max']")"
fi

# a 1e-3 kg body on 1e9 N/m rings about 9 times the beads' shortest contact's
# pi/tau, their own kind of motion: a 1,400-bead column (the longest within
# the column's work bound, N^2 <= 2e6; 20,000 beads, 5.1e5 radians, before
# that bound) turns about 3.6e4 radians of it over the collision and is not
# refused (the plan's check, without the run)
printf '[sweep]\nmodel = chain\n[grid]\nn = 1400\n[params]\nsensor_mass = 1e-3\nsensor_stiffness = 1e9\nsolver = arkode\n' >long.ini
cpu_run 20 "$GW" sweep long.ini --out lo --check >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 0 ] && ok "sweep --check of a 1,400-bead column on a 1e-3 kg, 1e9 N/m body under arkode erk passes" ||
    ko "sweep --check of a long column on a slow body: exit $rc ($(head -c 300 "$tmp/stderr"))"

# --- Python: the same refusal (an alarm stops the code before's run of 33 s) ---
py_checks 3 <<'EOF'
import signal
def alarm(*_):
    raise TimeoutError("still running after 20 s")
signal.signal(signal.SIGALRM, alarm)
for what, kw in (("arkode erk", dict(solver="arkode")), ("cvode adams", dict(solver="cvode", method="adams"))):
    signal.alarm(20)
    try:
        refused("Python chain on 1e-7 kg, 1e14 N/m under %s" % what, ("sensor_stiffness", "bdf", "steps"),
                granwave.chain, n=3, sensor_mass=1e-7, sensor_stiffness=1e14, **kw)
    except TimeoutError as e:
        print("FAIL: Python chain under %s: %s" % (what, e))
    signal.alarm(0)
r = granwave.chain(n=3, sensor_mass=1e-7, sensor_stiffness=1e14, solver="arkode", method="dirk")
check(r["steps"] < 1e5, "Python chain on that body under arkode dirk runs (%d steps)" % r["steps"])
EOF

test_summary test_sensor_ring_explicit
