#!/bin/bash
# test_layer_settled_once.sh GRANWAVE SRCDIR: a layer run finds its sample's
# settling verdict once, and weighs a union-clump pile once (issue 18).
# A run's plan checked the settling (gw_layer_impact_settled_check and the
# floor's load, layer_rest_check), then the run checked it again, and the
# load ratio q was found for each check, the rest check and the result: on a
# union-clump pile hit under clump-mass sum each finding builds the pile's
# model to weigh its clumps' unions (0.13 s against 0.06 s for a 150-clump
# run at t-max 0.002). The run now takes its plan's verdict, and q is found
# once per verdict (layer_settled_check_q). Observed from outside: the calls
# counted by valgrind's callgrind (no counter in the library; SKIP without
# valgrind, in a sanitizer build, or where the calls cannot be counted):
#  - checks: entries into the settling check (gw_layer_impact_settled_check,
#    or layer_settled_check_q not through it);
#  - weighings: gw_layer_create's calls from the weighing (union_weight;
#    the run's own model is made elsewhere).
#  1 a sweep of one layer case on a 20-clump union pile under clump-mass sum
#    (--quiet: the plain run): 2 checks (the check pass and the case run;
#    3 before), 2 weighings (7 before);
#  2 the same case run twice (two speeds): 3 checks (5 before), 3 weighings
#    (12 before);
#  3 layer-impact on that pile: 1 check and 1 weighing (its plan's, which
#    the run takes; 2 and 2 before, the plan's and gw_layer_impact's own,
#    and 2 and 6 before that);
#  4 the outcome is the same: the sweep's table and layer-impact's JSON (but
#    its wall time) those of a run without callgrind and of the disc pile's
#    warning-free case (these pass before).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"

make_sample u.txt --n 20 --clumps --seed 1 --clump-mass union

# counts CMD...: "CHECKS WEIGHINGS" of CMD from valgrind's call graph (each
# call site's "calls=" count under its cfn= line, with the caller of that
# site: the fn= line above it); empty when valgrind could not run it
counts() {
    local e
    e=$(callgrind_edges "$@") || return
    # the check is entered as gw_layer_impact_settled_check, or as its body
    # layer_settled_check_q: either, but not the one through the other
    awk '$2 ~ /^(gw_layer_impact_settled_check|layer_settled_check_q)$/ && $1 !~ /^(gw_layer_impact_settled_check|layer_settled_check_q)$/ { c += $3 } $1 == "union_weight" && $2 == "gw_layer_create" { w += $3 }
         END { print c + 0, w + 0 }' <<<"$e"
}
ini() { # ini FILE VIS: one layer case per speed on u.txt under clump-mass sum
    printf '[sweep]\nmodel = layer\n[grid]\nsample = u.txt\nvi = %s\n[params]\nt-max = 1e-4\nclump-mass = sum\n' \
        "$2" >"$1"
}
ini one.ini 2
ini two.ini '2, 3'

base=""
command -v valgrind >/dev/null 2>&1 && ! sanitizer_build &&
    base=$(counts layer-impact --sample u.txt --clump-mass sum --t-max 1e-4 --out "$tmp/li")
if [ -z "$base" ] || [ "${base%% *}" -lt 1 ] || [ "${base##* }" -lt 1 ]; then
    echo "SKIP: the calls cannot be counted here (valgrind: ${base:-absent, or it could not run the program})"
else
    [ "$base" = "1 1" ] && ok "layer-impact: the settling checked once, the union pile weighed once" ||
        ko "layer-impact: checks and weighings '$base', want '1 1' (its plan's, which its run takes)"
    for c in "one.ini|2 2|one case" "two.ini|3 3|two cases"; do
        f=${c%%|*}; rest=${c#*|}; want=${rest%%|*}; what=${rest#*|}
        rm -rf "$tmp/o"
        got=$(counts sweep "$f" --out "$tmp/o" --quiet)
        [ "$got" = "$want" ] && ok "sweep, $what on the union pile: checks and weighings $got" ||
            ko "sweep, $what on the union pile: checks and weighings '${got:-?}', want '$want'"
    done
fi

# --- 4 the same outcome
rm -rf o1 o2
"$GW" sweep two.ini --out o1 --quiet 2>/dev/null && "$GW" sweep two.ini --out o2 2>/dev/null &&
    cmp -s o1/results.csv o2/results.csv && [ "$(grep -vc '^#' o1/results.csv)" = 3 ] &&
    ok "sweep: the same table with and without progress lines" || ko "sweep: the tables differ or are missing"
"$GW" layer-impact --sample u.txt --clump-mass sum --t-max 1e-4 --json >a.json 2>a.err; rc=$?
/usr/bin/python3 - a.json <<'PY' && [ $rc -eq 0 ] && ok "layer-impact: exit 0, its JSON records q in (0.5, 1) and the warning" || ko "layer-impact: exit $rc, $(head -c 300 a.err)"
import json, sys
d = json.load(open(sys.argv[1]))
q = d["settings"]["sample_settled"]["load_ratio"]
sys.exit(0 if 0.5 < q < 1 and any("clump-mass union" in w for w in d.get("warnings", [])) else 1)
PY

test_summary test_layer_settled_once
