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
#  6 a --dt given that --dt-out is not a multiple of was refused (verlet:
#    `--dt 1e-5 --dt-out 7e-6`, `--dt 3e-6` at the default --dt-out; rk4 a
#    --dt above --dt-out: `--solver rk4 --dt 1e-5 --dt-out 7e-6`, `--exact
#    --dt 3e-6 --dt-out 2e-6`), though the samples off the steps are read
#    between them. Now run: the outcome and the steps are those of the same
#    --dt at a --dt-out it divides, bit for bit, from the command, a layer
#    sweep's case and Python.
#  7 verlet's samples between two steps took the tangential forces and the
#    ledgers' integrated terms (E_d, W_K) on a line between the step's ends:
#    a slip puts its increments anywhere in the step, and to 3 ms at
#    --dt-out 7e-6 the tangential strain energy and E_d were off a run at
#    steps of 1 us by up to 51.5 and 49.8 J at those samples against 2.7 and
#    2.5 J at the step ends (1.8e4 J dissipated). They are now a partial
#    step from the step's start, not committed (layer_dem_peek): 2.66 and
#    2.77 J, and a sample reads the E_d and W_K of a run whose last step ends
#    there (--t-max at the sample; 5245.07 against 5245.42 J before).
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

# 6: a --dt given that --dt-out is not a multiple of, run as the same --dt
# at a --dt-out it divides (the steps compared too)
impact g0 --dt 1e-5 || ko "verlet --dt 1e-5 at the default --dt-out ran (exit $?)"
impact g7 --dt 1e-5 --dt-out 7e-6 || ko "verlet --dt 1e-5 --dt-out 7e-6 ran (exit $?: $(head -c 200 g7.err))"
same g0 g7 "verlet --dt 1e-5 --dt-out 7e-6 (was refused)" steps
[ "$(jq_py g7.json "d['settings']['solver']['dt']" 2>/dev/null)" = 1e-05 ] && ok "  its settings record dt 1e-05 s" ||
    ko "  verlet --dt 1e-5 --dt-out 7e-6 records dt $(jq_py g7.json "d['settings']['solver']['dt']" 2>/dev/null)"
impact g3 --dt 3e-6 --dt-out 6e-5 || ko "verlet --dt 3e-6 --dt-out 6e-5 ran (exit $?)"
impact g3d --dt 3e-6 || ko "verlet --dt 3e-6 at the default --dt-out ran (exit $?: $(head -c 200 g3d.err))"
same g3 g3d "verlet --dt 3e-6 at the default --dt-out 2e-5 (was refused)" steps
impact k0 --solver rk4 --dt 1e-5 --dt-out 2e-4 --t-max 0.004 --until verdict || ko "rk4 --dt 1e-5 --dt-out 2e-4 ran (exit $?)"
impact k7 --solver rk4 --dt 1e-5 --dt-out 7e-6 --t-max 0.004 --until verdict ||
    ko "rk4 --dt 1e-5 --dt-out 7e-6 ran (exit $?: $(head -c 200 k7.err))"
same k0 k7 "rk4 --dt 1e-5 above --dt-out 7e-6 (was refused)" steps
impact x0 --exact --dt 3e-6 --dt-out 6e-5 --t-max 0.004 --until verdict || ko "--exact --dt 3e-6 --dt-out 6e-5 ran (exit $?)"
impact x2 --exact --dt 3e-6 --dt-out 2e-6 --t-max 0.004 --until verdict ||
    ko "--exact --dt 3e-6 --dt-out 2e-6 ran (exit $?: $(head -c 200 x2.err))"
same x0 x2 "--exact --dt 3e-6 above --dt-out 2e-6 (was refused)" steps
# a layer sweep's case: its row, less the wave speed (read from the samples
# when they are finer than the checks) and the case's config hash, the same
# at dt-out 7e-6 as at 2e-5
for d in 7e-6 2e-5; do
    printf '[sweep]\nmodel = layer\n[grid]\nvi = 20\n[params]\nsample = s40\ndt = 1e-5\ndt-out = %s\n' "$d" >"sw$d.ini"
    cpu_run 120 "$GW" sweep "sw$d.ini" --out "sw$d" --quiet --jobs 1 >/dev/null 2>"sw$d.err" ||
        ko "a layer sweep with dt = 1e-5 and dt-out = $d ran (exit $?: $(head -c 200 "sw$d.err"))"
done
row() {
    /usr/bin/python3 - "$1/results.csv" <<'PY'
import csv, sys
try:
    rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
except OSError:
    rows = []
print(";".join("%s=%s" % (k, v) for k, v in rows[0].items() if k not in ("wave_speed", "case_config_fnv1a64"))
      if len(rows) == 1 else "no row")
PY
}
r7=$(row sw7e-6)
r2=$(row sw2e-5)
# the fields of row $1 that are not row $2's (at most 4)
row_diff() {
    /usr/bin/python3 -c "import sys; b = sys.argv[2].split(';'); print([x for x in sys.argv[1].split(';') if x not in b][:4])" \
        "$1" "$2"
}
if [ "$r7" != "no row" ] && [ "$r7" = "$r2" ]; then
    ok "a layer sweep's case at dt = 1e-5, dt-out = 7e-6: the row at dt-out 2e-5 ($(echo "$r2" | tr ';' '\n' |
        grep -E '^(e_n|steps)=' | tr '\n' ' '))"
else
    ko "a layer sweep's case at dt = 1e-5, dt-out = 7e-6: $(row_diff "$r7" "$r2")"
fi
py_checks 2 <<'PY'
ks = ("bounced", "e_n", "e", "alpha_r", "e_n_first", "t_f", "penetration", "t_end", "dissipated_first_contact",
      "energy_error", "steps")
def run(**kw):
    try:
        r, _ = caught(granwave.layer_impact, sample="s40", **kw)
        return [repr(r[k]) for k in ks]
    except Exception as e:  # noqa: BLE001
        return ["raised %s" % str(e)[:160]]
a, b = run(dt=1e-5, dt_out=7e-6), run(dt=1e-5, dt_out=2e-5)
check(a == b, "Python: layer_impact(dt=1e-5, dt_out=7e-6) is dt_out=2e-5's (%s)" % [x for x in a if x not in b][:3])
a = run(solver="rk4", dt=1e-5, dt_out=7e-6, t_max=0.004, until="verdict")
b = run(solver="rk4", dt=1e-5, dt_out=2e-4, t_max=0.004, until="verdict")
check(a == b, "Python: rk4 dt=1e-5 above dt_out=7e-6 is dt_out=2e-4's (%s)" % [x for x in a if x not in b][:3])
PY

# 7: verlet's samples between two steps, their tangential strain energy and
# E_d against steps of 1 us (vo, vr of section 5: within twice the step
# ends' own error) and against runs whose last step ends at the sample
e=$(/usr/bin/python3 - vo/ledger.csv vr/ledger.csv <<'PY'
import sys
def load(p):
    try:
        rows = [l.strip().split(",") for l in open(p) if not l.startswith("#")]
    except OSError:
        return None, []
    return rows[0], [[float(x) for x in r] for r in rows[1:]]
h, a = load(sys.argv[1])
_, b = load(sys.argv[2])
on = lambda t: abs(t / 1e-5 - round(t / 1e-5)) < 1e-6
for c in ("strain_tangent", "dissipated"):
    if not a or len(a) != len(b):
        print("%s nan nan" % c)
        continue
    j = h.index(c)
    off = max(abs(x[j] - y[j]) for x, y in zip(a, b) if not on(x[0]))
    at = max(abs(x[j] - y[j]) for x, y in zip(a, b) if on(x[0]))
    print("%s %.4g %.4g" % (c, off, at))
PY
)
while read -r c off at; do
    if /usr/bin/python3 -c "import sys; sys.exit(not float('$off') <= 2 * float('$at'))"; then
        ok "verlet's samples between two steps: $c within $off J of steps of 1 us (the step ends' $at J)"
    else
        ko "verlet's samples between two steps: $c off by $off J against steps of 1 us (the step ends' $at J)"
    fi
done <<<"$e"
for tm in 0.001498 0.002989; do
    cpu_run 120 "$GW" layer-impact --sample s40 --quiet --t-max "$tm" --dt-out 7e-6 --out "ve$tm" >/dev/null 2>&1 ||
        ko "verlet --t-max $tm --out ran"
    d=$(/usr/bin/python3 - vo/ledger.csv "ve$tm/ledger.csv" "$tm" <<'PY'
import sys
def at(p, t):
    try:
        rows = [l.strip().split(",") for l in open(p) if not l.startswith("#")]
    except OSError:
        return {}
    h = rows[0]
    for r in rows[1:]:
        if abs(float(r[0]) - t) < 1e-12:
            return {c: float(r[h.index(c)]) for c in ("dissipated", "mindlin_excess", "strain_tangent")}
    return {}
t = float(sys.argv[3])
a, b = at(sys.argv[1], t), at(sys.argv[2], t)
if not a or not b:
    print("nan no row")
else:
    # the written ledger holds 9 digits: E_d and W_K to them (a partial step
    # of the same arithmetic), E_st to 1e-5 (it takes K_t and the cap at the
    # sample's interpolated positions, the run its last step's end)
    rel = max(abs(a[c] - b[c]) / abs(b[c]) / (2e-9 if c != "strain_tangent" else 1e-5) for c in a)
    print("%.3g %s" % (rel, " ".join("%s %.9g/%.9g" % (c, a[c], b[c]) for c in a)))
PY
)
    read -r rel rest <<<"$d"
    if /usr/bin/python3 -c "import sys; sys.exit(not float('$rel') <= 1)"; then
        ok "verlet's sample at $tm s between two steps: the ledger of a run ending there ($rest)"
    else
        ko "verlet's sample at $tm s between two steps is not the ledger of a run ending there: $rest"
    fi
done

test_summary test_dt_out_bitwise
