#!/bin/bash
# test_hostile_sweeps39.sh GRANWAVE SRCDIR: a sweep's journal written into
# while the sweep ran. A journal rewritten in place (`> DIR/journal.csv`, an
# editor writing into the file, another program adding a line) is the same
# file as the sweep's: its name and inode checks passed, the sweep appended its
# rows to the other content and found them lost only when it wrote the table
# (exit 1 after every case). A journal removed and put back, then written
# into by the editor that removed it more than 0.2 s later (the put-back
# watches its free name that long), had the sweep's rows written into the
# editor's text alike. Now the sweep checks before each row that its journal
# holds what it wrote (its size, its last bytes, the whole file when its times
# changed) and, found otherwise, keeps its journal whole beside it
# (DIR/journal.kept.csv), hands out no case after it and exits 1 in one line
# naming both files; the file written into is left as it is.
#  1 threads (--jobs 2), the journal cut to nothing (`: >`) after
#    its first row: exit 1, one line naming journal.csv and journal.kept.csv,
#    no table, journal.csv empty still, the kept journal holding the rows of
#    before and after the cut, each case once, fewer than the grid's (no case
#    handed out after it); moved over journal.csv, the rerun (the other way:
#    mpirun -np 2 when here) resumes every row, table byte-identical
#  2 mpirun -np 2 (threads without MPI): a row's digit changed in place (the
#    same length: found by the file's times, its bytes compared): alike, the
#    file left byte for byte as edited; resumed on threads, byte-identical
#  3 a line added by another program (echo >> journal.csv): alike
#  4 the journal removed, put back by the sweep, then the copy the remover
#    took before written into the put-back file after the sweep's next row
#    (later than the 0.2 s watch), threads and MPI: the sweep never writes
#    into it again, keeps its rows whole, exit 1 (after the put-back's
#    warning line); resumed (threads on --jobs 2, MPI on --jobs 1),
#    byte-identical
#  6 a journal of 24 rows before the sweep resumed (5 kB), a row outside
#    its last 4096 bytes edited in place, its length kept: found by the
#    file's events (inside the row's write), alike; resumed, byte-identical
#  5 kept: the journal touched (its times changed) and its mode changed mid-
#    sweep, the bytes the sweep's: exit 0, the undisturbed table, nothing said
# Each disturbance is made right before the second row of the run is
# written (at_row, the move shim): mid-sweep on any machine, where one made once
# the first row showed raced the end of the sweep. That row is then appended
# after it (the sweep checked before it): the file is what was written and that
# row. The late save's write comes from the script, after the put-back and a
# row; a sweep that ended before it is run again. SKIP without the shim. 6's
# edit is made inside the second row's write too: found since the file's
# events are watched (test_journal_window; the times the sweep recorded after
# its own append covered it, and only the end found the rows lost), where it
# came from the script once a row showed, racing the sweep's three cases.
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
mpi_setup
chain_sweep8_reference
# a 16-case grid (about 1.2 s of CPU) for the put-back's runs, which need time
# after the 0.2 s watch
printf '[sweep]\nmodel = chain\n[grid]\nn = 60, 70, 80, 90\nvimp = 0.1, 0.2, 0.3, 0.4\n[params]\nsolver = rk4\n' >"$tmp/b.ini"
"$GW" sweep "$tmp/b.ini" --out "$tmp/refb" --quiet --jobs 1 || ko "reference sweep of 16 cases"

# written WHAT DIR TOTAL WARN DISTURB CMD...: CMD (a sweep of TOTAL cases into
# DIR) run, DISTURB (a function of DIR that leaves what it wrote into the
# journal in DIR.left) run right before the sweep's second row of this run is
# appended (at_row: mid-sweep on any machine; once its first row showed, it
# raced the sweep's end); checks what it left: WARN lines said before the
# error line (the put-back's warning). late_save's removal is made there, its
# late write from the script after the put-back and a row: a sweep that ended
# before it (a table) is run again, three times at most.
written() {
    local what=$1 d=$2 total=$3 warn=$4 disturb=$5 pa rc attempt
    shift 5
    for attempt in 1 2 3; do
        rm -rf "$d" "$d.err" "$d.left" "$d.removed"
        ${prep:-true} "$d" # (a journal to resume: the rows it holds, and one more awaited)
        if [ "${async:-0}" = 1 ]; then
            # (from the script once the first row shows: see 6)
            "$@" >/dev/null 2>"$d.err" & pa=$!
            wait_rows "$d/journal.csv" $(($(journal_rows "$d/journal.csv") + 1)) 60 || ko "$what: the sweep journaled nothing"
            $disturb "$d"
            wait $pa; rc=$?
            break
        elif [ "$disturb" = late_save ]; then
            at_row 2 "cp '$d/journal.csv' '$d.left' && rm '$d/journal.csv' && : >'$d.removed'" "$@" >/dev/null 2>"$d.err" & pa=$!
            wait_file $pa "$d.removed" && late_write "$d"
            wait $pa; rc=$?
        else
            at_row_fn 2 "$disturb" "$d" "$@" >/dev/null 2>"$d.err"; rc=$?
        fi
        [ $rc -eq 77 ] || [ ! -e "$d/results.csv" ] && break
        echo "note: $what, attempt $attempt: the sweep ended before the late write; run again"
    done
    if [ $rc -eq 77 ]; then echo "SKIP: $what (no move shim in this build)"; return; fi
    # (mpirun adds its block of lines on a rank's exit status 1, after the program's)
    sweep_stopped "$what" $rc "$d.err" $((warn + 1)) \
        "^granwave sweep: $d/journal.csv was written into while the sweep ran.*kept whole as $d/journal.kept.csv, the file left as it is"
    # at_row's disturbance comes inside the second row's write, which then
    # appends that row (the sweep checked before it): what was written, then
    # that one row of the kept journal, nothing of the sweep's after it
    if [ "$disturb" = late_save ] || [ "${async:-0}" = 1 ]; then
        cp "$d.left" "$d.expected"
    else
        { cat "$d.left"; tail -c +$(($(stat -c %s "$d.left") + 1)) "$d/journal.csv" | head -1 |
            grep -xF -f - "$d/journal.kept.csv"; } >"$d.expected"
    fi
    [ ! -e "$d/results.csv" ] && cmp -s "$d/journal.csv" "$d.expected" &&
        ok "$what: no table, the file written into left as it is (and the row written as it was written into)" ||
        ko "$what: table $(ls "$d" | tr '\n' ' '), journal.csv against what was written: $(cmp "$d/journal.csv" "$d.expected" 2>&1)"
    kept_rows "$what" "$d/journal.kept.csv" "$d.left" "$total" "$d.err"
}

# resumed WHAT DIR REF CMD...: the kept journal moved over journal.csv, CMD
# resumes DIR to REF's table, skipping its rows
resumed() {
    local what=$1 d=$2 ref=$3 had rc
    shift 3
    mv "$d/journal.kept.csv" "$d/journal.csv"
    had=$(journal_rows "$d/journal.csv")
    "$@" 2>"$d.err2" >/dev/null; rc=$?
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$ref/results.csv" && grep -q "cases, $had already done" "$d.err2" &&
        ok "$what: the kept journal moved back resumed its $had rows, table byte-identical" ||
        ko "$what: exit $rc: $(grep -v '^sweep: [0-9]*/' "$d.err2" | head -3)"
}
# the other way: mpirun -np 2 after threads, threads after MPI (threads alone without MPI)
other_way() {
    if [ $have_mpi = 1 ] && [ "$1" = threads ]; then
        echo mpirun --oversubscribe -np 2 "$GW"
    else
        echo "$GW"
    fi
}

# late_save: an editor's save that removes the file and writes the text it
# read more than 0.2 s later: the copy taken and the journal removed (written),
# then late_write: its put-back awaited and a row appended to it, then the
# copy written into that file
late_write() {
    local n0
    wait_rows "$1/journal.csv" 1 60
    n0=$(journal_rows "$1/journal.csv")
    wait_rows "$1/journal.csv" $((n0 + 1)) 60
    cat "$1.left" >"$1/journal.csv"
}

# --- 1: threads, the journal cut to nothing
d=$tmp/t2
written "1 --jobs 2" "$d" 8 0 journal_cut "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 2
# shellcheck disable=SC2046
resumed "1 --jobs 2" "$d" "$tmp/ref" $(other_way threads) sweep "$tmp/a.ini" --out "$d"

# --- 2: MPI, a row edited in place (its length kept)
d=$tmp/m
if [ $have_mpi = 1 ]; then
    written "2 mpirun -np 2" "$d" 8 0 journal_edit_row mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/a.ini" --out "$d" --quiet
else
    echo "SKIP: 2 under MPI (no mpirun or not an MPI build): on threads"
    written "2 --jobs 1" "$d" 8 0 journal_edit_row "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1
fi
resumed "2" "$d" "$tmp/ref" "$GW" sweep "$tmp/a.ini" --out "$d" --jobs 2

# --- 3: a line added by another program
d=$tmp/a
written "3 --jobs 1" "$d" 8 0 journal_add_line "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1
# shellcheck disable=SC2046
resumed "3" "$d" "$tmp/ref" $(other_way threads) sweep "$tmp/a.ini" --out "$d"

# --- 4: removed, put back, then written into by the remover's late save
d=$tmp/p
written "4 --jobs 1" "$d" 16 1 late_save "$GW" sweep "$tmp/b.ini" --out "$d" --quiet --jobs 1
grep -q "^granwave sweep: warning: $d/journal.csv was removed while the sweep ran: put back" "$d.err" ||
    ko "4 --jobs 1: no put-back warning: $(head -1 "$d.err")"
resumed "4 --jobs 1" "$d" "$tmp/refb" "$GW" sweep "$tmp/b.ini" --out "$d" --jobs 2
if [ $have_mpi = 1 ]; then
    d=$tmp/pm
    written "4 mpirun -np 2" "$d" 16 1 late_save mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/b.ini" --out "$d" --quiet
    resumed "4 mpirun -np 2" "$d" "$tmp/refb" "$GW" sweep "$tmp/b.ini" --out "$d" --jobs 1
else
    echo "SKIP: 4 under MPI (no mpirun or not an MPI build)"
fi

# --- 6: a journal longer than the 4096 bytes compared at each row, a row
# before them edited in place, the length kept: found by the file's times
printf '[sweep]\nmodel = chain\n[grid]\nn = %s\n[params]\nsolver = rk4\nvimp = 0.1\n' \
    "$(seq -s ', ' 10 33), 150, 151, 152" >"$tmp/c.ini"
"$GW" sweep "$tmp/c.ini" --out "$tmp/refc" --quiet --jobs 1 || ko "reference sweep of 27 cases"
# its head and first 24 rows (cases 10 to 33 beads, about 5 kB): the three
# long cases left to run
first24() { mkdir -p "$1" && head -n 29 "$tmp/refc/journal.csv" >"$1/journal.csv"; }
d=$tmp/l
# (inside the second row's write, at_row: the file's events say another wrote
# it, and the check after the row compares the whole file)
prep=first24 written "6 --jobs 1" "$d" 27 0 journal_edit_row "$GW" sweep "$tmp/c.ini" --out "$d" --quiet --jobs 1
[ "$(stat -c %s "$d.left")" -gt 5000 ] || ko "6: the journal was $(stat -c %s "$d.left") bytes: the edit inside the last 4096"
resumed "6" "$d" "$tmp/refc" "$GW" sweep "$tmp/c.ini" --out "$d" --jobs 1

# --- 5 (kept): touched and its mode changed, the bytes the sweep's
d=$tmp/k
rm -rf "$d"
# (both right before the second row: at_row)
at_row 2 "touch -d '2001-01-01' '$d/journal.csv' && chmod 0640 '$d/journal.csv'" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 \
    >/dev/null 2>"$d.err"; rc=$?
if [ $rc -eq 77 ]; then
    echo "SKIP: 5 (no move shim in this build)"
else
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && [ ! -s "$d.err" ] &&
        [ "$(rows_once "$d/journal.csv")" -eq 8 ] &&
        ok "5: touched and chmod-ed mid-sweep: exit 0, the undisturbed table, nothing said" ||
        ko "5: touched mid-sweep: exit $rc: $(head -3 "$d.err")"
fi

test_summary test_hostile_sweeps39
