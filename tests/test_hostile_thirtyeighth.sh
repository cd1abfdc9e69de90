#!/bin/bash
# test_hostile_thirtyeighth.sh GRANWAVE SRCDIR: what the thirty-eighth hostile
# pass found, fixed at its root and asserted here.
#  1 What acts on bead contacts given to one body. k is the bead-bead Hertz
#    coefficient; one bead (chain --n 1, drop --n 1) or a drop's block (one
#    body of the column's mass) has no bead contact, and the run ignored it
#    with exit 0: chain --n 1 --k 1e9 gave F_max 66.3889 N, as without it (and
#    as --k 1e3 or 1e14), drop --block --n 3 --k 1e9 its 136.861 N. A bead
#    material given with --mass and the wall's coefficient (--kwall, or a sheet
#    under its fitted law) gives only that k: --material glass changed nothing.
#    Refused naming --k or --material (exit 2, one line, nothing written), by
#    chain, drop and Python's chain and drop. A study over sizes from 1 (its k
#    acts on its other columns), two beads, a sheet under a law that takes the
#    bead's material, and a block whose radii give its mass from the material,
#    still run.
#  2 layer-impact --other-settling where it lets nothing through. The flag runs
#    a sample whose settings line puts its pile away from rest under the
#    impact's material (or a lower friction than the settling's); on a pile of
#    layer-make's defaults hit with the defaults, on one whose contacts carry
#    0.75 of their weight (shear modulus 3e10 against 4e10: a warning, run
#    without the flag too), or on a sample without a settings line, it had no
#    effect, exit 0, nothing said. Refused naming --other-settling (exit 2,
#    nothing written), in the program and Python's layer_impact; where it lets
#    a pile through (friction 20 on a pile settled at 30, shear modulus 4e9)
#    it still runs with its warning, and a sweep's key over samples is kept.
#  3 layer-impact --zero-springs on a sample that carries no springs (no
#    springs section: an older or hand-written sample) starts every spring at
#    zero as it is: the flag ran with exit 0 and no effect. Refused naming
#    --zero-springs (exit 2, nothing written), in the program and Python; on a
#    sample with springs it still runs, and a layer sweep's key is kept.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 k (and a material that gives only k) on one body ---
ONE='has no effect on one body \(n = 1, or a drop.s block\)'
refused "chain --n 1 --k 1e9: refused naming --k, nothing written" \
    "^granwave chain --k: $ONE" chain --n 1 --k 1e9 --out o
refused "chain (n 1 by default) --k 1e14 --json: refused" "^granwave chain --k: $ONE" chain --k 1e14 --json
refused "drop --n 1 --k 1e9: refused naming --k" "^granwave drop --k: $ONE" drop --n 1 --k 1e9 --out o
refused "drop --block --n 3 --k 1e9: the block is one body, refused" \
    "^granwave drop --k: $ONE" drop --block --n 3 --k 1e9 --out o
refused "chain --n 1 --mass 2e-3 --kwall 1e10 --material glass: refused naming --material" \
    "^granwave chain --material: $ONE with mass and the wall.s coefficient given" \
    chain --n 1 --mass 2e-3 --kwall 1e10 --material glass --out o
refused "chain --n 1 --mass 2e-3 --sheet brass (fitted) --material glass: refused naming --material" \
    "^granwave chain --material: $ONE" chain --n 1 --mass 2e-3 --sheet brass --material glass --out o
refused "drop --block --n 3 --mass 2e-3 --kwall 1e10 --material glass: refused naming --material" \
    "^granwave drop --material: $ONE" drop --block --n 3 --mass 2e-3 --kwall 1e10 --material glass --out o

# the law behind it: one bead's collision does not depend on k (what made the
# option idle), and the column's does (what keeps it on two beads)
if runs_json "chain --n 1" c1.json chain --n 1 --quiet && runs_json "chain --n 2" c2.json chain --n 2 --quiet &&
    runs_json "chain --n 2 --k 1e9" c2k.json chain --n 2 --k 1e9 --quiet; then
    f1=$(jq_py c1.json "repr(d['f_max'])") f2=$(jq_py c2.json "repr(d['f_max'])") f2k=$(jq_py c2k.json "repr(d['f_max'])")
    # one bead: F_max = (5/4 m v^2)^(3/5) K^(2/5) (F.13), K alone
    jq_py c1.json "abs(d['f_max'] / ((1.25 * d['settings']['model']['mass'] * 0.09) ** 0.6 * d['settings']['model']['kwall'] ** 0.4) - 1) < 1e-6" | grep -q True &&
        ok "one bead: F_max $f1 N is the Hertz closed form of the wall's K alone" || ko "one bead: F_max $f1 N off F.13"
    /usr/bin/python3 -c "import sys; sys.exit(0 if abs($f2k / $f2 - 1) > 1e-3 else 1)" &&
        ok "two beads: k moves F_max ($f2 -> $f2k N)" || ko "two beads: F_max $f2 and $f2k with --k 1e9"
fi
# controls: where k or the material acts, still run
for args in "chain --n 2 --k 1e9" "chain --n 1 --mass 2e-3 --material glass" \
    "chain --n 1 --mass 2e-3 --sheet brass --sheet-law hertz --material glass" \
    "drop --n 2 --k 1e9" "drop --block --n 3 --radii 4e-3,3e-3,4e-3 --kwall 1e10 --material glass" \
    "falcon --n 1:3 --k 1e9 --heights none" "softwall --n 1:3 --k 1e9"; do
    # shellcheck disable=SC2086
    runs_quiet "$args: runs" $args
done
# a chain sweep's case of n = 1 keeps a k that the grid's other cases take
printf '[sweep]\nmodel = chain\nout = o\n[grid]\nn = 1, 2\n[params]\nk = 1e9\n' >k.ini
runs_quiet "chain sweep over n = 1, 2 with k: valid" sweep k.ini --check
py_checks 6 <<'PYEOF'
refused("Python chain(n=1, k=1e9)", ["k:", "no effect on one body"], granwave.chain, n=1, k=1e9)
refused("Python drop(n=1, k=1e9)", ["k:", "no effect on one body"], granwave.drop, n=1, k=1e9)
refused("Python drop(block=True, n=3, k=1e9)", ["k:", "one body"], granwave.drop, block=True, n=3, k=1e9)
refused("Python chain(n=1, mass, kwall, material)", ["material:", "one body"], granwave.chain, n=1, mass=2e-3,
        kwall=1e10, material="glass")
r = granwave.chain(n=2, k=1e9)
check(r["f_max"] > 0, "Python chain(n=2, k=1e9) runs: F_max %.6g N" % r["f_max"])
r = granwave.sweep("chain", {"n": [1, 2]}, k=1e9)
check(len(r["f_max"]) == 2, "Python sweep over n = 1, 2 with k=1e9 runs both cases")
PYEOF

# --- 2 other-settling with nothing to let through ---
make_sample s.txt --n 20 --width-rm 8
grep -v '^# settings' s.txt >bare.txt
IDLE="^granwave layer-impact --other-settling: has no effect: sample '(s|bare)\.txt' runs without it"
refused "layer-impact --other-settling on a pile settled under the impact's material: refused, nothing written" \
    "$IDLE \(the settling its settings line records is within" layer-impact --sample s.txt --other-settling --out o
refused "layer-impact --other-settling --shear-modulus 3e10 (q 0.75: runs with a warning without it): refused" \
    "$IDLE" layer-impact --sample s.txt --shear-modulus 3e10 --other-settling --out o
refused "layer-impact --other-settling on a sample without a settings line: refused" \
    "$IDLE \(it has no settings line" layer-impact --sample bare.txt --other-settling --out o
# controls: where the flag lets the pile through, it runs (with its warning)
refused "layer-impact --friction 20 on a pile settled at 30, without the flag: refused (the control's premise)" \
    "^granwave layer-impact: sample 's\.txt': it settled with friction 30 deg" layer-impact --sample s.txt --friction 20 --out o
for args in "--friction 20" "--shear-modulus 4e9"; do
    # shellcheck disable=SC2086
    timeout -s KILL 60 "$GW" layer-impact --sample s.txt $args --other-settling --t-max 0.002 --quiet --json \
        >os.json 2>"$tmp/stderr" </dev/null &&
        jq_py os.json "any('run by other-settling' in w for w in d['warnings'])" | grep -q True &&
        ok "layer-impact $args --other-settling: runs, its warning in the JSON" ||
        ko "layer-impact $args --other-settling: exit $? ($(head -c 200 "$tmp/stderr"))"
done
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nx = 0, 0.3\n[params]\nsample = s.txt\nother-settling = 1\nt-max = 0.002\n' >os.ini
runs_quiet "layer sweep with other-settling = 1: valid" sweep os.ini --check
py_checks 3 <<'PYEOF'
refused("Python layer_impact(other_settling=True) on a pile settled under its material",
        ["settling", "no effect"], granwave.layer_impact, sample="s.txt", other_settling=True, t_max=0.002)
refused("Python layer_impact(other_settling=True) on a sample without a settings line",
        ["settling", "no settings line"], granwave.layer_impact, sample="bare.txt", other_settling=True)
warned("Python layer_impact(friction=20, other_settling=True) runs", "settled with friction 30 deg",
       granwave.layer_impact, sample="s.txt", friction=20, other_settling=True, t_max=0.002)
PYEOF

# --- 3 zero-springs on a sample without springs ---
awk '/^springs /{exit} {print}' s.txt | grep -v "^# lines after 'springs'" >nos.txt
refused "layer-impact --zero-springs on a sample without springs: refused, nothing written" \
    "^granwave layer-impact --zero-springs: has no effect: sample 'nos\.txt' carries no springs" \
    layer-impact --sample nos.txt --zero-springs --out o
for smp in s.txt nos.txt; do
    a=--zero-springs
    [ "$smp" = nos.txt ] && a=
    # shellcheck disable=SC2086
    runs_quiet "layer-impact --sample $smp ${a:-(no flag)}: runs" layer-impact --sample "$smp" $a --t-max 0.002
done
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nx = 0, 0.3\n[params]\nsample = nos.txt\nzero-springs = 1\nt-max = 0.002\n' >zs.ini
runs_quiet "layer sweep with zero-springs = 1: valid" sweep zs.ini --check
py_checks 2 <<'PYEOF'
refused("Python layer_impact(zero_springs=True) on a sample without springs", ["springs", "no effect"],
        granwave.layer_impact, sample="nos.txt", zero_springs=True, t_max=0.002)
r = granwave.layer_impact(sample="s.txt", zero_springs=True, t_max=0.002)
check(r is not None, "Python layer_impact(zero_springs=True) on a sample with springs runs")
PYEOF

test_summary test_hostile_thirtyeighth
