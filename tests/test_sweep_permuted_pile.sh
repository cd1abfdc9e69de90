#!/bin/bash
# test_sweep_permuted_pile.sh GRANWAVE SRCDIR: one pile listed in two orders
# (issue 18, class 8: duplicated cases counted silently).
# A layer sweep refuses a grid whose two samples hold one pile
# (gw_layer_sample_pile_hash; test_sweep_same_pile), but the hash took the
# particles in their file's order: the same particles listed in another order,
# which run the same impact to rounding (the order in which contact forces
# are summed), counted as another pile and each case ran twice. The pile is
# now hashed as a set of bodies, each a set of discs:
#  1 a shuffled copy of a text sample, of an HDF5 sample, and of a clump
#    sample (its lines shuffled and its clumps numbered otherwise) is refused
#    by `sweep`, `sweep --check` and Python's sweep naming both files (exit 2,
#    one line, nothing written);
#  2 a shuffled copy differing in one particle (a radius 1e-9 m smaller, or
#    one disc moved by 1e-9 m), and the clump sample with two touching clumps
#    made one (the same discs grouped otherwise; a hand edit, its settings
#    line dropped), still run as two piles.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

make_sample a.txt --n 20 --width-rm 10 --seed 2 --t-max 0.05
make_sample c.txt --n 20 --clumps --seed 1

# shuffle SRC DST SEED [EDIT]: DST lists SRC's particles in another order
# (and, with a body column, its clumps numbered otherwise), its springs
# following their discs; EDIT: "radius"
# adds 1e-9 m to one radius, "move" moves one disc by 1e-9 m in x, "merge"
# makes two touching clumps one
shuffle() {
    $PY - "$@" <<'EOF'
import math, random, sys
src, dst, seed = sys.argv[1], sys.argv[2], int(sys.argv[3])
edit = sys.argv[4] if len(sys.argv) > 4 else ""
rnd = random.Random(seed)
lines = open(src).read().split("\n")
k = next(i for i, l in enumerate(lines) if l.split()[:1] == ["n"])
n = int(lines[k].split()[1])
rows = [l.split() for l in lines[k + 1:k + 1 + n]]
# the contacts' springs, which follow their two discs
springs = [l.split() for l in lines[k + 2 + n:] if l.strip()] if lines[k + 1 + n].startswith("springs") else []
if edit == "merge":  # the first two clumps with discs that overlap
    pair = next((a[3], b[3]) for a in rows for b in rows if a[3] != b[3] and
                math.hypot(float(a[0]) - float(b[0]), float(a[1]) - float(b[1])) < float(a[2]) + float(b[2]))
    rows = [r[:3] + [pair[0]] if r[3] == pair[1] else r for r in rows]
    # the contacts between the two are no more
    springs = [q for q in springs if q[1] in ("left", "right", "bottom") or rows[int(q[0])][3] != rows[int(q[1])][3]]
    # a hand edit: layer-make's settings line (n 20 clumps) no longer its file's
    # (19), which the reader refuses; without it the sample is a hand-made one
    drop = [i for i, l in enumerate(lines[:k]) if l.startswith("# settings:")]
    lines = [l for i, l in enumerate(lines) if i not in drop]
    k -= len(drop)
order = list(range(n))
rnd.shuffle(order)
where = {old: new for new, old in enumerate(order)}
rows = [rows[i] for i in order]
springs = [[str(where[int(a)]), b if b in ("left", "right", "bottom") else str(where[int(b)]), u] for a, b, u in springs]
rnd.shuffle(springs)
if edit == "radius":  # (larger: the springs' Coulomb bound grows with the overlaps)
    rows[0][2] = repr(float(rows[0][2]) + 1e-9)
if edit == "move":
    rows[0][0] = repr(float(rows[0][0]) + 1e-9)
if len(rows[0]) > 3:  # the clumps numbered otherwise
    ids = list(range(len(rows)))
    rnd.shuffle(ids)
    rows = [r[:3] + [str(ids[int(r[3])])] for r in rows]
tail = ["springs %d" % len(springs)] + [" ".join(q) for q in springs] if springs else []
open(dst, "w").write("\n".join(lines[:k + 1] + [" ".join(r) for r in rows] + tail) + "\n")
EOF
}
shuffle a.txt p.txt 1
shuffle c.txt cp.txt 2
shuffle a.txt pr.txt 3 radius
shuffle a.txt pm.txt 4 move
shuffle c.txt cm.txt 5 merge
[ "$(sort a.txt)" = "$(sort p.txt)" ] && ! cmp -s a.txt p.txt && ok "p.txt: a.txt's lines in another order" ||
    ko "p.txt is not a.txt's lines reordered"
"$GW" layer-impact --sample cp.txt --t-max 1e-4 >/dev/null 2>&1 && "$GW" layer-impact --sample cm.txt --t-max 1e-4 >/dev/null 2>&1 &&
    ok "cp.txt (shuffled, renumbered) and cm.txt (two clumps made one) are samples that run" ||
    ko "cp.txt or cm.txt is not read"
h5=0
if "$GW" version --json | grep -q '"hdf5":[[:space:]]*"'; then
    h5=1
    make_sample a.h5 --n 20 --width-rm 10 --seed 2 --t-max 0.05
    $PY - <<'EOF'
import random, shutil, h5py
shutil.copy("a.h5", "p.h5")
with h5py.File("p.h5", "r+") as f:
    order = list(range(f.attrs["n"]))
    random.Random(6).shuffle(order)
    for k in ("x", "y", "r"):
        v, attrs = f[k][()], dict(f[k].attrs)
        del f[k]
        f.create_dataset(k, data=v[order])
        for a, b in attrs.items():
            f[k].attrs[a] = b
    if "spring_a" in f:  # the springs follow their discs (walls: b < 0)
        where = {old: new for new, old in enumerate(order)}
        for k in ("spring_a", "spring_b"):
            v = f[k][()]
            f[k][...] = [where[int(i)] if i >= 0 else i for i in v]
EOF
fi

# ini FILE SAMPLES: a layer sweep of 2 impact points over SAMPLES
ini() {
    printf '[sweep]\nmodel = layer\n[grid]\nsample = %s\npoint = 0:1\npoints = 2\n[params]\nt-max = 0.002\n' "$2" >"$1"
}

# --- 1 refused: sweep, sweep --check
same=("a.txt, p.txt|a|p" "c.txt, cp.txt|c|cp")
[ $h5 = 1 ] && same+=("a.h5, p.h5|a|p")
for c in "${same[@]}"; do
    two=${c%%|*}; rest=${c#*|}; x=${rest%%|*}; y=${rest#*|}
    ini f.ini "$two"
    pat="^granwave sweep: f.ini: case [0-9]+: sample: '.*/$x\.(txt|h5)' and '.*/$y\.(txt|h5)' hold the same pile"
    rm -rf o
    if exits_refused "sample = $two" "$pat" 60 "$GW" sweep f.ini --out o --jobs 1; then
        ok "sample = $two: one pile in two orders refused"
    fi
    [ -e o ] && ko "sample = $two: wrote o" || ok "sample = $two: nothing written"
    rm -rf o
    if exits_refused "sample = $two --check" "$pat" 60 "$GW" sweep f.ini --out o --check; then
        ok "sample = $two: sweep --check refuses it"
    fi
    [ -e o ] && ko "sample = $two --check: wrote o" || ok "sample = $two --check: nothing written"
done
[ $h5 = 1 ] || echo "SKIP: HDF5 (this build has none)"

# --- 2 two piles: one particle differs, or the clumps are grouped otherwise
for two in "a.txt, pr.txt" "a.txt, pm.txt" "c.txt, cm.txt"; do
    ini f.ini "$two"
    rm -rf o
    "$GW" sweep f.ini --out o --jobs 1 >/dev/null 2>err.txt && [ "$(grep -vc '^#' o/results.csv)" -eq 5 ] &&
        ok "sample = $two: two piles, 4 cases" || ko "sample = $two did not run ($(head -c 300 err.txt))"
done

# --- Python's sweep
py_checks 4 <<'EOF'
def run(samples):
    return granwave.sweep("layer", {"sample": samples, "point": [0, 1]}, points=2, t_max=0.002, jobs=1)
refused("Python sweep over a.txt, p.txt", ["sample", "a.txt", "p.txt", "same pile"], run, ["a.txt", "p.txt"])
refused("Python sweep over c.txt, cp.txt", ["sample", "c.txt", "cp.txt", "same pile"], run, ["c.txt", "cp.txt"])
for two in (["a.txt", "pr.txt"], ["c.txt", "cm.txt"]):
    try:
        check(len(run(two)["bounced"]) == 4, "Python sweep over %s: two piles, 4 rows" % two)
    except Exception as e:  # noqa: BLE001
        print("FAIL: Python sweep over %s raised %s: %s" % (two, type(e).__name__, e))
EOF

test_summary test_sweep_permuted_pile
