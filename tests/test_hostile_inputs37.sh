#!/bin/bash
# test_hostile_inputs37.sh GRANWAVE SRCDIR: what the thirty-seventh hostile
# pass (over the input files and the physics) found, fixed at its root and
# asserted here.
#  1 An HDF5 sample whose spring_u is an external link to a FIFO hung the
#    reader for ever. Its springs were read by first opening spring_u for its
#    length, and H5Dopen2 follows an external link: HDF5 opened the file the
#    link names, and open() on a FIFO without a writer blocks. The particles'
#    columns were checked to be datasets of the file itself (h5_in_file)
#    before they were opened; the springs' only after. layer-impact, sweep,
#    sweep --check and Python's layer_impact hung (killed at the time limit);
#    each now refuses the file (exit 2, one line naming the file and
#    spring_u as an external link), as it refused such an x. A soft link for
#    spring_u is named too (it was refused as "must be a 1-D array of at
#    most 328 numbers", its target's length). The same sample with its
#    springs in the file still runs.
#  2 A text sample cut inside its last line ran. A file cut short (a full
#    disk, a copy stopped) inside its particles or springs is refused by its
#    counts, but a cut inside the last record left a number cut in its
#    digits, which still reads: a 40-disc sample without its springs section
#    cut 15 bytes short read the last radius 0.2296 m as 0.22 and ran with
#    exit 0, the penetration 0.0258 m against 0.0168 (e_n_first 0.219
#    against 0.264); with springs and no settings line, the last spring's
#    exponent e-06 cut to e-0 read u a million times larger (the impact clips
#    it to the Coulomb bound), exit 0. A record without its newline is now
#    refused as the end of a cut file (layer-make and the library's writer
#    end every line), naming the file and the line, by layer-impact, sweep
#    --check and Python; the same file with its newline (LF or CRLF) runs.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

# --- 2 a text sample cut inside its last line ---
make_sample s.txt --n 40 --seed 2
sed -e "/^# lines after 'springs'/d" -e '/^springs /,$d' s.txt >p.txt # the particles alone (a sample before springs)
sed '/^# settings:/d' s.txt >h.txt           # springs, no settling record (hand-made)
runs() { # runs WHAT FILE: layer-impact on FILE exits 0
    timeout -s KILL 60 "$GW" layer-impact --sample "$2" --t-max 0.002 --quiet >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$1" || ko "$1: exit $? ($(head -c 300 "$tmp/stderr"))"
}
runs "the particles alone, ending with a newline: run" p.txt
sed 's/$/\r/' p.txt >pc.txt
runs "the particles alone in CRLF: run" pc.txt
CUT="the file ends inside this line \\(no newline after it\\): cut short"
for k in 1 5 15; do
    head -c -$((k + 1)) p.txt >c$k.txt        # k bytes of the last radius and its newline gone
    refused "the particles alone cut $k bytes into the last radius: refused naming the file and line" \
        "^granwave layer-impact: sample 'c$k.txt': line [0-9]+: $CUT" layer-impact --sample c$k.txt --t-max 0.002 --out o
done
head -c -1 p.txt >n.txt                        # the newline alone gone: a cut file too
refused "the particles alone without the last newline: refused" \
    "^granwave layer-impact: sample 'n.txt': line [0-9]+: $CUT" layer-impact --sample n.txt --t-max 0.002 --out o
# cut exactly where its springs section began: every count still agrees, and
# the sample read as one without springs (the lead's check after the pass)
sed '/^springs /,$d' s.txt >sc.txt
refused "cut exactly before the springs the header announces: refused naming the announcing line" \
    "^granwave layer-impact: sample 'sc.txt': ends after its 40 particles, but line [0-9]+ says a 'springs M' section follows: the file is cut short" \
    layer-impact --sample sc.txt --t-max 0.002 --out o
runs "springs without a settling record, whole: run" h.txt
head -c -2 h.txt >hc.txt                       # the last spring's exponent e-0N cut to e-0
refused "springs without a settling record, the last exponent cut: refused" \
    "^granwave layer-impact: sample 'hc.txt': line [0-9]+: $CUT" layer-impact --sample hc.txt --t-max 0.002 --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nvi = 10, 20\n[params]\nsample = c5.txt\nt-max = 0.002\n' >cs.ini
refused "sweep --check over the cut sample: refused naming it" \
    "^granwave sweep: cs.ini: case 0: sample '.*/c5.txt': line [0-9]+: $CUT" sweep cs.ini --check
py_checks 1 <<'EOF'
refused("Python layer_impact on the cut sample", ["c5.txt", "the file ends inside this line"],
        granwave.layer_impact, sample="c5.txt", t_max=0.002)
EOF

if ! $PY -c 'import h5py' 2>/dev/null || ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: h5py or an HDF5 build missing"
    test_summary test_hostile_inputs37
    exit 0
fi

# --- 1 an HDF5 sample's springs through a link ---
make_sample s.h5 --n 40 --seed 2
mkfifo fifo
$PY - <<'EOF' || ko "making the linked samples"
import h5py, shutil
for name, link in (("ext.h5", h5py.ExternalLink("fifo", "/spring_u")),
                   ("ext_abs.h5", h5py.ExternalLink("s.h5", "/spring_u")),
                   ("soft.h5", h5py.SoftLink("/x"))):
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as f:
        assert f["spring_u"].shape[0] > 0
        del f["spring_u"]
        f["spring_u"] = link
EOF
# a hang is killed at 10 s: a failed check, not a stuck test
REFUSE_TIMEOUT=10
EXT="^granwave layer-impact: sample 'ext.h5': HDF5 dataset 'spring_u' is an external link: a sample holds its data in the file itself"
refused "layer-impact on a sample whose spring_u links to a FIFO: refused naming spring_u, no hang" \
    "$EXT" layer-impact --sample ext.h5 --t-max 0.002 --out o
refused "layer-impact on a sample whose spring_u links to another sample's: refused naming spring_u" \
    "^granwave layer-impact: sample 'ext_abs.h5': HDF5 dataset 'spring_u' is an external link" \
    layer-impact --sample ext_abs.h5 --t-max 0.002 --out o
refused "layer-impact on a sample whose spring_u is a soft link to x: refused naming the link" \
    "^granwave layer-impact: sample 'soft.h5': HDF5 dataset 'spring_u' is a soft link" \
    layer-impact --sample soft.h5 --t-max 0.002 --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nvi = 10, 20\n[params]\nsample = ext.h5\nt-max = 0.002\n' >e.ini
refused "sweep --check over that sample: refused naming the file, no hang" \
    "^granwave sweep: e.ini: case 0: sample '.*/ext.h5': HDF5 dataset 'spring_u' is an external link" sweep e.ini --check
refused "sweep over that sample: refused before any case, nothing written, no hang" \
    "^granwave sweep: e.ini: case 0: sample '.*/ext.h5': HDF5 dataset 'spring_u' is an external link" sweep e.ini --quiet
# the library's reader through Python (a hang is a failed check)
if sanitizer_build; then
    echo "SKIP: the Python check (a sanitizer build's library does not load into Python)"
else
    pyenv cpu_run 10 $PY - >py.out 2>&1 <<'EOF'
import granwave
try:
    granwave.layer_impact(sample="ext.h5", t_max=0.002)
    print("ran")
except granwave.GranwaveValueError as e:
    print("refused:", e)
EOF
    grep -q "^refused: .*ext.h5.*spring_u' is an external link" py.out &&
        ok "Python layer_impact on that sample: GranwaveValueError naming spring_u" ||
        ko "Python layer_impact on that sample: $(head -c 300 py.out)"
fi
# the sample with its springs in the file still runs, from its springs (the
# ledger's tangential strain at t = 0 above 0; 0.59 J on this pile)
rm -rf ok
if timeout -s KILL 60 "$GW" layer-impact --sample s.h5 --t-max 0.002 --out ok --quiet >/dev/null 2>&1 </dev/null; then
    st=$(grep -v '^#' ok/ledger.csv | $PY -c "import csv, sys; print(float(next(csv.DictReader(sys.stdin))['strain_tangent']) > 0)")
    [ "$st" = True ] && ok "the unlinked sample runs from its springs (strain_tangent at t = 0 above 0)" ||
        ko "the unlinked sample: strain_tangent at t = 0 '$st'"
else
    ko "layer-impact on the unlinked sample: exit $?"
fi


# --- a NUL inside a fixed-length header attribute (the lead's check after the
# pass): HDF5's string conversion ended the header at the NUL, dropping the
# settings line after it, so the settling's record was lost and a friction of
# 10 deg on a pile settled at 30 ran with exit 0 (s.h5 itself is refused) ---
$PY - <<'EOF' || ko "making nul.h5"
import h5py, shutil, numpy as np
shutil.copy("s.h5", "nul.h5")
with h5py.File("nul.h5", "r+") as f:
    h = f.attrs["header"]
    h = h.decode() if isinstance(h, bytes) else str(h)
    i = h.index("settings:")
    del f.attrs["header"]
    f.attrs["header"] = np.bytes_((h[:i] + "\0" + h[i:]).encode())  # fixed length, the NUL kept
EOF
refused "an HDF5 header with a NUL before its settings line: refused naming the attribute" \
    "^granwave layer-impact: sample 'nul.h5': HDF5 attribute header has a NUL byte at byte [0-9]+ of its [0-9]+, text after it" \
    layer-impact --sample nul.h5 --t-max 0.002 --friction 10 --out o
refused "the same sample whole at 10 deg: refused by its settling record (the control)" \
    "^granwave layer-impact: sample 's.h5': it settled with friction 30 deg against the impact's 10" \
    layer-impact --sample s.h5 --t-max 0.002 --friction 10 --out o

# --- the header's padding (the lead's, when the reader took the fixed-length
# header from its own bytes in one read instead of a converted read and a raw
# one): a space-padded and a NUL-padded header are read to their end, so the
# settling's record on their last lines still holds, and a NUL inside a
# space-padded one is refused as in a NUL-terminated one ---
$PY - <<'EOF' || ko "making space.h5, nullpad.h5 and spacenul.h5"
import h5py, shutil, numpy as np
with h5py.File("s.h5", "r") as f:
    h = f.attrs["header"]
    h = h.decode() if isinstance(h, bytes) else str(h)
i = h.index("settings:")
for name, pad, text, fill in (("space.h5", h5py.h5t.STR_SPACEPAD, h, b" "),
                              ("nullpad.h5", h5py.h5t.STR_NULLPAD, h, b"\0"),
                              ("spacenul.h5", h5py.h5t.STR_SPACEPAD, h[:i] + "\0" + h[i:], b" ")):
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as f:
        del f.attrs["header"]
        b = text.encode() + fill * 40
        tid = h5py.h5t.C_S1.copy()
        tid.set_size(len(b))
        tid.set_strpad(pad)
        a = h5py.h5a.create(f.id, b"header", tid, h5py.h5s.create(h5py.h5s.SCALAR))
        a.write(np.array(b, dtype="S%d" % len(b)), mtype=tid)  # the bytes as they are
EOF
for p in space nullpad; do
    refused "a $p-padded header at 10 deg: refused by its settling record (read to its end)" \
        "^granwave layer-impact: sample '$p.h5': it settled with friction 30 deg against the impact's 10" \
        layer-impact --sample $p.h5 --t-max 0.002 --friction 10 --out o
    runs "the $p-padded header at the pile's own friction: run" $p.h5
done
refused "a space-padded header with a NUL before its settings line: refused naming the attribute" \
    "^granwave layer-impact: sample 'spacenul.h5': HDF5 attribute header has a NUL byte at byte [0-9]+ of its [0-9]+, text after it" \
    layer-impact --sample spacenul.h5 --t-max 0.002 --friction 10 --out o

test_summary test_hostile_inputs37
