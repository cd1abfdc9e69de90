#!/bin/bash
# test_side_walls_slump.sh GRANWAVE SRCDIR: a pile slumping when its side wall is
# taken away (layer-impact --side-walls left|right|none; session 46). Every pile
# slumps some from t = 0 without a wall; a block that arrives late meets it in
# motion. The run reads the pile's kinetic energy at the block's touch
# (slump_ke, in the JSON only when a side wall is taken away) and warns when it
# is above 0.1 of the impact's energy (GW_LAYER_SLUMP_WARN). On the 20-disc pile
# of `layer-make --n 20 --width-rm 8 --seed 1` (its left wall carries 0.58 of
# its weight, the right 0.35; floor 0.72), measured without its left wall: 0.72 J
# of kinetic energy by 0.5 ms, 2.5 J by 1 ms (0.16 and 0.71 J with both walls,
# a block of 0.2 R_m at 0.5 m/s on it). Checks:
#  1 --side-walls right, a block of 0.02 R_m at 5 m/s over a gap of 2.4e-3 m
#    (the touch at 0.48 ms, inside the fall rule): slump_ke 0.626 J against an
#    impact of 4.4 J (0.14), the warning on stderr and in --json's warnings,
#    naming both, exit 0 (before: no slump_ke, no warning);
#  2 the same at the default gap (the touch at 2e-7 s): slump_ke 8.2e-6 J
#    (below 1e-5 J), no slump warning (before: no slump_ke);
#  3 the same as 1 with both side walls kept: no slump_ke key and no warning
#    (the default's JSON unchanged);
#  4 Python's layer_impact with the inputs of 1 gives the program's warning,
#    as one GranwaveWarning and in the result's warnings (before: none);
#  5 slump_ke is read at the touch, not at a sample: the run of 1 at --dt-out
#    1e-3 (no sample between t = 0 and the touch) gives the same slump_ke bit
#    for bit and the same warning (read at the sample before the touch it was
#    0 there).
# About 3 s of CPU.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
cpu_run 120 "$GW" layer-make --n 20 --width-rm 8 --seed 1 --quiet --out p.txt >/dev/null 2>p.err ||
    ko "layer-make --n 20 --width-rm 8 --seed 1: $(head -c 300 p.err)"
RUN=(--sample p.txt --rb-rm 0.02 --vi 5 --until verdict --t-max 0.01 --json --quiet)

# --- 1 a late block meets the pile slumping: slump_ke and the warning ---
cpu_run 60 "$GW" layer-impact "${RUN[@]}" --side-walls right --gap 2.4e-3 >a.json 2>a.err
rc=$?
v=$(jq_py a.json 'abs(d["slump_ke"] - 0.6256) < 0.01 and abs(d["e_incident"] - 4.3968) < 1e-3 and d["slump_ke"] > 0.1 * d["e_incident"] and any(w.startswith("the pile was slumping when the block arrived: with a side wall taken away its kinetic energy at the block\x27s touch was 0.626 J, 0.142 of the impact\x27s 4.4 J (above 0.1)") for w in d.get("warnings", []))' 2>/dev/null)
if [ $rc -eq 0 ] && [ "$v" = True ] &&
    grep -q "warning: the pile was slumping when the block arrived: .* was 0.626 J, 0.142 of the impact's 4.4 J" a.err; then
    ok "--side-walls right, the touch at 0.48 ms: slump_ke $(jq_py a.json 'd["slump_ke"]') J of 4.4, warned"
else
    ko "--side-walls right, the touch at 0.48 ms: exit $rc, $v, $(head -c 300 a.json) $(head -c 300 a.err)"
fi

# --- 2 at the default gap the block meets the pile at rest ---
cpu_run 60 "$GW" layer-impact "${RUN[@]}" --side-walls right >b.json 2>b.err
rc=$?
v=$(jq_py b.json '0 < d["slump_ke"] < 1e-5 and not any("slumping" in w for w in d.get("warnings", []))' 2>/dev/null)
if [ $rc -eq 0 ] && [ "$v" = True ] && ! grep -q "slumping" b.err; then
    ok "--side-walls right at the default gap: slump_ke $(jq_py b.json 'd["slump_ke"]') J, no warning"
else
    ko "--side-walls right at the default gap: exit $rc, $v, $(head -c 300 b.json) $(head -c 300 b.err)"
fi

# --- 3 both side walls: no key, no warning ---
cpu_run 60 "$GW" layer-impact "${RUN[@]}" --gap 2.4e-3 >c.json 2>c.err
rc=$?
v=$(jq_py c.json '"slump_ke" not in d and not any("slumping" in w for w in d.get("warnings", []))' 2>/dev/null)
if [ $rc -eq 0 ] && [ "$v" = True ] && ! grep -q "slumping" c.err; then
    ok "both side walls: no slump_ke, no warning"
else
    ko "both side walls: exit $rc, $v, $(head -c 300 c.json) $(head -c 300 c.err)"
fi

# --- 4 Python: the same warning ---
# (the slump's line: the run, stopped at the verdict, also says its crowns were cut)
v=$(pyenv /usr/bin/python3 - "$(jq_py a.json '[w for w in d["warnings"] if "slumping" in w][0]' 2>/dev/null)" <<'PY' 2>&1
import sys, warnings
import granwave
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.layer_impact(sample="p.txt", side_walls="right", rb_rm=0.02, vi=5, gap=2.4e-3, until="verdict",
                              t_max=0.01)
texts = [str(x.message) for x in w if issubclass(x.category, granwave.GranwaveWarning)]
print(sum(t == "layer_impact: " + sys.argv[1] for t in texts) == 1 and list(r.warnings).count(sys.argv[1]) == 1
      and "slumping" in sys.argv[1])
PY
)
if [ "$v" = True ]; then
    ok "Python's layer_impact: the program's warning, once"
else
    ko "Python's layer_impact: $(echo "$v" | tail -3)"
fi

# --- 5 the same at --dt-out 1e-3 ---
cpu_run 60 "$GW" layer-impact "${RUN[@]}" --side-walls right --gap 2.4e-3 --dt-out 1e-3 >e.json 2>e.err
rc=$?
v=$(/usr/bin/python3 - a.json e.json <<'PY' 2>&1
import json, sys
a, e = (json.load(open(p)) for p in sys.argv[1:3])
print(e["slump_ke"] == a["slump_ke"] and e["slump_ke"] > 0.1 * e["e_incident"] and e["warnings"] == a["warnings"])
PY
)
if [ $rc -eq 0 ] && [ "$v" = True ]; then
    ok "--dt-out 1e-3: slump_ke $(jq_py e.json 'd["slump_ke"]') J, as at the default, warned"
else
    ko "--dt-out 1e-3: exit $rc, $v, $(head -c 300 e.err)"
fi

test_summary test_side_walls_slump
