#!/bin/bash
# test_hostile_inputs40.sh GRANWAVE SRCDIR: what the fortieth hostile pass
# (over the input files) found, fixed at its root and asserted here.
#  1 A sample whose layer-make settings line disagrees with its header or
#    body was taken. layer-make writes both from one value (the header's rm,
#    width = width_rm rm, volume_ratio and seed are the settings' own
#    doubles, its mass law and clump mass the material's, a clump pile's
#    bodies one per clump), so a disagreement is a file altered after it was
#    written: a seed edited in the header only, an rm or width_rm edited in
#    the line only, a cut file whose n was fixed up by hand (one particle
#    line and its springs removed, "n 39" under "n":40), a disc sample whose
#    line says clumps, a header mass law edited against the line's. Each ran
#    (exit 0). Now refused naming the file, the settings line and the field
#    (and the header's line), by layer-impact, sweep --check, Python and for
#    HDF5 samples (the seed attribute edited).
#  3 A sweep journal whose "# grid" or "# param" line was edited under its
#    first line (the config's hash: the same config writes the same lines)
#    was resumed and checked with exit 0 ("# param t-max = 2e-4" over rows
#    that ran at 1e-4). Refused now naming the journal's line and the line
#    the config writes; a journal as written, and one whose head was torn
#    (cut and resumed: fewer lines), pass.
#  2 What stays legitimate: a pile trimmed by --height-rm holds fewer
#    bodies than the line's n (text and HDF5, discs and clumps, the
#    library's dialect too), and a hand-made sample (no settings line) may
#    edit its header freely within the other checks.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

make_sample s.txt --n 40 --width-rm 12 --seed 1
grep -q '^seed 1$' s.txt && grep -q '"rm":0.325,' s.txt && grep -q '"n":40,' s.txt ||
    ko "the sample's header or settings line is not as expected"

# --- 1 a settings line against the header and the body ---
sed 's/^seed 1$/seed 7/' s.txt >seed.txt                          # the header's seed edited
sed 's/"rm":0.325,/"rm":0.33,/' s.txt >rm.txt                      # the line's rm edited
sed 's/"width_rm":12,/"width_rm":13,/' s.txt >width.txt            # the line's width edited
sed 's/"volume_ratio":10,/"volume_ratio":9,/' s.txt >vr.txt        # the line's volume ratio edited
sed 's/"clumps":false/"clumps":true/' s.txt >clumps.txt            # a disc sample said to be clumps
sed 's/^mass_law disc$/mass_law sphere/' s.txt >law.txt            # the header's mass law edited
# the last particle cut away with its springs, n fixed up by hand
$PY - <<'PYEOF' || ko "making the sample with one particle fewer"
L = open("s.txt").read().split("\n")
k = [i for i, l in enumerate(L) if l.startswith("n ")][0]
n = int(L[k].split()[1])
L[k] = "n %d" % (n - 1)
rest = L[k + 1 + n:]
assert rest[0].startswith("springs ")
spr = [l for l in rest[1:] if l.strip() and str(n - 1) not in l.split()[:2]]
open("cut.txt", "w").write("\n".join(L[:k + n] + ["springs %d" % len(spr)] + spr) + "\n")
PYEOF
SAYS="layer-make's settings line says"
refused "a header seed edited (7 under the line's 1): refused naming the line and seed" \
    "^granwave layer-impact: sample 'seed.txt': line 4: $SAYS seed 1 where the header line 12 'seed' says 7 \\(an altered file\\?" \
    layer-impact --sample seed.txt --t-max 1e-4 --out o
refused "the line's rm edited (0.33 over the header's 0.325): refused naming rm" \
    "^granwave layer-impact: sample 'rm.txt': line 4: $SAYS rm 0.33 m where the header line 9 'rm' says 0.325 m" \
    layer-impact --sample rm.txt --t-max 1e-4 --out o
refused "the line's width_rm edited (13 R_m over a 12 R_m box): refused naming width_rm and width" \
    "^granwave layer-impact: sample 'width.txt': line 4: $SAYS width_rm 13 and rm 0.325 m, a box 4.225 m wide, where the header line 8 'width' says 3.9000000000000004 m" \
    layer-impact --sample width.txt --t-max 1e-4 --out o
refused "the line's volume_ratio edited (9 over 10): refused naming volume_ratio" \
    "^granwave layer-impact: sample 'vr.txt': line 4: $SAYS volume_ratio 9 where the header line 10 'volume_ratio' says 10" \
    layer-impact --sample vr.txt --t-max 1e-4 --out o
refused "a disc sample whose line says clumps true: refused naming clumps" \
    "^granwave layer-impact: sample 'clumps.txt': line 4: $SAYS clumps true where the file has no body column" \
    layer-impact --sample clumps.txt --t-max 1e-4 --out o
refused "a header mass law edited (sphere under the line's disc): refused naming the mass law" \
    "^granwave layer-impact: sample 'law.txt': line 4: $SAYS mass law disc where the header line 13 'mass_law' says sphere" \
    layer-impact --sample law.txt --t-max 1e-4 --out o
refused "a cut file's n fixed up by hand (39 particles, the line's n 40, no trim): refused naming n" \
    "^granwave layer-impact: sample 'cut.txt': line 4: $SAYS n 40 and height_rm 0 \\(no trim\\) where the file holds 39 particles \\(header line 14 'n'\\)" \
    layer-impact --sample cut.txt --t-max 1e-4 --out o
printf '[sweep]\nmodel = layer\nout = o\n[params]\nsample = seed.txt\nt-max = 1e-4\n[grid]\nvi = 10, 20\n' >seed.ini
refused "sweep --check over a config whose sample's header seed was edited: refused" \
    "^granwave sweep: .*seed.txt'?: line 4: $SAYS seed 1 where the header line 12 'seed' says 7" sweep seed.ini --check
py_checks 1 <<'PYEOF'
refused("Python layer_impact on the sample whose header seed was edited", ["seed.txt", "line 4", "says seed 1", "'seed' says 7"],
        granwave.layer_impact, sample="seed.txt", t_max=1e-4)
PYEOF

# --- 2 what stays legitimate ---
runs_quiet "the sample as layer-make wrote it runs" layer-impact --sample s.txt --t-max 1e-4
make_sample trim.txt --n 40 --width-rm 12 --seed 1 --height-rm 3
n=$(sed -n 's/^n //p' trim.txt)
[ "${n:-40}" -lt 40 ] && ok "the pile trimmed to 3 R_m holds $n of the line's 40 particles" ||
    ko "the trimmed pile holds ${n:-no} particles"
runs_quiet "a pile trimmed by --height-rm (fewer particles than the line's n) runs" layer-impact --sample trim.txt --t-max 1e-4
make_sample ctrim.txt --n 12 --clumps --width-rm 12 --seed 2 --height-rm 2
runs_quiet "a clump pile trimmed by --height-rm runs" layer-impact --sample ctrim.txt --t-max 1e-4
sed '/^# settings:/d' cut.txt >hand.txt
runs_quiet "the cut file without the settings line (a hand-made sample) runs" layer-impact --sample hand.txt --t-max 1e-4
py_checks 1 <<'PYEOF'
r = caught(granwave.layer_make, n=30, seed=3, width_rm=12, height_rm=3, out="lib.txt")[0]
res = caught(granwave.layer_impact, sample="lib.txt", t_max=1e-4)[0]
check(r is not None and res is not None, "the library's trimmed pile (its dialect, height-rm) runs")
PYEOF

# --- 3 a sweep journal's head edited ---
# the journal's "# grid" and "# param" lines under a first line holding the
# config's hash: a line that differs was edited by hand (resumed and checked
# as it was, exit 0)
printf '[sweep]\nmodel = chain\nout = jo\n[grid]\nn = 2, 3\n[params]\nt-max = 1e-4\n' >j.ini
timeout 60 "$GW" sweep j.ini --quiet >/dev/null 2>&1 && [ -s jo/journal.csv ] || ko "the chain sweep for its journal"
cp jo/journal.csv j.orig
grep -q '^# param t-max = 1e-4$' j.orig || ko "the journal has no '# param t-max = 1e-4' line"
jtry() { # WHAT EDIT (a sed script over the journal) EXIT PATTERN: sweep --check, then the resume
    sed "$2" j.orig >jo/journal.csv
    cp jo/journal.csv j.before
    local rc
    for mode in --check --quiet; do
        cpu_run 30 "$GW" sweep j.ini $mode >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
        rc=$?
        if [ "$3" = 0 ]; then
            [ $rc -eq 0 ] && ok "$1 ($mode): exit 0" || ko "$1 ($mode): exit $rc ($(head -c 300 "$tmp/stderr"))"
        elif [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && grep -qE -- "$4" "$tmp/stderr" &&
            cmp -s jo/journal.csv j.before; then
            ok "$1 ($mode): refused in one line naming the line, the journal left as it is"
        else
            ko "$1 ($mode): exit $rc ($(head -c 300 "$tmp/stderr"))"
        fi
    done
}
EDITED="the journal's first line holds that config's hash: the journal was edited by hand"
jtry "a journal whose '# param t-max' line says 2e-4 under the hash of 1e-4" 's/^# param t-max = 1e-4$/# param t-max = 2e-4/' 2 \
    "^granwave sweep: .*jo/journal.csv:4: '# param t-max = 2e-4' is not the line this sweep's config writes there \\('# param t-max = 1e-4'\\), and $EDITED"
jtry "a journal with a second, other '# param t-max' line" 's/^# param t-max = 1e-4$/&\n# param t-max = 2e-4/' 2 \
    "^granwave sweep: .*jo/journal.csv:5: '# param t-max = 2e-4' is not the line .*\\(none: its keys end before\\), and $EDITED"
jtry "a journal as the sweep wrote it" '' 0
jtry "a journal whose head was torn in its '# param' line (cut, its cases resumed)" '/^# param t-max/,$d' 0

if ! $PY -c 'import h5py' 2>/dev/null || ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: h5py or an HDF5 build missing"
    test_summary test_hostile_inputs40
    exit 0
fi
make_sample s.h5 --n 40 --width-rm 12 --seed 1
make_sample trim.h5 --n 40 --width-rm 12 --seed 1 --height-rm 3
$PY - <<'PYEOF' || ko "making the HDF5 sample with its seed edited"
import h5py, numpy as np, shutil
shutil.copy("s.h5", "seed.h5")
with h5py.File("seed.h5", "r+") as f:
    assert int(f.attrs["seed"]) == 1
    del f.attrs["seed"]
    f.attrs["seed"] = np.int64(7)
PYEOF
refused "an HDF5 sample whose seed attribute was edited: refused naming the attribute" \
    "^granwave layer-impact: sample 'seed.h5': HDF5 attribute header: $SAYS seed 1 where the HDF5 attribute 'seed' says 7" \
    layer-impact --sample seed.h5 --t-max 1e-4 --out o
runs_quiet "the HDF5 pile trimmed by --height-rm runs" layer-impact --sample trim.h5 --t-max 1e-4

test_summary test_hostile_inputs40
