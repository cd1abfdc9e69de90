# wide R_b = 3 R_m column (7 H, 5 points 1.25 m apart) per sample: shares and H* from layer-stats
import json, os, subprocess
os.chdir(os.path.dirname(os.path.abspath(__file__)))
gw = os.environ.get("GW", "../../../../build/granwave")
print("# R_b = 3 R_m, V_i = 20 m/s, normal incidence, 5 points 1.25 m apart (5 m span), H/R_m = 4, 6, 8, 10, 12, 16, 20")
print("# A = layer-make --seed S (discs), B = layer-make --clumps --seed S (clumps of aspect 1 to 4); seed 1: ../wide/wide_A.csv, wide_B.csv; made by run.sh and /usr/bin/python3 summ.py")
print(f"{'kind':4} {'seed':4} {'poros':>6} {'shares':>36} {'H*':>8} {'pen_rm(H=20)':>12}")
for kind in ("A", "B"):
    for seed in (1, 2, 3, 4):
        f = f"../wide/wide_{kind}.csv" if seed == 1 else f"wide_{kind}_seed{seed}.csv"
        mk = "../seeds/make_A_seed1.json" if (seed, kind) == (1, "A") else f"make_{kind}_seed{seed}.json"
        if not os.path.exists(f):
            continue
        por = json.load(open(mk))["porosity"] if os.path.exists(mk) else float("nan")
        st = json.loads(subprocess.run([gw, "layer-stats", f, "--json"], capture_output=True, text=True, check=True).stdout)
        gs = sorted(st["groups"], key=lambda g: g["keys"]["height-rm"])
        sh = ", ".join(f"{g['bounce_share']:g}" for g in gs)
        # H*: first crossing of S between a bouncing cell and the next one up
        S, hs = st["criterion"], None
        for a, b in zip(gs, gs[1:]):
            if a["bounce_share"] >= S and b["bounce_share"] < S:
                ha, hb = a["keys"]["height-rm"], b["keys"]["height-rm"]
                hs = ha + (a["bounce_share"] - S) / (a["bounce_share"] - b["bounce_share"]) * (hb - ha)
                break
        hstr = "every H" if hs is None and gs[-1]["bounce_share"] >= S else (f"{hs:.2f}" if hs is not None else "none")
        print(f"{kind:4} {seed:4} {por:6.3f} {sh:>36} {hstr:>8} {gs[-1]['penetration_rm']['mean']:12.2f}")
