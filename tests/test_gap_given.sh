#!/bin/bash
# test_gap_given.sh GRANWAVE SRCDIR: a slow impact's refusal names the gap
# the user gave, and "the default gap" only when none was given (issue 18).
# The fall check (gw_layer_impact_fall_check) refuses a gap whose fall
# changes the normal speed by more than 0.1 %; at the default gap (1 um, no
# --gap) the refusal names --vi and "the default gap" (session 43). It told
# the gap from the default by its value, so an explicit --gap 1e-6 (or
# 1e-06, 0.000001) was told "--vi: ... too slow for the default gap of
# 1e-06 m ... give vi at least ... with the default gap". The setup's gap
# row is now optional (gw_param_given tells a gap given at the default's
# value from none): a gap given is the gap's refusal, "--gap: falling 1e-06
# m ... lower gap to G m, or give vi the speed at contact (at least V m/s
# with this gap)", in the program, a sweep's check and Python alike.
#  1 layer-impact --vi 0.05 --gap 1e-6, 1e-06, 0.000001: "--gap: falling
#    1e-06 m", no "default"; the gap and the speed it names run;
#  2 no --gap: "--vi: 0.05 m/s is too slow for the default gap" (a guard),
#    --gap 2e-6 "--gap:" (a guard);
#  3 a sweep's check: a case with gap = 1e-6 given names gap, one without
#    names vi and the default gap;
#  4 Python: layer_impact(gap=1e-6, vi=0.05) names gap, without gap vi and
#    the default gap; a sweep with gap = 1e-6 names gap;
#  5 a run with --gap 1e-6 and one without give the same JSON, the wall
#    time aside (a guard: the gap given is the default's value).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

make_sample s20.txt --n 20 --width-rm 8

# runs_ok WHAT ARGS...: layer-impact on s20.txt exits 0 (t-max 20 ms: the block reaches the layer)
runs_ok() {
    local what=$1
    shift
    timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --t-max 0.02 --quiet "$@" >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$what" || ko "$what: exit $? ($(head -c 300 "$tmp/stderr"))"
}

# --- 1 a gap given at the default's value: the gap's refusal ---
for g in 1e-6 1e-06 0.000001; do
    refused "layer-impact --vi 0.05 --gap $g: names --gap" \
        "^granwave layer-impact --gap: falling 1e-06 m \\(g = 9\\.81 m/s\\^2\\).* lower gap to [0-9.e-]+ m, or give vi the speed at contact \\(at least [0-9.e-]+ m/s with this gap\\)$" \
        layer-impact --sample s20.txt --t-max 1e-3 --vi 0.05 --gap "$g" --out o
    if grep -q default "$tmp/stderr"; then ko "--gap $g: the refusal says default: $(head -c 200 "$tmp/stderr")"; else ok "--gap $g: no 'default' in the refusal"; fi
done
gmax=$(sed -nE 's/.* lower gap to ([0-9.e-]+) m.*/\1/p' "$tmp/stderr")
vmin=$(sed -nE 's/.*\(at least ([0-9.e-]+) m\/s with this gap.*/\1/p' "$tmp/stderr")
[ -n "$gmax" ] && runs_ok "--vi 0.05 --gap $gmax (the gap named) runs" --vi 0.05 --gap "$gmax"
[ -n "$vmin" ] && runs_ok "--vi $vmin --gap 1e-6 (the speed named) runs" --vi "$vmin" --gap 1e-6

# --- 2 guards: no gap given, another gap given ---
refused "layer-impact --vi 0.05 (no --gap): names --vi and the default gap" \
    "^granwave layer-impact --vi: 0\\.05 m/s is too slow for the default gap of 1e-06 m: .* give vi at least [0-9.e-]+ m/s with the default gap" \
    layer-impact --sample s20.txt --t-max 1e-3 --vi 0.05 --out o
refused "layer-impact --vi 0.05 --gap 2e-6: names --gap" "^granwave layer-impact --gap: falling 2e-06 m " \
    layer-impact --sample s20.txt --t-max 1e-3 --vi 0.05 --gap 2e-6 --out o

# --- 3 a sweep's check ---
printf '[sweep]\nmodel = layer\n[grid]\nvi = 20, 0.05\n[params]\nsample = s20.txt\nt-max = 1e-3\ngap = 1e-6\n' >sg.ini
refused "sweep --check: gap = 1e-6 given, vi 0.05: names gap" \
    "sg\\.ini: case 1: gap: falling 1e-06 m .* lower gap to" sweep sg.ini --out o --check
printf '[sweep]\nmodel = layer\n[grid]\nvi = 20, 0.05\n[params]\nsample = s20.txt\nt-max = 1e-3\n' >sd.ini
refused "sweep --check: no gap, vi 0.05: names vi and the default gap (a guard)" \
    "sd\\.ini: case 1: vi: 0\\.05 m/s is too slow for the default gap of 1e-06 m" sweep sd.ini --out o --check

# --- 4 Python ---
PY_TIMEOUT=120 py_checks 3 <<'EOF'
refused("Python layer_impact(vi=0.05, gap=1e-6)", ["gap: falling 1e-06 m", "lower gap to"],
        granwave.layer_impact, sample="s20.txt", vi=0.05, gap=1e-6, t_max=1e-3)
refused("Python layer_impact(vi=0.05) (a guard)", ["vi: 0.05 m/s is too slow for the default gap of 1e-06 m"],
        granwave.layer_impact, sample="s20.txt", vi=0.05, t_max=1e-3)
refused("Python sweep(layer, gap=1e-6, vi 20 and 0.05)", ["gap: falling 1e-06 m"],
        granwave.sweep, "layer", {"vi": [20, 0.05]}, jobs=1, sample="s20.txt", t_max=1e-3, gap=1e-6)
EOF

# --- 5 the run: the gap given at the default's value is the default's ---
a=$(timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --t-max 0.02 --json 2>/dev/null | grep -v wall_time_ms)
b=$(timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --t-max 0.02 --gap 1e-6 --json 2>/dev/null | grep -v wall_time_ms)
[ -n "$a" ] && [ "$a" = "$b" ] && ok "--gap 1e-6 and no --gap: the same JSON (wall time aside)" ||
    ko "--gap 1e-6 and no --gap: the JSON differs ($(diff <(echo "$a") <(echo "$b") | head -5 | tr '\n' ' '))"

test_summary test_gap_given
