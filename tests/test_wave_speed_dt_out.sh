#!/bin/bash
# test_wave_speed_dt_out.sh GRANWAVE SRCDIR: layer-impact's crown wave speeds
# and its cvode outcome do not depend on --dt-out.
#  1 The wave speeds were read from the written series: on the stored
#    300-disc sample (data/measured/restitution_full/sample.txt, 20 m/s),
#    the default 2e-5 s gives 579.95, 570.11 and 609.50 m/s (strain peaks,
#    kinetic peaks, cross-correlation); --dt-out 2e-4 (10 x) gave 578.81,
#    554.31 and 612.64, and 2e-3 (100 x) nulled all three with a warning
#    naming dt-out. They now come from the rings' series at the run's
#    checks (every 2e-5 s on the step grid, whatever dt-out): the three
#    speeds and the rings' arrival times are the default's to 1e-12 (they
#    are equal bit for bit), with no dt-out warning.
#  2 With cvode, --dt-out 0.2 moved e_n in its 12th digit (4.2e-12 relative
#    on the 40-disc pile of `layer-make --n 40`): the checks were at the
#    last sample plus 2e-5 s, summed, where the default's samples are at
#    k 2e-5 s, so the solver stopped at times a rounding apart, and at each
#    stop the layer projects the interpolated state and may restart CVODE
#    from it. The checks now lie at j 2e-5 s and a sample on one stops
#    there: e_n, e, T_f, the penetration and energy_error are the default's
#    to 1e-15 (bit for bit).
#  Controls: a --dt-out that is no multiple of the checks (3e-5 s) moves
#  cvode's e_n within 1e-7 (it stopped cvode between them until the
#  forty-fourth session, 1.2e-9 measured; bit for bit since:
#  test_dt_out_bitwise); rk4 at a step that does not divide --dt-out 5e-3
#  reads its speeds at its checks (every 20 steps; they were null, put to
#  dt-out, when its samples were its checks).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
export LC_ALL=C
SRC=$(cd "$SRC" && pwd)
cd "$tmp" || exit 1
PY=/usr/bin/python3
SAMPLE=$SRC/data/measured/restitution_full/sample.txt

# run NAME SAMPLE ARGS...: layer-impact --json into NAME.json; sets rc
run() {
    local name=$1 smp=$2
    shift 2
    cpu_run 120 "$GW" layer-impact --sample "$smp" --quiet --json "$@" >"$name.json" 2>"$name.err"; rc=$?
}
# diff A B TOL KEYS...: "ok", or the keys (and crowns arrays) that differ by more
# than TOL relative, or are null in either
differ() {
    $PY - "$@" <<'EOF'
import json, math, sys
a, b = (json.load(open(f + ".json")) for f in sys.argv[1:3])
tol = float(sys.argv[3])
def close(x, y):
    if x is None or y is None:
        return False
    return abs(x - y) <= tol * abs(y)
bad = []
for k in sys.argv[4:]:
    if k.startswith("crowns."):
        x, y = a["crowns"][k[7:]], b["crowns"][k[7:]]
        if len(x) != len(y) or any(not ((p is None and q is None) or close(p, q)) for p, q in zip(x, y)):
            bad.append(k)
    elif not close(a.get(k), b.get(k)):
        bad.append("%s (%s vs %s)" % (k, a.get(k), b.get(k)))
print("ok" if not bad else " ".join(bad))
EOF
}
# warned NAME: the --json warnings starting "dt-out:" (empty when none)
warned() { json_warnings "$1.json" dt-out:; }

speeds=(wave_speed wave_speed_kinetic wave_speed_xcorr wave_speed_err crowns.peak_strain_t crowns.peak_kinetic_t
        crowns.xcorr_delay)
# --- 1 the wave speeds at 10 x and 100 x the default --dt-out ---
run d0 "$SAMPLE"
[ $rc -eq 0 ] && [ "$(differ d0 d0 0 wave_speed wave_speed_kinetic wave_speed_xcorr)" = ok ] &&
    ok "control: the default impact on the stored sample gives the three wave speeds" ||
    ko "control: the default impact on the stored sample: exit $rc, speeds not all given: $(head -c 300 d0.err)"
for m in 10:2e-4 100:2e-3; do
    run "d${m%%:*}" "$SAMPLE" --dt-out "${m#*:}"
    got=$(differ "d${m%%:*}" d0 1e-12 "${speeds[@]}")
    [ $rc -eq 0 ] && [ "$got" = ok ] &&
        ok "--dt-out ${m#*:} (${m%%:*} x the default): the three wave speeds and arrivals are the default's" ||
        ko "--dt-out ${m#*:}: exit $rc, differ from the default: $got"
    [ -z "$(warned "d${m%%:*}")" ] && ok "--dt-out ${m#*:}: no dt-out warning" ||
        ko "--dt-out ${m#*:}: warned '$(warned "d${m%%:*}")'"
done
got=$(differ d100 d0 1e-12 e_n t_f t_end energy_error penetration)
[ "$got" = ok ] && ok "control: --dt-out 2e-3 gives the default's outcome and end" || ko "--dt-out 2e-3: $got"

# Python: the same run through the library
lib=$(dirname "$GW")/lib/libgranwave.so
if [ -f "$lib" ] && [ -d "$SRC/python/granwave" ]; then
    out=$(GRANWAVE_LIB=$lib PYTHONPATH=$SRC/python PYTHONDONTWRITEBYTECODE=1 cpu_run 120 $PY -c '
import json, sys, warnings, granwave
d0 = json.load(open("d0.json"))
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.layer_impact(sample=sys.argv[1], dt_out=2e-3)
keys = ("wave_speed", "wave_speed_kinetic", "wave_speed_xcorr")
print(all(abs(r[k] - d0[k]) <= 1e-12 * abs(d0[k]) for k in keys), sum("dt_out" in str(x.message) for x in w))
' "$SAMPLE" 2>&1 | tr '\n' ' ')
    [ "$out" = "True 0 " ] && ok "Python layer_impact(dt_out=2e-3): the default's three speeds, no warning" ||
        ko "Python layer_impact(dt_out=2e-3): $out"
else
    echo "SKIP: Python check (no $lib)"
fi

# --- 2 cvode: e_n at --dt-out 0.2 ---
cpu_run 120 "$GW" layer-make --n 40 --out s40 --quiet >/dev/null 2>&1 ||
    { ko "layer-make --n 40 (the pile the cvode checks impact)"; test_summary test_wave_speed_dt_out; exit; }
outcome=(e_n e t_f e_n_first penetration energy_error t_end)
run c0 s40 --solver cvode
[ $rc -eq 0 ] || ko "control: cvode at the default --dt-out: exit $rc: $(head -c 300 c0.err)"
run c2 s40 --solver cvode --dt-out 0.2
got=$(differ c2 c0 1e-15 "${outcome[@]}")
[ $rc -eq 0 ] && [ "$got" = ok ] && ok "cvode --dt-out 0.2: e_n, e, T_f, the penetration, energy_error are the default's" ||
    ko "cvode --dt-out 0.2: exit $rc, differ from the default: $got"
run c3 s40 --solver cvode --dt-out 3e-5
got=$(differ c3 c0 1e-7 e_n e t_f)
[ $rc -eq 0 ] && [ "$got" = ok ] && ok "control: cvode --dt-out 3e-5 (off the checks) moves e_n within 1e-7" ||
    ko "control: cvode --dt-out 3e-5: exit $rc: $got"

# --- rk4 at a step not dividing dt-out: its samples were its checks (null
# speeds put to dt-out); since the forty-fourth session its checks are every
# 20 steps whatever --dt-out, and the speeds come from them ---
run r5 s40 --solver rk4 --dt 3e-6 --dt-out 5e-3
[ $rc -eq 0 ] && [ -z "$(warned r5)" ] && [ "$($PY -c "import json; print(json.load(open('r5.json')).get('wave_speed_kinetic'))")" != None ] &&
    ok "rk4 --dt 3e-6 --dt-out 5e-3: speeds read at its checks, no dt-out warning" ||
    ko "rk4 --dt 3e-6 --dt-out 5e-3: exit $rc, warning '$(warned r5)'"

test_summary test_wave_speed_dt_out
