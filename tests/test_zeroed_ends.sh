#!/bin/bash
# test_zeroed_ends.sh GRANWAVE SRCDIR: files whose end is zeros.
#  1 A text sample with a valid head longer than the 64 KiB the sweep's
#    sample rule looks at (a 20-particle sample and a 70000-character comment
#    line), followed by sparse zeros up to 4 GiB, passed the rule, was hashed
#    whole (about a minute under load) and refused by the reader only then.
#    Now the rule finds the hole (SEEK_HOLE) or a NUL byte in the file's last
#    4 KiB at once: sweep and sweep --check refuse it within 5 s naming the
#    file and its size, nothing written; the same with 5000 NUL bytes written
#    after the text (no hole). Control: the sample with its long comment
#    alone is taken.
#  2 A sweep journal whose end a power cut left zeroed (NUL bytes after its
#    last complete row) was refused as binary data, to be moved away by hand.
#    Now the zeros are cut on resume as a torn row is: --check says so, the
#    resume runs the case left and writes a table and a journal byte-identical
#    to an uninterrupted run's. A NUL byte inside a line (a torn row then
#    zeros), or text after the zeros, is still refused naming its line, the
#    journal left as it is.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 a sample's zeros after 64 KiB of valid text ---
make_sample s20.txt --n 20 --width-rm 8
cp s20.txt long.txt
{ printf '# '; head -c 70000 /dev/zero | tr '\0' x; printf '\n'; } >>long.txt
sweep_ini() { printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = %s\nt-max = 0.002\n' "$1" >"$2"; }
sweep_ini long.txt long.ini
timeout -s KILL 60 "$GW" sweep long.ini --check --out o >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "sweep --check takes the sample with a 70000-character comment (the control)" ||
    ko "sweep --check on the long sample: exit $? ($(head -c 200 "$tmp/stderr"))"
cp long.txt sparse.txt
truncate -s 4294967296 sparse.txt
sweep_ini sparse.txt sparse.ini
cp long.txt zeros.txt
head -c 5000 /dev/zero >>zeros.txt
zsize=$(stat -c %s zeros.txt)
sweep_ini zeros.txt zeros.ini
for mode in run check; do
    extra=()
    [ $mode = check ] && extra=(--check)
    REFUSE_TIMEOUT=5 refused "sweep ($mode): the sample's 4 GiB of sparse zeros after its text" \
        "^granwave sweep: sparse\\.ini: \\[params\\] sample '[^']*sparse\\.txt': 4294967296 bytes, and its bytes from [0-9]+ on are a hole" \
        sweep sparse.ini "${extra[@]}" --out o
    REFUSE_TIMEOUT=5 refused "sweep ($mode): the sample's 5000 NUL bytes written after its text" \
        "^granwave sweep: zeros\\.ini: \\[params\\] sample '[^']*zeros\\.txt': $zsize bytes, and its byte [0-9]+ is a NUL byte, near its end" \
        sweep zeros.ini "${extra[@]}" --out o
done

# --- 2 a journal's zeroed end ---
printf '[sweep]\nmodel = chain\n[grid]\nn = 2:4\n[params]\nsolver = rk4\n' >c.ini
timeout -s KILL 120 "$GW" sweep c.ini --out a --quiet >/dev/null 2>"$tmp/stderr" </dev/null ||
    ko "the uninterrupted sweep: exit $? ($(head -c 200 "$tmp/stderr"))"
# the head (4 lines) and 2 of the 3 rows, then a power cut's 4096 NUL bytes
mkdir b
head -n 6 a/journal.csv >b/journal.csv
head -c 4096 /dev/zero >>b/journal.csv
timeout -s KILL 60 "$GW" sweep c.ini --out b --check >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
rc=$?
grep -q "2 of 3 cases done, 1 to run on a resume; its zeroed end (4096 NUL bytes after its last line" "$tmp/stdout" &&
    [ $rc = 0 ] && ok "sweep --check: the zeroed end counted, to be cut" ||
    ko "sweep --check on the zeroed journal: exit $rc ($(head -c 300 "$tmp/stdout" "$tmp/stderr"))"
timeout -s KILL 120 "$GW" sweep c.ini --out b --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc = 0 ] && ok "the resume after the zeroed end runs" || ko "the resume: exit $rc ($(head -c 300 "$tmp/stderr"))"
cmp -s a/results.csv b/results.csv && ok "its table is byte-identical to the uninterrupted run's" ||
    ko "the resumed table differs from the uninterrupted run's"
cmp -s a/journal.csv b/journal.csv && ok "its journal too (the zeros cut, the case left appended)" ||
    ko "the resumed journal differs from the uninterrupted run's"
# a NUL byte inside a line: a torn row and then zeros, or text after the zeros
mkdir c d
head -n 6 a/journal.csv >c/journal.csv
printf '2,4,1' >>c/journal.csv
head -c 4096 /dev/zero >>c/journal.csv
head -n 6 a/journal.csv >d/journal.csv
head -c 4096 /dev/zero >>d/journal.csv
echo x >>d/journal.csv
for dir in c d; do
    cp $dir/journal.csv "$tmp/before"
    for mode in run check; do
        extra=()
        [ $mode = check ] && extra=(--check)
        if exits_refused "sweep ($mode, $dir): a NUL byte after a torn row, or text after the zeros" \
            "^granwave sweep: sweep journal '$dir/journal\\.csv': line 7 \\(byte [0-9]+\\): a NUL byte" 30 \
            "$GW" sweep c.ini --out $dir "${extra[@]}"; then
            cmp -s $dir/journal.csv "$tmp/before" && [ ! -e $dir/results.csv ] &&
                ok "sweep ($mode, $dir): refused naming line 7, the journal as it was, no table" ||
                ko "sweep ($mode, $dir): the journal was changed or a table written"
        fi
    done
done

test_summary test_zeroed_ends
