#!/bin/bash
# test_layer_sample_units.sh GRANWAVE SRCDIR: an HDF5 sample's units attributes
# (docs/formats.md, "Sample files"). granwave writes the file's `units` as
# "SI: x, y, r, width, rm in metres" and each dataset's x, y, r as "m", and
# reads the values as metres. Before the twenty-first hostile pass the reader
# never looked at them: a sample converted to millimetres (values x 1000, its
# units attributes saying so) ran as metres with exit 0, an 8.79e8 kg block
# instead of 879 kg. Checked:
#  1 units other than granwave's on the file or on a dataset, or not a string,
#    are refused by layer-impact (exit 2, one line naming the sample and the
#    units, nothing written), by a layer sweep's --check and by Python's
#    layer_impact (GranwaveValueError): the library's reader;
#  2 a sample as written runs, and one without units attributes (the format's
#    SI) runs with the same numbers.
# 6 of the 8 checks fail on the code before (the two that pass: part 2).
# Skipped (passes) in a build without HDF5 or without h5py.
set -u
GW=$1
SRC=$2
PY=/usr/bin/python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=refusal_lib.sh
. "$SRC/tests/refusal_lib.sh"
cd "$tmp" || exit 1

if ! "$GW" version --json | grep -q '"hdf5":[[:space:]]*"'; then
    echo "SKIP: a build without HDF5"; exit 0
fi
if ! $PY -c "import h5py" 2>/dev/null; then
    echo "SKIP: no h5py"; exit 0
fi
"$GW" layer-make --n 40 --width-rm 10 --seed 4 --out s.h5 >/dev/null 2>&1 || { echo "FAIL: layer-make h5"; exit 1; }
$PY - <<'EOF' || { echo "FAIL: h5py edits"; exit 1; }
import h5py, shutil
def edit(name, fn):
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as h:
        fn(h)
def mm(h):  # the whole sample converted to millimetres, its units saying so
    for k in ("x", "y", "r"):
        h[k][:] = h[k][:] * 1000
        h[k].attrs["units"] = "mm"
    h.attrs["width"] = h.attrs["width"] * 1000
    h.attrs["rm"] = h.attrs["rm"] * 1000
    h.attrs["units"] = "SI: x, y, r, width, rm in millimetres"
edit("mm.h5", mm)
edit("xmm.h5", lambda h: h["x"].attrs.__setitem__("units", "mm"))
edit("filemm.h5", lambda h: h.attrs.__setitem__("units", "mm"))
edit("rnum.h5", lambda h: h["r"].attrs.__setitem__("units", 3.0))
def nounits(h):
    del h.attrs["units"]
    for k in ("x", "y", "r"):
        del h[k].attrs["units"]
edit("none.h5", nounits)
EOF

# 1: refusals
imp() { echo layer-impact --sample "$1" --t-max 0.002 --out "$tmp/o"; }
# shellcheck disable=SC2046
{
refused "a sample in millimetres, its units saying so" "sample 'mm.h5': HDF5 attribute units is 'SI: x, y, r, width, rm in millimetres', not 'SI: x, y, r, width, rm in metres'" $(imp mm.h5)
refused "dataset x in mm" "sample 'xmm.h5': HDF5 dataset 'x' has units 'mm', not 'm'" $(imp xmm.h5)
refused "the file's units mm" "sample 'filemm.h5': HDF5 attribute units is 'mm'" $(imp filemm.h5)
refused "dataset r's units a number" "sample 'rnum.h5': HDF5 attribute units of dataset 'r' is not one string" $(imp rnum.h5)
}
settling_sweep_ini sw.ini "$tmp/mm.h5"
refused "a layer sweep over the millimetre sample (--check)" "sample '.*mm.h5': HDF5 attribute units is" sweep sw.ini --out "$tmp/o" --check
py_checks 1 <<'EOF'
warnings.simplefilter("ignore", granwave.GranwaveWarning)
refused("Python: the millimetre sample", ["HDF5 attribute units is"], granwave.layer_impact, sample="mm.h5", t_max=0.002)
EOF

# 2: the sample as written, and without units attributes, run alike
num() { jq_py "$1" "'%.12g %.12g %.12g' % (d['block_mass'], d['penetration'], d['energy_error'])"; }
runs_json "the sample as written" ref.json layer-impact --sample s.h5 --t-max 0.002 && ok "the sample as written runs"
if runs_json "no units attributes" none.json layer-impact --sample none.h5 --t-max 0.002; then
    [ "$(num none.json)" = "$(num ref.json)" ] && ok "no units attributes: runs, the same numbers" ||
        ko "no units attributes: $(num none.json) against $(num ref.json)"
fi

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
