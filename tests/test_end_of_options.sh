#!/bin/bash
# test_end_of_options.sh GRANWAVE SRCDIR: "--" ends the options the POSIX way
# (guideline 10) for every command; before, it was refused as "unknown option
# '--'" (exit 2), so a file whose name begins with "--" could not be given.
#  1 sweep --out D -- --odd.ini reads the config named "--odd.ini" (its two
#    cases in D/results.csv), -odd.ini (one dash) needs no "--" (before and
#    after), and an option after "--" is a second positional argument;
#  2 layer-stats --out D -- --odd.csv reads the table named "--odd.csv";
#  3 every command without positional arguments: CMD --out D -- x is refused
#    as an unexpected argument naming x (exit 2, one line, D not made), and
#    CMD --out D -- --help is such an argument too (no help, exit 2);
#  4 a "--" with nothing after it changes nothing: chain --n 3 -- prints what
#    chain --n 3 prints; an option after "--" is not taken (chain -- --n 3:
#    exit 2 naming --n, nothing written);
#  5 the program's own words: granwave -- chain --n 3 runs chain, granwave --
#    --help is an unknown command; help -- chain is chain's help; version --
#    prints the version, version -- --json is refused; sweep --help -- helps.
# 21 of its 22 checks fail on the code before (all but the one-dash config);
# the refusals of 3 and 4 exited 2 there too, but naming '--' ("unknown
# option '--'"), not the argument after it.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# refused WHAT DIR CMD...: CMD exits 2 with one line on stderr naming the
# argument WHAT, and DIR was not made
refused() {
    local what=$1 dir=$2
    shift 2
    "$GW" "$@" >out.txt 2>err.txt
    local rc=$? lines
    lines=$(wc -l <err.txt)
    if [ $rc -eq 2 ] && [ "$lines" -eq 1 ] && grep -qF -- "'$what'" err.txt && [ ! -e "$dir" ]; then
        ok "$* : exit 2, one line naming '$what', nothing written"
    else
        ko "$* : exit $rc, $lines lines ($(head -c 200 err.txt)), $dir $( [ -e "$dir" ] && echo made || echo 'not made')"
    fi
}

# 1: a config whose name begins with dashes
cat >cfg.ini <<CFG
[sweep]
model = chain
[grid]
n = 1:2
vimp = 0.2
[params]
solver = cvode
CFG
cp cfg.ini ./--odd.ini
cp cfg.ini ./-odd.ini
rows() { grep -vc '^#' "$1" 2>/dev/null || echo 0; }
"$GW" sweep --out s1 --quiet -- --odd.ini >/dev/null 2>err.txt
rc=$?
n=$(rows s1/results.csv)
[ $rc -eq 0 ] && [ "$n" -eq 3 ] && ok "sweep --out s1 -- --odd.ini: exit 0, its two cases (and the header) in results.csv" ||
    ko "sweep --out s1 -- --odd.ini: exit $rc, $n lines ($(head -c 200 err.txt))"
"$GW" sweep --out s2 --quiet -odd.ini >/dev/null 2>err.txt
rc=$?
n=$(rows s2/results.csv)
[ $rc -eq 0 ] && [ "$n" -eq 3 ] && ok "sweep --out s2 -odd.ini (one dash, no --): exit 0, two cases" ||
    ko "sweep --out s2 -odd.ini: exit $rc, $n lines ($(head -c 200 err.txt))"
"$GW" sweep --quiet -- --odd.ini --out s3 >/dev/null 2>err.txt
rc=$?
[ $rc -eq 2 ] && grep -qF -- "'--out'" err.txt && [ ! -e s3 ] &&
    ok "sweep -- --odd.ini --out s3: --out after -- is a second positional argument (exit 2, s3 not made)" ||
    ko "sweep -- --odd.ini --out s3: exit $rc ($(head -c 200 err.txt))"

# 2: a results table whose name begins with dashes (a small layer sweep's)
"$GW" layer-make --n 8 --width-rm 6 --seed 1 --t-max 0.2 --out s.txt >/dev/null 2>&1 &&
cat >layer.ini <<CFG &&
[sweep]
model = layer
[grid]
rb-rm = 0.8, 2
point = 0:1
[params]
sample = $tmp/s.txt
points = 2
t-max = 0.01
CFG
"$GW" sweep layer.ini --out lsw --quiet --jobs 1 >/dev/null 2>&1 && cp lsw/results.csv ./--odd.csv ||
    ko "the layer sweep for layer-stats' input"
if [ -f ./--odd.csv ]; then
    "$GW" layer-stats --out st --json -- --odd.csv >out.json 2>err.txt
    rc=$?
    [ $rc -eq 0 ] && [ -f st/groups.csv ] && ok "layer-stats --out st -- --odd.csv: exit 0, st/groups.csv written" ||
        ko "layer-stats --out st -- --odd.csv: exit $rc ($(head -c 200 err.txt))"
fi

# 3: the commands without positional arguments
refused x o1 chain --n 3 --out o1 -- x
refused --help o2 chain --n 3 --out o2 -- --help
refused x o3 falcon --n 1:2 --out o3 -- x
refused x o4 dispersion --n 64 --out o4 -- x
refused x o5 wavespeed --n 5:6 --out o5 -- x
refused x o6 softwall --n 1:2 --out o6 -- x
refused x o7 drop --out o7 -- x
refused x o8 layer-make --n 8 --out o8 -- x
refused --help o9 layer-impact --sample s.txt --out o9 -- --help
refused x o10 layer-stats --out o10 -- ./--odd.csv x

# 4: "--" at the end, and an option after it
"$GW" chain --n 3 >plain.txt 2>/dev/null
"$GW" chain --n 3 -- >ended.txt 2>err.txt
rc=$?
[ $rc -eq 0 ] && [ -s plain.txt ] && cmp -s plain.txt ended.txt && ok "chain --n 3 --: exit 0, the same output as without --" ||
    ko "chain --n 3 --: exit $rc ($(head -c 200 err.txt))"
refused --n o11 chain --out o11 -- --n 3

# 5: the program's own words
"$GW" -- chain --n 3 >ended.txt 2>err.txt
rc=$?
[ $rc -eq 0 ] && cmp -s plain.txt ended.txt && ok "granwave -- chain --n 3: runs chain" ||
    ko "granwave -- chain --n 3: exit $rc ($(head -c 200 err.txt))"
refused --help o12 -- --help
"$GW" help -- chain >h1.txt 2>err.txt
rc=$?
"$GW" chain --help >h2.txt 2>/dev/null
[ $rc -eq 0 ] && [ -s h1.txt ] && cmp -s h1.txt h2.txt && ok "help -- chain: chain's help" ||
    ko "help -- chain: exit $rc ($(head -c 200 err.txt))"
"$GW" version -- >v.txt 2>err.txt
rc=$?
[ $rc -eq 0 ] && grep -q '^granwave ' v.txt && ok "version --: the version, exit 0" ||
    ko "version --: exit $rc ($(head -c 200 err.txt))"
refused --json o13 version -- --json
"$GW" sweep --help -- >/dev/null 2>&1
rc=$?
[ $rc -eq 0 ] && ok "sweep --help --: the help, exit 0 (a -- after the options changes nothing)" ||
    ko "sweep --help --: exit $rc"

test_summary test_end_of_options
