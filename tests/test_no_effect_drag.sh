#!/bin/bash
# test_no_effect_drag.sh GRANWAVE SRCDIR: the "no effect" checks that softwall,
# the sensor body's dashpot and the guide's friction lacked.
#  1 softwall --damping kk --gamma 1e-8 ran its cases undamped in silence:
#    the contact damping predicted below rtol is counted per case (its wall's
#    stiffness, its size) and said once on stderr with the count (control:
#    gamma 1e2 is not warned).
#  2 chain --sensor-damping and --guide-friction/--guide-viscous had no check:
#    below rtol (sensor: zeta = c/(2 sqrt(k_s m_s)); guide: (F_c/v + c_g)
#    t_col/m) they are warned of, on stderr and in --json; eps_eff measured on
#    both sides: warned, within 1e-11 of the constant 1e-30's (any dashpot or friction at all moves the integration by up to 1.1e-10); a small value
#    not warned moves eps_eff by more than the solver's noise (5e-11).
#  3 A chain sweep whose every case is one body (n = 1) given k ran (chain
#    --n 1 --k 1e3 is refused): its --check and run refuse it, exit 2, one
#    line naming the config, the key and the first case, nothing written; a
#    grid where k acts on the cases of n 3 runs.
#  4 A sweep's warnings named the single run's flags (--vimp) where its
#    config has keys (vimp): a chain sweep's overlap warning says "a lower
#    vimp or gravity", no "--" left of a key.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$2/tests/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# eps FLAGS...: chain's eps_eff (repr) and W when a warning says "has no effect", else -
eps() { timeout 120 "$GW" chain "$@" --json --quiet 2>/dev/null | /usr/bin/python3 -c '
import json, sys
d = json.load(sys.stdin)
print(repr(d["eps_eff"]), "W" if any("has no effect" in w for w in d["warnings"]) else "-")'; }
# near A B TOL / far A B TOL: |A - B| below / above TOL
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < t) }'; }
far() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d > t) }'; }

# --- 1 softwall ---
timeout 300 "$GW" softwall --n 1:4 --damping kk --gamma 1e-8 --quiet >/dev/null 2>sw.err; rc=$?
if [ $rc -eq 0 ] && [ "$(grep -c 'no effect' sw.err)" -eq 1 ] &&
    grep -q "granwave softwall: warning: the contact damping has no effect in 4 of 4 cases" sw.err; then
    ok "1 softwall gamma 1e-8: $(cut -c1-110 sw.err)"
else
    ko "1 softwall gamma 1e-8: exit $rc, '$(head -c 300 sw.err)'"
fi
timeout 300 "$GW" softwall --n 1:4 --damping kk --gamma 1e2 --quiet >/dev/null 2>sw2.err; rc=$?
if [ $rc -eq 0 ] && ! grep -q 'no effect' sw2.err; then
    ok "  control: softwall gamma 1e2 not warned"
else
    ko "  softwall gamma 1e2: exit $rc, '$(head -c 300 sw2.err)'"
fi

# --- 2 the sensor's dashpot and the guide's friction ---
S="--n 1 --sensor-mass 1e-2 --sensor-stiffness 1e7"
read -r e0 _ <<<"$(eps $S --sensor-damping 1e-30)"
read -r e1 w1 <<<"$(eps $S --sensor-damping 1e-10)"   # zeta 1.6e-13
read -r e2 w2 <<<"$(eps $S --sensor-damping 1e-6)"    # zeta 1.6e-9
if [ "$w1" = W ] && near "$e1" "$e0" 1e-11; then
    ok "2 sensor-damping 1e-10 (zeta 1.6e-13) warned, eps_eff $e1 against $e0"
else
    ko "2 sensor-damping 1e-10: warned '$w1', eps_eff $e1 against $e0"
fi
if [ "$w2" = - ] && far "$e2" "$e0" 5e-11; then
    ok "  sensor-damping 1e-6 (zeta 1.6e-9) not warned, eps_eff moved to $e2"
else
    ko "  sensor-damping 1e-6: warned '$w2', eps_eff $e2 against $e0"
fi
read -r g0 _ <<<"$(eps --n 1 --guide-friction 1e-30)"
read -r v0 _ <<<"$(eps --n 1 --guide-viscous 1e-30)"
read -r g1 w1 <<<"$(eps --n 1 --guide-friction 1e-12)"
read -r g2 w2 <<<"$(eps --n 1 --guide-friction 1e-6)"
read -r g3 w3 <<<"$(eps --n 1 --guide-viscous 1e-12)"
read -r g4 w4 <<<"$(eps --n 1 --guide-viscous 1e-6)"
if [ "$w1" = W ] && near "$g1" "$g0" 1e-11 && [ "$w3" = W ] && near "$g3" "$v0" 1e-11; then
    ok "  guide-friction 1e-12 and guide-viscous 1e-12 warned, eps_eff $g1 $g3 against $g0"
else
    ko "  guide 1e-12: warned '$w1' '$w3', eps_eff $g1 $g3 against $g0"
fi
if [ "$w2" = - ] && far "$g2" "$g0" 5e-11 && [ "$w4" = - ] && far "$g4" "$v0" 5e-11; then
    ok "  guide-friction 1e-6 and guide-viscous 1e-6 not warned, eps_eff $g2 $g4"
else
    ko "  guide 1e-6: warned '$w2' '$w4', eps_eff $g2 $g4 against $g0"
fi
timeout 60 "$GW" chain --n 1 --guide-friction 1e-12 --quiet >/dev/null 2>g.err
if [ "$(wc -l <g.err)" -eq 1 ] && grep -q "^granwave chain: warning: the guide's friction (--guide-friction 1e-12 N" g.err; then
    ok "  stderr: $(cut -c1-100 g.err)"
else
    ko "  chain --guide-friction 1e-12 stderr: '$(head -c 300 g.err)'"
fi
# --- 3 a chain sweep's k on one body ---
printf '[sweep]\nmodel = chain\nout = O\n[grid]\nk = 1e3, 2e3\n[params]\nn = 1\n' >one.ini
printf '[sweep]\nmodel = chain\nout = P\n[grid]\nn = 1, 3\n[params]\nk = 1e9\n' >mixed.ini
want="granwave sweep: one.ini: k: has no effect on one body (n = 1) in any case (2 of 2 cases; the first, case 0)"
for how in --check run; do
    [ "$how" = run ] && how=
    timeout 120 "$GW" sweep one.ini $how --quiet >/dev/null 2>one.err; rc=$?
    if [ $rc -eq 2 ] && [ "$(wc -l <one.err)" -eq 1 ] && grep -qF "$want" one.err && [ ! -e O ]; then
        ok "3 sweep ${how:-run} of n = 1 given k: exit 2, $(cut -c1-110 one.err)"
    else
        ko "3 sweep ${how:-run} of n = 1 given k: exit $rc, O $( [ -e O ] && echo made || echo absent), '$(head -c 300 one.err)'"
    fi
done
timeout 300 "$GW" sweep mixed.ini --quiet >/dev/null 2>mixed.err; rc=$?
if [ $rc -eq 0 ] && [ "$(grep -vc '^#' P/results.csv)" -eq 3 ]; then
    ok "  a grid over n = 1, 3 given k runs its 2 cases"
else
    ko "  grid over n = 1, 3 given k: exit $rc, '$(head -c 300 mixed.err)'"
fi
# --- 4 a sweep's warnings name its keys ---
printf '[sweep]\nmodel = chain\nout = V\n[grid]\nvimp = 1e-6, 1000\n[params]\nmass = 1e3\nkwall = 1e3\n' >v.ini
timeout 300 "$GW" sweep v.ini --quiet >/dev/null 2>v.err; rc=$?
if [ $rc -eq 0 ] && grep -q "the largest contact overlap was .*(a lower vimp or gravity," v.err && ! grep -q -- '--' v.err; then
    ok "4 sweep warning names keys: $(grep -o '(a lower vimp[^)]*)' v.err)"
else
    ko "4 sweep warning: exit $rc, '$(head -c 400 v.err)'"
fi
test_summary test_no_effect_drag
