#!/bin/bash
# test_bounded_hash.sh GRANWAVE SRCDIR: the content hash of an input is
# bounded, and a sample the reader refuses is not hashed whole first.
#  1 A file with the HDF5 signature and then sparse zeros up to 4 GiB, named
#    as a sample, passed the sample rules (HDF5: no look at its bytes) and was
#    hashed whole, three times by `sweep --check` (about a minute) and twice
#    by layer-impact (10 s), before the HDF5 library refused it. Now a sample
#    with a hole is refused before a byte of it is hashed: sweep, sweep
#    --check and layer-impact exit 2 within 10 s (a hang check: each call
#    returns at once) naming the file, its size and the hole, nothing written.
#    An HDF5 sample's own zero runs may be holes (the default pile of
#    layer-make copied by cp --sparse=always ends in a 16-byte hole, and was
#    refused): only holes over half its bytes and over 1 MiB refuse one. The
#    control: layer-make's sample with 8 KiB of sparse zeros after its end
#    (the HDF5 library reads past them) runs.
#  2 A text sample with NUL bytes written (no hole) between 64 KiB of valid
#    text and a last line, past the rules' look at its head and its end: the
#    sweep refuses it naming the line of the NUL (it is read up to it in the
#    pass that hashes it), nothing written.
#  3 Inputs that are no files on disk: a sweep table linked to
#    /proc/self/pagemap (a regular file of 0 bytes that gives 256 GiB) was
#    read by layer-stats until memory ran out (exit 1 under a 2 GB limit), a
#    sweep config linked to /proc/self/maps read as a config. Now an input
#    that gives more bytes than its size said is refused after one byte more
#    (gw_input_read): exit 2 naming it, within 10 s, under the same limit.
#  4 A sweep table made a sparse 3 GB file (a line, then zeros) was read
#    whole into memory by layer-stats (out of memory, exit 1, under a 2 GB
#    limit). Now a text input with a hole is refused before it is read: exit
#    2 naming the file, its size and the hole, within 10 s.
# Controls: layer-make's HDF5 sample, and the text sample without its NUL
# bytes, are taken by sweep --check.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

sweep_ini() { printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n' "$1" >"$2"; }

# --- 1 an HDF5 signature and 4 GiB of sparse zeros ---
if ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: part 1 needs an HDF5 build"
else
    make_sample s.h5 --n 40 --width-rm 12 --seed 1
    sweep_ini s.h5 s5.ini
    timeout -s KILL 60 "$GW" sweep s5.ini --check --out o5 >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "sweep --check takes layer-make's HDF5 sample (the control: no hole in it)" ||
        ko "sweep --check on layer-make's HDF5 sample: exit $? ($(head -c 200 "$tmp/stderr"))"
    printf '\211HDF\r\n\032\n' >h5hole.h5
    truncate -s 4294967296 h5hole.h5
    sweep_ini h5hole.h5 h5hole.ini
    cp s.h5 sparse.h5
    truncate -s +8192 sparse.h5
    sweep_ini sparse.h5 sparse.ini
    timeout -s KILL 60 "$GW" sweep sparse.ini --check --out osp >/dev/null 2>"$tmp/stderr" </dev/null &&
        timeout -s KILL 60 "$GW" layer-impact --sample sparse.h5 --t-max 0.002 --out osp2 >/dev/null \
            2>>"$tmp/stderr" </dev/null &&
        ok "sweep --check and layer-impact take layer-make's HDF5 sample with an 8 KiB hole at its end" ||
        ko "layer-make's HDF5 sample with an 8 KiB hole at its end refused: $(head -c 300 "$tmp/stderr")"
    hole="4294967296 bytes, 42949[0-9]+ of them holes .*not a sample granwave wrote"
    for mode in run check; do
        extra=()
        [ $mode = check ] && extra=(--check)
        REFUSE_TIMEOUT=10 refused "sweep ($mode): an HDF5 signature and 4 GiB of sparse zeros" \
            "^granwave sweep: h5hole\\.ini: \\[params\\] sample '[^']*h5hole\\.h5': $hole" \
            sweep h5hole.ini "${extra[@]}" --out o
    done
    REFUSE_TIMEOUT=10 refused "layer-impact: an HDF5 signature and 4 GiB of sparse zeros" \
        "^granwave layer-impact: sample 'h5hole\\.h5': $hole" \
        layer-impact --sample h5hole.h5 --out o
fi

# --- 2 NUL bytes written between a text sample's text and its last line ---
make_sample s20.txt --n 20 --width-rm 8
cp s20.txt long.txt
{ printf '# '; head -c 70000 /dev/zero | tr '\0' x; printf '\n'; } >>long.txt
sweep_ini long.txt long.ini
timeout -s KILL 60 "$GW" sweep long.ini --check --out ol >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "sweep --check takes the text sample with a 70000-character comment (the control)" ||
    ko "sweep --check on the long text sample: exit $? ($(head -c 200 "$tmp/stderr"))"
cp long.txt mid.txt
head -c 20000 /dev/zero >>mid.txt
{ printf '# '; head -c 8000 /dev/zero | tr '\0' y; printf '\n'; } >>mid.txt
nul_line=$(($(wc -l <long.txt) + 1))
sweep_ini mid.txt mid.ini
for mode in run check; do
    extra=()
    [ $mode = check ] && extra=(--check)
    refused "sweep ($mode): 20000 NUL bytes written between the text and a last line" \
        "^granwave sweep: .*mid\\.txt'?: line $nul_line: NUL byte" \
        sweep mid.ini "${extra[@]}" --out o
done

# --- 3 /proc files as inputs ---
ln -s /proc/self/pagemap pm.csv
ln -s /proc/self/maps maps.ini
grew="more bytes than the 0 its size said when it was opened: it grew while it was read, or it is no file on disk"
# the program under a 2 GB address-space limit: the reads ran out of memory
printf '#!/bin/bash\nulimit -v 2000000\nexec "%s" "$@"\n' "$GW" >limited.sh
chmod +x limited.sh
real_gw=$GW
sanitizer_build || GW=$tmp/limited.sh # (a sanitizer's shadow memory needs more address space)
if [ -r /proc/self/pagemap ]; then
    REFUSE_TIMEOUT=10 refused "layer-stats: a table linked to /proc/self/pagemap, under a 2 GB memory limit" \
        "^granwave layer-stats: sweep table: pm\\.csv: $grew" layer-stats pm.csv
else
    echo "SKIP: /proc/self/pagemap not readable"
fi
# --- 4 a sparse 3 GB table ---
printf 'x\n' >sparse.csv
truncate -s 3000000000 sparse.csv
REFUSE_TIMEOUT=10 refused "layer-stats: a sparse 3 GB table, under a 2 GB memory limit" \
    "^granwave layer-stats: sweep table: sparse\\.csv: 3000000000 bytes, and its bytes from 4097 on are a hole" \
    layer-stats sparse.csv
GW=$real_gw
REFUSE_TIMEOUT=10 refused "sweep --check: a config linked to /proc/self/maps" \
    "^granwave sweep CONFIG: maps\\.ini: $grew" sweep maps.ini --check --out o

test_summary test_bounded_hash
