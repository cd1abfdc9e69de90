#!/bin/bash
# test_sweep.sh GRANWAVE SRCDIR: `granwave sweep` (issue 5).
#  - malformed configs are refused with exit code 2 and "file:line:" (or the
#    key) in one line; nothing is run (an unknown section is reported at its
#    first key's line: libinih hands over keys, not section headers);
#  - a sweep killed with kill -9 or SIGINT mid-run and resumed gives the same
#    results.csv, byte for byte, as an uninterrupted run; a torn journal row is
#    dropped and its case rerun;
#  - serial (threads) and MPI (2 ranks, --oversubscribe) give identical tables.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"

badcfg() { # name expected-text config-body
    printf '%b' "$3" >"$tmp/$1.ini"
    "$GW" sweep "$tmp/$1.ini" --out "$tmp/o_$1" >"$tmp/out" 2>"$tmp/err"; rc=$?
    if [ $rc -eq 2 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q -- "$2" "$tmp/err" && [ ! -e "$tmp/o_$1" ]; then
        ok "malformed config $1 -> exit 2: $(cat "$tmp/err")"
    else
        ko "malformed config $1 -> exit $rc: $(cat "$tmp/err")"
    fi
}
badcfg unknown_key "unknown_key.ini:5:" "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nbogus = 2\n"
badcfg unknown_section ":4:" "[sweep]\nmodel = chain\n[grdi]\nn = 1:3\n"
badcfg bad_syntax ":4:" "[sweep]\nmodel = chain\n[grid]\nthis line has no equals sign\n"
badcfg bad_model ":2:" "[sweep]\nmodel = nosuch\n[grid]\nn = 1:3\n"
badcfg empty_item ":4:" "[sweep]\nmodel = chain\n[grid]\nvimp = 0.1,,0.3\n"
badcfg duplicate ":5:" "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nn = 4\n"
badcfg no_grid "grid" "[sweep]\nmodel = chain\n"
badcfg bad_value "n" "[sweep]\nmodel = chain\n[grid]\nn = 0:3\n"
badcfg bad_value2 "vimp" "[sweep]\nmodel = chain\n[grid]\nn = 1:3\nvimp = 0.3, -1\n"
"$GW" sweep "$tmp/missing.ini" --out "$tmp/x" 2>"$tmp/err"; [ $? -eq 2 ] && ok "missing config -> exit 2: $(cat "$tmp/err")" || ko "missing config"

cat >"$tmp/s.ini" <<CFG
[sweep]
model = chain
[grid]
n = 1:30
vimp = 0.1, 0.2, 0.3
[params]
solver = cvode
CFG
"$GW" sweep "$tmp/s.ini" --out "$tmp/ref" --quiet || ko "reference sweep failed"
rows=$(grep -vc '^#' "$tmp/ref/results.csv")
[ "$rows" -eq 91 ] && ok "reference table has 90 rows + header" || ko "reference table has $rows lines"

# the signal lands once the first case is journaled (90 cases, about 2.5 s of
# CPU: 89 are left); it must land mid-sweep: a journaled row, no table, and
# the exit of a killed process (137) or of the sweep's own SIGINT handling (130)
for sig in KILL INT; do
    if stop_mid_sweep $sig "$tmp/r_$sig" 90 "$GW" sweep "$tmp/s.ini" --out "$tmp/r_$sig" --quiet --jobs 2; then
        want=$([ $sig = KILL ] && echo 137 || echo 130)
        [ "$rc" -eq "$want" ] && ok "SIG$sig mid-sweep: exit $rc, $rows of 90 cases journaled, no table (attempt $attempt)" ||
            ko "SIG$sig mid-sweep: exit $rc, expected $want"
    else
        ko "SIG$sig did not land mid-sweep in 3 attempts (exit $rc, $rows rows journaled, table $(ls "$tmp/r_$sig" 2>/dev/null | tr '\n' ' '))"
    fi
    "$GW" sweep "$tmp/s.ini" --out "$tmp/r_$sig" --quiet || ko "resume after SIG$sig failed"
    cmp -s "$tmp/ref/results.csv" "$tmp/r_$sig/results.csv" && ok "resumed after SIG$sig: table identical to the uninterrupted one" || ko "resumed after SIG$sig: tables differ"
done

# a torn row at the end of the journal is dropped and its case rerun
cp -r "$tmp/ref" "$tmp/torn"
head -c -20 "$tmp/ref/journal.csv" >"$tmp/torn/journal.csv"
rm "$tmp/torn/results.csv"
"$GW" sweep "$tmp/s.ini" --out "$tmp/torn" --quiet || ko "resume with a torn row failed"
cmp -s "$tmp/ref/results.csv" "$tmp/torn/results.csv" && ok "torn journal row dropped and rerun: identical table" || ko "torn row: tables differ"

# a different config in the same directory is refused
sed 's/0.3/0.5/' "$tmp/s.ini" >"$tmp/s2.ini"
"$GW" sweep "$tmp/s2.ini" --out "$tmp/ref" --quiet 2>"$tmp/err"; [ $? -eq 2 ] && ok "other config in the same directory refused: $(cat "$tmp/err")" || ko "other config accepted"

if command -v mpirun >/dev/null && ! ldd "$GW" 2>/dev/null | grep -q libmpi; then
    echo "SKIP: granwave built without MPI (two ranks would run two serial sweeps)"
elif command -v mpirun >/dev/null; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -n 2 "$GW" sweep "$tmp/s.ini" --out "$tmp/mpi" --quiet >"$tmp/mpi.log" 2>&1
    cmp -s "$tmp/ref/results.csv" "$tmp/mpi/results.csv" && ok "MPI (2 ranks) table identical to the threaded one" || { ko "MPI table differs or failed"; tail -5 "$tmp/mpi.log"; }
else
    echo "SKIP: mpirun not installed"
fi
test_summary
