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
# walls' vertical forces with the floor's. Checks:
#  1 --width-rm 4 and 5.38 are refused: exit 2, one line naming --width-rm and
#    "--width-rm 5.39 or more", no --out file; Python's
#    layer_make(clumps=True, width_rm=4, n=20) raises GranwaveValueError naming
#    width_rm 5.39, nothing written;
#  2 the bound follows --aspect-max: --aspect-max 2 --width-rm 4 runs (t-max
#    0.01 s, sample written);
#  3 the width named runs and settles: --width-rm 5.39 --n 20 --seed 1 exits 0,
#    converged, the floor carrying 0.5 to 1.5 of the weight;
#  4 the narrow pile now settles: --width-rm 6 --n 60 --seed 2 exits 0 with no
#    warning on stderr, converged, every member disc inside the box to 0.02 r
#    (read from the file), the largest overlap below 0.05 R_p, the floor
#    carrying below 0.5 of the weight (the walls the rest: the case fixed);
#  5 layer-impact on that sample says nothing of an unsettled sample (its
#    floor check counts the walls' springs too).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
REFUSE_TIMEOUT=60 # (only a guard: the code before ran the 20 clumps about 9 s of CPU)
PY_TIMEOUT=120

msg() { # msg W: the refusal's line as a pattern
    echo "^granwave layer-make --width-rm: a box of $1 R_m is narrower than the longest clump lies flat in .*5\.11 R_m long.*: the clumps stand on end, topple and wedge across the box; give --width-rm 5\.39 or more, or a smaller --aspect-max\$"
}

# --- 1 refused before any work, nothing written ---
refused "layer-make --clumps --width-rm 4 --n 20 (the longest clump 5.11 R_m)" "$(msg 4)" \
    layer-make --clumps --width-rm 4 --n 20 --out "$tmp/o"
refused "layer-make --clumps --width-rm 5.38 --n 20 (below 5.382)" "$(msg 5\\.38)" \
    layer-make --clumps --width-rm 5.38 --n 20 --out "$tmp/o"
py_checks 2 <<'PYEOF'
import os
refused("layer_make(clumps=True, width_rm=4, n=20)", ["width_rm", "width_rm 5.39 or more"], granwave.layer_make,
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

# --- 3 the width named settles ---
if runs_json "layer-make --clumps --width-rm 5.39 --n 20" w.json layer-make --clumps --width-rm 5.39 --n 20 --seed 1 \
    --quiet --out w.txt; then
    v=$(jq_py w.json 'd["converged"] is True and 0.5 <= d["floor_load"] <= 1.5')
    [ "$v" = True ] && ok "--width-rm 5.39 --n 20 (the width named): settled, floor load $(jq_py w.json 'd["floor_load"]')" ||
        ko "--width-rm 5.39 --n 20: converged $(jq_py w.json 'd["converged"]'), floor load $(jq_py w.json 'd["floor_load"]')"
fi

# --- 4 a narrow pile held partly by its walls settles ---
if cpu_run 200 "$GW" layer-make --clumps --width-rm 6 --n 60 --seed 2 --json --quiet --out n60.txt \
    >n60.json 2>n60.err; then
    [ -s n60.err ] && ko "--width-rm 6 --n 60 --seed 2: stderr: $(head -c 300 n60.err)" ||
        ok "--width-rm 6 --n 60 --seed 2: no warning"
    /usr/bin/python3 - n60.txt n60.json <<'PYEOF' >n60.out
import json, sys
d = json.load(open(sys.argv[2]))
width, n, rows = None, None, []
for line in open(sys.argv[1]):
    f = line.split()
    if not f or line.startswith("#"):
        continue
    if f[0] == "width":
        width = float(f[1])
    elif f[0] == "n":
        n = int(f[1])
    elif f[0] == "springs":
        break
    elif n is not None and len(f) >= 3 and len(rows) < n:
        rows.append(tuple(map(float, f[:3])))
out = [i for i, (x, y, r) in enumerate(rows) if x - r < -0.02 * r or x + r > width + 0.02 * r or y - r < -0.02 * r]
ok = (d["converged"] is True and len(rows) == n and d["n_bodies"] == 60 and not out
      and d["max_overlap_over_rp"] < 0.05 and d["floor_load"] < 0.5)
print(("PASS" if ok else "FAIL") + ": --clumps --n 60 --width-rm 6 --seed 2: converged %s, %d bodies, %d outside the "
      "box, max overlap %g R_p, floor load %g (the walls hold the rest)"
      % (d["converged"], d["n_bodies"], len(out), d["max_overlap_over_rp"], d["floor_load"]))
PYEOF
    if grep -q "^PASS" n60.out; then ok "$(cut -c7- n60.out)"; else ko "$(cat n60.out)"; fi
    # --- 5 the impact takes it as settled ---
    cpu_run 120 "$GW" layer-impact --sample n60.txt --t-max 0.001 --quiet --out impdir >/dev/null 2>imp.err
    rc=$?
    if [ $rc -eq 0 ] && ! grep -q "did not settle" imp.err; then
        ok "layer-impact on the narrow pile: exit 0, no 'did not settle' warning"
    else
        ko "layer-impact on the narrow pile: exit $rc: $(head -c 300 imp.err)"
    fi
else
    ko "--clumps --n 60 --width-rm 6 --seed 2: $(head -c 300 n60.err)"
fi

test_summary test_layer_make_clump_wedge
