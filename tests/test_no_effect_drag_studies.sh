#!/bin/bash
# test_no_effect_drag_studies.sh GRANWAVE SRCDIR: the studies' "no effect"
# check of the sensor body's dashpot and the guide's friction (the forty-second
# session left it to chain and drop: falcon, wavespeed and softwall given
# --sensor-damping 1e-12 or --guide-friction 1e-15 ran in silence). Each study
# tallies the predicted effect over its columns (sensor: zeta = c/(2 sqrt(k_s
# m_s)); guide: (F_c/v + c_g) t_col/m at each column's size and speed, its
# wall's stiffness for softwall) and warns once, on stderr and in --json, when
# even the largest is below rtol, naming how many columns:
#  1 falcon --sensor-damping 1e-12: warned; its F_max (mean, least, largest),
#    T_q and tau_N those of --sensor-damping 1e-30 to 1e-11 relative (the
#    warning is true; any dashpot at all moves RK4's steps, 2.4e-7 from none,
#    as test_no_effect_drag found for chain); --sensor-damping 10 (zeta 0.016)
#    not warned.
#  2 wavespeed --guide-friction 1e-15: warned, --json too; --guide-friction
#    1e-3 not warned.
#  3 softwall --sensor-damping 1e-12 --guide-viscous 1e-15: both warned, once
#    each, --json too; --guide-viscous 1e-2 not warned.
# Each study's run, --json and control are one function (study).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$2/tests/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

SB="--sensor-mass 1e-2 --sensor-stiffness 1e7"
F="falcon --n 1:3 --vimp 0.3 --heights none --quiet"
W="wavespeed --n 6:8 --vimp 0.3 --quiet"
S="softwall --n 1:3 --quiet"

# study NUM CMD WARN CONTROL PATTERN WHAT...: the study CMD (its flags, one
# string) run with the flags WARN says once of each WHAT (its text after
# "the ": "sensor body's dashpot", "guide's friction") that it has no effect,
# on stderr, where a line matches PATTERN too, and in --json (NUM.json kept);
# run with the flags CONTROL it says "no effect" nowhere. Three checks.
study() {
    local num=$1 cmd=$2 warn=$3 control=$4 pattern=$5 name=${2%% *} rc w bad=""
    shift 5
    # shellcheck disable=SC2086 # CMD, WARN, CONTROL: flags split at blanks
    timeout 300 "$GW" $cmd $warn >/dev/null 2>"$num.err"; rc=$?
    for w in "$@"; do
        [ "$(grep -c "^granwave $name: warning: the $w.* has no effect" "$num.err")" -eq 1 ] || bad="$bad [$w]"
    done
    if [ $rc -eq 0 ] && [ -z "$bad" ] && grep -q "$pattern" "$num.err"; then
        ok "$num $name $warn: warned once of each ($*): $(grep -o 'no effect: [^,]*' "$num.err" | head -1)"
    else
        ko "$num $name $warn: exit $rc, not once or not as expected:$bad '$(head -c 500 "$num.err")'"
    fi
    # shellcheck disable=SC2086
    timeout 300 "$GW" $cmd $warn --json >"$num.json" 2>/dev/null
    if /usr/bin/python3 - "$num.json" "$@" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["warnings"]
sys.exit(any(sum(x.startswith("the " + what) and "has no effect" in x for x in w) != 1 for what in sys.argv[2:]))
PY
    then
        ok "  and in --json"
    else
        ko "  $name $warn --json: not one warning of each ($*): $(head -c 300 "$num.json")"
    fi
    # shellcheck disable=SC2086
    timeout 300 "$GW" $cmd $control >/dev/null 2>"$num.c.err"; rc=$?
    if [ $rc -eq 0 ] && ! grep -q "no effect" "$num.c.err"; then
        ok "  control: $name $control not warned"
    else
        ko "  $name $control: exit $rc, '$(head -c 300 "$num.c.err")'"
    fi
}

# --- 1 falcon: its numbers those of a dashpot of 1e-30 ---
study 1 "$F $SB" "--sensor-damping 1e-12" "--sensor-damping 10" \
    "granwave falcon: warning: the sensor body's dashpot (--sensor-damping 1e-12 N s/m) has no effect: its damping ratio c/(2 sqrt(k_s m_s)) = 1.58e-15 (the largest over the study's 3 columns) is below the solver's rtol" \
    "sensor body's dashpot"
# shellcheck disable=SC2086
timeout 300 "$GW" $F $SB --sensor-damping 1e-30 --json >f0.json 2>/dev/null
if /usr/bin/python3 - 1.json f0.json <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
keys = ("f_max_mean", "f_max_min", "f_max_max", "t_q", "tau_n_last")
fa = [a["velocities"][0][k] for k in keys]
fb = [b["velocities"][0][k] for k in keys]
assert all(abs(x - y) <= 1e-11 * abs(y) for x, y in zip(fa, fb)), (fa, fb)
PY
then
    ok "  its F_max, T_q and tau_N those of --sensor-damping 1e-30 to 1e-11"
else
    ko "  falcon --sensor-damping 1e-12 --json: F_max, T_q or tau_N differ from --sensor-damping 1e-30"
fi
# --- 2 wavespeed ---
study 2 "$W" "--guide-friction 1e-15" "--guide-friction 1e-3" \
    "granwave wavespeed: warning: the guide's friction (--guide-friction 1e-15 N, --guide-viscous 0 N s/m) has no effect: .* (the largest over the study's 3 columns), is below the solver's rtol" \
    "guide's friction"
# --- 3 softwall: both at once ---
study 3 "$S" "$SB --sensor-damping 1e-12 --guide-viscous 1e-15" "--guide-viscous 1e-2" \
    "^granwave softwall: warning: the sensor body's dashpot (--sensor-damping 1e-12 N s/m) has no effect" \
    "sensor body's dashpot" "guide's friction"
test_summary test_no_effect_drag_studies
