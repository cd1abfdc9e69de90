#!/bin/bash
# test_h5_unheld.sh GRANWAVE SRCDIR: a valid HDF5 sample whose stated end
# covers bytes no HDF5 object holds is refused before it is hashed. h5py
# (Debian's python3) adds a 100 MB dataset of zeros to layer-make's 40-disc
# sample and a small one after it, then deletes the large one: HDF5 accepts
# the file (its checksums and end address are right) and the 100 MB are
# space freed and never reused. It was hashed whole, three times by `sweep
# --check` (1.4 s) and twice by layer-impact (0.5 s, which ran on it). The
# open check now counts what the file's objects hold (superblock, headers,
# indexes and heaps, datasets' stored data) and refuses a file past that by
# more than 1 MiB and more than as much again:
#  1 sweep --check and layer-impact exit 2 in one line naming the file, its
#    size and what its objects hold, nothing written
#  2 the bytes read by each (strace, every read and pread summed) stay under
#    1 MiB (they were 3 x and 2 x 100 MB)
#  3 controls, taken: the same file with 0.5 MB freed (within the slack), and
#    with the 4 MB of zeros kept as a dataset (held: hashed whole, as the
#    bound is what the datasets hold)
# SKIP without HDF5 or h5py. Checks that fail on the code before: docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

if ! "$GW" version --json 2>/dev/null | grep -q hdf5 || ! /usr/bin/python3 -c 'import h5py' 2>/dev/null; then
    echo "SKIP: needs an HDF5 build and h5py"
    test_summary test_h5_unheld
    exit 0
fi
make_sample s.h5 --n 40 --width-rm 12 --seed 1
# zeros.py SRC DST MB KEEP: SRC with MB of zeros in a dataset, then a small
# dataset after it; the zeros deleted unless KEEP is 1
cat >zeros.py <<'PY'
import shutil, sys
import h5py, numpy as np
src, dst, mb, keep = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4] == "1"
shutil.copy(src, dst)
with h5py.File(dst, "a") as f:
    f.create_dataset("zeros", data=np.zeros(int(mb * 2**20) // 8))
    f.create_dataset("after", data=np.zeros(4))
if not keep:
    with h5py.File(dst, "a") as f:
        del f["zeros"]
PY
/usr/bin/python3 zeros.py s.h5 z100.h5 100 0 && /usr/bin/python3 zeros.py s.h5 z05.h5 0.5 0 &&
    /usr/bin/python3 zeros.py s.h5 held4.h5 4 1 || ko "h5py could not write the samples"
[ "$(stat -c %s z100.h5)" -gt 104857600 ] || ko "z100.h5 is $(stat -c %s z100.h5) bytes"
sweep_ini() { printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n' "$1" >"$2"; }
for f in z100 z05 held4; do sweep_ini "$f.h5" "$f.ini"; done

# --- 1 refused, one line, nothing written ---
unheld="104[0-9]{6} bytes, of which its [0-9]+ HDF5 objects hold [0-9]+ .*: 104[0-9]{6} bytes that no object holds"
REFUSE_TIMEOUT=10 refused "sweep --check: 100 MB that no object holds" \
    "^granwave sweep: z100\\.ini: \\[params\\] sample '[^']*z100\\.h5': $unheld" sweep z100.ini --check --out o
REFUSE_TIMEOUT=10 refused "layer-impact: 100 MB that no object holds" \
    "^granwave layer-impact: sample 'z100\\.h5': $unheld" layer-impact --sample z100.h5 --out o

# --- 2 the bytes read ---
# read_bytes CMD...: the bytes CMD's read and pread calls returned, summed
read_bytes() {
    strace -f -qq -e trace=read,pread64 -o "$tmp/strace" "$@" >/dev/null 2>&1 </dev/null
    awk '/= [0-9]+$/ {s += $NF} END {print s + 0}' "$tmp/strace"
}
if ! command -v strace >/dev/null || sanitizer_build; then
    echo "SKIP: part 2 needs strace (and no sanitizer build)"
else
    for c in "sweep z100.ini --check --out o" "layer-impact --sample z100.h5 --out o"; do
        rm -rf o
        # shellcheck disable=SC2086
        n=$(read_bytes "$GW" $c)
        [ "$n" -lt 1048576 ] && ok "2 ${c%% *}: $n bytes read (under 1 MiB)" ||
            ko "2 ${c%% *}: $n bytes read, 1 MiB or more"
    done
fi

# --- 3 controls ---
for f in z05 held4; do
    timeout -s KILL 60 "$GW" sweep $f.ini --check --out o$f >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "3 sweep --check takes $f.h5" || ko "3 sweep --check on $f.h5: exit $? ($(head -c 300 "$tmp/stderr"))"
done
timeout -s KILL 60 "$GW" layer-impact --sample held4.h5 --t-max 0.0001 --out oh --quiet >/dev/null \
    2>"$tmp/stderr" </dev/null && ok "3 layer-impact takes held4.h5" ||
    ko "3 layer-impact on held4.h5: exit $? ($(head -c 300 "$tmp/stderr"))"

test_summary test_h5_unheld
