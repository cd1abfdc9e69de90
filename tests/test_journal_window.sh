#!/bin/bash
# test_journal_window.sh GRANWAVE SRCDIR: a sweep's journal written into
# between the sweep's check before a row and the row's write. The sweep checks
# before each row that its journal holds what it wrote (size, last 4096 bytes,
# the whole file when its times changed), then appends the row; a file written
# into in between had the row appended to it, and the times the sweep recorded
# after its own write covered the other write: a same-length edit outside the
# last 4096 bytes was found only at the end (exit 1, "lost rows", after every
# case ran into the edited file), and any other at the next row, or at the end
# after the last. The file's events are watched now: anything besides the
# row's own write between the check and the write makes the check after the
# row (which the sweep makes at once) compare the whole file, and the journal
# is kept at that row.
# Each disturbance is made by the move shim right inside the K-th row's write
# of the run (at_row K: the window itself, on any machine), one thread:
#  1 a resumed journal of 24 rows (5.6 kB), its first row edited in place
#    (one digit: the length kept, outside the last 4096 bytes) at the first
#    row of this run: exit 1, one line naming journal.csv, journal.kept.csv
#    and the row (case 24); no table; the kept journal holds the 25 rows
#    (no case run after); journal.csv is the edited text and that one row;
#    the kept journal moved back resumes to the undisturbed table
#  2 an 8-case sweep, a line added at its last row: found at that row, not
#    at the end: the kept journal holds 8 rows, journal.csv the added line and
#    the row
#  3 the journal cut to nothing at the third row: the kept journal holds
#    exactly 3 rows (the check before the fourth row kept 4: one case more)
#  5 as 1, the edit made by a writer that opened the journal before the run
#    and writes through that descriptor alone (no open or close inside the
#    window: one IN_MODIFY, merged by the kernel with the row's own)
#  4 controls, exit 0 and the undisturbed table, no kept journal: the journal
#    touched and chmod-ed at the second row (its bytes the sweep's), and read
#    (cat) at the second row
# What the check-then-write window ("the journal's microsecond race") still
# allows, and these checks pin down: the row written inside it lands in the
# other content (a file offers no append that fails when its bytes changed),
# that one row alone, and it is found at that row, the sweep's journal kept
# whole (the journal.csv and journal.kept.csv checks of parts 1, 2, 3 and 5).
# Release and sanitizer builds (setup.sh's sanitizer list since session 43).
# SKIP without the shim. Checks that fail on the code before: docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
# an eight-case grid of short columns (6 to 9 beads: the disturbances are
# made inside a row's write by the shim, so no case need last) and its
# undisturbed table in $tmp/ref
printf '[sweep]\nmodel = chain\n[grid]\nn = 6, 7, 8, 9\nvimp = 0.1, 0.2\n[params]\nsolver = rk4\n' >"$tmp/a.ini"
"$GW" sweep "$tmp/a.ini" --out "$tmp/ref" --quiet --jobs 1 || ko "reference sweep"

# a journal of its own sweep of 27 cases (10 to 36 beads; the three last were
# 150 to 152 beads, 518 s of the sanitizer build's run); its reference table
printf '[sweep]\nmodel = chain\n[grid]\nn = %s\n[params]\nsolver = rk4\nvimp = 0.1\n' \
    "$(seq -s ', ' 10 36)" >"$tmp/c.ini"
"$GW" sweep "$tmp/c.ini" --out "$tmp/refc" --quiet --jobs 1 || ko "reference sweep of 27 cases"


# window WHAT DIR K DISTURB CASE ROWS CMD...: CMD (a sweep into DIR, one thread)
# with DISTURB (a function of DIR leaving what it wrote in DIR.left) run inside
# its K-th row's write; asserts exit 1 with one line naming the journal, the
# kept journal and the row of CASE, no table, ROWS rows kept (each case once),
# journal.csv the disturbed text and that one row. Returns 1 on SKIP.
window() {
    local what=$1 d=$2 k=$3 disturb=$4 case=$5 want=$6 rc n
    shift 6
    at_row_fn "$k" "$disturb" "$d" "$@" >/dev/null 2>"$d.err"; rc=$?
    if [ $rc -eq 77 ]; then echo "SKIP: $what (no move shim in this build)"; return 1; fi
    [ $rc -eq 1 ] && [ "$(wc -l <"$d.err")" -eq 1 ] &&
        grep -q "^granwave sweep: $d/journal.csv was written into while the sweep ran.*kept whole as $d/journal.kept.csv, the file left as it is (found as the row of case $case was written)" "$d.err" &&
        ok "$what: exit 1, one line naming journal.csv, journal.kept.csv and the row of case $case" ||
        ko "$what: exit $rc: $(head -2 "$d.err" | cut -c1-400)"
    [ ! -e "$d/results.csv" ] && ok "$what: no table" || ko "$what: a table written"
    if n=$(rows_once "$d/journal.kept.csv") && [ "$n" -eq "$want" ]; then
        ok "$what: journal.kept.csv holds $n rows, each case once (no case run after the row)"
    else
        ko "$what: the kept journal holds ${n:-no} rows, not $want"
    fi
    # what was written into it, then the one row the sweep wrote inside it
    { cat "$d.left"; grep "^$case," "$d/journal.kept.csv"; } >"$d.expected"
    cmp -s "$d/journal.csv" "$d.expected" &&
        ok "$what: journal.csv holds what was written into it and that row, nothing appended after" ||
        ko "$what: journal.csv against what was written and the row: $(cmp "$d/journal.csv" "$d.expected" 2>&1)"
}

# --- 1: a same-length edit outside the last 4096 bytes, at the first row ---
d=$tmp/l
mkdir -p "$d" && head -n 29 "$tmp/refc/journal.csv" >"$d/journal.csv"
[ "$(stat -c %s "$d/journal.csv")" -gt 5000 ] || ko "1: the journal was $(stat -c %s "$d/journal.csv") bytes"
if window "1 a row edited in place, 4 kB before the end" "$d" 1 journal_edit_row 24 25 "$GW" sweep "$tmp/c.ini" --out "$d" --quiet --jobs 1; then
    mv "$d/journal.kept.csv" "$d/journal.csv"
    "$GW" sweep "$tmp/c.ini" --out "$d" --quiet --jobs 1 2>"$d.err2" && cmp -s "$d/results.csv" "$tmp/refc/results.csv" &&
        ok "1: the kept journal moved back resumed to the undisturbed table" ||
        ko "1: resume: $(head -2 "$d.err2")"
fi

# --- 5: the same edit by a writer that opened the journal before the run ---
# (its write inside the window is one IN_MODIFY, which the kernel merges with
# the row's own: before, every case ran into the edited file, "lost rows")
d=$tmp/h
mkdir -p "$d" && head -n 29 "$tmp/refc/journal.csv" >"$d/journal.csv"
journal_held_writer "$d" &
held=$!
if window "5 a row edited in place by a writer holding the journal open since before the run" "$d" 1 \
    journal_held_edit 24 25 "$GW" sweep "$tmp/c.ini" --out "$d" --quiet --jobs 1; then
    : >"$d.end"
    wait $held || ko "5: the held writer failed"
    mv "$d/journal.kept.csv" "$d/journal.csv"
    "$GW" sweep "$tmp/c.ini" --out "$d" --quiet --jobs 1 2>"$d.err2" && cmp -s "$d/results.csv" "$tmp/refc/results.csv" &&
        ok "5: the kept journal moved back resumed to the undisturbed table" ||
        ko "5: resume: $(head -2 "$d.err2")"
else
    : >"$d.end"
    wait $held
fi

# --- 2: a line added at the last row ---
d=$tmp/a
window "2 a line added at the last row" "$d" 8 journal_add_line 7 8 "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1

# --- 3: cut to nothing at the third row ---
d=$tmp/c
window "3 cut to nothing at the third row" "$d" 3 journal_cut 2 3 "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1

# --- 4: controls: the bytes the sweep's ---
nk=0
for dist in "touch -d 2001-01-01 '\$d/journal.csv' && chmod 0640 '\$d/journal.csv'" "cat '\$d/journal.csv' >/dev/null"; do
    d=$tmp/k$((++nk))
    at_row 2 "$(eval echo "\"$dist\"")" "$GW" sweep "$tmp/a.ini" --out "$d" --quiet --jobs 1 >/dev/null 2>"$d.err"; rc=$?
    if [ $rc -eq 77 ]; then echo "SKIP: 4 (no move shim)"; break; fi
    [ $rc -eq 0 ] && [ ! -s "$d.err" ] && cmp -s "$d/results.csv" "$tmp/ref/results.csv" && [ ! -e "$d/journal.kept.csv" ] &&
        ok "4 control ($dist): exit 0, the undisturbed table, nothing kept" ||
        ko "4 control ($dist): exit $rc: $(head -2 "$d.err")"
done

test_summary test_journal_window
