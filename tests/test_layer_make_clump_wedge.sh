#!/bin/bash
# test_layer_make_clump_wedge.sh GRANWAVE SRCDIR: clump piles that wedge in a
# box narrower than their longest clump, and narrow clump piles at rest that
# were called unsettled.
# `layer-make --clumps --width-rm 4 --n 20` (the longest clump the defaults can
# draw is 5.11 R_m long) stood its clumps on end; they toppled and jammed across
# the box, and seeds 1 and 2 ended unsettled at t-max (floors carrying 6.57 and
# 0.054 of the weight). gw_layer_make now refuses, before any work, a box in
# which the longest clump cannot lie flat with the lay-out's gaps (5.38 R_m at
# the defaults), naming --width-rm and the smallest width of three digits that
# passes (5.39). `--clumps --width-rm 6 --n 60 --seed 2` (rows within the 16x
# bound) ended "did not settle" at t-max 6 s with E_k 1e-4 of the threshold:
# its floor carried 0.203 of the weight and the side walls' friction the rest
# (Janssen), which the rest criterion did not count; it now counts the side
# walls' vertical forces with the floor's.
# The bound was that of the longest clump any draw could give (R_eq = R_max
# at the largest aspect ratio), so `--clumps --n 1` (one clump 3.53 R_m long
# at seed 1) was refused below 5.39 R_m; it is now the longest clump the
# seed's n draws give (the draw does not depend on the box): 3.81 R_m for
# --n 1, 4.92 for --n 20 at seed 1. `--clumps --width-rm 6 --n 40 --seed 3`
# ended unsettled at t-max with E_k 1e-2 of the threshold, its floor carrying
# 1.60 of the weight and the side walls' friction pulling it down by 0.60 (the
# pile thrown up by its landing, caught by the walls on its way back): at
# rest, refused for the floor's load alone; it now settles, and layer-impact
# counts the walls' springs with the floor. Checks:
#  1 refused below the longest clump drawn: exit 2, one line naming
#    --width-rm and "--width-rm W or more", no --out file: --n 20 at 4 and
#    4.91 (W 4.92, clump 17 of 20, 4.64 R_m long), --n 1 at 3.8 (W 3.81);
#    Python's layer_make(clumps=True, width_rm=4, n=20) raises
#    GranwaveValueError naming width_rm 4.92, nothing written;
#  2 the bound follows --aspect-max and the draw: --aspect-max 2 --width-rm 4
#    runs (t-max 0.01 s, sample written), and so do --n 1 at 3.81 and 4;
#  3 the width named runs and settles: --width-rm 4.92 --n 20 --seed 1 exits
#    0, converged, the floor carrying 0.5 to 1.5 of the weight;
#  4 the narrow pile now settles: --width-rm 6 --n 60 --seed 2 exits 0 with no
#    warning on stderr, converged, every member disc inside the box to 0.02 r
#    (read from the file), the largest overlap below 0.05 R_p, the floor
#    carrying below 0.5 of the weight (the walls the rest: the case fixed);
#  5 layer-impact on that sample says nothing of an unsettled sample (its
#    floor check counts the walls' springs too);
#  6 a pile the walls press onto its floor settles: --width-rm 6 --n 40
#    --seed 3 exits 0 with no warning, converged, its floor carrying above
#    1.5 of the weight (the case fixed), every member disc inside the box to
#    0.02 r; layer-impact on it runs (exit 0, no refusal, no "did not
#    settle").
#  7 a narrow pile rocking between its walls is not called settled at a dip
#    of its E_k: `--width-rm 6 --n 40 --seed 4` (floor 2.25, walls -1.24 of
#    the weight) was called settled at 4.47 s, E_k 0.88 of the threshold,
#    below it for 10 checks (4.47 to 4.56 s) and 84 times it at 4.96 s; a
#    pile the walls help hold must now pass the rest rules at 20 successive
#    checks (0.2 s). Run to --t-max 4.7 s: exit 0, converged false, a warning
#    on stderr and in the JSON's "warnings".
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
REFUSE_TIMEOUT=60 # (only a guard: the code before ran the 20 clumps about 9 s of CPU)
PY_TIMEOUT=120

msg() { # msg W BOUND LONG: the refusal's line as a pattern (each a pattern)
    echo "^granwave layer-make --width-rm: a box of $1 R_m is narrower than the longest clump drawn lies flat in .*: $3 R_m long.*: the clumps stand on end, topple and wedge across the box; give --width-rm $2 or more, or a smaller --aspect-max\$"
}

# --- 1 refused before any work, nothing written ---
refused "layer-make --clumps --width-rm 4 --n 20 (its longest clump drawn 4.64 R_m)" "$(msg 4 '4\.92' '4\.64')" \
    layer-make --clumps --width-rm 4 --n 20 --out "$tmp/o"
refused "layer-make --clumps --width-rm 4.91 --n 20 (below 4.916)" "$(msg '4\.91' '4\.92' '4\.64')" \
    layer-make --clumps --width-rm 4.91 --n 20 --out "$tmp/o"
refused "layer-make --clumps --width-rm 3.8 --n 1 (its clump 3.53 R_m)" "$(msg '3\.8' '3\.81' '3\.53')" \
    layer-make --clumps --width-rm 3.8 --n 1 --out "$tmp/o"
py_checks 2 <<'PYEOF'
import os
refused("layer_make(clumps=True, width_rm=4, n=20)", ["width_rm", "width_rm 4.92 or more"], granwave.layer_make,
        clumps=True, width_rm=4, n=20, out="py.txt")
check(not os.path.exists("py.txt"), "layer_make(clumps=True, width_rm=4, n=20): nothing written")
PYEOF

# --- 2 the bound follows the aspect ratio ---
rm -f a2.txt
if cpu_run 60 "$GW" layer-make --clumps --aspect-max 2 --width-rm 4 --n 20 --t-max 0.01 --quiet --out a2.txt \
    >/dev/null 2>a2.err && [ -s a2.txt ]; then
    ok "layer-make --clumps --aspect-max 2 --width-rm 4 (its longest clump 3.67 R_m): runs"
else
    ko "layer-make --clumps --aspect-max 2 --width-rm 4: $(head -c 300 a2.err)"
fi

for w in 3.81 4; do
    rm -f a1.txt
    if cpu_run 60 "$GW" layer-make --clumps --n 1 --width-rm $w --t-max 0.01 --quiet --out a1.txt \
        >/dev/null 2>a1.err && [ -s a1.txt ]; then
        ok "layer-make --clumps --n 1 --width-rm $w (its clump 3.53 R_m at seed 1): runs"
    else
        ko "layer-make --clumps --n 1 --width-rm $w: $(head -c 300 a1.err)"
    fi
done

# --- 3 the width named settles ---
if runs_json "layer-make --clumps --width-rm 4.92 --n 20" w.json layer-make --clumps --width-rm 4.92 --n 20 --seed 1 \
    --quiet --out w.txt; then
    v=$(jq_py w.json 'd["converged"] is True and 0.5 <= d["floor_load"] <= 1.5')
    [ "$v" = True ] && ok "--width-rm 4.92 --n 20 (the width named): settled, floor load $(jq_py w.json 'd["floor_load"]')" ||
        ko "--width-rm 4.92 --n 20: converged $(jq_py w.json 'd["converged"]'), floor load $(jq_py w.json 'd["floor_load"]')"
fi

# narrow_pile N SEED FLOOR WHAT: `--clumps --width-rm 6 --n N --seed SEED`
# settles: exit 0, no warning, converged, N bodies, every member disc inside
# the box (discs_outside), the largest overlap below 0.05 R_p, the floor's
# load passing the Python test FLOOR on f (WHAT says it); then layer-impact
# runs on it (exit 0) saying nothing of an unsettled sample
narrow_pile() {
    local tag="n$1s$2" what="--clumps --n $1 --width-rm 6 --seed $2"
    if ! cpu_run 200 "$GW" layer-make --clumps --width-rm 6 --n "$1" --seed "$2" --json --quiet --out $tag.txt \
        >$tag.json 2>$tag.err; then
        ko "$what: $(head -c 300 $tag.err)"
        return
    fi
    [ -s $tag.err ] && ko "$what: stderr: $(head -c 300 $tag.err)" || ok "$what: no warning"
    local box v
    box=$(discs_outside $tag.txt)
    v=$(jq_py $tag.json "d['converged'] is True and d['n_bodies'] == $1 and d['max_overlap_over_rp'] < 0.05 and \
(lambda f: $3)(d['floor_load'])")
    if [ "$v" = True ] && [ "$(echo "$box" | awk '{ print ($1 == $2 && $3 == 0) }')" = 1 ]; then
        ok "$what: converged, n/discs/outside $box, max overlap $(jq_py $tag.json 'd["max_overlap_over_rp"]') R_p, floor load $(jq_py $tag.json 'd["floor_load"]') ($4)"
    else
        ko "$what: converged $(jq_py $tag.json 'd["converged"]'), n/discs/outside $box, floor load $(jq_py $tag.json 'd["floor_load"]') (wanted: $4)"
    fi
    # the impact takes it as settled
    cpu_run 120 "$GW" layer-impact --sample $tag.txt --t-max 0.001 --quiet --out imp$tag >/dev/null 2>imp$tag.err
    local rc=$?
    if [ $rc -eq 0 ] && ! grep -q "did not settle" imp$tag.err; then
        ok "layer-impact on $what: exit 0, no 'did not settle' warning"
    else
        ko "layer-impact on $what: exit $rc: $(head -c 300 imp$tag.err)"
    fi
}

# --- 4, 5 a narrow pile held partly up by its walls settles ---
narrow_pile 60 2 "f < 0.5" "below 0.5: the walls hold the rest"
# --- 6 a narrow pile pressed onto its floor by its walls settles ---
narrow_pile 40 3 "f > 1.5" "above 1.5: the walls pull the pile down"
# --- 7 a pile rocking between its walls is not settled at a dip of its E_k ---
if cpu_run 200 "$GW" layer-make --clumps --width-rm 6 --n 40 --seed 4 --t-max 4.7 --json --quiet --out n40s4.txt \
    >n40s4.json 2>n40s4.err; then
    v=$(jq_py n40s4.json 'd["converged"] is False and len(d.get("warnings", [])) == 1')
    if [ "$v" = True ] && [ "$(wc -l <n40s4.err)" = 1 ]; then
        ok "--clumps --n 40 --width-rm 6 --seed 4 to t-max 4.7 s (E_k below the threshold 4.47 to 4.56 s only): unsettled, warned: $(head -c 200 n40s4.err)"
    else
        ko "--clumps --n 40 --width-rm 6 --seed 4 to t-max 4.7 s: converged $(jq_py n40s4.json 'd["converged"]') at t $(jq_py n40s4.json 'd["t_settle"]'), stderr: $(head -c 200 n40s4.err)"
    fi
else
    ko "--clumps --n 40 --width-rm 6 --seed 4 --t-max 4.7: $(head -c 300 n40s4.err)"
fi

test_summary test_layer_make_clump_wedge
