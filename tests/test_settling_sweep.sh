#!/bin/bash
# test_settling_sweep.sh GRANWAVE SRCDIR: a layer sweep over a sample settled
# under another material says so in its table (issue 18, class 5: silent
# wrong answers). Before, the rows of such a sweep (a pile settled at density
# 2000 and hit at 2650, q = 0.755 within [0.5, 1.5]; a pile settled at
# density 100 run with other-settling, q = 0.038) were those of any sample,
# and only a line on the sweep's stderr said it: a reader of results.csv, as
# layer-stats is, could not tell. Checked:
#  1 the table's header ends its model columns with settled_load_ratio and
#    settling_warning; every row of the density-2000 sweep has
#    settling_warning 1 and settled_load_ratio 2000/2650 (to 1e-12: the
#    weights' ratio, G the same), of the other-settling sweep 1 and 100/2650,
#    of the matched pile 0 and 1, of a hand-written copy (no settings line) 0
#    and nan;
#  2 layer-stats warns (exit 0) on stderr, naming the rows and the load
#    ratio, for the density-2000 table without its "# warning:" lines (a
#    table before the forty-fifth session; with them the sweep's line says
#    it, once) (Python's layer_stats: a GranwaveWarning), and says nothing of
#    it for the matched one;
#  3 the table stays reproducible: the same sweep on 1 and 2 jobs, and one
#    resumed from a journal cut to its first row, write results.csv byte for
#    byte the same.
# 7 of the 10 checks fail on the code before (the 3 that pass: layer-stats
# silent on the matched table, the tables of 1 and 2 jobs and of the resume
# the same).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
PY=/usr/bin/python3

mk() { make_sample "$1" --n 40 --seed 1 "${@:2}"; }
mk s.txt
mk d2000.txt --density 2000
mk d100.txt --density 100
grep -v '^# settings:' s.txt >hand.txt

sweep() { # NAME SAMPLE [EXTRA PARAM LINE]
    settling_sweep_ini "$1.ini" "$tmp/$2" "${3:-}"
    "$GW" sweep "$1.ini" --out "$tmp/$1" --quiet --jobs "${4:-1}" 2>"$1.err"
}

# 1: the columns
cols() { # TABLE WANT_FLAG WANT_Q: every row's settling_warning and settled_load_ratio
    $PY - "$1" "$2" "$3" <<'PY'
import csv, math, sys
lines = [l for l in open(sys.argv[1]) if not l.startswith("#")]
head = lines[0].strip().split(",")
want = ["t_f", "settled_load_ratio", "settling_warning", "fell_off", "slump_ke", "crowns_nulled",
        "case_config_fnv1a64"]
i = head.index("t_f") if "t_f" in head else -1
if i < 0 or head[i:i + 7] != want:
    print("header %s" % head[i:i + 7])
    sys.exit(1)
rows = list(csv.DictReader(lines))
flag, q = float(sys.argv[2]), float(sys.argv[3])
bad = [r for r in rows if float(r["settling_warning"]) != flag or
       not (math.isnan(q) and math.isnan(float(r["settled_load_ratio"])) or
            abs(float(r["settled_load_ratio"]) - q) <= 1e-12 * q)]
if len(rows) != 2 or bad:
    print("%d rows, off: %s" % (len(rows), [(r["settling_warning"], r["settled_load_ratio"]) for r in bad]))
    sys.exit(1)
PY
}
check_cols() { # WHAT NAME FLAG Q
    local got
    if [ ! -s "$2/results.csv" ]; then ko "$1: no table ($(head -c 300 "$2.err"))"; return; fi
    got=$(cols "$2/results.csv" "$3" "$4") && ok "$1: every row settling_warning $3, settled_load_ratio $4" ||
        ko "$1: $got"
}
sweep d2000 d2000.txt
check_cols "a sweep over the pile settled at density 2000" d2000 1 "$($PY -c 'print(repr(2000/2650))')"
grep -q "settling_warning = 1" d2000.err && ok "the sweep's warning names the column" ||
    ko "the sweep's warning: $(cat d2000.err)"
sweep d100 d100.txt "other-settling = true"
check_cols "a sweep over the density-100 pile with other-settling" d100 1 "$($PY -c 'print(repr(100/2650))')"
sweep s s.txt
check_cols "a sweep over the matched pile" s 0 1
sweep hand hand.txt
check_cols "a sweep over a hand-written copy (no settings line)" hand 0 nan

# 2: layer-stats
# (on the table without its "# warning:" lines, as tables were before the
# forty-fifth session: layer-stats' own line counts the column; on the table
# with them the sweep's line says it, once: test_sweep_warnings_table 7)
if [ -s d2000/results.csv ]; then
    grep -v '^# warning: ' d2000/results.csv >d2000_old.csv
    "$GW" layer-stats d2000_old.csv >st.out 2>st.err; rc=$?
    [ $rc -eq 0 ] && grep -q "warning: 2 of 2 rows ran on a sample settled under another material.*settled_load_ratio 0.755 to 0.755" st.err &&
        ok "layer-stats warns of the 2 rows settled under another material" || ko "layer-stats: exit $rc, $(cat st.err)"
    py_checks 1 <<'EOF'
warned("Python layer_stats", "2 of 2 rows ran on a sample settled", granwave.layer_stats, "d2000_old.csv")
EOF
else
    ko "layer-stats: no density-2000 table"
    ko "Python layer_stats: no density-2000 table"
fi
if [ -s s/results.csv ]; then
    "$GW" layer-stats s/results.csv >/dev/null 2>st0.err && ! grep -q "settled under another" st0.err &&
        ok "layer-stats says nothing of it for the matched pile" || ko "layer-stats, matched: $(cat st0.err)"
else
    ko "layer-stats, matched: no table"
fi

# 3: reproducible bytes, across jobs and a resume
sweep d2000j d2000.txt "" 2
cmp -s d2000/results.csv d2000j/results.csv && ok "results.csv the same on 1 and 2 jobs" ||
    ko "results.csv differs between 1 and 2 jobs"
mkdir -p res && awk '/^[0-9]/ { if (++n > 1) next } { print }' d2000/journal.csv >res/journal.csv
"$GW" sweep d2000.ini --out "$tmp/res" --quiet 2>res.err; rc=$?
[ $rc -eq 0 ] && cmp -s d2000/results.csv res/results.csv && ok "a sweep resumed from its first row: the same table" ||
    ko "resumed: exit $rc ($(head -c 300 res.err)), tables $(cmp d2000/results.csv res/results.csv 2>&1)"

test_summary test_settling_sweep
