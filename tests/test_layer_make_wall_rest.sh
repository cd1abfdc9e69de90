#!/bin/bash
# test_layer_make_wall_rest.sh GRANWAVE SRCDIR: a pile its side walls help hold
# is told the rule the code applies, the floor and the walls together carrying
# its weight (layer_load_rests, layer_impl.h: the one rule layer-make settles
# by, its warning states and layer-impact's rest check refuses by).
# `layer-make --clumps --width-rm 6 --n 40 --seed 4` rocks between its walls,
# its floor carrying 2.25 of the weight and the walls pulling down 1.22 to
# 1.25. Stopped at --t-max 4.5 s with E_k below the threshold (a pile the walls
# help hold must pass the rest rules at 20 successive checks), it was told "its
# floor carries 2.25 times the pile's weight (at rest: about 1; layer-impact
# refuses above 1.5)", and layer-impact took the sample. Checks:
#  1 the JSON gives wall_load, the floor above 1.5 and floor + walls within
#    [0.5, 1.5] (at rest by the rule);
#  2 the warning (stderr and JSON) names the floor's and the walls' shares and
#    their sum as the JSON gives them, and the 20 checks, not "refuses above
#    1.5";
#  3 layer-impact takes that sample (exit 0, no refusal): the rule the
#    warning states;
#  4 the same sample with its wall springs cut to a fifth (the walls holding
#    about 0.25 of the weight, floor + walls about 2) is refused (exit 2, one
#    line) naming the floor's load, the side walls' share and the sum, as the
#    warning names them (before: the floor's alone).
# About 20 s of CPU (the pluviation).
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1, 2 the pile stopped while its walls help hold it ---
if cpu_run 120 "$GW" layer-make --clumps --width-rm 6 --n 40 --seed 4 --t-max 4.5 --json --quiet --out p.txt \
    >p.json 2>p.err; then
    v=$(jq_py p.json 'd["converged"] is False and d["floor_load"] > 1.5 and 0.5 <= d["floor_load"] + d["wall_load"] <= 1.5')
    [ "$v" = True ] &&
        ok "--t-max 4.5: unsettled, floor $(jq_py p.json 'round(d["floor_load"], 3)'), walls $(jq_py p.json 'round(d["wall_load"], 3)') of the weight" ||
        ko "--t-max 4.5: converged, floor, walls: $(jq_py p.json 'd["converged"], d["floor_load"], d.get("wall_load")')"
    want=$(jq_py p.json '"its floor carries %.3g of the pile'"'"'s weight and its side walls %.3g (together %.3g: at rest" % (d["floor_load"], d["wall_load"], d["floor_load"] + d["wall_load"])')
    jw=$(jq_py p.json '" | ".join(d["warnings"])')
    if grep -qF "$want" p.err && grep -qF "$want" <<<"$jw" && grep -q "20 successive checks" p.err &&
        ! grep -q "refuses above" p.err; then
        ok "the warning states the rule applied: '$want', 20 checks"
    else
        ko "the warning (wanted '$want'): $(head -c 500 p.err)"
    fi
else
    ko "layer-make --t-max 4.5: $(head -c 300 p.err)"
fi

# --- 3 layer-impact takes it ---
if cpu_run 60 "$GW" layer-impact --sample p.txt --t-max 1e-4 --json --quiet >i.json 2>i.err; then
    ok "layer-impact takes the sample (floor and walls at rest by the rule)"
else
    ko "layer-impact on the sample: $(head -c 300 i.err)"
fi

# --- 4 the walls holding less: refused naming both ---
/usr/bin/python3 - p.txt q.txt <<'PY'
import sys
out, springs = [], False
for line in open(sys.argv[1]):
    f = line.split()
    if f and f[0] == "springs":
        springs = True
    elif springs and len(f) == 3 and f[1] in ("left", "right"):
        line = "%s %s %.17g\n" % (f[0], f[1], float(f[2]) / 5)
    out.append(line)
open(sys.argv[2], "w").writelines(out)
PY
cpu_run 60 "$GW" layer-impact --sample q.txt --t-max 1e-4 --json --quiet >q.json 2>q.err
rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <q.err)" = 1 ] &&
    grep -qE "its floor carries 2\.2[0-9]* times the weight of the pile and its side walls -0\.2[0-9]* \(together (2|1\.9[0-9]*|2\.0[0-9]*); at rest: 0\.5 to 1\.5\)" q.err; then
    ok "wall springs cut to a fifth: refused naming floor, walls and their sum: $(grep -oE 'its floor carries .{0,40}|its side walls [^)]*\)' q.err | tr '\n' ' ')"
else
    ko "wall springs cut to a fifth: exit $rc, $(head -c 600 q.err)"
fi

test_summary test_layer_make_wall_rest
