# The size sweep to T_f (sizes/results.csv) against the notebook's full grid stopped at
# the first free-flight maximum with t-max 0.05 s (../restitution_full/sizes/results.csv,
# same sample, sizes and points). Per R_b/R_m: bounce share; mean +- std over the bouncing
# points of e_n, e, alpha_r (T_f, docs/physics.md 2.3) and of e_n_first, e_first,
# alpha_r_first (the same runs read at the first free-flight maximum); the old table's
# values; T_f and the largest e_n - e_n_first; first-contact block loss in both tables.
# Run: /usr/bin/python3 sizes_compare.py (numbers only read from the two tables).
import os
import numpy as np

os.chdir(os.path.dirname(os.path.abspath(__file__)))


def load(path):
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    head = lines[0].strip().split(",")
    cols = {h: [] for h in head}
    for l in lines[1:]:
        for h, v in zip(head, l.strip().split(",")):
            cols[h].append(float(v))
    return {h: np.array(v) for h, v in cols.items()}


new = load("sizes/results.csv")
old = load("../restitution_full/sizes/results.csv")


def ms(x):
    x = x[np.isfinite(x)]
    if len(x) == 0:
        return "-"
    return f"{x.mean():.3f}+-{x.std(ddof=1):.3f}" if len(x) > 1 else f"{x[0]:.3f}"


print(f"{'R_b/R_m':>7} {'n':>3} {'share':>5} {'share0':>6} {'e_n T_f':>13} {'e_n_first':>13} {'e_n old':>13} "
      f"{'e T_f':>13} {'e_first':>13} {'e old':>13} {'alpha_r T_f':>13} {'alpha_r_1st':>13} {'alpha_r old':>13} "
      f"{'T_f min-max (s)':>16} {'dmax':>6} {'loss':>6} {'loss0':>6}")
for rb in sorted(set(new["rb-rm"])):
    s, s0 = new["rb-rm"] == rb, old["rb-rm"] == rb
    b, b0 = s & (new["bounced"] == 1), s0 & (old["bounced"] == 1)
    d = new["e_n"][b] - new["e_n_first"][b]
    tf = new["t_f"][b]
    print(f"{rb:7g} {s.sum():3d} {b.sum() / s.sum():5.2f} {b0.sum() / s0.sum():6.2f} {ms(new['e_n'][b]):>13} "
          f"{ms(new['e_n_first'][b]):>13} {ms(old['e_n'][b0]):>13} {ms(new['e'][b]):>13} {ms(new['e_first'][b]):>13} "
          f"{ms(old['e'][b0]):>13} {ms(new['alpha_r'][b]):>13} {ms(new['alpha_r_first'][b]):>13} "
          f"{ms(old['alpha_r'][b0]):>13} {tf.min():7.3f}-{tf.max():7.3f} {d.max():6.3f} "
          f"{new['block_loss_first_contact'][s].mean():6.3f} {old['block_loss_first_contact'][s0].mean():6.3f}")

# The first free-flight maximum of the new runs against the old table, point by point, where both bounced
key = {(r, p): i for i, (r, p) in enumerate(zip(old["rb-rm"], old["point"]))}
io = np.array([key[(r, p)] for r, p in zip(new["rb-rm"], new["point"])])
both = (new["bounced"] == 1) & (old["bounced"][io] == 1)
dif = np.abs(new["e_n_first"][both] - old["e_n"][io][both])
print(f"points bouncing in both tables: {both.sum()} of {len(both)}; |e_n_first - e_n old| largest "
      f"{dif.max():.2e}, median {np.median(dif):.2e}, over 0.01 on {np.sum(dif > 0.01)}")
print(f"mean over all bouncing points of e_n - e_n_first: "
      f"{np.mean((new['e_n'] - new['e_n_first'])[new['bounced'] == 1]):.3f}; "
      f"impacts with e_n > e_n_first + 1e-9: {np.sum((new['e_n'] - new['e_n_first'] > 1e-9) & (new['bounced'] == 1))}")
print(f"largest energy_error: {np.nanmax(new['energy_error']):.2e}; T_f up to {np.nanmax(new['t_f']):.3f} s; "
      f"undecided (bounced nan): {int(np.isnan(new['bounced']).sum())}; no bounce: {int((new['bounced'] == 0).sum())}")
