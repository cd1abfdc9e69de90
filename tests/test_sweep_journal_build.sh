#!/bin/bash
# test_sweep_journal_build.sh GRANWAVE SRCDIR: a sweep journal records the
# build that computes its rows, and resumes only under that build (issue 18).
# Before, a journal recorded no build: a sweep started by one granwave and
# resumed by another (a later version, another commit, other compile flags, a
# SUNDIALS updated under it) took the first one's rows as its own whenever
# they had the form this build writes, byte for byte, and its table mixed the
# two builds' numbers, exit 0. Now the journal's second line is "# build
# granwave VERSION, commit C, COMPILER FLAGS, SUNDIALS v, GSL v, FFTW v", and
#  1 a new journal and its table carry it: the version `granwave version`
#    prints, a commit (or "commit unknown"), the numerical libraries;
#  2 a resume under the same build runs the cases left (the table byte for
#    byte the uninterrupted sweep's);
#  3 a journal of another build (its version, commit, compile flags or
#    SUNDIALS version changed on that line; rows left as they are, each the
#    row this build writes): exit 2, one line naming DIR/journal.csv, the
#    journal's build and this one (the field that differs, with the version
#    and commit), nothing run, the journal byte for byte as it was and
#    nothing else in DIR; `--check` refuses alike;
#  4 a format 3 journal without its build line: exit 2 naming journal.csv:2;
#  5 a journal of format 2 (the head before it, no build line), of this very
#    config: exit 2, named as an earlier granwave's that does not record the
#    build (it resumed before).
# Why refuse and not resume when the rows are byte-identical to what this
# build writes: the form says nothing about the numbers (this issue's rebound
# definition changed e_n without changing a row's columns).
# 12 checks; on the code before, 10 fail (it wrote no build line, resumed
# the format 2 journal, and refused the edited ones as a newer format or as
# edited rows, naming no build); the two resumes under the same build pass.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

printf '[sweep]\nmodel = chain\n[grid]\nn = 1:3\n[params]\nsolver = rk4\n' >a.ini
timeout 60 "$GW" sweep a.ini --out ref --quiet --jobs 1 2>err.txt || ko "the reference sweep: $(head -c 200 err.txt)"
ver=$("$GW" version)
ver=${ver#granwave }

# 1 the build line, in the journal and in the table
b=$(sed -n 2p ref/journal.csv)
commit=
if [[ $b =~ ^"# build granwave $ver, commit "([0-9a-f]{12}\+?|unknown)", ".*", SUNDIALS "[0-9.]+", GSL "[0-9.]+", fftw-3" ]]; then
    ok "the journal's second line names the build: $b"
    commit=${BASH_REMATCH[1]}
else
    ko "the journal's second line: '$b'"
fi
[ "$(sed -n 2p ref/results.csv)" = "$b" ] && ok "the table records the same build" ||
    ko "the table's second line: '$(sed -n 2p ref/results.csv)'"

# 2 a resume under the same build
mkdir r && grep -v '^[12],' ref/journal.csv >r/journal.csv
timeout 60 "$GW" sweep a.ini --out r --jobs 1 >/dev/null 2>err.txt
rc=$?
[ $rc -eq 0 ] && grep -q "3 cases, 1 already done" err.txt && cmp -s r/results.csv ref/results.csv &&
    ok "resumed under the same build: exit 0, the table byte for byte the sweep's" ||
    ko "resume under the same build: exit $rc ($(head -c 200 err.txt))"

# refused WHAT DIR PATTERN [--check]: the sweep (or its --check) over DIR
# exits 2 with one stderr line matching PATTERN, nothing on stdout, the
# journal byte for byte as before and nothing else in DIR
refused() {
    local what=$1 dir=$2 pat=$3
    shift 3
    cp "$dir/journal.csv" "$dir.orig"
    timeout 60 "$GW" sweep a.ini --out "$dir" --quiet --jobs 1 "$@" >out.txt 2>err.txt </dev/null
    local rc=$? lines
    lines=$(wc -l <err.txt)
    if [ $rc -eq 2 ] && [ "$lines" -eq 1 ] && grep -Eq "$pat" err.txt && [ ! -s out.txt ] &&
        cmp -s "$dir/journal.csv" "$dir.orig" && [ "$(ls -A "$dir")" = journal.csv ]; then
        ok "$what: exit 2, $(cut -c1-230 err.txt)"
    else
        ko "$what: exit $rc, $lines lines ($(head -c 300 err.txt)); $dir holds $(ls -A "$dir" | tr '\n' ' ')"
    fi
}

# 3 journals of other builds: the line edited as another build writes it
other() { mkdir "$1" && sed "2s/$2/$3/" r/journal.csv >"$1/journal.csv"; }
rm -f r/results.csv
other v "granwave $ver, " "granwave 0.0.9, "
refused "another version" v "^granwave sweep: v/journal\.csv: a journal of another granwave build \(its rows: granwave 0\.0\.9, commit [^;]*; this one: granwave $ver, commit .*\): finish the sweep with the build that started it, or remove the journal"
other c "commit [0-9a-fun+k]*, " "commit 0123456789ab, "
# (this build's own commit, as the journal's line gave it: a pattern that only
# ruled out a leading 0 failed whenever the commit's hash began with one)
refused "another commit" c "^granwave sweep: c/journal\.csv: a journal of another granwave build \(its rows: granwave $ver, commit 0123456789ab; this one: granwave $ver, commit ${commit//+/\\+}\)"
other o " -O3 " " -O0 "
[ "$(sed -n 2p o/journal.csv)" != "$b" ] || sed -i '2s/, SUNDIALS/ -ffast-math, SUNDIALS/' o/journal.csv
refused "other compile flags" o "^granwave sweep: o/journal\.csv: a journal of another granwave build \(its rows: granwave $ver, commit [^,]*, [^;]*(-O0|-ffast-math)"
other s "SUNDIALS [0-9.]*," "SUNDIALS 99.0.0,"
refused "another SUNDIALS" s "^granwave sweep: s/journal\.csv: a journal of another granwave build \(its rows: .*SUNDIALS 99\.0\.0; this one: .*SUNDIALS [0-9]"
refused "another commit, --check" c "^granwave sweep: c/journal\.csv: a journal of another granwave build" --check

# 4 no build line
mkdir n && sed '2d' r/journal.csv >n/journal.csv
refused "a format 3 journal without its build line" n "^granwave sweep: n/journal\.csv:2: not the '# build' line"

# 5 format 2: the head before this change
mkdir f2 && sed -e '1s/, format 3$/, format 2/' -e '2d' r/journal.csv >f2/journal.csv
head -1 f2/journal.csv | grep -q ', format 2$' || sed -i '1s/$/, format 2/' f2/journal.csv
refused "a format 2 journal of this config" f2 "^granwave sweep: f2/journal\.csv: a journal of an earlier granwave, whose rows do not record the build that computed them \(format 2; granwave [^ ]+ reads format 3 only"
refused "a format 2 journal, --check" f2 "^granwave sweep: f2/journal\.csv: a journal of an earlier granwave" --check

# the same build's journal still resumes after all this
timeout 60 "$GW" sweep a.ini --out r --quiet --jobs 1 >/dev/null 2>err.txt && cmp -s r/results.csv ref/results.csv &&
    ok "the same build's journal resumes" || ko "the same build's journal: $(head -c 200 err.txt)"

test_summary test_sweep_journal_build
