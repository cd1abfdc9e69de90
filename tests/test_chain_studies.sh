#!/bin/bash
# test_chain_studies.sh GRANWAVE SRCDIR: the wave-speed and soft-wall studies
# (issue 3) through the program's JSON.
#  - wavespeed: the fitted exponent of each estimator within 0.005 of 1/5 (the
#    Hertz chain's exact scaling); the T_q and front estimators within 5 % of
#    each other at every velocity for short columns (N = 5..20, the paper's fit
#    range) and C3 within 5 % of the momentum balance's 2 (F.27). The long-wave
#    group speed c0 of the compressed chain is not a front speed: the momentum
#    balance gives c0 = sqrt(3/2) V, so c0/v_front must be within 5 % of
#    sqrt(3/2), and c0/sqrt(3/2) within 5 % of the other two estimators.
#  - softwall: F_max(N) non-decreasing for K = 1e9 < K_c; N_d grows as K falls
#    (2e9, 1e9, 5e8); (F.8) at the measured N_d within 1 of it (the paper's
#    relation); F_max flat (spread < 5 %) for K = 2e10 > K_c; verdicts.
set -u
GW=$1
PY=/usr/bin/python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$GW" wavespeed --quiet --n 5:20 --vimp 0.1,0.3,0.6 --json >"$tmp/ws.json" || { echo "FAIL: wavespeed run"; exit 1; }
for K in 2e10 2e9 1e9 5e8; do
    "$GW" softwall --quiet --n 1:25 --kwall $K --json >"$tmp/sw_$K.json" || { echo "FAIL: softwall K=$K"; exit 1; }
done
$PY - "$tmp" <<'PYEOF'
import json, sys
d = sys.argv[1]
fails = passes = 0
def check(ok, what):
    global fails, passes
    print(("PASS" if ok else "FAIL") + ": " + what)
    if ok: passes += 1
    else: fails += 1
ws = json.load(open(f"{d}/ws.json"))
for name, fit in ws["fits"].items():
    check(abs(fit["beta"] - 0.2) < 0.005, f"wavespeed {name}: beta = {fit['beta']:.6f} within 0.005 of 1/5")
for v, a, b, g in zip(ws["v_imp"], ws["v_tq"], ws["v_front"], ws["v_group"]):
    check(abs(a - b) / a < 0.05, f"v_imp {v}: 4R/T_q {a:.1f} and front {b:.1f} m/s within 5 %")
    check(abs(g / b / 1.5**0.5 - 1) < 0.05, f"v_imp {v}: group speed {g:.1f} / front {b:.1f} = {g/b:.4f} within 5 % of sqrt(3/2)")
    gf = g / 1.5**0.5
    check(max(abs(gf - a) / a, abs(gf - b) / b) < 0.05, f"v_imp {v}: group/sqrt(3/2) {gf:.1f} within 5 % of 4R/T_q and front")
check(ws["max_disagreement"] < 0.05, f"three front-speed estimators within {100*ws['max_disagreement']:.1f} % < 5 %")
check(abs(ws["c3"] - 2) / 2 < 0.05, f"C3 (T_q, N = 5..20) = {ws['c3']:.4f} within 5 % of 2 (F.27)")
sw = {K: json.load(open(f"{d}/sw_{K}.json")) for K in ["2e10", "2e9", "1e9", "5e8"]}
f = sw["1e9"]["f_max"]
check(all(f[i+1] >= f[i] * (1 - 1e-6) for i in range(len(f)-1)), "K = 1e9: F_max(N) non-decreasing")
check(f[-1] > 1.5 * f[0], f"K = 1e9: F_max grows with N ({f[0]:.2f} -> {f[-1]:.2f} N)")
nd = [sw[K]["n_d"] for K in ["2e9", "1e9", "5e8"]]
check(None not in nd and nd[0] < nd[1] < nd[2], f"N_d grows as K falls: {nd}")
for K in ["2e9", "1e9", "5e8"]:
    p = sw[K]["n_d_predicted"]
    check(p is not None and abs(p - sw[K]["n_d"]) <= 1, f"K = {K}: (F.8) ceil(tau_max(N_d)/T_q) = {p} within 1 of the measured N_d = {sw[K]['n_d']}")
for K in ["2e9", "1e9", "5e8"]:
    check(sw[K]["wall"] == "soft", f"K = {K} < K_c is soft")
r = sw["2e10"]["f_max"]
check(sw["2e10"]["wall"] == "rigid" and (max(r) - min(r)) / min(r) < 0.05, f"K = 2e10 rigid, F_max spread {(max(r)-min(r))/min(r):.4f} < 5 %")
check(abs(sw["1e9"]["k_c"] - 4.0e9) / 4.0e9 < 0.02, f"K_c = {sw['1e9']['k_c']:.4g} within 2 % of 4.0e9 (docs/physics.md)")
print(f"{passes} passed, {fails} failed")
sys.exit(1 if fails else 0)
PYEOF
