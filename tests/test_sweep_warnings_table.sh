#!/bin/bash
# test_sweep_warnings_table.sh GRANWAVE SRCDIR: a sweep's warnings in its
# results.csv. They were said on stderr alone (and by the library and Python):
# a user who kept the table lost them. The table now holds one "# warning:
# TEXT" line for each, after its "# grid" lines, TEXT the stderr line's after
# "granwave sweep: warning: ", from the config and the journal's rows alone.
#  1 a chain sweep whose sensor dashpot has no effect in 2 of 4 cases (the
#    check pass's warning): the line in the table, between the "# grid" lines
#    and the header, the stderr's text; stderr says it once, as before.
#  2 a chain sweep with a case cut at t-max (the rows' warning, "1 of 2
#    cases did not end their collision"): the line in the table.
#  3 each of them killed (kill -9) before its second row and resumed: the
#    table byte for byte the uninterrupted one's, warning lines included (the
#    rows' warning of a row run before the kill, the check pass's of the rerun);
#    the first on 2 threads and on 2 MPI ranks (when the build links MPI): the
#    same table.
#  4 a layer sweep on a sample settled at density 2000 and hit at 2650 (the
#    settling warning of the check pass): the line in the table; layer-stats
#    reads the table (exit 0) and says what it says of the table without the
#    warning lines (its stdout and groups.csv the same, but for the table's
#    path and hash).
#  5 layer-stats says the table's warnings (it ignored them): on stderr first,
#    "granwave layer-stats: warning: TABLE: the sweep that wrote it warned:
#    TEXT", then its own as before (but the settling's: 7); first in --json's
#    "warnings"; a warning line given twice in the table said once. (The
#    settling's TEXT goes on with the table's rows and their load ratio range
#    since the forty-eighth session: test_layer_stats_settling_line.)
#  6 the library's older table call gw_sweep_write_table (a C caller's, by
#    tests/gw_grid_probe) writes the check pass's warnings too: table 1's
#    byte for byte the program's (it wrote the rows' alone); control: table
#    2's (a rows' warning alone) the program's.
#  7 layer-stats says the settling of table 4 once (the sweep's line, which
#    it repeats, and its own "2 of 2 rows ran on a sample settled under
#    another material" said it twice, the forty-sixth session): one line
#    naming it on stderr, in --json's "warnings", in boundary_fit.json's and
#    in Python's layer_stats warnings, the sweep's; the table without the
#    sweep's lines (an older table) still gets layer-stats' own line, once.
#  Control: a sweep without warnings writes no "# warning:" line, its header
#  right after its "# grid" lines (its table is the build before's, but for
#  the "# build" line's commit: checked by hand, see docs/tests.md).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
cd "$tmp" || exit 1
export LC_ALL=C

# sweep_config NAME MODEL GRID PARAMS, sweep_dashpot_config NAME and
# sweep_quiet NAME [FLAGS] (NAME.ini into NAME.out, stderr in NAME.err, sets
# rc): test_lib.sh's
# table_warnings NAME: the texts of NAME.out/results.csv's "# warning:" lines
table_warnings() { sed -n 's/^# warning: //p' "$1.out/results.csv" 2>/dev/null; }
# said NAME: the texts of NAME.err's warning lines
said() { sed -n 's/^granwave sweep: warning: //p' "$1.err"; }
# placed NAME: the warning lines sit right after the "# grid" lines, the header right after them
placed() {
    awk '/^# grid / { g = NR } /^# warning: / { if (!g || (w ? NR != w + 1 : NR != g + 1)) bad = 1; w = NR }
         /^case,/ { h = NR; exit } END { exit !(g && h == (w ? w : g) + 1 && !bad) }' "$1.out/results.csv"
}
# resumed NAME TOTAL: NAME.ini killed (kill -9) before its second row into
# NAME.k, then run again there: its table against NAME.out's, byte for byte
resumed() {
    local name=$1 total=$2
    if ! stop_mid_sweep KILL "$name.k" "$total" "$GW" sweep "$name.ini" --out "$name.k" --jobs 1 --quiet; then
        ko "3 $name: kill -9 mid-sweep did not land (rc $rc, rows ${rows:-?})"
        return
    fi
    local before=$rows
    cpu_run 120 "$GW" sweep "$name.ini" --out "$name.k" --jobs 1 --quiet >/dev/null 2>"$name.k.err"; rc=$?
    if [ $rc -eq 0 ] && [ -n "$(table_warnings "$name")" ] && cmp -s "$name.out/results.csv" "$name.k/results.csv"; then
        ok "3 $name killed at $before of $total rows and resumed: the table byte for byte, its $(table_warnings "$name" | wc -l) warning line(s) too"
    else
        ko "3 $name resumed: exit $rc, $(diff "$name.out/results.csv" "$name.k/results.csv" 2>&1 | head -c 400)"
    fi
}

# --- 1 the check pass's warning: a sensor dashpot of no effect ---
sweep_dashpot_config d
sweep_quiet d
w=$(table_warnings d)
if [ $rc -eq 0 ] && [ "$(grep -c "^granwave sweep: warning: the sensor body's dashpot" d.err)" -eq 1 ] &&
    grep -q "^the sensor body's dashpot has no effect in 2 of 4 cases (the first, case 0): " <<<"$w" &&
    [ "$w" = "$(said d)" ] && placed d; then
    ok "1 chain sweep, dashpot of no effect in 2 of 4 cases: the table's line, the stderr's text, before the header"
else
    ko "1 dashpot: exit $rc, table '$w', stderr '$(head -c 400 d.err)'"
fi

# --- 2 the rows' warning: a case cut at t-max ---
sweep_config u chain "n = 6:7" "t-max = 1.94e-4"
sweep_quiet u
w=$(table_warnings u)
if [ $rc -eq 0 ] && [ "$w" = "$(said u)" ] && placed u &&
    grep -q "^1 of 2 cases did not end their collision (column converged = 0; the first, case 1)" <<<"$w"; then
    ok "2 chain sweep with n 7 cut at t-max: the table's line, 1 of 2 cases, the first case 1"
else
    ko "2 undecided: exit $rc, table '$w', stderr '$(head -c 400 u.err)'"
fi

# --- 3 killed and resumed: the same table ---
resumed d 4
resumed u 2
# on 2 threads and 2 MPI ranks (rank 0 checks the cases and writes): the same table
cpu_run 120 "$GW" sweep d.ini --out d.j2 --jobs 2 --quiet >/dev/null 2>d.j2.err; rc=$?
mpi_setup
if [ $have_mpi -eq 1 ]; then
    cpu_run 120 mpirun --oversubscribe -n 2 "$GW" sweep d.ini --out d.mpi --quiet >/dev/null 2>d.mpi.err; rcm=$?
else
    rcm=0; cp -r d.j2 d.mpi
fi
if [ $rc -eq 0 ] && [ $rcm -eq 0 ] && [ -n "$(table_warnings d)" ] && cmp -s d.out/results.csv d.j2/results.csv &&
    cmp -s d.out/results.csv d.mpi/results.csv; then
    ok "3 d on --jobs 2$([ $have_mpi -eq 1 ] && echo " and 2 MPI ranks"): the same table, its warning line too"
else
    ko "3 d on --jobs 2 / MPI: exit $rc, $rcm, $(head -c 300 d.mpi.err)"
fi

# --- 4 a layer sweep's settling warning; layer-stats reads the table ---
make_sample d2000.txt --n 40 --seed 1 --density 2000
settling_sweep_ini l.ini "$tmp/d2000.txt"
sweep_quiet l
w=$(table_warnings l)
if [ $rc -eq 0 ] && [ "$w" = "$(said l)" ] && placed l &&
    grep -q "^2 of 2 cases run on a sample settled under another material or not settled" <<<"$w"; then
    ok "4 layer sweep on a pile settled at density 2000: the table's line, 2 of 2 cases"
else
    ko "4 layer settling: exit $rc, table '$w', stderr '$(head -c 400 l.err)'"
fi
grep -v '^# warning: ' l.out/results.csv >plain.csv
cpu_run 60 "$GW" layer-stats l.out/results.csv --out ls1 >ls1.out 2>ls1.err; rc1=$?
cpu_run 60 "$GW" layer-stats plain.csv --out ls2 >ls2.out 2>ls2.err; rc2=$?
# its numbers the same: stdout and groups.csv as the table's without the warning lines
if [ -n "$w" ] && [ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] &&
    cmp -s <(sed 's|l.out/results.csv|T|g' ls1.out) <(sed 's|plain.csv|T|g' ls2.out) &&
    [ -s ls1/groups.csv ] && cmp -s <(grep -v '^# \(input\|command\)' ls1/groups.csv) <(grep -v '^# \(input\|command\)' ls2/groups.csv); then
    ok "4 layer-stats reads the table with its warning lines: its numbers as without them (exit 0, stdout, groups.csv)"
else
    ko "4 layer-stats: warned '$w', exit $rc1 and $rc2, $(head -c 300 ls1.err)"
fi
# --- 5 layer-stats says the table's warnings: first on stderr, once each, as its own; in --json ---
# (they were dropped: a user reading layer-stats' output alone lost them)
sweep_said=$(while IFS= read -r t; do
    echo "granwave layer-stats: warning: l.out/results.csv: the sweep that wrote it warned: $t"; done <<<"$w")
nw=$(grep -c . <<<"$w")
cpu_run 60 "$GW" layer-stats l.out/results.csv --json >ls1.json 2>/dev/null; rcj=$?
# (its own settling line is said by the sweep's: 7)
# (each the table's text; the settling's followed by the table's rows and their
# load ratio range since the forty-eighth session: a prefix)
if [ $rc1 -eq 0 ] && /usr/bin/python3 -c '
import sys
got, want = sys.argv[1].split("\n"), sys.argv[2].split("\n")
sys.exit(0 if len(got) == len(want) and all(g.startswith(w) for g, w in zip(got, want)) else 1)' \
    "$(head -n "$nw" ls1.err)" "$sweep_said" &&
    cmp -s <(tail -n +"$((nw + 1))" ls1.err | sed 's|l.out/results.csv|T|g') \
        <(grep -v 'rows ran on a sample settled under another material' ls2.err | sed 's|plain.csv|T|g'); then
    ok "5 layer-stats says the table's $nw warning(s) on stderr, first, as its own, then its own as before"
else
    ko "5 layer-stats stderr: '$(head -c 500 ls1.err)'"
fi
if [ $rcj -eq 0 ] && python3 -c '
import json, sys
w = json.load(open(sys.argv[1]))["warnings"]
want = ["l.out/results.csv: the sweep that wrote it warned: " + t for t in sys.argv[2].split("\n")]
sys.exit(0 if all(g.startswith(t) for g, t in zip(w, want)) and len(w) >= len(want) else 1)' ls1.json "$w"; then
    ok "5 layer-stats --json: the table's warnings first in \"warnings\""
else
    ko "5 layer-stats --json (exit $rcj): $(head -c 300 ls1.json | tr '\n' ' ')"
fi
# a table whose warning line is given twice (edited, or two heads joined): said once
awk '/^# warning: / && !d { print; d = 1 } { print }' l.out/results.csv >twice.csv
cpu_run 60 "$GW" layer-stats twice.csv >/dev/null 2>tw.err; rct=$?
if [ $rct -eq 0 ] && [ "$(grep -c 'the sweep that wrote it warned: ' tw.err)" -eq "$nw" ] &&
    [ "$(grep -c '^# warning: ' twice.csv)" -gt "$nw" ]; then
    ok "5 a warning line given twice in the table: said once ($nw line(s))"
else
    ko "5 twice: exit $rct, $(grep -c 'the sweep that wrote it warned: ' tw.err) said"
fi

# --- 6 the library's older call (gw_sweep_write_table, a C caller's) writes the check pass's warnings too ---
# (it wrote the rows' alone: a C caller's table of d lost the dashpot's line)
probe=${GW_GRID_PROBE:-$(dirname "$GW")/tests/gw_grid_probe} # (GW_GRID_PROBE: one built on another library)
cp -r d.out d.old && rm -f d.old/results.csv
if [ -x "$probe" ] && cpu_run 60 "$probe" table d.ini d.old >/dev/null 2>d.old.err &&
    cmp -s d.out/results.csv d.old/results.csv; then
    ok "6 gw_sweep_write_table: d's table byte for byte the program's, its dashpot line too"
else
    ko "6 gw_sweep_write_table: $(head -c 300 d.old.err) $(diff d.out/results.csv d.old/results.csv 2>&1 | head -c 300)"
fi
cp -r u.out u.old && rm -f u.old/results.csv
if [ -x "$probe" ] && cpu_run 60 "$probe" table u.ini u.old >/dev/null 2>u.old.err &&
    cmp -s u.out/results.csv u.old/results.csv; then
    ok "6 control: gw_sweep_write_table of u (the rows' warning alone): the program's table"
else
    ko "6 control u: $(head -c 300 u.old.err)"
fi

# --- 7 layer-stats says the settling once: the sweep's line, not its own beside it ---
settled='settled under another material'
cpu_run 60 "$GW" layer-stats l.out/results.csv --out ls7 --json >ls7.json 2>ls7.err; rc7=$?
cpu_run 60 "$GW" layer-stats plain.csv --json >ls8.json 2>ls8.err; rc8=$?
n_err=$(grep -c "$settled" ls1.err)
if [ $rc1 -eq 0 ] && [ "$n_err" -eq 1 ] && grep -q "the sweep that wrote it warned: .*$settled" ls1.err; then
    ok "7 layer-stats stderr: the settling said once, in the sweep's line"
else
    ko "7 layer-stats stderr: the settling said $n_err times: $(grep "$settled" ls1.err | cut -c1-160)"
fi
# count_json FILE: the entries of FILE's "warnings" (JSON) that name the settling
count_json() {
    python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
print(sum(1 for w in d.get("warnings", []) if sys.argv[2] in w))' "$1" "$settled" 2>/dev/null || echo "unreadable"
}
nj=$(count_json ls7.json)
nb=$(count_json ls7/boundary_fit.json)
[ $rc7 -eq 0 ] && [ "$nj" = 1 ] && ok "7 layer-stats --json: the settling once in \"warnings\"" ||
    ko "7 layer-stats --json (exit $rc7): the settling $nj times"
[ -s ls7/boundary_fit.json ] && [ "$nb" = 1 ] && ok "7 boundary_fit.json: the settling once in \"warnings\"" ||
    ko "7 boundary_fit.json: the settling $nb times ($(ls ls7 2>&1 | tr '\n' ' '))"
py_checks 1 <<'EOF'
r, ws = caught(granwave.layer_stats, "l.out/results.csv")
n = sum(1 for w in ws if "settled under another material" in w)
check(n == 1, "7 Python layer_stats: the settling once among its warnings (%d: %s)" % (n, [w[:90] for w in ws]))
EOF
# an older table (no "# warning:" line): layer-stats' own line, once
if [ $rc8 -eq 0 ] && [ "$(grep -c "$settled" ls8.err)" -eq 1 ] &&
    grep -q "warning: 2 of 2 rows ran on a sample $settled" ls8.err && [ "$(count_json ls8.json)" = 1 ]; then
    ok "7 a table without the sweep's line: layer-stats' own settling line, once (stderr, --json)"
else
    ko "7 older table (exit $rc8): $(grep -c "$settled" ls8.err) lines: $(head -c 300 ls8.err)"
fi

# --- control: a sweep without warnings has no such line ---
sweep_config c chain "n = 1:2" ""
sweep_quiet c
if [ $rc -eq 0 ] && [ ! -s c.err ] && [ -z "$(table_warnings c)" ] && ! grep -q '^# warning' c.out/results.csv &&
    placed c; then
    ok "control: a sweep without warnings: no '# warning:' line, the header after the '# grid' line"
else
    ko "control: exit $rc, $(head -c 300 c.err), $(grep -c '^# warning' c.out/results.csv) warning lines"
fi

test_summary test_sweep_warnings_table
