#!/bin/bash
# test_layer_stats_settling_line.sh GRANWAVE SRCDIR: layer-stats says the
# settling of a layer sweep's table in one line, and that line carries the
# rows' settled_load_ratio range in every case. A sweep over a pile settled
# at density 2000 and hit at 2650 (every case warned, q = 2000/2650 = 0.755)
# writes its settling line into its table ("# warning: 3 of 3 cases run on a
# sample settled under another material or not settled ..."). Before,
# layer-stats repeated that line alone when its count was the table's (the
# rows' range was then said nowhere), and said it beside its own line when
# the table was cut by hand (the settling said twice). Checked:
#  1 the whole table: one settling line on stderr, the sweep's words, with
#    "3 of its 3 rows" and "settled_load_ratio 0.755 to 0.755";
#  2 the table cut by hand to 2 rows (its "# grid" line and case count
#    edited to match, as layer-stats refuses a table missing cases): one line, the sweep's words, with "2 of
#    its 2 rows" and the range; the same one entry in --json's "warnings";
#  3 control: the table without its "# warning:" lines (an older table):
#    layer-stats' own line, once, with the range (as before);
#  4 the exit code 0 and the statistics (stdout but for the table's path) of
#    the table with and without its warning lines the same.
# 3 of the 5 checks fail on the code before (1, and 2 on stderr and in --json; 3 and 4
# pass before).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
settled='settled under another material'
range='settled_load_ratio 0.755 to 0.755, 1 at rest'

make_sample d2000.txt --n 40 --seed 1 --density 2000
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20, 30\n[params]\nsample = %s\nt-max = 0.002\n' \
    "$tmp/d2000.txt" >l.ini
cpu_run 180 "$GW" sweep l.ini --out l.out --jobs 1 --quiet >/dev/null 2>l.err; rc=$?
if [ $rc -ne 0 ] || ! grep -q "^# warning: 3 of 3 cases run on a sample $settled" l.out/results.csv; then
    ko "setup: the sweep (exit $rc) did not warn of its settling: $(head -c 300 l.err)"
    test_summary
    exit 1
fi
# lines FILE: the stderr lines of FILE that name the settling
lines() { grep -c "$settled" "$1"; }

# --- 1 the whole table ---
cpu_run 60 "$GW" layer-stats l.out/results.csv >ls1.out 2>ls1.err; rc1=$?
if [ $rc1 -eq 0 ] && [ "$(lines ls1.err)" -eq 1 ] &&
    grep "$settled" ls1.err | grep -q "the sweep that wrote it warned: 3 of 3 cases.*3 of its 3 rows.*$range"; then
    ok "1 the whole table: one settling line, the sweep's, with its 3 rows and their load ratio range"
else
    ko "1 whole table: exit $rc1, $(lines ls1.err) line(s): $(grep "$settled" ls1.err | cut -c1-400)"
fi

# --- 2 the table cut by hand to its first 2 rows (its grid and count lines with them) ---
awk '/^#/ || /^case,/ { print; next } { if (++n <= 2) print }' l.out/results.csv |
    sed -e 's/^# grid vi = 10, 20, 30$/# grid vi = 10, 20/' -e 's/, 3 of 3 cases$/, 2 of 2 cases/' >cut.csv
cpu_run 60 "$GW" layer-stats cut.csv >ls2.out 2>ls2.err; rc2=$?
if [ $rc2 -eq 0 ] && [ "$(lines ls2.err)" -eq 1 ] &&
    grep "$settled" ls2.err | grep -q "the sweep that wrote it warned: 3 of 3 cases.*2 of its 2 rows.*$range"; then
    ok "2 the table cut to 2 rows: one settling line, with its 2 rows and their range"
else
    ko "2 cut table: exit $rc2, $(lines ls2.err) line(s): $(grep "$settled" ls2.err | cut -c1-400)"
fi
cpu_run 60 "$GW" layer-stats cut.csv --json >ls2.json 2>/dev/null; rcj=$?
if [ $rcj -eq 0 ] && /usr/bin/python3 - ls2.json "$settled" "$range" <<'PY'
import json, sys
w = [t for t in json.load(open(sys.argv[1]))["warnings"] if sys.argv[2] in t]
sys.exit(0 if len(w) == 1 and sys.argv[3] in w[0] and "2 of its 2 rows" in w[0] else 1)
PY
then
    ok "2 --json of the cut table: one settling entry in \"warnings\", with the range"
else
    ko "2 --json of the cut table (exit $rcj): $(head -c 400 ls2.json)"
fi

# --- 3 control: the table without its warning lines ---
grep -v '^# warning: ' l.out/results.csv >plain.csv
cpu_run 60 "$GW" layer-stats plain.csv >ls3.out 2>ls3.err; rc3=$?
if [ $rc3 -eq 0 ] && [ "$(lines ls3.err)" -eq 1 ] && grep -q "3 of 3 rows ran on a sample $settled.*$range" ls3.err; then
    ok "3 control: the table without its warning lines, layer-stats' own line once, with the range"
else
    ko "3 plain table: exit $rc3, $(grep "$settled" ls3.err | cut -c1-300)"
fi

# --- 4 the statistics the same with and without the warning lines ---
if cmp -s <(sed 's|l.out/results.csv|T|g' ls1.out) <(sed 's|plain.csv|T|g' ls3.out); then
    ok "4 the statistics (stdout) of the table with and without its warning lines the same"
else
    ko "4 stdout differs: $(diff <(sed 's|l.out/results.csv|T|g' ls1.out) <(sed 's|plain.csv|T|g' ls3.out) | head -c 300)"
fi
test_summary
