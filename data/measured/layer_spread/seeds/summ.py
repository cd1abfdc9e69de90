# Per sample and H: share bouncing, penetration (mean +- std over the points, R_m), first-contact
# block loss and mean e_n of the bouncing points, all from `granwave layer-stats`.
import json, os, subprocess
os.chdir(os.path.dirname(os.path.abspath(__file__)))
gw = os.environ.get("GW", "../../../../build/granwave")
print(f"{'kind':4} {'seed':4} {'poros':6} {'H':>3} {'share':>5} {'pen_rm':>12} {'loss1':>6} {'e_n':>6}")
for kind in ("A", "a1"):
    for seed in (1, 2, 3, 4):
        f = f"{kind}_seed{seed}.csv"
        if not os.path.exists(f):
            continue
        por = json.load(open(f"make_{kind}_seed{seed}.json"))["porosity"]
        st = json.loads(subprocess.run([gw, "layer-stats", f, "--json"], capture_output=True, text=True, check=True).stdout)
        for g in sorted(st["groups"], key=lambda g: g["keys"]["height-rm"]):
            pen, en = g["penetration_rm"], g["e_n"]["mean"]
            print(f"{kind:4} {seed:4} {por:.3f} {g['keys']['height-rm']:3g} {g['bounce_share']:5.2f} "
                  f"{pen['mean']:5.2f}+-{pen['std']:.2f} {g['block_loss_first_contact']['mean']:6.2f} "
                  f"{en if en is not None else float('nan'):6.3f}")
