#!/bin/bash
# test_sweep_dir_moved.sh GRANWAVE SRCDIR MOVE_SHIM: a sweep whose directory
# is moved, renamed, replaced or removed while it runs (issue 18). The sweep
# appended its rows through the journal it held open, but read the journal
# back by name for its table: a directory moved mid-run exited 1 ("D/journal.csv:
# cannot read"), its complete journal in the moved directory and no table. The
# sweep now opens its directory once and finds, reads and writes its journal
# and table through it: it finishes in the moved directory (exit 0, its table
# byte-identical to an undisturbed sweep's) and says in one line where they
# are, with --quiet too; removed, it stops at its next row (exit 1, one line).
# The shim (tests/move_shim.c) runs the move right before the K-th row is
# appended to the journal: the same point of the sweep on any machine.
#  1 mv D D.old at row 3 of 8 (--jobs 1): exit 0, D.old's table the
#    reference's, one line naming D and D.old, no D, no temporary;
#  2 mv D D.old; mkdir D at row 3 (--jobs 2): the same, the new D empty;
#  3 mv D D.old at row 8 (the last; the table comes after it): the same;
#  4 mv D D.old; ln -s D.old D (the same directory): exit 0, no warning;
#  5 mv D D.old and SIGTERM at row 3: exit 130 saying where D went; after
#    mv D.old D the rerun resumes and its table is the reference's;
#  6 rm -rf D at row 3: exit 1, one line saying the directory was removed;
#  7 under mpirun -n 2 (when the program has MPI): as 1.
# 18 checks (15 without MPI); on the code before, 11 fail (exit 1 "cannot
# read" and no table in 1 to 3 and 7, the messages of 5 and 6, and 6 ran on
# to its last row); 4, the resume of 5, "no D" and the new D empty are
# controls.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
SHIM=$(shim_path "${3:-}" move) || { echo "SKIP: no move shim (not built here)"; exit 0; }
cd "$tmp" || exit 1
export LC_ALL=C
printf '[sweep]\nmodel = chain\nout = D\n[grid]\nn = 2:9\n[params]\nvimp = 0.1\n' >s.ini
"$GW" sweep s.ini --out ref --quiet 2>err.txt || { echo "FAIL: the reference sweep: $(head -c 300 err.txt)"; exit 1; }

# moved K CMD [ARGS]: granwave sweep s.ini --out D --quiet ARGS, CMD run right
# before the K-th row is appended; sets rc and err.txt
moved() {
    local k=$1 cmd=$2
    shift 2
    rm -rf D D.old
    GW_MOVE_AT=$k GW_MOVE_RUN=$cmd GW_MOVE_COUNT=count.txt LD_PRELOAD=$SHIM \
        "$GW" sweep s.ini --out D --quiet "$@" >/dev/null 2>err.txt
    rc=$?
}
said_moved() { [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^granwave sweep: warning: D was moved while the sweep ran: its journal and table are in $tmp/D.old$" err.txt; }
# finished_in DIR: DIR holds the journal and a table identical to the reference's, nothing else
finished_in() { cmp -s "$1/results.csv" ref/results.csv && [ "$(ls -A "$1" | tr '\n' ' ')" = "journal.csv results.csv " ]; }

moved 3 'mv D D.old' --jobs 1
[ $rc -eq 0 ] && said_moved && ok "1 moved at row 3: exit 0, $(cut -c1-160 err.txt)" || ko "1 moved at row 3: exit $rc, $(head -c 300 err.txt)"
finished_in D.old && ok "  D.old: the journal and the reference's table" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
[ ! -e D ] && ok "  no D" || ko "  D exists: $(ls -A D | tr '\n' ' ')"

moved 3 'mv D D.old && mkdir D' --jobs 2
[ $rc -eq 0 ] && said_moved && ok "2 moved and a new D made at row 3, --jobs 2: exit 0, the line" || ko "2 moved, new D: exit $rc, $(head -c 300 err.txt)"
finished_in D.old && ok "  D.old: the journal and the reference's table" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
[ -d D ] && [ -z "$(ls -A D)" ] && ok "  the new D is empty" || ko "  the new D holds $(ls -A D 2>&1 | tr '\n' ' ')"

moved 8 'mv D D.old'
[ $rc -eq 0 ] && said_moved && ok "3 moved at row 8 of 8: exit 0, the line" || ko "3 moved at the last row: exit $rc, $(head -c 300 err.txt)"
finished_in D.old && ok "  D.old: the journal and the reference's table" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"

moved 3 'mv D D.old && ln -s D.old D'
[ $rc -eq 0 ] && [ ! -s err.txt ] && ok "4 D a link to the moved directory: exit 0, nothing said" || ko "4 D a link to D.old: exit $rc, $(head -c 300 err.txt)"
finished_in D.old && ok "  D.old: the journal and the reference's table" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"

# 5: the signal from the command's shell to the sweep ($PPID; system() holds SIGINT off, not SIGTERM)
moved 3 'mv D D.old && kill -TERM $PPID' --jobs 1
[ $rc -eq 130 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "D was moved to $tmp/D.old while the sweep ran: move it back" err.txt &&
    ok "5 moved and stopped at row 3: exit 130, $(cut -c1-200 err.txt)" || ko "5 moved and stopped: exit $rc, $(head -c 300 err.txt)"
n=$(journal_rows D.old/journal.csv)
[ ! -e D.old/results.csv ] && [ "$n" -ge 2 ] && [ "$n" -lt 8 ] && ok "  D.old: $n rows, no table" || ko "  D.old: $n rows, $(ls -A D.old | tr '\n' ' ')"
mv D.old D
"$GW" sweep s.ini --out D --quiet --jobs 1 2>err.txt
rc=$?
[ $rc -eq 0 ] && cmp -s D/results.csv ref/results.csv && ok "  moved back: the rerun resumes, the reference's table" ||
    ko "  moved back and rerun: exit $rc, $(head -c 300 err.txt)"

moved 3 'rm -rf D' --jobs 1
[ $rc -eq 1 ] && [ "$(wc -l <err.txt)" -eq 1 ] && grep -q "^granwave sweep: D: the sweep's directory was removed while the sweep ran" err.txt &&
    ok "6 removed at row 3: exit 1, $(cut -c1-120 err.txt)" || ko "6 removed at row 3: exit $rc, $(head -c 300 err.txt)"
rows=$(sed 's/rows //' count.txt 2>/dev/null)
[ ! -e D ] && [ "${rows:-0}" -eq 3 ] && ok "  no D; stopped at that row (3 journal writes)" || ko "  D: $(ls -A D 2>&1 | tr '\n' ' '); $rows journal writes"

if command -v mpirun >/dev/null && ldd "$GW" 2>/dev/null | grep -q libmpi; then
    rm -rf D D.old
    GW_MOVE_AT=3 GW_MOVE_RUN='mv D D.old' LD_PRELOAD=$SHIM OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
        mpirun --oversubscribe -n 2 "$GW" sweep s.ini --out D --quiet >mpi.log 2>err.txt
    rc=$?
    [ $rc -eq 0 ] && grep -q "^granwave sweep: warning: D was moved while the sweep ran: its journal and table are in $tmp/D.old$" err.txt &&
        ok "7 under mpirun -n 2, moved at row 3: exit 0, the line" || ko "7 mpirun, moved: exit $rc, $(head -c 300 err.txt) $(head -c 300 mpi.log)"
    finished_in D.old && ok "  D.old: the journal and the reference's table" || ko "  D.old holds $(ls -A D.old | tr '\n' ' ')"
    [ ! -e D ] && ok "  no D" || ko "  D exists"
else
    echo "SKIP: 7 (mpirun, or the program without MPI)"
fi

test_summary test_sweep_dir_moved
