#!/bin/bash
# test_hostile_inputs39.sh GRANWAVE SRCDIR: what the thirty-ninth hostile
# pass (over the input files and the physics) found, fixed at its root and
# asserted here.
#  1 A sample's settings line holding a name twice was read by its first
#    value. JSON leaves a repeated name to the reader: cJSON's lookup takes
#    the first, Python's json and jq the last. '"friction_deg":30,
#    "friction_deg":5' in layer-make's settings line ran as a pile settled at
#    30 degrees (exit 0) where those tools read 5, and the reverse order was
#    refused as a spring beyond the Coulomb bound "of the settling the sample
#    records (friction 5 deg)", a record the file gives two ways. A settings
#    line (text sample, or the HDF5 header attribute) that holds any name
#    twice, at any depth, is now refused naming the file, the line and the
#    name, by layer-impact, sweep --check and Python; the sample without the
#    duplicate still runs.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

make_sample s.txt --n 40 --seed 2

# --- 1 a settings line holding a name twice ---
grep -q '"friction_deg":30,' s.txt || ko "the sample's settings line has no friction_deg 30"
sed 's/"friction_deg":30,/"friction_deg":30,"friction_deg":5,/' s.txt >dup1.txt   # read as 30 (first)
sed 's/"friction_deg":30,/"friction_deg":5,"friction_deg":30,/' s.txt >dup2.txt   # read as 5 (first)
sed 's/"poisson":0.25,/"poisson":0.25,"poisson":0.25,/' s.txt >dup3.txt          # the same value twice
sed 's/{"n":40,/{"n":40,"n":40,/' s.txt >dup4.txt                                 # at the top level
TWICE="layer-make's settings line holds a name twice \\(JSON readers differ on which value counts\\)"
refused "layer-impact on a sample whose settings give friction_deg twice (30, then 5): refused naming it" \
    "^granwave layer-impact: sample 'dup1.txt': line 4: $TWICE: 'friction_deg'" \
    layer-impact --sample dup1.txt --t-max 0.002 --out o
refused "layer-impact on friction_deg twice (5, then 30): refused as the name twice, not as a spring beyond 5 deg" \
    "^granwave layer-impact: sample 'dup2.txt': line 4: $TWICE: 'friction_deg'" \
    layer-impact --sample dup2.txt --t-max 0.002 --out o
refused "layer-impact on a settings line with poisson twice at one value: refused" \
    "^granwave layer-impact: sample 'dup3.txt': line 4: $TWICE: 'poisson'" \
    layer-impact --sample dup3.txt --t-max 0.002 --out o
refused "layer-impact on a settings line with its top-level n twice: refused" \
    "^granwave layer-impact: sample 'dup4.txt': line 4: $TWICE: 'n'" \
    layer-impact --sample dup4.txt --t-max 0.002 --out o
printf '[sweep]\nmodel = layer\nout = o\n[params]\nsample = dup1.txt\nt-max = 0.002\n[grid]\nvi = 10, 0.25\n' >dup1.ini
refused "sweep --check over a config whose sample has a name twice in its settings: refused" \
    "^granwave sweep: .*dup1.txt'?: line 4: $TWICE: 'friction_deg'" sweep dup1.ini --check
runs_quiet "layer-impact on the sample as layer-make wrote it: runs" layer-impact --sample s.txt --t-max 0.002
py_checks 1 <<'PYEOF'
refused("Python layer_impact on the sample with friction_deg twice", ["dup1.txt", "holds a name twice", "friction_deg"],
        granwave.layer_impact, sample="dup1.txt", t_max=0.002)
PYEOF

if ! $PY -c 'import h5py' 2>/dev/null || ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: h5py or an HDF5 build missing"
    test_summary test_hostile_inputs39
    exit 0
fi
make_sample s.h5 --n 40 --seed 2
$PY - <<'PYEOF' || ko "making the HDF5 sample with a name twice"
import h5py, numpy as np, shutil
shutil.copy("s.h5", "dup1.h5")
with h5py.File("dup1.h5", "r+") as f:
    h = bytes(f.attrs["header"])
    h2 = h.replace(b'"friction_deg":30,', b'"friction_deg":30,"friction_deg":5,')
    assert h2 != h
    del f.attrs["header"]
    f.attrs["header"] = np.bytes_(h2)
PYEOF
refused "layer-impact on an HDF5 sample whose header's settings give friction_deg twice: refused naming it" \
    "^granwave layer-impact: sample 'dup1.h5': HDF5 attribute header: $TWICE: 'friction_deg'" \
    layer-impact --sample dup1.h5 --t-max 0.002 --out o
runs_quiet "layer-impact on the HDF5 sample as layer-make wrote it: runs" layer-impact --sample s.h5 --t-max 0.002

test_summary test_hostile_inputs39
