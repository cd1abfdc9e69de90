#!/bin/bash
# test_hostile_inputs43.sh GRANWAVE SRCDIR: what the forty-third hostile pass
# (over the input files) found, fixed at its root and asserted here. Every
# refusal is bounded (refusal_lib.sh: killed after 20 s, a failed check):
# a hang fails the check, it is not timed.
#  1 A sweep hashed the files its cases read (the layer's sample) whole, with
#    no bound, before the case's reader looked at them: a sparse 200 GB file
#    named as the sample kept `granwave sweep`, `sweep --check` and Python's
#    sweep hashing for minutes. The model now registers its reader's rules
#    (gw_sweep_model.input_check; the layer's: a regular file of at most 4
#    GiB, HDF5 or text without a NUL byte at its start), applied to every
#    such file before the sweep hashes it, and the sample reader itself
#    refuses a file above 4 GiB: exit 2, one line naming the file and the
#    limit, nothing written.
#  2 The sweep journal was read whole into a buffer of the size fstat gave
#    (up to 16 GiB): a 10 GB sparse journal was allocated and read before a
#    byte was looked at, and a NUL byte cut the text there (rows misread).
#    It is now read in chunks of 1 MiB, at most what this sweep's journal can
#    hold (its head and each case's row twice over), a NUL byte refused
#    naming the journal and its line; the journal is left as it is.
#  3 layer-stats read the case field with strtol: "00", "+0" and " 0" were
#    case 0. A case must now be written as a sweep writes it (decimal digits,
#    no sign, blank or leading zero), refused naming the file and line, also
#    by Python's layer_stats.
#  4 An HDF5 sample's attribute of shape (1,) (n = [40]) was read as a
#    scalar: the attributes the reader takes must be scalars, as granwave
#    writes them, refused naming the attribute and its shape.
#  5 dispersion --wisdom read st_mode after a stat() that failed with other
#    than ENOENT (uninitialised): the errno is said now, exit 2. A shim
#    (GW_STAT_SHIM, tests/stat_fail_shim.c) makes stat fail with EIO and
#    leave the buffer as an empty regular file: the wisdom file was taken as
#    empty and overwritten with wisdom (exit 0); skipped without the shim.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

# py_timed N: py_checks, the script killed after 60 s (a hang is a failed check)
py_timed() { PY_TIMEOUT=60 py_checks "$1"; }

make_sample s.txt --n 40 --width-rm 12 --seed 1

# --- 1 a sparse 200 GB sample named in a sweep ---
truncate -s 200G big.sample 2>/dev/null || ko "truncate -s 200G (a sparse file)"
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = big.sample\nt-max = 0.002\n' >big.ini
printf '[sweep]\nmodel = layer\n[grid]\nsample = s.txt, big.sample\n[params]\nvi = 10\nt-max = 0.002\n' >bigg.ini
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = s.txt\nt-max = 0.002\n' >l.ini
LIMIT="214748364800 bytes, larger than a sample file may be \\(4294967296 bytes, 4 GiB\\)"
refused "sweep: a sparse 200 GB [params] sample refused by its size, not hashed" \
    "^granwave sweep: big.ini: \\[params\\] sample '$tmp/big.sample': $LIMIT" sweep big.ini --out o
refused "sweep --check: the same" \
    "^granwave sweep: big.ini: \\[params\\] sample '$tmp/big.sample': $LIMIT" sweep big.ini --check --out o
refused "sweep: a sparse 200 GB sample in the [grid] refused by its size" \
    "^granwave sweep: bigg.ini: \\[grid\\] sample '$tmp/big.sample': $LIMIT" sweep bigg.ini --out o
refused "layer-impact: the sample reader says the limit too" \
    "^granwave layer-impact: sample 'big.sample': $LIMIT" layer-impact --sample big.sample --t-max 1e-4 --out o
timeout -s KILL 60 "$GW" sweep l.ini --check --out ck >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "sweep --check of the sample as layer-make wrote it passes" || ko "sweep --check l.ini: $(cat "$tmp/stderr")"
py_timed 1 <<'PYEOF'
refused("Python sweep with the sparse 200 GB sample", ["big.sample", "4294967296 bytes"],
        granwave.sweep, "layer", grid={"vi": [10, 20]}, sample="big.sample", t_max=0.002)
PYEOF

# --- 2 the journal read bounded ---
printf '[sweep]\nmodel = chain\n[grid]\nn = 5, 6\n[params]\nsolver = rk4\n' >ch.ini
"$GW" sweep ch.ini --out j --quiet >/dev/null 2>&1 || ko "the chain sweep of two cases"
rm -f j/results.csv
cp -r j j10 && truncate -s 10G j10/journal.csv
BIG="^granwave sweep: sweep journal 'j10/journal.csv' is 10737418240 bytes, more than this sweep's journal can hold"
for mode in run check; do
    args=(sweep ch.ini --out j10 --quiet)
    [ $mode = check ] && args=(sweep ch.ini --out j10 --check)
    if exits_refused "sweep ($mode): a 10 GB sparse journal" "$BIG" 20 "$GW" "${args[@]}"; then
        if [ "$(stat -c %s j10/journal.csv)" = 10737418240 ] && [ ! -e j10/results.csv ]; then
            ok "sweep ($mode): a 10 GB sparse journal refused by its size, left as it is, no table"
        else
            ko "sweep ($mode): the 10 GB journal changed or a table was written: $(ls -la j10 | tr '\n' ' ')"
        fi
    fi
done
cp -r j jn
$PY - <<'PYEOF' || ko "a NUL byte into the journal's last row"
b = open("jn/journal.csv", "rb").read()
i = b.rindex(b"\n", 0, len(b) - 1)
open("jn/journal.csv", "wb").write(b[:i + 5] + b"\0" + b[i + 6:])
PYEOF
cp jn/journal.csv jn.copy
for mode in run check; do
    args=(sweep ch.ini --out jn --quiet)
    [ $mode = check ] && args=(sweep ch.ini --out jn --check)
    if exits_refused "sweep ($mode): a NUL byte in the journal" \
        "^granwave sweep: sweep journal 'jn/journal.csv': line 6 \\(byte [0-9]+\\): a NUL byte" 20 "$GW" "${args[@]}"; then
        if cmp -s jn/journal.csv jn.copy && [ ! -e jn/results.csv ]; then
            ok "sweep ($mode): a NUL byte in the journal refused naming its line, the journal as it was, no table"
        else
            ko "sweep ($mode): the journal with a NUL byte was changed or a table written"
        fi
    fi
done
cp -r j jok
timeout -s KILL 60 "$GW" sweep ch.ini --out jok --quiet >/dev/null 2>"$tmp/stderr" </dev/null && [ -s jok/results.csv ] &&
    ok "the journal as written resumes and the table is written" || ko "resume of the intact journal: $(cat "$tmp/stderr")"

# --- 3 layer-stats: case numbers as a sweep writes them ---
"$GW" sweep l.ini --out L --quiet >/dev/null 2>&1 || ko "the layer sweep of two cases"
ln0=$(grep -n '^0,' L/results.csv | cut -d: -f1)
for v in '00' '+0' ' 0'; do
    sed "s/^0,/$v,/" L/results.csv >t.csv
    pat=$(printf '%s' "$v" | sed 's/+/\\+/')
    refused "layer-stats: case '$v' refused naming the file and line" \
        "^granwave layer-stats: t.csv:$ln0: case '$pat' is not a case number as a sweep writes it" layer-stats t.csv --out o
done
sed "s/^0,/+0,/" L/results.csv >tp.csv
timeout -s KILL 60 "$GW" layer-stats L/results.csv >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "layer-stats reads the table as the sweep wrote it" || ko "layer-stats L/results.csv: $(cat "$tmp/stderr")"
py_timed 1 <<'PYEOF'
refused("Python layer_stats on case '+0'", ["tp.csv", "case '+0' is not a case number"], granwave.layer_stats, "tp.csv")
PYEOF

# --- 4 an HDF5 sample's attributes: scalars only ---
if "$GW" layer-make --out s.h5 --n 40 --width-rm 12 --seed 1 >/dev/null 2>&1 && $PY -c 'import h5py' 2>/dev/null; then
    $PY - <<'PYEOF' || ko "making the HDF5 samples"
import shutil, h5py, numpy as np
for name, attr, scalar in [("n1.h5", "n", False), ("w1.h5", "width", False), ("n0.h5", "n", True)]:
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as f:
        v = f.attrs[attr]
        f.attrs.create(attr, v if scalar else np.array([v]))
PYEOF
    refused "an HDF5 sample whose n has shape (1,): refused naming it" \
        "^granwave layer-impact: sample 'n1.h5': HDF5 attribute 'n' is an array of shape \\(1,\\), not a scalar" \
        layer-impact --sample n1.h5 --t-max 1e-4 --out o
    refused "an HDF5 sample whose width has shape (1,): refused naming it" \
        "^granwave layer-impact: sample 'w1.h5': HDF5 attribute 'width' is an array of shape \\(1,\\), not a scalar" \
        layer-impact --sample w1.h5 --t-max 1e-4 --out o
    runs_quiet "the same sample with n written again as a scalar runs" layer-impact --sample n0.h5 --t-max 1e-4
else
    echo "SKIP: the HDF5 checks (no HDF5 in this build, or no h5py)"
fi

# --- 5 dispersion --wisdom after a failed stat ---
refused "dispersion --wisdom through a file: the errno said" \
    "^granwave dispersion.*/etc/passwd/x.*Not a directory" dispersion --n 64 --wisdom /etc/passwd/x --out o
if [ -n "${GW_STAT_SHIM:-}" ] && [ -f "$GW_STAT_SHIM" ]; then
    echo "my notes, not wisdom" >notes.txt
    cp notes.txt notes.copy
    if exits_refused "dispersion --wisdom, stat failing with EIO" \
        "^granwave dispersion --wisdom: 'notes.txt': cannot read: Input/output error$" 60 \
        env LD_PRELOAD="$GW_STAT_SHIM" GW_STAT_FAIL=notes.txt "$GW" dispersion --n 64 --wisdom notes.txt --quiet; then
        if cmp -s notes.txt notes.copy; then
            ok "dispersion --wisdom, stat failing with EIO: refused with the errno, the file as it was"
        else
            ko "dispersion --wisdom, stat failing with EIO: the file was overwritten"
        fi
    elif ! cmp -s notes.txt notes.copy; then
        ko "dispersion --wisdom, stat failing with EIO: the file was overwritten"
    fi
else
    echo "SKIP: dispersion --wisdom with stat failing (no stat shim: GW_STAT_SHIM)"
fi

test_summary
