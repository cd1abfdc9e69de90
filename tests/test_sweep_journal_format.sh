#!/bin/bash
# test_sweep_journal_format.sh GRANWAVE SRCDIR: a sweep resumed into a
# directory whose journal.csv is of another journal format than this build's
# (format 3, GW_SWEEP_JOURNAL_FORMAT; format 2 before the journal recorded its
# build, test_sweep_journal_build; the cases below were written for format 2
# and moved up by one with it) says so, naming the journal and both
# formats (issue 18). Before, a journal of this very config with the head of a
# later format ("..., format 4"), of an unknown one (", format x", a short
# hash, its lines converted to CR LF) or of format 1 over another config was
# refused as "this directory holds another sweep (different config)", naming
# neither the file nor its format. Each refusal: exit 2, one stderr line naming
# DIR/journal.csv, the journal byte-identical, no table and no other file in
# DIR, nothing on stdout. Kept: format 1 of this config is refused as an
# earlier granwave's; this format with and without its key lines resumes to
# the same table; this format of another config is still refused as another
# sweep.
# 9 of the 13 checks fail on the code before (the four that pass: the kept ones).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

printf '[sweep]\nmodel = chain\n[grid]\nn = 1:3\n[params]\nsolver = rk4\n' >a.ini
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:3\n[params]\nsolver = rk4\nvimp = 0.2\n' >b.ini
timeout 60 "$GW" sweep a.ini --out ref --quiet --jobs 1 2>err.txt ||
    { echo "FAIL: the reference sweep: $(cat err.txt)"; exit 1; }
timeout 60 "$GW" sweep b.ini --out refb --quiet --jobs 1 2>err.txt ||
    { echo "FAIL: the other config's sweep: $(cat err.txt)"; exit 1; }
[ "$(grep -c '^[0-9]' ref/journal.csv)" -eq 3 ] || { echo "FAIL: the reference journal has not 3 rows"; exit 1; }

# refused_journal WHAT DIR PATTERN [CONFIG]: the sweep over DIR (its journal
# made beforehand) refused (exits_refused), DIR/journal.csv unchanged, DIR
# holding nothing else
refused_journal() {
    local what=$1 dir=$2 pat=$3 ini=${4:-a.ini}
    cp "$dir/journal.csv" "$dir.orig"
    exits_refused "$what" "$pat" 30 "$GW" sweep "$ini" --out "$dir" --quiet --jobs 1 || return
    if ! cmp -s "$dir/journal.csv" "$dir.orig"; then ko "$what: the journal was changed"; return; fi
    if [ "$(ls -A "$dir")" != journal.csv ]; then ko "$what: $dir holds $(ls -A "$dir" | tr '\n' ' ')"; return; fi
    ok "$what"
}

# journal DIR SED: DIR/journal.csv made from the reference journal by SED
journal() { mkdir "$1" && sed "$2" ref/journal.csv >"$1/journal.csv"; }

# 1, 2 a later format's head over this config's journal
journal f4 '1s/, format 3$/, format 4/'
refused_journal "format 4 (this config)" f4 \
    "^granwave sweep: f4/journal\.csv: a sweep journal of format 4, newer than granwave [^ ]+'s format 3"
journal f12 '1s/, format 3$/, format 12/'
refused_journal "format 12 (this config)" f12 "^granwave sweep: f12/journal\.csv: a sweep journal of format 12, newer than .*format 3"
# 3 a format no granwave writes
journal fx '1s/, format 3$/, format 3a/'
refused_journal "format '3a'" fx \
    "^granwave sweep: fx/journal\.csv: a sweep journal of a format granwave [^ ]+ does not know \(its first line '# granwave sweep journal [0-9a-f]{16}, format 3a'; this granwave writes and reads format 3\)"
# 4 a hash cut short
journal fh '1s/^\(# granwave sweep journal [0-9a-f]\{8\}\)[0-9a-f]*/\1/'
refused_journal "a head with an 8-digit hash" fh "^granwave sweep: fh/journal\.csv: a sweep journal of a format .* does not know"
# 5 the journal converted to CR LF line ends
journal fcr 's/$/\r/'
refused_journal "a journal with CR LF line ends" fcr \
    "^granwave sweep: fcr/journal\.csv: a sweep journal of a format .* does not know .*CR LF where a sweep writes LF"
# 6 format 1 (no ', format N') of another config: its format first
mkdir f1b && sed '1s/, format 3$//' refb/journal.csv >f1b/journal.csv
refused_journal "format 1 of another config" f1b \
    "^granwave sweep: f1b/journal\.csv: a journal of an earlier granwave, .*\(format 1, of another config \([0-9a-f]{16}; this one is [0-9a-f]{16}\); granwave [^ ]+ reads format 3 only"
# 7 an explicit 'format 1' (format 1 had no suffix)
journal fe1 '1s/, format 3$/, format 1/'
refused_journal "an explicit ', format 1'" fe1 "^granwave sweep: fe1/journal\.csv: a sweep journal of a format .* does not know"

# kept 8: format 1 of this config, refused as an earlier granwave's
journal f1 '1s/, format 3$//'
refused_journal "format 1 of this config (kept)" f1 "^granwave sweep: f1/journal\.csv: a journal of an earlier granwave, whose rows"
# kept 9: format 3 of another config: another sweep, the key named
mkdir o2 && cp refb/journal.csv o2/journal.csv
refused_journal "format 3 of another config (kept)" o2 "^granwave sweep: o2: this directory holds another sweep: its journal has 2 \[params\] keys, the config 1"

# kept 10, 11: format 3 with one row to resume, with and without its key lines
# (a journal written without them), gives the reference table
resumes() {
    local what=$1 dir=$2
    timeout 60 "$GW" sweep a.ini --out "$dir" --jobs 1 >out.txt 2>err.txt </dev/null
    local rc=$?
    if [ $rc -eq 0 ] && grep -q "3 cases, 1 already done" err.txt && cmp -s "$dir/results.csv" ref/results.csv; then
        ok "$what"
    else
        ko "$what: exit $rc: $(head -c 300 err.txt)"
    fi
}
mkdir r2 && grep -v '^[12],' ref/journal.csv >r2/journal.csv
resumes "format 3 with its key lines resumes (kept)" r2
mkdir r2o && grep -v '^[12],\|^# grid \|^# param ' ref/journal.csv >r2o/journal.csv
resumes "format 3 without key lines resumes (kept)" r2o

# 12 a later format over another config's journal: its format first (which
# config a later format's head names cannot be told here)
mkdir f4b && sed '1s/, format 3$/, format 4/' refb/journal.csv >f4b/journal.csv
refused_journal "format 4 of another config" f4b "^granwave sweep: f4b/journal\.csv: a sweep journal of format 4, newer"
# 13 the most digits read as a format
journal f9 '1s/, format 3$/, format 999999999/'
refused_journal "format 999999999" f9 "^granwave sweep: f9/journal\.csv: a sweep journal of format 999999999, newer"

test_summary
