#!/bin/bash
# test_sweep_same_pile.sh GRANWAVE SRCDIR: one pile under two names (issue 18,
# class 8: duplicated cases counted silently).
#  1 A layer sweep told its grid's samples apart by file identity (device and
#    inode) alone: a copy of a sample, or layer-make run twice with one seed
#    and options into two files, is another file with other bytes (its
#    comments record the command that made it) and the same particles. Each
#    case ran twice (exit 0) and layer-stats' binary check counted each point
#    twice ("n 8" where 4 are distinct). The sweep compares samples by their
#    pile now (particles, box, mass law, clump mass, settling record:
#    gw_layer_sample_pile_hash): refused naming both files, exit 2, one line,
#    nothing written, by `sweep`, `sweep --check` and Python's sweep
#    (GranwaveValueError naming sample). Samples differing in one particle's
#    radius by 1e-9 m, or made with another seed, still run.
#  2 A table with such rows (a sweep of a build before, or two sweeps joined)
#    is refused by layer-stats naming the table, the line, both samples and
#    the cases (exit 2, nothing written), made here by a sweep over two samples
#    that the old build ran; a table of two different piles is read as before.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

mk() { make_sample "$1" --n 20 --width-rm 10 --t-max 0.05 "${@:2}"; }
mk a.txt --seed 2
mk b.txt --seed 2
mk c.txt --seed 3
cp a.txt copy.txt && printf '# a comment added\n' >>copy.txt
# the same pile, with one radius changed by 1e-9 m (the last particle line's third column)
$PY - <<'EOF'
lines = open("a.txt").read().split("\n")
i = max(k for k, l in enumerate(lines) if l and not l.startswith("#") and len(l.split()) >= 3)
f = lines[i].split()
f[2] = repr(float(f[2]) - 1e-9)
lines[i] = " ".join(f)
open("near.txt", "w").write("\n".join(lines))
EOF
cmp -s a.txt b.txt && ko "a.txt and b.txt are byte-identical: the case needs two files with different bytes" ||
    ok "a.txt and b.txt: one seed and options, different bytes (their comments)"

# ini FILE SAMPLES: a layer sweep of 4 impact points over SAMPLES
ini() {
    printf '[sweep]\nmodel = layer\n[grid]\nsample = %s\npoint = 0:3\npoints = 4\n[params]\nt-max = 0.002\n' "$2" >"$1"
}

# --- 1 the sweep ---
for two in "a.txt, b.txt" "a.txt, copy.txt" "c.txt, a.txt, b.txt"; do
    ini f.ini "$two"
    rm -rf o
    if exits_refused "sample = $two" "^granwave sweep: f.ini: case [0-9]+: sample: '.*/a.txt' and '.*/(b|copy).txt' hold the same pile" 60 \
        "$GW" sweep f.ini --out o --jobs 1; then ok "sample = $two: one pile under two names refused"; fi
    [ -e o ] && ko "sample = $two: wrote o" || ok "sample = $two: nothing written"
    rm -rf o
    if exits_refused "sample = $two --check" "^granwave sweep: f.ini: case [0-9]+: sample: .* hold the same pile" 60 \
        "$GW" sweep f.ini --out o --check; then ok "sample = $two: sweep --check refuses it"; fi
    [ -e o ] && ko "sample = $two --check: wrote o" || ok "sample = $two --check: nothing written"
done
for two in "a.txt, c.txt" "a.txt, near.txt"; do
    ini f.ini "$two"
    rm -rf o
    "$GW" sweep f.ini --out o --jobs 1 >/dev/null 2>err.txt && [ "$(grep -vc '^#' o/results.csv)" -eq 9 ] &&
        ok "sample = $two: two piles, 8 cases" || ko "sample = $two did not run ($(head -c 300 err.txt))"
done

# (a module that does not load prints one check, failed: py_checks 2 says so too)
py_checks 2 <<'EOF'
def run(samples):
    return granwave.sweep("layer", {"sample": samples, "point": [0, 1, 2, 3]}, points=4, t_max=0.002, jobs=1)
refused("Python sweep over a.txt, b.txt (naming sample and both files)", ["sample", "a.txt", "b.txt"], run,
        ["a.txt", "b.txt"])
try:
    r = run(["a.txt", "c.txt"])
    check(len(r["bounced"]) == 8, "Python sweep over two piles: %d rows" % len(r["bounced"]))
except Exception as e:  # noqa: BLE001
    print("FAIL: Python sweep over a.txt, c.txt raised %s: %s" % (type(e).__name__, e))
EOF

# --- 2 layer-stats on a table that ran one pile twice ---
# the table an older build wrote for "a.txt, b.txt": the sweep over
# "a.txt, c.txt" with c.txt's rows given a.txt's cells (its file name and
# hash kept, as the older build wrote them: the hashes differed)
ini f.ini "a.txt, c.txt"
rm -rf ac && "$GW" sweep f.ini --out ac --jobs 1 >/dev/null 2>&1 || ko "sweep a.txt, c.txt failed"
mkdir -p dup
$PY - <<'EOF'
lines = open("ac/results.csv").read().split("\n")
head = next(i for i, l in enumerate(lines) if l.startswith("case,"))
cols = lines[head].split(",")
ks, ns = cols.index("sample"), cols.index("settling_warning")
rows = [l.split(",") for l in lines[head + 1:] if l]
a = [r for r in rows if r[ks].endswith("/a.txt")]
for r in rows:
    if r[ks].endswith("/c.txt"):
        twin = next(x for x in a if x[2] == r[2])    # the same point
        r[4:ns + 1] = twin[4:ns + 1]                  # every model cell from x_impact on
open("dup/results.csv", "w").write("\n".join(lines[:head + 1] + [",".join(r) for r in rows]) + "\n")
EOF
if exits_refused "layer-stats over one pile twice" "^granwave layer-stats: dup/results.csv:[0-9]+: sample '.*/c.txt' holds the pile of sample '.*/a.txt' \(line [0-9]+\) under another name: each of their 4 rows" 60 \
    "$GW" layer-stats dup/results.csv --out so; then ok "layer-stats: a table of one pile under two names refused"; fi
[ -e so ] && ko "layer-stats: wrote so" || ok "layer-stats: nothing written"
# one row alike by chance is not one pile: only point 0 copied
$PY - <<'EOF'
lines = open("ac/results.csv").read().split("\n")
head = next(i for i, l in enumerate(lines) if l.startswith("case,"))
cols = lines[head].split(",")
ks, ns = cols.index("sample"), cols.index("settling_warning")
rows = [l.split(",") for l in lines[head + 1:] if l]
a0 = next(r for r in rows if r[ks].endswith("/a.txt") and r[2] == "0")
for r in rows:
    if r[ks].endswith("/c.txt") and r[2] == "0":
        r[4:ns + 1] = a0[4:ns + 1]
open("one.csv", "w").write("\n".join(lines[:head + 1] + [",".join(r) for r in rows]) + "\n")
EOF
"$GW" layer-stats one.csv >/dev/null 2>err.txt && ok "layer-stats: one row alike of four read" ||
    ko "layer-stats: one row alike refused ($(head -c 300 err.txt))"
"$GW" layer-stats ac/results.csv --json >ac.json 2>err.txt && $PY - ac.json <<'EOF' && ok "layer-stats: two piles read, binary n 8" || ko "layer-stats: two piles ($(head -c 300 err.txt))"
import json, sys
d = json.load(open(sys.argv[1]))
b = d["binary"]
sys.exit(0 if len(b) == 1 and b[0]["block_loss_first_contact"]["n"] == 8 else 1)
EOF

test_summary test_sweep_same_pile
