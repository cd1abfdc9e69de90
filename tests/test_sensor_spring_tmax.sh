#!/usr/bin/env bash
# test_sensor_spring_tmax.sh: the default t-max of a column on a soft sensor
# spring (the fortieth session).
#
# The default t-max is 20 times the collision's expected length, which counted
# the bead transits and the wall contact only. On a sensor body whose spring
# is soft beside the contacts the column rides the spring as one mass, for
# half the period of the column's and the body's mass on it, pi sqrt((sum m +
# M) / k_s): chain --n 3 --sensor-mass 1e-7 --sensor-stiffness 1e3 (7.9 ms) was
# cut at the default 2.2 ms with eps_eff -0.64 and a "raise --t-max" warning,
# as were falcon, softwall, sweeps and Python on it. The expected length now
# counts that ride (chain_collision_length, the plan's one source for every
# path); a rigid sensor's t-max is unchanged to the last bit.
#
# Asserted:
#   1 the fault's command ends by default: no warning, converged, eps_eff in
#     [0, 1] (an elastic spring: within 1e-3 of 1), the momentum restitution
#     equal to -sum m v_f / sum m v_0 of its final velocities, the energy
#     ledger closed within 1e-6; its last wall contact ends within 0.5 % of the
#     spring-mass estimate pi sqrt((3 m + M)/k_s) (measured 1e-4 short);
#     its t-max is 20 (3 T_q + tau_1 + that estimate) to 1e-12;
#   2 a rigid sensor's default t-max is 20 (n T_q + tau_1) to 1e-14 (n = 3, 5);
#   3 a 1 g body on 1e3 N/m ends by default in chain, falcon (--n 1:4), a
#     sweep (n = 2:3, the same eps_eff as chain's, bit for bit) and Python
#     (the program's t_max);
#   4 the heaviest body on the softest spring (1e3 kg on 1e3 N/m, a ride of
#     3.1 s): refused before the run at the default dt-out, naming dt-out and
#     the sensor spring, nothing written; at the dt-out it names it runs to the
#     sensor reading's peak, a quarter of the body's period (pi/2) sqrt(M/k_s),
#     within 1 %;
#   5 a light body on a heavy column (--mass 1e3), whose ride takes 5.5 s and
#     whose body's ring about 7e9 steps, refused naming sensor-stiffness and
#     the spring (it ran: 20.5 ms expected, t-max 0.41 s, its progress
#     saying more than 2 minutes left after 6 s).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

# py FILE EXPR: EXPR over the JSON d of FILE (math imported), printed
py() { $PY -c "import json, math; d = json.load(open('$1')); print($2)"; }

# --- 1 the fault's command (about 5e6 steps: the light body chatters)
timeout -s KILL 600 "$GW" chain --n 3 --sensor-mass 1e-7 --sensor-stiffness 1e3 --quiet --json >"$tmp/f.json" \
    2>"$tmp/f.err" </dev/null
rc=$?
if [ $rc -eq 0 ]; then
    # ended by default; its only warning the chatter on the light body (too
    # costly to run again: test_chatter_warned), on stderr and in --json
    [ "$(grep -c . "$tmp/f.err")" = 1 ] && grep -q "^granwave chain: warning: bead 1 chattered on the sensor body" "$tmp/f.err" &&
        [ "$(py "$tmp/f.json" "len(d['warnings']) == 1 and d['warnings'][0].startswith('bead 1 chattered') and d['converged'] is True and d['wall_done'] is True")" = True ] &&
        ok "1: the fault's command ends by default, its only warning the chatter" || ko "1: cut or warned: $(head -c 300 "$tmp/f.err")"
    [ "$(py "$tmp/f.json" "0 <= d['eps_eff'] <= 1 and abs(d['eps_eff'] - 1) < 1e-3")" = True ] &&
        ok "1: eps_eff $(py "$tmp/f.json" "d['eps_eff']") in [0, 1], within 1e-3 of the elastic spring's 1" ||
        ko "1: eps_eff $(py "$tmp/f.json" "d['eps_eff']")"
    [ "$(py "$tmp/f.json" "abs(-sum(d['final_velocities']) / (3 * d['v_imp']) - d['eps_eff']) < 1e-12 and d['energy_error'] < 1e-6 and d['eps_col'] <= 1 + 1e-9")" = True ] &&
        ok "1: momentum restitution from the final velocities, energy ledger $(py "$tmp/f.json" "d['energy_error']")" ||
        ko "1: momentum/energy: $(py "$tmp/f.json" "(d['final_velocities'], d['eps_eff'], d['energy_error'], d['eps_col'])")"
    est="math.pi * math.sqrt((3 * d['settings']['model']['mass'] + 1e-7) / 1e3)"
    [ "$(py "$tmp/f.json" "abs(d['tau_n'] / ($est) - 1) < 0.005")" = True ] &&
        ok "1: tau_N $(py "$tmp/f.json" "d['tau_n']") s within 0.5 % of pi sqrt((3 m + M)/k_s) = $(py "$tmp/f.json" "$est") s" ||
        ko "1: tau_N $(py "$tmp/f.json" "d['tau_n']") against $(py "$tmp/f.json" "$est")"
    [ "$(py "$tmp/f.json" "abs(d['settings']['solver']['t_max'] / (20 * (3 * d['closed_forms']['t_q'] + d['closed_forms']['tau_1'] + $est)) - 1) < 1e-12")" = True ] &&
        ok "1: t_max $(py "$tmp/f.json" "d['settings']['solver']['t_max']") s = 20 (3 T_q + tau_1 + pi sqrt((3 m + M)/k_s))" ||
        ko "1: t_max $(py "$tmp/f.json" "d['settings']['solver']['t_max']")"
else
    ko "1: the fault's command: exit $rc ($(head -c 300 "$tmp/f.err"))"
fi

# --- 2 a rigid sensor: the default t-max as before, to the last bits
for n in 3 5; do
    runs_json "2: chain --n $n" "$tmp/r.json" chain --n $n || continue
    [ "$(py "$tmp/r.json" "abs(d['settings']['solver']['t_max'] / (20 * ($n * d['closed_forms']['t_q'] + d['closed_forms']['tau_1'])) - 1) < 1e-14")" = True ] &&
        ok "2: chain --n $n: t_max = 20 (n T_q + tau_1) as before" ||
        ko "2: chain --n $n: t_max $(py "$tmp/r.json" "d['settings']['solver']['t_max']") moved"
done

# --- 3 a 1 g body on 1e3 N/m by every path
S="--sensor-mass 1e-3 --sensor-stiffness 1e3"
if runs_json "3: chain --n 3 $S" "$tmp/c.json" chain --n 3 $S; then
    [ "$(py "$tmp/c.json" "d['warnings'] == [] and d['converged'] is True and 0 <= d['eps_eff'] <= 1 and d['t_end'] > 7e-3")" = True ] &&
        ok "3: chain: ends by default at $(py "$tmp/c.json" "d['t_end']") s, eps_eff $(py "$tmp/c.json" "d['eps_eff']")" ||
        ko "3: chain: $(py "$tmp/c.json" "(d['warnings'], d['converged'], d['eps_eff'])")"
fi
if runs_json "3: falcon --n 1:4 $S" "$tmp/fa.json" falcon --n 1:4 --heights none $S --quiet; then
    [ "$(py "$tmp/fa.json" "d['unfinished'] == 0 and d['warnings'] == []")" = True ] &&
        ok "3: falcon: every collision ends by default" || ko "3: falcon: $(py "$tmp/fa.json" "(d['unfinished'], d['warnings'])")"
fi
mkdir -p "$tmp/sw"
printf '[sweep]\nmodel = chain\n[grid]\nn = 2:3\n[params]\nsensor_mass = 1e-3\nsensor_stiffness = 1e3\n' >"$tmp/sw/s.ini"
if timeout -s KILL 120 "$GW" sweep "$tmp/sw/s.ini" --out "$tmp/sw/o" --quiet >/dev/null 2>"$tmp/sw.err" </dev/null; then
    v=$($PY - "$tmp/sw/o/results.csv" "$tmp/c.json" <<'EOF'
import csv, json, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
c = json.load(open(sys.argv[2]))
three = [r for r in rows if r["n"] == "3"]
ok = len(rows) == 2 and all(r["converged"] == "1" and 0 <= float(r["eps_eff"]) <= 1 for r in rows) and \
    len(three) == 1 and float(three[0]["eps_eff"]) == c["eps_eff"]
print("True" if ok else "False: %s" % [(r["n"], r["converged"], r["eps_eff"]) for r in rows])
EOF
)
    [ "$v" = True ] && ok "3: sweep n = 2:3: both converged, n = 3 as chain's" || ko "3: sweep: $v"
else
    ko "3: sweep: $(head -c 300 "$tmp/sw.err")"
fi
pyenv $PY -c "
import json, granwave
r = granwave.chain(n=3, sensor_mass=1e-3, sensor_stiffness=1e3)
c = json.load(open('$tmp/c.json'))
assert r.converged and 0 <= r.eps_eff <= 1, (r.converged, r.eps_eff)
assert r.t_max == c['settings']['solver']['t_max'] and r.eps_eff == c['eps_eff'], (r.t_max, r.eps_eff)
" 2>"$tmp/pyerr" && ok "3: granwave.chain on the 1 g body ends, the program's t_max and eps_eff" ||
    ko "3: Python: $(tail -1 "$tmp/pyerr")"

# --- 4 the heaviest body on the softest spring
H="--n 3 --sensor-mass 1e3 --sensor-stiffness 1e3"
refused "4: chain $H at the default dt-out: refused naming dt-out and the spring" \
    "^granwave chain --dt-out: the default tau_1/200 = .* samples over the collision on the sensor body's spring \(about 3.14 s\).*raise dt-out to 1.1e-06 s or more \(the column rides the sensor body's spring for pi sqrt\(\(sum m \+ M\)/k_s\) = 3.14 s" \
    chain $H --out "$tmp/o"
if runs_json "4: chain $H --dt-out 1.1e-6" "$tmp/h.json" chain $H --dt-out 1.1e-6 --quiet; then
    [ "$(py "$tmp/h.json" "d['converged'] is True and d['warnings'] == [] and abs(d['t_end'] / (math.pi / 2 * math.sqrt(1e3 / 1e3)) - 1) < 0.01")" = True ] &&
        ok "4: ends at the reading's peak, $(py "$tmp/h.json" "d['t_end']") s, a quarter of the body's period (pi/2 s)" ||
        ko "4: $(py "$tmp/h.json" "(d['converged'], d['t_end'], d['warnings'])")"
fi

# --- 5 a light body under a heavy column: refused, not minutes of steps
refused "5: chain --n 3 --mass 1e3 --sensor-mass 1e-7 --sensor-stiffness 1e3: refused naming sensor-stiffness" \
    "^granwave chain --sensor-stiffness: a sensor body oscillating at .* needs about .* steps over the collision on the sensor body's spring \(about 5.46 s" \
    chain --n 3 --mass 1e3 --sensor-mass 1e-7 --sensor-stiffness 1e3 --out "$tmp/o"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
