#!/bin/bash
# test_crowns_nulled.sh: a crown speed left null by a rule reaches every reader
# (issue 18 class 6: an undecided value is null with a warning line).
#  - the default impact on the 40-disc pile of `layer-make --n 40`:
#    wave_speed_xcorr null (44.03 +- 31.1 m/s from 10 ring pairs, the standard
#    error above half the speed) with "warnings": [] before; now one line
#    naming the speed, its value and its error, in --json, on stderr and in
#    Python's warnings;
#  - Python's layer_impact outcome has slump_ke: NaN with both side walls,
#    with side_walls left the JSON's slump_ke (the key --json gives then);
#  - a layer sweep over that pile at vi 10, 20 with until = verdict: every
#    row's wave_speed nan (the run ended at the bounce verdict before the wave
#    reached 3 rings) and no "# warning:" line before; now the rows'
#    crowns_nulled 2 and one "# warning: crowns: 2 of 2 cases ..." line in the
#    table and on stderr, the same table from 1 and 2 threads and after a
#    resume (results.csv removed, the journal kept), and in Python's sweep;
#  - a side-walls sweep's slump_ke column: the single run's value;
#  - crowns_nulled in --json (absent before): 8 on the default impact, 0 at
#    --vi 10 (every speed read), 2 with --until verdict, 4 at --vi 40 (locked),
#    Python's the same, and a sweep row's the single run's.
. "$2/tests/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

"$GW" layer-make --n 40 --out S40 --quiet >/dev/null 2>&1 || { echo "FAIL: layer-make"; exit 1; }

# --- the default impact: wave_speed_xcorr nulled by its scatter ---
"$GW" layer-impact --sample S40 --json --quiet >d.json 2>d.err; rc=$?
got=$($PY - d.json <<'PY' 2>&1
import json, sys
d = json.load(open(sys.argv[1]))
w = [x for x in d["warnings"] if "wave_speed_xcorr" in x and "+-" in x and "half the speed" in x]
print("ok" if d["wave_speed_xcorr"] is None and len(w) == 1 and " 44.03 +- 31.1 m/s" in w[0] else
      "xcorr %r warnings %r" % (d["wave_speed_xcorr"], d["warnings"]))
PY
)
[ $rc -eq 0 ] && [ "$got" = ok ] && ok "--json: wave_speed_xcorr null, one warning with 44.03 +- 31.1 m/s" ||
    ko "--json: exit $rc, $got"
[ "$(grep -c 'warning: crowns: wave_speed_xcorr 44.03 +- 31.1 m/s' d.err)" = 1 ] &&
    ok "stderr: the same line" || ko "stderr: $(head -c 400 d.err)"
"$GW" layer-impact --sample S40 --quiet >d.txt 2>/dev/null
grep -q "wave speed undecided, its scatter (cross-correlation" d.txt && ok "text: undecided, its scatter" ||
    ko "text: $(grep 'cross-correlation' d.txt)"

# --- crowns_nulled in --json: the rules as bits, as a sweep's row and Python's
# outcome carry them (absent from the JSON before): the default impact 8 (the
# scatter), --vi 10 0 (every speed read, no crowns warning), --until verdict 2
# (the run's end), --vi 40 4 (the pile's slow motion) ---
"$GW" layer-impact --sample S40 --vi 10 --json --quiet >n0.json 2>/dev/null
"$GW" layer-impact --sample S40 --until verdict --json --quiet >n2.json 2>/dev/null
"$GW" layer-impact --sample S40 --vi 40 --json --quiet >n4.json 2>/dev/null
got=$($PY - d.json n0.json n2.json n4.json <<'PY' 2>&1
import json, sys
want, bad = [8, 0, 2, 4], []
for f, w in zip(sys.argv[1:], want):
    d = json.load(open(f))
    v = d.get("crowns_nulled", "absent")
    speeds = [d[k] for k in ("wave_speed", "wave_speed_kinetic", "wave_speed_xcorr")]
    # a rule's bit set: a speed null and a warning; 0: every speed read, no crowns warning
    if v != w or (w and (None not in speeds or not d["warnings"])) or (not w and (None in speeds or d["warnings"])):
        bad.append("%s: crowns_nulled %r (want %d), speeds %r, warnings %r" % (f, v, w, speeds, [x[:60] for x in d["warnings"]]))
print("ok" if not bad else "; ".join(bad))
PY
)
[ "$got" = ok ] && ok "--json: crowns_nulled 8 (scatter), 0 (none), 2 (run's end), 4 (locked)" || ko "--json crowns_nulled: $got"

# --- sweeps ---
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = S40\nuntil = verdict\n' >lv.ini
"$GW" sweep lv.ini --out lv1 --quiet --jobs 1 2>lv1.err; rc=$?
got=$($PY - lv1/results.csv <<'PY' 2>&1
import csv, sys
lines = open(sys.argv[1]).read().splitlines()
w = [l for l in lines if l.startswith("# warning: crowns: 2 of 2 cases") and "run's end" in l and "case 0" in l]
rows = list(csv.DictReader([l for l in lines if not l.startswith("#")]))
bad = []
if len(w) != 1: bad.append("warning lines %r" % [l for l in lines if l.startswith("# warning")])
if [r.get("crowns_nulled") for r in rows] != ["2", "2"]: bad.append("crowns_nulled %r" % [r.get("crowns_nulled") for r in rows])
if [r["wave_speed"] for r in rows] != ["nan", "nan"]: bad.append("wave_speed %r" % [r["wave_speed"] for r in rows])
print("ok" if not bad else "; ".join(bad))
PY
)
[ $rc -eq 0 ] && [ "$got" = ok ] && ok "sweep: wave_speed nan, crowns_nulled 2 in both rows, one '# warning: crowns: 2 of 2 cases' line" ||
    ko "sweep: exit $rc, $got"
# the single run of the first case: its JSON's crowns_nulled the row's
"$GW" layer-impact --sample S40 --vi 10 --until verdict --json --quiet >lv0.json 2>/dev/null
got=$($PY - lv1/results.csv lv0.json <<'PY' 2>&1
import csv, json, sys
rows = list(csv.DictReader([l for l in open(sys.argv[1]) if not l.startswith("#")]))
v = json.load(open(sys.argv[2])).get("crowns_nulled", "absent")
print("ok" if rows and str(v) == rows[0].get("crowns_nulled") == "2" else "JSON %r, row %r" % (v, rows[0].get("crowns_nulled") if rows else None))
PY
)
[ "$got" = ok ] && ok "sweep: the case's single run gives the row's crowns_nulled (2) in --json" || ko "sweep against --json: $got"
[ "$(grep -c "warning: crowns: 2 of 2 cases" lv1.err)" = 1 ] && ok "sweep: the line on stderr" ||
    ko "sweep stderr: $(head -c 400 lv1.err)"
"$GW" sweep lv.ini --out lv2 --quiet --jobs 2 2>/dev/null
cmp -s lv1/results.csv lv2/results.csv && ok "sweep: the same table from 2 threads" || ko "sweep: 1 and 2 threads differ"
rm -f lv2/results.csv
"$GW" sweep lv.ini --out lv2 --quiet --jobs 2 2>lv2.err
cmp -s lv1/results.csv lv2/results.csv && [ "$(grep -c "warning: crowns: 2 of 2 cases" lv2.err)" = 1 ] &&
    ok "sweep: the same table and line after a resume" || ko "sweep: resume: $(head -c 300 lv2.err)"
# a side wall taken away: slump_ke in the row, the single run's
printf '[sweep]\nmodel = layer\n[grid]\nvi = 20\n[params]\nsample = S40\nside-walls = left\n' >sw.ini
"$GW" sweep sw.ini --out sw --quiet 2>/dev/null
"$GW" layer-impact --sample S40 --vi 20 --side-walls left --json --quiet >sw.json 2>/dev/null
got=$($PY - sw/results.csv sw.json <<'PY' 2>&1
import csv, json, sys
rows = list(csv.DictReader([l for l in open(sys.argv[1]) if not l.startswith("#")]))
d = json.load(open(sys.argv[2]))
v, want = float(rows[0].get("slump_ke", "nan")), d.get("slump_ke")
print("ok" if want is not None and want >= 0 and abs(v - want) <= 1e-12 * max(1, abs(want)) else "slump_ke %r, JSON %r" % (v, want))
PY
)
[ "$got" = ok ] && ok "side-walls sweep: slump_ke the single run's" || ko "side-walls sweep: $got"

# --- Python ---
py_checks 6 <<EOF
import math
r, ws = caught(granwave.layer_impact, sample="$tmp/S40")
check(r is not None and math.isnan(r.get("wave_speed_xcorr", 0.0)) and
      sum("wave_speed_xcorr 44.03 +- 31.1 m/s" in w for w in ws) == 1, "Python: the warning, wave_speed_xcorr NaN")
check(r is not None and "slump_ke" in r and math.isnan(r["slump_ke"]), "Python: slump_ke NaN with both walls")
r2, _ = caught(granwave.layer_impact, sample="$tmp/S40", vi=20, side_walls="left")
import json
want = json.load(open("$tmp/sw.json"))["slump_ke"]
check(r2 is not None and abs(r2.get("slump_ke", float("nan")) - want) <= 1e-12 * max(1, abs(want)),
      "Python: slump_ke with side_walls left, the JSON's")
check(r2 is not None and r2.get("crowns_nulled", -1) >= 0 and r.get("crowns_nulled") == 8,
      "Python: crowns_nulled 8 (the scatter) on the default impact")
got = [(caught(granwave.layer_impact, sample="$tmp/S40", **kw)[0] or {}).get("crowns_nulled")
       for kw in ({"vi": 10}, {"vi": 40})]
want = [json.load(open("$tmp/%s.json" % f)).get("crowns_nulled") for f in ("n0", "n4")]
check(got == want == [0, 4], "Python: crowns_nulled %r, --json's %r (want [0, 4])" % (got, want))
s, ws = caught(granwave.sweep, "layer", {"vi": [10, 20]}, sample="$tmp/S40", until="verdict")
check(sum("crowns: 2 of 2 cases" in w for w in ws) == 1, "Python sweep: one crowns line %r" % [w[:80] for w in ws])
EOF

test_summary test_crowns_nulled
