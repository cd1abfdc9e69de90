#!/bin/bash
# test_sweep_check_settling.sh GRANWAVE SRCDIR: the settling check once per
# sample and material in a layer sweep's check pass (issue 18).
# `sweep --check` (and the check pass before every sweep) checked each case's
# settling twice, gw_layer_impact_settled_check entered by the case's
# resolution and again by the tally of its warning, though the cases of a grid
# share a few samples and materials; on a union-clump pile hit under
# clump-mass sum each check weighs the clumps' unions (a model built): 7.7 s
# of CPU for 200 impact points on a pile of 150 clumps, 0.04 s now. The verdict is now kept per sample read and
# material (layer_settling_verdict). Observed from outside: the number of
# times the program enters gw_layer_impact_settled_check, counted by
# valgrind's callgrind (no counter in the library; SKIP without valgrind, in a
# sanitizer build, or where a run's calls cannot be counted: a stripped or
# inlined symbol):
#  1 20 cases over 2 disc samples, one material: 2 calls (40 before);
#  2 8 cases over 2 samples and 2 densities, the density varying fastest:
#    4 calls (16 before);
#  3 10 impact points on a union-clump pile under clump-mass sum: 1 call (20);
#  4 the pass says the same as before: its tally warning (20 of 40 cases),
#    a refusal at the case that is refused, exit 0 and 2 (these pass before).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"

make_sample s.txt --n 40 --seed 1
make_sample s2.txt --n 40 --seed 2
make_sample u.txt --n 20 --clumps --seed 1 --clump-mass union

# calls CMD...: the times CMD enters the settling check
# (gw_layer_impact_settled_check or layer_settled_check_q), from
# valgrind's call graph (callgrind: each call site's "calls=" count under the
# function's cfn= line; the first cfn= or fn= line naming it gives its id);
# empty when valgrind could not run it
calls() {
    local e
    e=$(callgrind_edges "$@") || return
    # the check is entered as gw_layer_impact_settled_check, or as its body
    # layer_settled_check_q (which the library's own callers call, to keep the
    # load ratio it finds): either, but not the one through the other
    awk '$2 ~ /^(gw_layer_impact_settled_check|layer_settled_check_q)$/ && $1 !~ /^(gw_layer_impact_settled_check|layer_settled_check_q)$/ { c += $3 } END { print c + 0 }' <<<"$e"
}
# ini FILE GRID [PARAMS]: a layer sweep, "key = value" lines given with \n
ini() {
    printf '[sweep]\nmodel = layer\n[grid]\n%b\n[params]\nt-max = 0.002\n%b\n' "$2" "${3:-}" >"$1"
}

ini one.ini 'sample = s.txt, s2.txt\npoint = 0:9' 'points = 10\nspacing = 0.05'
ini dens.ini 'sample = s.txt, s2.txt\nvi = 10, 20\ndensity = 2650, 2000'
ini union.ini 'sample = u.txt\npoint = 0:9' 'points = 10\nspacing = 0.05\nclump-mass = sum'
ini fric.ini 'sample = s.txt\nvi = 10, 20\nfriction = 30, 10'

base=""
# (valgrind does not run a sanitizer build's program)
command -v valgrind >/dev/null 2>&1 && ! sanitizer_build &&
    base=$(calls layer-impact --sample s.txt --t-max 1e-4 --out "$tmp/li")
if [ -z "$base" ] || [ "$base" -lt 1 ]; then
    echo "SKIP: the calls cannot be counted here (valgrind: ${base:-absent, or it could not run the program})"
else
    ok "a layer-impact run enters gw_layer_impact_settled_check $base times: the calls are counted"
    for c in "one.ini|2|20 cases, 2 samples, one material" "dens.ini|4|8 cases, 2 samples, 2 densities" \
        "union.ini|1|10 points on the union-clump pile under clump-mass sum"; do
        f=${c%%|*}; rest=${c#*|}; want=${rest%%|*}; what=${rest#*|}
        rm -rf o
        got=$(calls sweep "$f" --out "$tmp/o" --check)
        [ "$got" = "$want" ] && ok "sweep --check, $what: the settling checked $got times" ||
            ko "sweep --check, $what: the settling checked ${got:-?} times, want $want"
    done
fi

# --- 4 the pass says what it said
rm -rf o
"$GW" sweep dens.ini --out "$tmp/o" --check >out.txt 2>err.txt; rc=$?
[ $rc -eq 0 ] && [ "$(grep -c '^granwave sweep: warning: 4 of 8 cases run on a sample settled under another material .*the first: the sample settled with density 2650 kg/m^3 against the impact.s 2000: its contacts carry 1.33 times' err.txt)" = 1 ] &&
    ok "2 densities: exit 0, 4 of 8 cases warned, the first warning's text" || ko "2 densities: exit $rc, $(head -c 400 err.txt)"
if exits_refused "friction 30, 10" "^granwave sweep: fric.ini: case 1: sample '.*/s.txt': it settled with friction 30 deg against the impact's 10" \
    60 "$GW" sweep fric.ini --out "$tmp/o" --check; then
    ok "friction 30, 10: case 1 refused, as before"
fi
"$GW" sweep union.ini --out "$tmp/o" --check >out.txt 2>err.txt; rc=$?
[ $rc -eq 0 ] && grep -q "10 of 10 cases run on a sample settled under another material .*clump-mass union against the impact's sum" err.txt &&
    ok "union pile under clump-mass sum: exit 0, 10 of 10 cases warned" || ko "union pile: exit $rc, $(head -c 400 err.txt)"

test_summary test_sweep_check_settling
