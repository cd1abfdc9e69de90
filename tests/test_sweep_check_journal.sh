#!/bin/bash
# test_sweep_check_journal.sh GRANWAVE SRCDIR: `granwave sweep CONFIG --check`
# reads the journal already in the output directory as a resume would, by the
# resume's own code (gw_sweep_journal_resume_check, the checks of
# gw_sweep_journal_open), and writes nothing (issue 18). Before, --check
# validated the config and its cases only: it said "is valid" beside the
# journal of another config, one edited by hand, one that is no journal, or one
# another sweep held locked, each of which the run then refused.
#  1 no output directory yet: "no journal yet: a run starts all N cases", exit 0,
#    nothing made;
#  2 a finished sweep: "N of N cases done: a rerun writes the table only",
#    journal and table unchanged;
#  3 an interrupted sweep (rows missing, a torn last row): the cases done and
#    to run, the torn row's bytes ("1 byte" in the singular); the journal not
#    cut; the resume that follows reports the same counts ("K already done, R
#    to run"); a torn line of the journal's head named as such, not as a row
#    whose case runs again, and cut by the resume, which runs every case once;
#  4 refusals, each exit 2 with one stderr line, byte for byte the line the
#    resume prints, nothing written: another config's journal, a row edited by
#    hand, a file that is no journal, a directory of its name, a journal locked
#    by a running sweep; under mpirun too (where available).
# 11 of the 15 checks fail on the code before (the four that pass: nothing made
# by --check, the two resumes' own counts and the resumed journal's rows); of
# the three on a one-byte row and a torn head line (issue 18, later), the two
# --check lines fail on the code before ("(1 bytes)", "its torn last row (10
# bytes) is cut then and its case run again").
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

printf '[sweep]\nmodel = chain\nout = out\n[grid]\nn = 2:5\n[params]\nvimp = 0.3\n' >s.ini

# out_state: out/'s listing (times to the ns) and the digest of its bytes
out_state() { ls -l --time-style=+%s.%N out 2>&1; cat out/* 2>/dev/null | md5sum; }

# run_check: `sweep s.ini --check`, stdout in o.txt, stderr in e.txt; sets rc
# (its exit) and changed (1 when out/ is not as it was)
run_check() {
    local before; before=$(out_state)
    "$GW" sweep s.ini --check >o.txt 2>e.txt </dev/null
    rc=$?
    changed=0
    [ "$before" = "$(out_state)" ] || changed=1
}

# check WHAT PATTERN: --check exits 0, stdout's second line matches PATTERN
# (ERE), nothing on stderr, out/ as it was (listing and bytes)
check() {
    local what=$1 pat=$2
    run_check
    if [ $rc -ne 0 ] || [ -s e.txt ]; then ko "$what: exit $rc, stderr '$(head -c 300 e.txt)'"
    elif ! sed -n 2p o.txt | grep -qE -- "$pat"; then ko "$what: said '$(cat o.txt)', not '$pat'"
    elif [ $changed -ne 0 ]; then ko "$what: out/ changed"
    else ok "$what"; fi
}

# refused WHAT PATTERN: --check exits 2 with one stderr line matching PATTERN,
# the same line (and exit code) as the resume that follows; out/ unchanged
refused() {
    local what=$1 pat=$2
    run_check
    timeout -s KILL 60 "$GW" sweep s.ini --quiet >/dev/null 2>r.txt </dev/null
    local rrc=$?
    if [ $rc -ne 2 ] || [ "$(wc -l <e.txt)" -ne 1 ]; then
        ko "$what: exit $rc, $(wc -l <e.txt) stderr lines ('$(head -c 300 e.txt)'; stdout '$(head -c 200 o.txt)')"
    elif ! grep -qE -- "$pat" e.txt; then ko "$what: said '$(cat e.txt)', not '$pat'"
    elif [ -s o.txt ]; then ko "$what: printed on stdout"
    elif [ $changed -ne 0 ]; then ko "$what: out/ changed"
    elif [ $rrc -ne $rc ] || ! cmp -s e.txt r.txt; then ko "$what: the resume said '$(cat r.txt)' (exit $rrc), the check '$(cat e.txt)'"
    else ok "$what"; fi
}

# 1 before the first run
check "no output directory yet" "^sweep: $tmp/out: no journal yet: a run starts all 4 cases$"
[ ! -e out ] && ok "  nothing made by --check" || ko "  --check made $(ls -d out/* out 2>/dev/null)"

# 2 a finished sweep
"$GW" sweep s.ini --quiet >/dev/null 2>&1 || ko "the sweep itself failed"
cp out/journal.csv full.csv
check "a finished sweep" "^sweep: $tmp/out/journal.csv: 4 of 4 cases done: a rerun writes the table only$"

# 3 an interrupted sweep: two rows gone, then a torn last row as kill -9 leaves it
head -n 6 full.csv >out/journal.csv   # the head (4 lines) and 2 rows
check "an interrupted sweep, 2 rows" "^sweep: $tmp/out/journal.csv: 2 of 4 cases done, 2 to run on a resume$"
"$GW" sweep s.ini >/dev/null 2>r.txt </dev/null
grep -q "^sweep: 4 cases, 2 already done, 2 to run" r.txt && ok "  the resume ran what --check said (2 done, 2 to run)" ||
    ko "  the resume said '$(head -1 r.txt)'"
head -c -40 full.csv >out/journal.csv
torn=$(( $(tail -n 1 out/journal.csv | wc -c) ))
check "a torn last row" "^sweep: $tmp/out/journal.csv: 3 of 4 cases done, 1 to run on a resume; its torn last row \($torn bytes\) is cut then and its case run again$"
"$GW" sweep s.ini >/dev/null 2>r.txt </dev/null
grep -q "^sweep: 4 cases, 3 already done, 1 to run" r.txt && ok "  the resume ran what --check said (3 done, 1 to run)" ||
    ko "  the resume said '$(head -1 r.txt)'"
cmp -s out/journal.csv full.csv || [ "$(sort out/journal.csv | md5sum)" = "$(sort full.csv | md5sum)" ] &&
    ok "  the resumed journal holds the sweep's rows" || ko "  the resumed journal differs from the finished sweep's"
# the count said in the singular for one byte ("(1 bytes)" before)
head -n 5 full.csv >out/journal.csv   # the head and 1 row
tail -n 1 full.csv | head -c 1 >>out/journal.csv
check "a torn last row of one byte" "^sweep: $tmp/out/journal.csv: 1 of 4 cases done, 3 to run on a resume; its torn last row \(1 byte\) is cut then and its case run again$"
# a torn line of the journal's head (its # param line cut short): no row, so
# no case to run again for it (before: "its torn last row ... and its case run again")
head -n 3 full.csv >out/journal.csv
printf '# param vi' >>out/journal.csv
check "a torn line of the journal's head" "^sweep: $tmp/out/journal.csv: 0 of 4 cases done, 4 to run on a resume; the torn last line of its head \(10 bytes\) is cut then, no case to run again for it$"
"$GW" sweep s.ini >/dev/null 2>r.txt </dev/null
grep -q "^sweep: 4 cases, 0 already done, 4 to run" r.txt && [ "$(journal_rows out/journal.csv)" -eq 4 ] &&
    ! grep -q '^# param vi' out/journal.csv && ok "  the resume cut the torn head line and ran the 4 cases, each once" ||
    ko "  the resume after a torn head line said '$(head -1 r.txt)', journal rows $(journal_rows out/journal.csv)"

# 4 refusals, as the resume's
cp full.csv out/journal.csv
sed -i 's/vimp = 0.3/vimp = 0.4/' s.ini
refused "the journal of another config" "^granwave sweep: $tmp/out: this directory holds another sweep: \[params\] vimp = 0.4 here, 0.3 in its journal"
sed -i 's/vimp = 0.4/vimp = 0.3/' s.ini
awk 'NR == 6 { sub(/,67\./, ",68.") } { print }' full.csv >out/journal.csv
refused "a row edited by hand" "^granwave sweep: $tmp/out/journal.csv:6: .*the journal was edited by hand"
printf 'case,n,f_max\n0,2,1\n' >out/journal.csv
refused "a file that is no journal" "^granwave sweep: $tmp/out/journal.csv: not a granwave sweep journal"
rm out/journal.csv; mkdir out/journal.csv
refused "a directory named journal.csv" "$tmp/out/journal.csv"
rmdir out/journal.csv; cp full.csv out/journal.csv
# the lock a running sweep holds (flock LOCK_EX on the journal), held by this shell
exec 9<>out/journal.csv
if flock -n -x 9; then
    refused "a journal locked by a running sweep" "^granwave sweep: $tmp/out: another sweep is running in this directory"
else
    ko "the journal could not be locked for the test"
fi
exec 9>&-

# under mpirun: the journal read by rank 0 as alone (before: "is valid"); and
# a refusal of rank 0 under --check (--out naming a file) sent the other ranks
# to the end while rank 0 waited for them in the journal's broadcast ("MPI
# Error in NBC subrequest", exit 15): every rank ends there now, exit 2
# (not in a sanitizer build, whose leak report of Open MPI's own allocations
# ends every rank with exit 1; told by its shadow memory failing under an
# address-space limit, as test_hostile_layer does)
if ! command -v mpirun >/dev/null; then
    echo "SKIP: mpirun not installed"
elif ! (ulimit -v 1700000; "$GW" --help >/dev/null 2>&1); then
    echo "SKIP: mpirun checks in a sanitizer build"
else
    cp full.csv out/journal.csv
    sed -i 's/vimp = 0.3/vimp = 0.5/' s.ini
    timeout -s KILL 60 mpirun --allow-run-as-root --oversubscribe -np 2 "$GW" sweep s.ini --check >o.txt 2>e.txt </dev/null
    rc=$?
    if [ $rc -eq 2 ] && grep -q "^granwave sweep: $tmp/out: this directory holds another sweep" e.txt && ! grep -q "MPI Error" e.txt; then
        ok "under mpirun -np 2: another config's journal refused, exit 2"
    else
        ko "under mpirun -np 2: exit $rc, $(head -c 300 e.txt)"
    fi
    sed -i 's/vimp = 0.5/vimp = 0.3/' s.ini
    timeout -s KILL 60 mpirun --allow-run-as-root --oversubscribe -np 2 "$GW" sweep s.ini --check --out s.ini >o.txt 2>e.txt </dev/null
    rc=$?
    if [ $rc -eq 2 ] && grep -q "^granwave sweep --out: 's.ini' exists and is not a directory" e.txt && ! grep -q "MPI Error" e.txt; then
        ok "under mpirun -np 2: --out naming a file refused, exit 2"
    else
        ko "under mpirun -np 2, --out s.ini: exit $rc, $(head -c 300 e.txt)"
    fi
fi

test_summary
