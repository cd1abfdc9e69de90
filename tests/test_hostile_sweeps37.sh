#!/bin/bash
# test_hostile_sweeps37.sh GRANWAVE SRCDIR: the thirty-seventh hostile pass, over
# sweeps. A journal removed from the sweep's directory while the sweep ran
# (`rm DIR/journal.csv`): the sweep went on appending its rows to a file in no
# directory, ran every case left, then exited 1 ("DIR/journal.csv: cannot read:
# No such file or directory"), no table, no journal: every finished row lost, a
# rerun ran them all again. Now the journal is put back whole at the next row
# (one warning line), the sweep finishes with the uninterrupted table.
#  1 threads (--jobs 1, --jobs 2): exit 0, one warning line naming the journal,
#    the table byte-identical to an undisturbed sweep's, each case journaled once
#  2 under mpirun -np 2 alike
#  3 removed, then the sweep killed with kill -9: the put-back journal holds the
#    rows finished before the kill, and the rerun's table is the undisturbed one
#  4 kept: the whole directory removed still stops the sweep (exit 1, naming it)
# The journal (the directory) is removed right before the sweep's second row is
# appended (at_row, the move shim): mid-sweep on any machine, where removing it
# once the first row showed raced the end of the 1.5 s sweep. SKIP without the shim.
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
mpi_setup
chain_sweep8_reference

# each case journaled once, all 8
once() { [ "$(grep -v '^#' "$1" 2>/dev/null | cut -d, -f1 | sort -u | wc -l)" -eq 8 ] && [ "$(journal_rows "$1")" -eq 8 ]; }

# --- 1, 2: the journal removed after the first row
removed() { # WHAT DIR CMD...
    local what=$1 d=$2 rc
    shift 2
    rm -rf "$d"
    # removed right before the second row is appended (at_row: mid-sweep on any machine)
    at_row 2 "rm -f '$d/journal.csv'" "$@" >/dev/null 2>"$d.err"; rc=$?
    if [ $rc -eq 77 ]; then echo "SKIP: $what (no move shim in this build)"; return; fi
    [ $rc -eq 0 ] && [ "$(wc -l <"$d.err")" -eq 1 ] && grep -q "journal.csv was removed while the sweep ran: put back" "$d.err" &&
        ok "$what: exit 0, one line: $(cat "$d.err")" ||
        ko "$what: journal removed mid-sweep: exit $rc: $(head -3 "$d.err")"
    cmp -s "$d/results.csv" "$tmp/ref/results.csv" && ok "$what: the table is the undisturbed one" ||
        ko "$what: table $( [ -e "$d/results.csv" ] && echo differs || echo missing)"
    once "$d/journal.csv" && ok "$what: the journal holds each case once" ||
        ko "$what: journal holds $(journal_rows "$d/journal.csv") rows"
}
removed "1 --jobs 1" "$tmp/d1" "$GW" sweep "$tmp/a.ini" --out "$tmp/d1" --quiet --jobs 1
removed "1 --jobs 2" "$tmp/d2" "$GW" sweep "$tmp/a.ini" --out "$tmp/d2" --quiet --jobs 2
if [ $have_mpi = 1 ]; then
    removed "2 mpirun -np 2" "$tmp/d3" mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/a.ini" --out "$tmp/d3" --quiet
else
    echo "SKIP: 2 (no mpirun or not an MPI build)"
fi

# --- 3: removed, put back, then kill -9: the rerun resumes the put-back rows
# removed right before the second row (at_row), the pid noted then; kill -9 once
# the put-back journal holds two rows. A sweep that ended before the kill (a
# table: the put-back journal was not killed) is run again, three times at most.
d=$tmp/d4
for attempt in 1 2 3; do
    rm -rf "$d" "$d.pid"
    at_row 2 "echo \$PPID >'$d.pid'; rm -f '$d/journal.csv'" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 \
        >/dev/null 2>"$d.err" & pa=$!
    if wait_file $pa "$d.pid" && wait_rows "$d/journal.csv" 2 60; then
        kill -KILL "$(cat "$d.pid")" 2>/dev/null
    fi
    wait $pa 2>/dev/null; rc=$?
    [ $rc -eq 77 ] || [ ! -e "$d/results.csv" ] && break
done
if [ $rc -eq 77 ]; then
    echo "SKIP: 3 (no move shim in this build)"
elif [ ! -e "$d/results.csv" ] && [ "$(journal_rows "$d/journal.csv")" -ge 2 ]; then
    kept=$(journal_rows "$d/journal.csv")
    ok "3: the journal was put back ($kept rows when kill -9 came, attempt $attempt)"
    "$GW" sweep "$tmp/a.ini" --out "$d" 2>"$d.err2"; rc=$?
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && once "$d/journal.csv" &&
        grep -q "$kept already done" "$d.err2" &&
        ok "3: the rerun resumed its $kept rows, table byte-identical" ||
        ko "3: rerun after kill -9: exit $rc: $(grep -v '^sweep: [0-9]*/' "$d.err2" | head -3)"
else
    ko "3: the removed journal never came back, or the sweep ended first in 3 attempts ($(ls "$d" | tr '\n' ' '))"
fi

# --- 4 (kept): the directory itself removed still stops the sweep
d=$tmp/p/d5
mkdir -p "$tmp/p"
at_row 2 "rm -rf '$tmp/p'" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 >/dev/null 2>"$tmp/e5"; rc=$?
if [ $rc -eq 77 ]; then
    echo "SKIP: 4 (no move shim in this build)"
else
    [ $rc -eq 1 ] && grep -q "the sweep's directory was removed while the sweep ran" "$tmp/e5" &&
        ok "4: a removed directory still stops the sweep (exit 1)" || ko "4: directory removed: exit $rc: $(cat "$tmp/e5")"
fi

test_summary test_hostile_sweeps37
