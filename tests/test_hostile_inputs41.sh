#!/bin/bash
# test_hostile_inputs41.sh GRANWAVE SRCDIR: what the forty-first hostile pass
# (over the input files) found, fixed at its root and asserted here.
#  1 A text sample whose line never ends was read to its end, however long:
#    a '#' and then a sparse file's zeros (200 GB that take no disk) kept
#    layer-impact and Python's layer_impact reading until killed (nothing
#    said), as did gigabytes of text without a newline. The NUL byte was
#    found only at the end of its line, and comment lines had no length
#    bound. The sample reader (layer_sample.c text_next) now refuses a NUL
#    byte where it reads it and any line longer than 1 MiB, a comment too
#    (layer-make's longest line, its settings line, is under 64 KiB), naming
#    the file and the line; a 900 kB comment line still reads. (A sweep
#    naming such a file still hashes it whole before its check reads it:
#    not fixed here.)
#  2 An HDF5 sample whose n attribute says more particles than its datasets
#    hold (a 7 kB file, n edited to 1e7) had n allocated before the
#    datasets' lengths were read: 240 MB for nothing, and under a memory
#    limit (ulimit -v 250 MB) "out of memory for 10000000 particles", exit 1,
#    as if the machine were short of memory. The lengths of x, y, r (and
#    body) are now checked against n first: exit 2 naming dataset 'x' and
#    its 40 values.
#  3 A text sample's n above the limit was named as "n = 1e+07" (%g), a value
#    inside the range the message gave; now as written, "n = 10000001".
#  4 A sweep table whose rows name one sample with two content hashes (the
#    rows of sweeps over two versions of one file, joined) was read as one
#    sample when its '# input' line was gone, or in a table made by hand:
#    every point of both piles counted in one group. The rows that name one
#    file must now carry one hash, with or without the head (layer-stats,
#    Python's layer_stats), naming the line and both cases; a second
#    '# input' line for one file (its rows were checked against the last
#    alone) is refused naming its line.
#  5 A sweep config's section header without its ']' ('[grid') was named by
#    what the INI reader did next: "c.ini:4: unknown key 'n' in [sweep]"
#    (the key of the next line, in the section before), '[sweep' as
#    "unknown section []". Refused now at its line: "the section header
#    '[grid' has no ']'".
#  6 A table row whose penetration_rm was edited (by 0.1 %) was read: it is
#    penetration over the sample's one R_m, and the diagram reads it (and
#    x_span_rm divides by the first row's ratio). The rows of one sample must
#    now give one R_m (to 1e-9), the row that differs from the others
#    refused naming its line (layer-stats, Python's layer_stats); a table
#    that names no sample is not checked.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

make_sample s.txt --n 40 --width-rm 12 --seed 1

# --- 1 a line that never ends ---
# (3 GB: a file above 4 GiB is refused by its size first, test_hostile_inputs43)
printf 'granwave-layer-sample 1\n#' >sparse.txt
truncate -s 3G sparse.txt 2>/dev/null || ko "truncate -s 3G (a sparse file)"
refused "a '#' and then 3 GB of a sparse file's zeros: refused at the NUL, not read to the end" \
    "^granwave layer-impact: sample 'sparse.txt': line 2: NUL byte \\(binary data, not a text sample\\)$" \
    layer-impact --sample sparse.txt --t-max 1e-4 --out o
$PY - <<'PYEOF' || ko "making the samples with long lines"
L = open("s.txt").read().split("\n")
open("long.txt", "w").write("\n".join(L[:3] + ["# " + "a" * 2000000] + L[3:]))
open("blank.txt", "w").write("\n".join(L[:3] + [" " * 2000000] + L[3:]))
open("ok900k.txt", "w").write("\n".join(L[:3] + ["# " + "a" * 900000] + L[3:]))
PYEOF
LONG="longer than 1048576 bytes, a comment too"
refused "a comment line of 2 MB: refused naming its line" \
    "^granwave layer-impact: sample 'long.txt': line 4: $LONG" layer-impact --sample long.txt --t-max 1e-4 --out o
refused "a blank line of 2 MB of spaces: refused naming its line" \
    "^granwave layer-impact: sample 'blank.txt': line 4: $LONG" layer-impact --sample blank.txt --t-max 1e-4 --out o
runs_quiet "a comment line of 900 kB reads (the bound is 1 MiB)" layer-impact --sample ok900k.txt --t-max 1e-4
runs_quiet "the sample as layer-make wrote it runs" layer-impact --sample s.txt --t-max 1e-4
py_checks 1 <<'PYEOF'
refused("Python layer_impact on the sample with a 2 MB comment line", ["long.txt", "line 4", "longer than 1048576 bytes"],
        granwave.layer_impact, sample="long.txt", t_max=1e-4)
PYEOF

# --- 3 n above the limit named as written ---
sed 's/^n 40$/n 10000001/' s.txt >nbig.txt
refused "n 10000001: named as written" \
    "^granwave layer-impact: sample 'nbig.txt': line 14: n = 10000001 must be an integer in \\[1, 10000000\\]$" \
    layer-impact --sample nbig.txt --t-max 1e-4 --out o

# --- 4 a table's rows naming one sample with two hashes ---
printf '[sweep]\nmodel = layer\n[grid]\nrb-rm = 0.5, 1\npoint = 0:1\n[params]\nsample = s.txt\npoints = 2\nspacing = 0.3\nvi = 5\nt-max = 0.002\n' >t.ini
timeout 60 "$GW" sweep t.ini --out ta --quiet >/dev/null 2>&1 && [ -s ta/results.csv ] || ko "the sweep over s.txt"
cp s.txt s1.txt
make_sample s.txt --n 40 --width-rm 12 --seed 2      # the same name, another pile
timeout 60 "$GW" sweep t.ini --out tb --quiet >/dev/null 2>&1 && [ -s tb/results.csv ] || ko "the sweep over the new s.txt"
$PY - <<'PYEOF' || ko "joining the two tables"
a = open("ta/results.csv").read().split("\n")
b = open("tb/results.csv").read().split("\n")
rows = lambda L: [i for i, l in enumerate(L) if l[:1].isdigit()]
ra, rb = rows(a), rows(b)
assert len(ra) == 4 and len(rb) == 4 and a[ra[0]].split(",")[-1] != b[rb[0]].split(",")[-1]
j = list(a)
j[ra[1]] = b[rb[1]]            # case 1 of the sweep over the other version
open("joined_input.csv", "w").write("\n".join(j))
open("joined.csv", "w").write("\n".join(l for l in j if not l.startswith("# input")))
open("asis_noinput.csv", "w").write("\n".join(l for l in a if not l.startswith("# input")))
inp = [l for l in a if l.startswith("# input")][0]
k = a.index(inp)
open("input_twice.csv", "w").write("\n".join(a[:k + 1] + [inp] + a[k + 1:]))
c = a[[i for i, l in enumerate(a) if l.startswith("case,")][0]].split(",")
k = ra[0]
v = a[k].split(",")
v[c.index("penetration_rm")] = repr(float(v[c.index("penetration_rm")]) * 1.001)
open("penrm.csv", "w").write("\n".join(a[:k] + [",".join(v)] + a[k + 1:]))
PYEOF
TWO="case 1 read sample '.*/s.txt' with content fnv1a64 [0-9a-f]{16}, but case 0 \\(line [0-9]+\\) read it with [0-9a-f]{16}: a sweep reads one version"
refused "the joined table without its '# input' line: refused naming the line and both cases" \
    "^granwave layer-stats: joined.csv:[0-9]+: $TWO" layer-stats joined.csv --out o
refused "the joined table with its '# input' line: refused (as before) naming the line" \
    "^granwave layer-stats: joined_input.csv:[0-9]+: case 1 read sample .* but the table's '# input' line gives" \
    layer-stats joined_input.csv --out o
refused "a table with its '# input' line given twice: refused naming the second" \
    "^granwave layer-stats: input_twice.csv:[0-9]+: input sample = .*/s.txt given twice" layer-stats input_twice.csv --out o
runs_json "the table as the sweep wrote it" ta.json layer-stats ta/results.csv &&
    ok "the table as the sweep wrote it is read"
runs_json "the table without its '# input' line" noinput.json layer-stats asis_noinput.csv &&
    cmp -s <(grep -v '"input\|"command' ta.json | sed 's#ta/results.csv#TABLE#g') \
        <(grep -v '"input\|"command' noinput.json | sed 's#asis_noinput.csv#TABLE#g') &&
    ok "the table without its '# input' line, its rows agreeing, is read, its statistics the same" ||
    ko "the table without its '# input' line: not read as the whole table"
refused "a table row's penetration_rm edited by 0.1 %: refused naming the line and the R_m of the other rows" \
    "^granwave layer-stats: penrm.csv:[0-9]+: column penetration_rm: [0-9.e-]+ with penetration [0-9.e-]+ gives the sample's R_m as 0.32467[0-9]* m, where 3 other row\\(s\\) of sample '.*/s.txt' give 0.325 m" \
    layer-stats penrm.csv --out o
py_checks 3 <<'PYEOF'
refused("Python layer_stats on the table with a penetration_rm edited", ["penrm.csv", "column penetration_rm", "0.325 m"],
        granwave.layer_stats, "penrm.csv")
refused("Python layer_stats on the joined table without its '# input' line", ["joined.csv", "case 1 read sample", "case 0"],
        granwave.layer_stats, "joined.csv")
refused("Python layer_stats on the table with its '# input' line twice", ["input_twice.csv", "given twice"],
        granwave.layer_stats, "input_twice.csv")
PYEOF

# --- 5 a config's section header without its ']' ---
printf '[sweep]\nmodel = chain\nout = o\n[grid\nn = 1:2\n' >nobr.ini
printf '[sweep\nmodel = chain\nout = o\n[grid]\nn = 1:2\n' >nobr1.ini
sed 's/^\[grid$/[grid]/' nobr.ini >br.ini
refused "a config's '[grid' without its ']': refused naming line 4 and the header" \
    "^granwave sweep: nobr.ini:4: the section header '\\[grid' has no '\\]'$" sweep nobr.ini --check
refused "a config's '[sweep' without its ']': refused naming line 1 and the header" \
    "^granwave sweep: nobr1.ini:1: the section header '\\[sweep' has no '\\]'$" sweep nobr1.ini --check
timeout 60 "$GW" sweep br.ini --check >/dev/null 2>"$tmp/stderr" && ok "the same config with its ']' is valid" ||
    ko "the config with its ']': $(head -c 200 "$tmp/stderr")"

# --- 2 an HDF5 sample's n against its datasets, under a memory limit ---
if ! $PY -c 'import h5py' 2>/dev/null || ! "$GW" version --json 2>/dev/null | grep -q hdf5; then
    echo "SKIP: h5py or an HDF5 build missing"
    test_summary test_hostile_inputs41
    exit 0
fi
make_sample s.h5 --n 40 --width-rm 12 --seed 1
$PY - <<'PYEOF' || ko "making the HDF5 sample with n 1e7"
import h5py, numpy as np, shutil
shutil.copy("s.h5", "nbig.h5")
with h5py.File("nbig.h5", "r+") as f:
    assert int(f.attrs["n"]) == 40
    del f.attrs["n"]
    f.attrs["n"] = np.int64(10000000)
PYEOF
NX="^granwave layer-impact: sample 'nbig.h5': HDF5 dataset 'x' has 40 values, n = 10000000$"
refused "an HDF5 sample whose n says 1e7 over 40 values: refused naming x" "$NX" \
    layer-impact --sample nbig.h5 --t-max 1e-4 --out o
if sanitizer_build; then
    echo "SKIP: the memory-limited run (a sanitizer build reserves its shadow memory beyond any ulimit -v)"
else
    printf '#!/bin/bash\nulimit -v 250000 || exit 9\nexec "%s" "$@"\n' "$GW" >lim.sh
    chmod +x lim.sh
    GW0=$GW GW=$tmp/lim.sh
    refused "the same under ulimit -v 250000 (240 MB of n allocated first: 'out of memory', exit 1)" "$NX" \
        layer-impact --sample nbig.h5 --t-max 1e-4 --out o
    runs_quiet "the HDF5 sample as written runs under the same limit" layer-impact --sample s.h5 --t-max 1e-4
    GW=$GW0
fi

test_summary test_hostile_inputs41
