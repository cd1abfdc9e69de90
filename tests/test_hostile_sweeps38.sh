#!/bin/bash
# test_hostile_sweeps38.sh GRANWAVE SRCDIR: the thirty-eighth hostile pass, over
# sweeps. A journal replaced by another file while the sweep ran (an editor
# saving through a rename, a copy moved over it) was found only when the table
# was written: every case after the swap ran for nothing, its row appended to a
# file in no directory (or under the name the editor gave the old one), then
# exit 1, "lost rows ... no table written". Now the sweep finds it at its next
# row: its journal is kept whole beside the other file (DIR/journal.kept.csv),
# which is left as it is, no case is handed out after it, and it exits 1 in
# one line naming both files; the kept journal moved over journal.csv resumes
# every row, a rerun as it is resumes from the other file.
#  1 threads (--jobs 1, --jobs 2), a copy moved over the journal after its
#    first row: exit 1, one line naming journal.csv and journal.kept.csv, no
#    table, the other file byte for byte what was moved there, the kept journal
#    holding the rows of before and after the swap, fewer than the grid's (no
#    case handed out after it); moved over journal.csv, the rerun (the other
#    way: MPI when here) resumes them all, table byte-identical
#  2 under mpirun -np 2 alike; the rerun as it is (threads) resumes from the
#    file moved in, table byte-identical
#  3 an editor that keeps a backup (the journal renamed to journal.csv~, a new
#    file written in its place): the renamed one still linked was not checked
#    at all; found alike now, and a journal.kept.csv already there (an earlier
#    swap's) is left as it is, the journal kept as journal.kept.2.csv
#  4 the journal moved away within the directory (mv journal.csv j.bak): put
#    back at the next row (exit 0, the undisturbed table; before: exit 1,
#    "cannot read" at the end)
#  5 kept: a symbolic link put in the journal's place, to the journal itself,
#    is the journal still (exit 0, the undisturbed table)
#  6 a disk that fills inside a journal row (a 64 KiB tmpfs, one page left),
#    threads and mpirun -np 3: "sweep journal: write failed: Success" (the
#    write took part of the row, errno untouched); now exit 1, one line naming
#    DIR/journal.csv, "No space left on device" and the rows kept; space freed,
#    the resume the other way gives the undisturbed table
# Each disturbance (1 to 5) is made right before the sweep's second row is
# appended (at_row, the move shim): mid-sweep on any machine, where one made
# once the first row showed raced the end of the 1.5 s sweep. SKIP without it.
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
mpi_setup
chain_sweep8_reference

# replaced WHAT DIR SWAP CMD...: CMD (a sweep into DIR) run, SWAP (a function
# of DIR: at_row_fn) run right before its second row
# is appended (at_row: mid-sweep on any machine; once the first row showed, it
# raced the end of the sweep); checks what it left
replaced() {
    local what=$1 d=$2 swap=$3 rc
    shift 3
    rm -rf "$d" "$d.err"
    at_row_fn 2 "$swap" "$d" "$@" >/dev/null 2>"$d.err"; rc=$?
    if [ $rc -eq 77 ]; then echo "SKIP: $what (no move shim in this build)"; return; fi
    # (mpirun adds its block of lines on a rank's exit status 1, after the program's)
    sweep_stopped "$what" $rc "$d.err" 1 \
        "^granwave sweep: $d/journal.csv was replaced by another file while the sweep ran.*kept whole as $d/$kept_name"
    [ ! -e "$d/results.csv" ] && cmp -s "$d/journal.csv" "$d.swapped" &&
        ok "$what: no table, the file moved in left as it is" ||
        ko "$what: table $(ls "$d" | tr '\n' ' '), the other file $(cmp "$d/journal.csv" "$d.swapped" 2>&1)"
    kept_rows "$what" "$d/$kept_name" "$d.swapped" 8 "$d.err"
}
# a copy of the journal moved over it (a tool's atomic save), kept in DIR.swapped
copy_over() { cp "$1/journal.csv" "$1.swapped" && cp "$1.swapped" "$1/j.tmp" && mv "$1/j.tmp" "$1/journal.csv"; }
# an editor with a backup: the journal renamed to journal.csv~, the copy written in its place
# (in one process, as an editor does: the name free for microseconds)
backup_save() {
    /usr/bin/python3 -c 'import os, sys
d = sys.argv[1]
os.rename(d + "/journal.csv", d + "/journal.csv~")
b = open(d + "/journal.csv~", "rb").read()
for p in (d + "/journal.csv", d + ".swapped"):
    with open(p, "wb") as f:
        f.write(b)' "$1"
}

# resumed WHAT DIR CMD...: CMD resumes DIR to the undisturbed table, skipping
# the rows of DIR/journal.csv
resumed() {
    local what=$1 d=$2 had rc
    shift 2
    had=$(journal_rows "$d/journal.csv")
    "$@" 2>"$d.err2" >/dev/null; rc=$?
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && grep -q "8 cases, $had already done" "$d.err2" &&
        ok "$what: resumed its $had rows, table byte-identical" ||
        ko "$what: exit $rc: $(grep -v '^sweep: [0-9]*/' "$d.err2" | head -3)"
}

kept_name=journal.kept.csv
# --- 1: threads
for j in 1 2; do
    d=$tmp/t$j
    replaced "1 --jobs $j" "$d" copy_over "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs $j
    mv "$d/journal.kept.csv" "$d/journal.csv"
    if [ $have_mpi = 1 ]; then
        resumed "1 --jobs $j, kept journal moved back, mpirun -np 2" "$d" \
            mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/a.ini" --out "$d"
    else
        resumed "1 --jobs $j, kept journal moved back" "$d" "$GW" sweep "$tmp/a.ini" --out "$d" --jobs 2
    fi
done

# --- 2: MPI
if [ $have_mpi = 1 ]; then
    d=$tmp/m
    replaced "2 mpirun -np 2" "$d" copy_over mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/a.ini" --out "$d" --quiet
    resumed "2 mpirun, rerun as it is on threads" "$d" "$GW" sweep "$tmp/a.ini" --out "$d" --jobs 1
    grep -q "kept whole" "$d.err2" && ko "2: the rerun kept a journal again"
else
    echo "SKIP: 2 (no mpirun or not an MPI build)"
fi

# --- 3: an editor's backup; a kept journal of an earlier swap already there
d=$tmp/e
echo "an earlier swap's kept journal" >"$d.old"
kept_name=journal.kept.2.csv
# (replaced starts in a new DIR: the earlier file put there by the swap's first step)
backup_then() { cp "$d.old" "$1/journal.kept.csv"; backup_save "$1"; }
replaced "3 editor backup" "$d" backup_then "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1
cmp -s "$d/journal.kept.csv" "$d.old" && [ -e "$d/journal.csv~" ] &&
    ok "3: the earlier journal.kept.csv and the editor's backup left as they are" ||
    ko "3: journal.kept.csv $(cmp "$d/journal.kept.csv" "$d.old" 2>&1), $(ls "$d" | tr '\n' ' ')"

# --- 4: moved away within the directory: put back
d=$tmp/v
rm -rf "$d"
at_row 2 "mv '$d/journal.csv' '$d/j.bak'" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 >/dev/null 2>"$d.err"; rc=$?
if [ $rc -eq 77 ]; then
    echo "SKIP: 4 (no move shim in this build)"
else
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && [ "$(wc -l <"$d.err")" -eq 1 ] &&
        grep -q "journal.csv was removed while the sweep ran: put back" "$d.err" &&
        [ "$(rows_once "$d/journal.csv")" -eq 8 ] &&
        ok "4: moved away, put back: exit 0, the undisturbed table" ||
        ko "4: journal moved away mid-sweep: exit $rc: $(head -3 "$d.err")"
fi

# --- 5 (kept): a symbolic link to the journal in its place
d=$tmp/s
rm -rf "$d"
at_row 2 "mv '$d/journal.csv' '$d/j.real' && ln -s j.real '$d/journal.csv'" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 \
    >/dev/null 2>"$d.err"; rc=$?
if [ $rc -eq 77 ]; then
    echo "SKIP: 5 (no move shim in this build)"
else
    [ $rc -eq 0 ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && [ ! -s "$d.err" ] &&
        ok "5: a link to the journal in its place: exit 0, the undisturbed table, nothing said" ||
        ko "5: a link to the journal: exit $rc: $(head -3 "$d.err")"
fi

# --- 6: a full file system inside a row (a 64 KiB tmpfs, when this user may
# mount one, one 4 KiB page left: the journal of 40 cases crosses it)
mkdir -p "$tmp/full"
if mount -t tmpfs -o size=64k tmpfs "$tmp/full" 2>/dev/null; then
    trap 'umount "$tmp/full" 2>/dev/null; rm -rf "$tmp"' EXIT
    printf '[sweep]\nmodel = chain\n[grid]\nn = 10:49\n[params]\nsolver = rk4\nvimp = 0.1\n' >"$tmp/c40.ini"
    "$GW" sweep "$tmp/c40.ini" --out "$tmp/c40ref" --quiet --jobs 1 || ko "6: reference sweep"
    full() { # WHAT RESUME-CMD... : the sweep run by $run, then resumed by RESUME-CMD
        local what=$1 rc
        shift
        rm -rf "$tmp/full/d"
        dd if=/dev/zero of="$tmp/full/fill" bs=4096 count=15 2>/dev/null
        $run >/dev/null 2>"$tmp/full.err"; rc=$?
        [ $rc -eq 1 ] && grep -q "^granwave sweep: $tmp/full/d/journal.csv: write failed: No space left on device: its [0-9]* rows before are kept" "$tmp/full.err" &&
            ! grep -q Success "$tmp/full.err" && [ ! -e "$tmp/full/d/results.csv" ] &&
            ok "6 $what: the disk full inside a row: exit 1, $(head -1 "$tmp/full.err" | cut -c1-140)" ||
            ko "6 $what: the disk full inside a row: exit $rc: $(head -1 "$tmp/full.err")"
        rm -f "$tmp/full/fill"
        "$@" >/dev/null 2>"$tmp/full.err2"; rc=$?
        [ $rc -eq 0 ] && cmp -s "$tmp/full/d/results.csv" "$tmp/c40ref/results.csv" &&
            ok "6 $what: space freed, the resume's table byte-identical" ||
            ko "6 $what: resume after a full disk: exit $rc: $(head -2 "$tmp/full.err2")"
    }
    run="$GW sweep $tmp/c40.ini --out $tmp/full/d --quiet --jobs 2"
    if [ $have_mpi = 1 ]; then
        full "--jobs 2" mpirun --oversubscribe -np 2 "$GW" sweep "$tmp/c40.ini" --out "$tmp/full/d" --quiet
        run="mpirun --oversubscribe -np 3 $GW sweep $tmp/c40.ini --out $tmp/full/d --quiet"
        full "mpirun -np 3" "$GW" sweep "$tmp/c40.ini" --out "$tmp/full/d" --quiet --jobs 1
    else
        full "--jobs 2" "$GW" sweep "$tmp/c40.ini" --out "$tmp/full/d" --quiet --jobs 1
    fi
    umount "$tmp/full"
else
    echo "SKIP: 6 (cannot mount a small tmpfs here)"
fi

test_summary test_hostile_sweeps38
