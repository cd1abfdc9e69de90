#!/bin/bash
# test_fell_off.sh: a block that leaves the layer for good, and two messages
# (docs/outcomes.md "Fell off the layer", docs/cli.md).
#  - layer-impact --remove-walls on the right edge of a 40-disc sample at 60 deg:
#    the block flies off beyond the layer's right side. It ends the run there
#    with bounced false and "fell_off" (JSON and a warning), never "raise
#    --t-max" (before: bounced null, the whole t-max run, that advice);
#  - the same impact with the walls: no "fell_off" key (the other runs' JSON
#    is unchanged);
#  - a sweep over that point and one that bounces: column fell_off 0 / 1,
#    bounced 1 / 0, and layer-stats counts the fell-off row apart, in its
#    warning and in groups.csv's column n_fell_off (1 of the group's 2);
#  - layer-stats on the sweep's journal names results.csv, writes nothing;
#  - chain --radii with 2 radii and the default n: says what was given, no
#    "1 beads"; drop --gap with 3 values for 2 beads: no "1 pairs".
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

"$GW" layer-make --n 40 --out "$tmp/S.txt" --quiet >/dev/null 2>&1 || { echo "FAIL: layer-make"; exit 1; }

# --- the block falls off the layer ---
cpu_run 60 "$GW" layer-impact --sample "$tmp/S.txt" --x 7.7999 --alpha 60 --remove-walls --json --quiet \
    >"$tmp/fall.json" 2>"$tmp/fall.err"; rc=$?
got=$($PY - "$tmp/fall.json" <<'PY' 2>&1
import json, sys
d = json.load(open(sys.argv[1]))
w = " | ".join(d["warnings"])
bad = []
if d["bounced"] is not False: bad.append("bounced %r" % d["bounced"])
if d.get("fell_off") != "beyond its right side": bad.append("fell_off %r" % d.get("fell_off"))
if d["undecided"] is not None: bad.append("undecided %r" % d["undecided"])
if "t-max" in w or "fell off the layer" not in w: bad.append("warnings %r" % w)
# the run ends at the event, not at t-max = 2 s (it leaves at about 66 ms)
if not d["t_end"] < 0.2: bad.append("t_end %r" % d["t_end"])
print("; ".join(bad) or "ok")
PY
)
[ $rc -eq 0 ] && [ "$got" = ok ] && ok "fell off: exit 0, bounced false, fell_off named, no t-max advice, run ended at the event" ||
    ko "fell off: exit $rc, $got"
grep -q "warning: the block fell off the layer" "$tmp/fall.err" && ! grep -q "raise --t-max" "$tmp/fall.err" &&
    ok "fell off: one warning on stderr, no 'raise --t-max'" || ko "fell off: stderr $(head -c 400 "$tmp/fall.err")"

cpu_run 60 "$GW" layer-impact --sample "$tmp/S.txt" --x 7.7999 --alpha 60 --until verdict --json --quiet \
    >"$tmp/wall.json" 2>/dev/null; rc=$?
got=$($PY -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['bounced'], 'fell_off' in d)" "$tmp/wall.json" 2>&1)
[ $rc -eq 0 ] && [ "$got" = "True False" ] && ok "with the walls: bounced, no fell_off key" ||
    ko "with the walls: exit $rc, bounced/fell_off '$got'"

# --- a sweep: the two points, then layer-stats ---
cat >"$tmp/s.ini" <<CFG
[sweep]
model = layer
[grid]
point = 0:1
[params]
sample = $tmp/S.txt
points = 2
x = 6.5499
spacing = 2.5
alpha = 60
remove-walls = true
t-max = 0.2
CFG
cpu_run 120 "$GW" sweep "$tmp/s.ini" --out "$tmp/sw" --quiet --jobs 1 >/dev/null 2>&1; rc=$?
got=$($PY - "$tmp/sw/results.csv" <<'PY' 2>&1
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
print(" ".join("%s/%s" % (r["bounced"], r.get("fell_off")) for r in rows))
PY
)
[ $rc -eq 0 ] && [ "$got" = "1/0 0/1" ] && ok "sweep: bounced/fell_off 1/0 and 0/1" || ko "sweep: exit $rc, '$got'"
"$GW" layer-stats "$tmp/sw/results.csv" --out "$tmp/st" >/dev/null 2>"$tmp/st.err"; rc=$?
[ $rc -eq 0 ] && grep -q "1 of 2 rows fell off the layer" "$tmp/st.err" && ok "layer-stats: the fell-off row counted apart" ||
    ko "layer-stats: exit $rc, $(head -c 400 "$tmp/st.err")"
# groups.csv counts it per group (column n_fell_off, session 43: the count was in the warning alone)
got=$($PY - "$tmp/st/groups.csv" <<'PY' 2>&1
import csv, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
print(" ".join("%s/%s/%s" % (r["n_points"], r["n_bounced"], r.get("n_fell_off")) for r in rows))
PY
)
[ "$got" = "2/1/1" ] && ok "groups.csv: n_points/n_bounced/n_fell_off 2/1/1" ||
    ko "groups.csv: n_points/n_bounced/n_fell_off '$got' (wanted 2/1/1)"

# --- layer-stats on the journal ---
"$GW" layer-stats "$tmp/sw/journal.csv" --out "$tmp/stj" >/dev/null 2>"$tmp/j.err"; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l <"$tmp/j.err")" -eq 1 ] && grep -q "journal" "$tmp/j.err" &&
    grep -qF "$tmp/sw/results.csv" "$tmp/j.err" && [ ! -e "$tmp/stj" ] &&
    ok "layer-stats on a journal: exit 2, one line naming results.csv, nothing written" ||
    ko "layer-stats on a journal: exit $rc, $(head -c 400 "$tmp/j.err")"

# --- messages with counts ---
"$GW" chain --radii 4e-3,4e-3 --mass 1e-3 >/dev/null 2>"$tmp/c.err"; rc=$?
[ $rc -eq 2 ] && grep -q "2 radii but n is 1" "$tmp/c.err" && ! grep -q "1 beads" "$tmp/c.err" &&
    ok "chain --radii: what was given against n, no '1 beads'" || ko "chain --radii: exit $rc, $(cat "$tmp/c.err")"
"$GW" drop --n 2 --gap 1e-4,1e-4,1e-4 >/dev/null 2>"$tmp/d.err"; rc=$?
[ $rc -eq 2 ] && grep -q "gap" "$tmp/d.err" && ! grep -q "1 pairs" "$tmp/d.err" &&
    ok "drop --gap: no '1 pairs'" || ko "drop --gap: exit $rc, $(cat "$tmp/d.err")"

test_summary test_fell_off
