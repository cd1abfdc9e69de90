#!/bin/bash
# test_dt_out_bitwise.sh GRANWAVE SRCDIR: layer-impact's outcome, and its
# energy_error, do not depend on --dt-out under cvode, rk4 and arkode, bit
# for bit.
#  1 cvode stopped at every sample: a --dt-out that is not a multiple of the
#    run's checks (2e-5 s), or finer, added stops between them, where the
#    layer projects the state and restarts cvode, CVODE's first step after a
#    restart knows the next stop and its root search ends there. On the
#    40-disc pile of `layer-make --n 40`, e_n moved by 1.7e-10 at --dt-out
#    3e-5 and by 7.5e-9 at 1e-5, and the run ended at a sample (t_end 0.30603
#    s against 0.30604). The samples between the checks are now read on the
#    way (layer_advance_peek): cvode integrates towards the next check and
#    the state at the sample is interpolated in the step that passed it.
#  2 rk4 stopped at its samples too (the last step to a sample shortened, the
#    state projected there): e_n moved by 1.6e-15 at 3e-5 and 1e-4 s and 1e-14
#    at 1e-5. At a step that does not divide --dt-out (--dt 3e-6) the
#    samples were its only checks: e_n moved by 4e-9 between --dt-out 2e-5,
#    3e-5, 1e-5 and 2e-3 and the crowns were read from the samples (96.7 m/s
#    and a dt-out warning at 2e-3, 98.06 at 2e-5). Its checks are now every
#    20 steps (on the step grid) whatever --dt-out, its samples between them
#    a step of rk4 from the start of the step that holds them, made aside;
#    the crowns are read at the checks when the samples are coarser.
#  3 arkode still stopped at every sample: e_n moved by 7.6e-8 at --dt-out
#    3e-5, 7.0e-8 at 1e-5 and 9.3e-9 at 7e-6 (t_end 0.30603 s against
#    0.30604). It now reads them on the way as cvode does (gw_sun_advance_peek:
#    ARKode's dense output in the step that passed the sample).
#  4 energy_error took the samples between the checks (read on the way,
#    interpolated): cvode at --dt-out 7e-6 read 1.41879066e-6 against
#    1.41879065e-6 at the default. It is now taken where the run stops (the
#    checks, the samples on them, t-max) and compared bit for bit here.
#  5 verlet (the default solver) made its automatic step the largest divisor
#    of --dt-out below it, so that every sample ended a step: e_n_first 0.1493427
#    (10000 steps) at --dt-out 1e-6 against 0.1493279 (1000) at the default, to
#    --t-max 0.01 on the pile; e_n 0.1493350 against 0.1493279 at 7e-6 over
#    the whole run; energy_error 3.3876e-5 against 3.3818e-5 at 1e-5 (a
#    multiple of the step, checked at every sample). Its step is now the
#    default's at every --dt-out, checked every 2e-5 s, and a sample off the
#    steps is read between two steps (a cubic Hermite between the step's ends
#    for positions and velocities, a line for the rest). A control: the block's
#    height at samples between the steps lies within 1e-6 m of a run at steps
#    of 1 us (2.9e-7 m measured; the step's end would be 6e-5 m off).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "$0")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

cpu_run 120 "$GW" layer-make --n 40 --out s40 --quiet >/dev/null 2>&1 ||
    { ko "layer-make --n 40 (the pile the checks impact)"; test_summary test_dt_out_bitwise; exit; }

# impact NAME ARGS...: layer-impact on s40, --json into NAME.json
impact() {
    local name=$1
    shift
    cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json "$@" >"$name.json" 2>"$name.err"
}
# the outcome fields compared bit for bit (repr of the doubles), and the
# wave speeds where the crowns are read at the checks
KEYS="bounced e_n e alpha_r e_n_first t_f penetration t_end dissipated_first_contact t_contact_open energy_error"
SPEEDS="wave_speed wave_speed_kinetic wave_speed_xcorr"
# differ NAME1 NAME2 [speeds]: the fields of NAME1 that are not NAME2's, as
# "KEY (V1 vs V2)"; empty when all are the same
differ() {
    local keys=$KEYS
    [ "${3:-}" = speeds ] && keys="$keys $SPEEDS"
    [ "${3:-}" = steps ] && keys="$keys steps"
    local -a k a b
    read -ra k <<<"$keys"
    read -ra a <<<"$(json_fields "$1.json" %r "${k[@]}")"
    read -ra b <<<"$(json_fields "$2.json" %r "${k[@]}")"
    local i out=
    for i in "${!k[@]}"; do
        [ "${a[$i]:-}" = "${b[$i]:-}" ] || out="$out ${k[$i]} (${a[$i]:-} vs ${b[$i]:-})"
    done
    echo "${out# }"
}
field() { json_fields "$1.json" %r "$2"; }
warned() { json_warnings "$1.json" | grep -e dt-out | tr -d '\n'; }

# same BASE NAME WHAT [speeds]: NAME's outcome (and wave speeds) is BASE's bit for bit
same() {
    local d
    d=$(differ "$2" "$1" "${4:-}")
    [ -z "$d" ] && ok "$3: the default's outcome bit for bit (e_n $(field "$1" e_n), t_end $(field "$1" t_end))" ||
        ko "$3 moves the outcome: $d"
}

# 1: cvode; the wave speeds too where the crowns are read at the checks (a
# --dt-out finer than them reads its own samples, which resolve them better)
impact c0 --solver cvode || ko "cvode at the default --dt-out ran (exit $?)"
for d in 3e-5 1e-5 7e-6 1e-4 2e-3; do
    impact "c_$d" --solver cvode --dt-out "$d" || ko "cvode at --dt-out $d ran (exit $?)"
    if [ "$d" = 1e-5 ] || [ "$d" = 7e-6 ]; then same c0 "c_$d" "cvode --dt-out $d"; else same c0 "c_$d" "cvode --dt-out $d" speeds; fi
done
[ "$(field c0 wave_speed)" != null ] && ok "control: cvode's default gives a wave speed" ||
    ko "cvode's default gives no wave speed"

# 2: rk4 at its default step (1e-6 s) and at a step that does not divide
# --dt-out (3e-6 s: checks every 6e-5 s, finer samples read the crowns)
impact r0 --solver rk4 --dt-out 2e-5 --t-max 0.004 --until verdict || ko "rk4 at the default --dt-out ran (exit $?)"
impact r3 --solver rk4 --dt-out 3e-5 --t-max 0.004 --until verdict || ko "rk4 at --dt-out 3e-5 ran (exit $?)"
same r0 r3 "rk4 --until verdict --dt-out 3e-5"
impact q0 --solver rk4 --dt 3e-6 || ko "rk4 --dt 3e-6 at the default --dt-out ran (exit $?)"
for d in 3e-5 1e-5 2e-3; do
    impact "q_$d" --solver rk4 --dt 3e-6 --dt-out "$d" || ko "rk4 --dt 3e-6 at --dt-out $d ran (exit $?)"
    same q0 "q_$d" "rk4 --dt 3e-6 --dt-out $d"
done
w=$(warned q_2e-3)
[ -z "$w" ] && [ "$(field q_2e-3 wave_speed_kinetic)" != null ] &&
    ok "rk4 --dt 3e-6 --dt-out 2e-3: wave speeds from the checks, no dt-out warning" ||
    ko "rk4 --dt 3e-6 --dt-out 2e-3: wave_speed_kinetic $(field q_2e-3 wave_speed_kinetic), warning '$w'"

# 3: arkode (erk), as cvode
impact a0 --solver arkode || ko "arkode at the default --dt-out ran (exit $?)"
for d in 3e-5 1e-5 7e-6 1e-4 2e-3; do
    impact "a_$d" --solver arkode --dt-out "$d" || ko "arkode at --dt-out $d ran (exit $?)"
    if [ "$d" = 1e-5 ] || [ "$d" = 7e-6 ]; then same a0 "a_$d" "arkode --dt-out $d"; else same a0 "a_$d" "arkode --dt-out $d" speeds; fi
done
[ "$(field a0 energy_error)" != null ] && [ "$(field a0 wave_speed)" != null ] &&
    ok "control: arkode's default gives an energy_error and a wave speed" ||
    ko "arkode's default gives energy_error $(field a0 energy_error), wave speed $(field a0 wave_speed)"

# 5: verlet, the default solver: its steps (compared too) and outcome at any
# --dt-out; to t-max 0.01 s (e_n_first, the first contact, the penetration
# decided) and, at 7e-6, the whole run (e_n)
impact v0 || ko "verlet at the default --dt-out ran (exit $?)"
impact v7 --dt-out 7e-6 || ko "verlet at --dt-out 7e-6 ran (exit $?)"
same v0 v7 "verlet --dt-out 7e-6" steps
impact vt0 --t-max 0.01 || ko "verlet --t-max 0.01 at the default --dt-out ran (exit $?)"
for d in 1e-6 3e-6 7e-6 1e-5; do
    impact "vt_$d" --t-max 0.01 --dt-out "$d" || ko "verlet --t-max 0.01 at --dt-out $d ran (exit $?)"
    same vt0 "vt_$d" "verlet --t-max 0.01 --dt-out $d" steps
done
# control: the samples between the steps (--dt-out 7e-6 on steps of 1e-5 s)
# against a run at steps of 1 us, the block's height (ledger.csv's block_y)
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --t-max 0.003 --dt-out 7e-6 --out vo >/dev/null 2>&1 &&
    cpu_run 120 "$GW" layer-impact --sample s40 --quiet --t-max 0.003 --dt-out 7e-6 --dt 1e-6 --out vr >/dev/null 2>&1 ||
    ko "verlet --t-max 0.003 --dt-out 7e-6 (--dt 1e-6) --out ran"
e=$(/usr/bin/python3 - vo/ledger.csv vr/ledger.csv <<'EOF'
import sys
def col(p):
    try:
        rows = [l.strip().split(",") for l in open(p) if not l.startswith("#")]
    except OSError:
        return []
    i, j = rows[0].index("t"), rows[0].index("block_y")
    return [(float(r[i]), float(r[j])) for r in rows[1:]]
a, b = col(sys.argv[1]), col(sys.argv[2])
off = [abs(x[1] - y[1]) for x, y in zip(a, b) if abs(x[0] / 1e-5 - round(x[0] / 1e-5)) > 1e-6]
print("%.3g %d" % (max(off), len(off)) if len(a) == len(b) and len(off) > 100 else "nan 0")
EOF
)
read -r emax noff <<<"$e"
/usr/bin/python3 -c "import sys; sys.exit(not float('$emax') < 1e-6)" &&
    ok "control: verlet's $noff samples between two steps within $emax m of steps of 1 us (block height)" ||
    ko "verlet's samples between two steps: block height off by $emax m ($noff samples) against steps of 1 us"

test_summary test_dt_out_bitwise
