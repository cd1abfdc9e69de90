#!/bin/bash
# test_layer_sample_grading.sh GRANWAVE SRCDIR: a sample's header against its
# particles' radii (docs/formats.md, "Sample files"). A header says the mean
# radius rm and volume_ratio V, the largest over the smallest particle volume;
# the radii then span at most V in volume and each lies within
# [rm / V^(1/3), rm V^(1/3)] (the mean lies between the smallest and the
# largest). layer-impact takes R_b, the rings and the heights in units of the
# header's rm, so a header edited by hand ran a block of another size in
# silence. Checked:
#  1 a layer-make sample whose rm was edited (0.5 and 0.1 for 0.325, the
#    diameter 0.65 for the radius) or whose volume_ratio was (1, 5 for the 9.3
#    the radii span) is refused by layer-impact (exit 2, one line naming the
#    sample, no --out), by a layer sweep's --check, by Python's layer_impact
#    (GranwaveValueError) and as HDF5 (the rm attribute edited);
#  2 what stays legitimate still runs with the same numbers: the sample as
#    written, a hand-made header (no settings line) with rm edited within the
#    bounds (0.4), volume_ratio 0 (unknown) or raised (20), a sample trimmed by --height-rm, a monodisperse sample at
#    volume_ratio 1, a clump sample (members smaller than their bodies).
# Before the fix (the header's rm and volume_ratio never compared with the
# radii) every refusal of part 1 ran: rm 0.5 gave a 2081 kg block instead of
# 879 kg with exit 0. 9 of the 16 checks fail on that binary.
set -u
GW=$1
SRC=$2
PY=/usr/bin/python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=refusal_lib.sh
. "$SRC/tests/refusal_lib.sh"
cd "$tmp" || exit 1

"$GW" layer-make --n 40 --width-rm 10 --seed 4 --out s.txt >/dev/null 2>&1 || { echo "FAIL: layer-make"; exit 1; }
"$GW" layer-make --n 40 --width-rm 10 --seed 4 --out s.h5 >/dev/null 2>&1 || { echo "FAIL: layer-make h5"; exit 1; }
edit() { sed "s/^$1 .*/$1 $2/" s.txt >"$3"; }
edit rm 0.5 rm05.txt
edit rm 0.1 rm01.txt
edit rm 0.65 rmdiam.txt
edit volume_ratio 1 vr1.txt
edit volume_ratio 5 vr5.txt
# a header edited by hand within the bounds is a hand-made sample: without
# layer-make's settings line (kept, the line's rm and volume_ratio disagree
# with the header's and the file is refused: test_hostile_inputs40)
hand() { sed "s/^$1 .*/$1 $2/; /^# settings:/d" s.txt >"$3"; }
hand rm 0.4 rm04.txt
hand volume_ratio 0 vr0.txt
hand volume_ratio 20 vr20.txt

# 1: refusals, naming the sample and what in it disagrees
imp() { echo layer-impact --sample "$1" --t-max 0.002 --out "$tmp/o"; }
# shellcheck disable=SC2046
{
refused "rm 0.5 for radii 0.207-0.434 m" "sample 'rm05.txt': particle [0-9]+'s radius 0.206678 m lies outside \[0.232079, 1.07722\] m.*rm 0.5 m" $(imp rm05.txt)
refused "rm 0.1 for radii 0.207-0.434 m" "sample 'rm01.txt': particle [0-9]+'s radius 0.43425 m lies outside" $(imp rm01.txt)
refused "rm the diameter (0.65)" "sample 'rmdiam.txt': .*rm 0.65 m cannot be the mean radius" $(imp rmdiam.txt)
refused "volume_ratio 1 for radii spanning 9.28" "sample 'vr1.txt': its radii span a volume ratio of 9.27.*volume_ratio 1 " $(imp vr1.txt)
refused "volume_ratio 5 for radii spanning 9.28" "sample 'vr5.txt': its radii span a volume ratio of 9.27.*volume_ratio 5 " $(imp vr5.txt)
}
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n' "$tmp/rm05.txt" >sw.ini
refused "a layer sweep over the rm 0.5 sample (--check)" "sample '.*rm05.txt'.*cannot be the mean radius" sweep sw.ini --out "$tmp/o" --check

# Python and HDF5: the library's reader, so the same refusal
py_checks <<'EOF'
import granwave, shutil, warnings
warnings.simplefilter("ignore", granwave.GranwaveWarning)
try:
    import h5py
except ImportError:
    h5py = None
def refused(what, pat, **kw):
    try:
        granwave.layer_impact(t_max=0.002, **kw)
    except granwave.GranwaveValueError as e:
        print(("PASS: " if pat in str(e) else "FAIL: ") + what + ": " + str(e)[:160])
        return
    print("FAIL: " + what + ": ran")
refused("Python: rm 0.5", "cannot be the mean radius", sample="rm05.txt")
refused("Python: volume_ratio 1", "its radii span a volume ratio", sample="vr1.txt")
if h5py is None:
    print("PASS: HDF5 edit (SKIP: no h5py)")
else:
    shutil.copy("s.h5", "rm05.h5")
    with h5py.File("rm05.h5", "r+") as f:
        f.attrs["rm"] = 0.5
    refused("HDF5: rm attribute 0.5", "cannot be the mean radius", sample="rm05.h5")
EOF

# 2: legitimate samples run; those whose rm is the written one give the same numbers
num() { jq_py "$1" "'%.12g %.12g' % (d['block_mass'], d['penetration'])"; }
runs_json "the sample as written" ref.json layer-impact --sample s.txt --t-max 0.002 && ok "the sample as written runs"
for f in vr0.txt vr20.txt; do
    if runs_json "volume_ratio edited ($f)" "$f.json" layer-impact --sample "$f" --t-max 0.002; then
        [ "$(num "$f.json")" = "$(num ref.json)" ] && ok "$f: runs, the same numbers" ||
            ko "$f: $(num "$f.json") against $(num ref.json)"
    fi
done
if runs_json "rm 0.4, within the bounds" rm04.json layer-impact --sample rm04.txt --t-max 0.002; then
    m=$(jq_py rm04.json "d['block_mass']"); ref=$(jq_py ref.json "d['block_mass']")
    $PY -c "import math,sys; sys.exit(0 if abs($m / $ref - (0.4 / 0.325) ** 2) < 1e-9 else 1)" &&
        ok "rm 0.4 runs, its block (R_b = rm) scaled as rm^2" || ko "rm 0.4: block mass $m against $ref"
fi
"$GW" layer-make --n 40 --width-rm 10 --seed 4 --height-rm 4 --out trim.txt >/dev/null 2>&1 &&
    runs_json "a trimmed sample" trim.json layer-impact --sample trim.txt --t-max 0.002 && ok "a trimmed sample runs"
"$GW" layer-make --n 30 --width-rm 12 --seed 2 --t-max 3 --volume-ratio 1 --out mono.txt >/dev/null 2>&1 &&
    runs_json "a monodisperse sample" mono.json layer-impact --sample mono.txt --t-max 0.002 &&
    ok "a monodisperse sample (volume_ratio 1) runs"
"$GW" layer-make --n 30 --width-rm 12 --seed 2 --t-max 3 --clumps --out cl.txt >/dev/null 2>&1 &&
    runs_json "a clump sample" cl.json layer-impact --sample cl.txt --t-max 0.002 && ok "a clump sample runs"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
