#!/bin/bash
# test_notebooks.sh GRANWAVE SRCDIR: the Python side of the Falcon study.
#  1. `granwave falcon --out TMP` (N = 1..30 so that every trace the figures use is
#     written), then notebooks/plot_falcon.py TMP must exit 0 and write the six PNGs of
#     TMP/figures/, each a non-empty PNG file.
#  1b. plot_falcon.py --module TMP2 (the same study through the Python module, as the
#     notebooks do) writes the same six PNGs, and its run dict equals the one read from
#     the program's files: F_max, tau_N, E_rel/E_K and the per-velocity fit to 1e-9
#     (the same library and solver; measured 1.1e-10, the CSV's 12 digits), the traces' peak force to 1e-4 and
#     the final velocities to 1e-5 m/s (granwave.chain's CVODE against the study's RK4 at
#     its 1e-6 accuracy target; measured 3.8e-7 relative and 2.3e-7 m/s).
#  2. plot_falcon.py must exit 2 (not crash) on a missing directory and on a directory
#     with a required file removed; --module with an --n range without N = 7 exits 2.
#  2b. notebooks/plot_drop.py draws the committed drop runs (a copy of
#     data/measured/drop) and exits 2 on a missing directory.
#  2c. notebooks/plot_sheets.py draws the stored sheet and plateau data (exit 0, four PNGs)
#     and exits 2 on a missing directory.
#  2d. notebooks/plot_wave_speed_layer.py: plot on the stored series (their fit.json
#     again), run + plot with this program (2 points: the title counts them), exit 2
#     on a missing directory.
#  3. Every notebooks/*.ipynb executes headless (nbconvert --execute, Agg backend) with
#     GRANWAVE set to the binary under test and GRANWAVE_LIB to the library beside it
#     (<build>/lib, when there); outputs go to a temp dir, never the repo.
#  4. What docs/notebooks.md quotes from them (the drop's contact time against chain,
#     the fresh sheets runs, bouncing_diagram's table, the plateau's cases, the paper's
#     numbers, figure sizes, 1b's 1.1e-10) equals what they printed in 3
#     (tests/notebook_numbers.py on 3's outputs: nothing runs twice).
# Exits non-zero with a message on the first failure. Skips (exit 0) only when
# /usr/bin/jupyter is missing. Python: Debian's /usr/bin/python3 (numpy, matplotlib).
set -u
if [ $# -ne 2 ]; then
    echo "usage: $0 GRANWAVE SRCDIR" >&2
    exit 2
fi
GW=$(readlink -f "$1")
SRC=$(readlink -f "$2")
PY=/usr/bin/python3
JUPYTER=/usr/bin/jupyter

if [ ! -x "$JUPYTER" ]; then
    echo "SKIP: $JUPYTER not found (install jupyter-nbconvert and python3-ipykernel)"
    exit 0
fi
fail() { echo "FAIL: $*"; exit 1; }
[ -x "$GW" ] || fail "granwave binary $1 not found or not executable"
[ -x "$PY" ] || fail "$PY not found"
[ -f "$SRC/notebooks/plot_falcon.py" ] || fail "$SRC/notebooks/plot_falcon.py not found"

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
export MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 GRANWAVE="$GW"
if [ -z "${GRANWAVE_LIB:-}" ] && [ -f "$(dirname "$GW")/lib/libgranwave.so" ]; then
    export GRANWAVE_LIB="$(dirname "$GW")/lib/libgranwave.so"
fi

# 1. plot_falcon.py on a fresh run
"$GW" falcon --out "$tmp/falcon" --n 1:30 --quiet >"$tmp/falcon.log" 2>&1 \
    || { cat "$tmp/falcon.log"; fail "granwave falcon --out $tmp/falcon"; }
"$PY" "$SRC/notebooks/plot_falcon.py" "$tmp/falcon" >"$tmp/plot.log" 2>&1 \
    || { cat "$tmp/plot.log"; fail "plot_falcon.py $tmp/falcon"; }
for f in fmax_vs_n taun_vs_n wall_force_n7_15_30 velocities_n7 erel_vs_n final_velocities; do
    p="$tmp/falcon/figures/$f.png"
    [ -s "$p" ] || fail "figure $f.png missing or empty"
    [ "$(head -c 8 "$p" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] \
        || fail "figure $f.png is not a PNG file"
    echo "PASS: figure $f.png ($(stat -c %s "$p") bytes)"
done

# 1b. the same figures through the Python module, and the same numbers
"$PY" "$SRC/notebooks/plot_falcon.py" --module "$tmp/falcon_mod" --n 1:30 >"$tmp/plotm.log" 2>&1 \
    || { cat "$tmp/plotm.log"; fail "plot_falcon.py --module $tmp/falcon_mod"; }
for f in fmax_vs_n taun_vs_n wall_force_n7_15_30 velocities_n7 erel_vs_n final_velocities; do
    p="$tmp/falcon_mod/figures/$f.png"
    [ -s "$p" ] && [ "$(head -c 8 "$p" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] \
        || fail "plot_falcon.py --module: figure $f.png missing or not a PNG"
done
echo "PASS: plot_falcon.py --module wrote the six figures"
"$PY" - "$SRC/notebooks" "$tmp/falcon" >"$tmp/cmp.log" 2>&1 <<'PYEOF' || { cat "$tmp/cmp.log"; fail "module run differs from the program's files"; }
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
import plot_falcon as pf
a, b = pf.load_run(sys.argv[2]), pf.run_from_module(n=(1, 30))
worst = 0.0
for k in ("v_imp_m_s", "n", "f_max_N", "tau_n_s", "e_rel_over_e_k"):
    x, y = a["runs"][k], b["runs"][k]
    assert x.shape == y.shape, (k, x.shape, y.shape)
    r = np.max(np.abs(x - y) / np.maximum(np.abs(x), 1e-300))
    assert r < 1e-9, f"runs {k}: relative difference {r:.2e} > 1e-9"
    worst = max(worst, r)
for va, vb in zip(a["summary"]["velocities"], b["summary"]["velocities"]):
    assert va["h_mm"] == vb["h_mm"], (va["h_mm"], vb["h_mm"])
    for k in ("v_imp", "t_q", "tau_fit_intercept", "f_max_1_theory"):
        assert abs(va[k] - vb[k]) <= 1e-9 * abs(va[k]), f"summary {k}: {va[k]} against {vb[k]}"
for n in (7, 15, 30):
    fa, fb = a["wall"][n]["f_wall_N"].max(), b["wall"][n]["f_wall_N"].max()
    assert abs(fa / fb - 1) < 1e-4, f"trace N = {n}: peak {fa} against {fb}"
sel = np.abs(a["final"]["v_imp_m_s"] - 0.3) < 1e-12
d = np.max(np.abs(a["final"]["final_v_m_s"][sel] - b["final"]["final_v_m_s"]))
assert d < 1e-5, f"final velocities differ by {d:.2e} m/s"
print(f"runs within {worst:.1e}, final velocities within {d:.1e} m/s")
PYEOF
echo "PASS: module run equals the program's files ($(tail -1 "$tmp/cmp.log"))"

# 2. clear errors (exit 2) on bad input
"$PY" "$SRC/notebooks/plot_falcon.py" "$tmp/does-not-exist" >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] || fail "plot_falcon.py on a missing directory: exit $rc, expected 2"
grep -q "does-not-exist" "$tmp/err.log" || fail "plot_falcon.py error does not name the directory"
echo "PASS: missing directory -> exit 2: $(head -1 "$tmp/err.log")"
mkdir "$tmp/partial"
cp "$tmp/falcon/falcon_summary.json" "$tmp/falcon/falcon_final_velocities.csv" "$tmp/partial/"
"$PY" "$SRC/notebooks/plot_falcon.py" "$tmp/partial" >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] || fail "plot_falcon.py without falcon_runs.csv: exit $rc, expected 2"
grep -q "falcon_runs.csv" "$tmp/err.log" || fail "plot_falcon.py error does not name the missing file"
echo "PASS: missing file -> exit 2: $(head -1 "$tmp/err.log")"
"$PY" "$SRC/notebooks/plot_falcon.py" --module "$tmp/falcon_bad" --n 8:30 >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] && grep -q -- "--n 8:30" "$tmp/err.log" && [ ! -e "$tmp/falcon_bad" ] \
    || fail "plot_falcon.py --module --n 8:30: exit $rc, $(head -1 "$tmp/err.log")"
echo "PASS: --module without N = 7 -> exit 2: $(head -1 "$tmp/err.log")"

# 2b. plot_drop.py on a copy of the committed drop runs (data/measured/drop), and its
#     refusal of a missing directory
cp -r "$SRC/data/measured/drop" "$tmp/drop"
rm -rf "$tmp/drop/figures"
"$PY" "$SRC/notebooks/plot_drop.py" "$tmp/drop" >"$tmp/plotdrop.log" 2>&1 \
    || { cat "$tmp/plotdrop.log"; fail "plot_drop.py on the committed runs"; }
for f in drop_signal drop_impacts; do
    p="$tmp/drop/figures/$f.png"
    [ -s "$p" ] && [ "$(head -c 8 "$p" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] \
        || fail "plot_drop.py: figure $f.png missing or not a PNG"
    echo "PASS: plot_drop.py figure $f.png ($(stat -c %s "$p") bytes)"
done
"$PY" "$SRC/notebooks/plot_drop.py" "$tmp/no-drop-here" >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] && grep -q "no-drop-here" "$tmp/err.log" \
    || fail "plot_drop.py on a missing directory: exit $rc, $(head -1 "$tmp/err.log")"
echo "PASS: plot_drop.py missing directory -> exit 2: $(head -1 "$tmp/err.log")"
# 2c. plot_sheets.py on the stored sheet and plateau data (issue 19): exit 0 and four
#     PNGs in a temp dir; exit 2 naming a missing directory
"$PY" "$SRC/notebooks/plot_sheets.py" "$SRC/data/measured/sheets" "$tmp/sheets" >"$tmp/plot.log" 2>&1 \
    || { cat "$tmp/plot.log"; fail "plot_sheets.py on data/measured/sheets"; }
for f in sheets_nd_tau1_tol05 sheets_nd_tau1_tol10 plateau fmax_vs_n_material; do
    p="$tmp/sheets/$f.png"
    [ -s "$p" ] && [ "$(head -c 8 "$p" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] \
        || fail "plot_sheets.py: $f.png missing or not a PNG"
done
echo "PASS: plot_sheets.py wrote its four figures"
"$PY" "$SRC/notebooks/plot_sheets.py" "$tmp/does-not-exist" >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] && grep -q "does-not-exist" "$tmp/err.log" || fail "plot_sheets.py on a missing directory: exit $rc"
echo "PASS: plot_sheets.py missing directory -> exit 2: $(head -1 "$tmp/err.log")"

# 2d. notebooks/plot_wave_speed_layer.py (docs/crowns.md section 5): `plot` on a copy of
#     the stored series reproduces their fit.json and draws its three figures; `run` with
#     today's program (one speed, 2 impact points, into a new directory) then `plot`: two
#     rows, the figures, and a title that counts the 2 points (it said "16" whatever the
#     run); a missing directory exits 2 naming it
cp -r "$SRC/data/measured/layer_wave_speed" "$tmp/lws"
rm -rf "$tmp/lws/figures"
"$PY" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/lws" >"$tmp/plot.log" 2>&1 \
    || { cat "$tmp/plot.log"; fail "plot_wave_speed_layer.py plot on the stored series"; }
cmp -s "$tmp/lws/fit.json" "$SRC/data/measured/layer_wave_speed/fit.json" \
    || fail "plot_wave_speed_layer.py: fit.json of the stored series differs from the committed one"
for f in wave_speed_vs_vi local_speed_vs_r gravity; do
    p="$tmp/lws/figures/$f.png"
    [ -s "$p" ] && [ "$(head -c 8 "$p" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] \
        || fail "plot_wave_speed_layer.py: $f.png missing or not a PNG"
done
echo "PASS: plot_wave_speed_layer.py plot: the stored fit.json and three figures"
"$PY" "$SRC/notebooks/plot_wave_speed_layer.py" run "$tmp/lwnew" --speeds 20 --points 2 >"$tmp/plot.log" 2>&1 \
    && "$PY" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/lwnew" >>"$tmp/plot.log" 2>&1 \
    || { cat "$tmp/plot.log"; fail "plot_wave_speed_layer.py run + plot with $GW"; }
rows=$(grep -v -c -e '^#' -e '^tag,' "$tmp/lwnew/impacts.csv")
[ "$rows" -eq 2 ] && [ -s "$tmp/lwnew/figures/wave_speed_vs_vi.png" ] || fail "plot_wave_speed_layer.py run: $rows rows"
label=$(cd "$SRC/notebooks" && "$PY" -c "import json, sys, plot_wave_speed_layer as p; print(p.points_label(json.load(open(sys.argv[1]))))" "$tmp/lwnew/fit.json")
[ "$label" = "2 impact points" ] || fail "plot_wave_speed_layer.py: the figure's title says '$label' for a 2-point run"
echo "PASS: plot_wave_speed_layer.py run + plot with this program: 2 rows, title '$label'"
"$PY" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/no-lws" >/dev/null 2>"$tmp/err.log"
rc=$?
[ $rc -eq 2 ] && grep -q "no-lws" "$tmp/err.log" || fail "plot_wave_speed_layer.py on a missing directory: exit $rc"
echo "PASS: plot_wave_speed_layer.py missing directory -> exit 2: $(head -1 "$tmp/err.log")"

# 2e. each plot script's --help prints its usage and exits 0 (plot_sheets.py took
#     '--help' for a data directory: "no directory --help", exit 2)
for s in plot_falcon plot_drop plot_sheets plot_wave_speed_layer; do
    "$PY" "$SRC/notebooks/$s.py" --help >"$tmp/help.log" 2>&1 && grep -q "$s.py" "$tmp/help.log" \
        || { cat "$tmp/help.log"; fail "$s.py --help"; }
done
echo "PASS: the plot scripts' --help"

# 3. every notebook, headless
shopt -s nullglob
nbs=("$SRC"/notebooks/*.ipynb)
[ ${#nbs[@]} -gt 0 ] || fail "no notebooks in $SRC/notebooks"
for nb in "${nbs[@]}"; do
    name=$(basename "$nb")
    start=$(date +%s)
    if ! "$JUPYTER" nbconvert --to notebook --execute --ExecutePreprocessor.timeout=600 \
            --output-dir "$tmp/nbout" "$nb" >"$tmp/nb.log" 2>&1; then
        grep -v -e "frozen modules" -e "Debugger warning" -e "make the debugger" \
             -e "PYDEVD_DISABLE_FILE_VALIDATION" "$tmp/nb.log" | tail -40
        fail "notebook $name did not execute"
    fi
    echo "PASS: notebook $name executed in $(( $(date +%s) - start )) s"
done

# 4. the numbers docs/notebooks.md quotes from the notebooks against what they printed
#    above (and the plot_falcon --module comparison of 1b): tests/notebook_numbers.py
"$PY" "$SRC/tests/notebook_numbers.py" "$SRC" "$tmp/nbout" "$tmp/cmp.log" >"$tmp/nn.log" 2>&1 \
    || { cat "$tmp/nn.log"; fail "docs/notebooks.md against the notebooks' output"; }
echo "PASS: docs/notebooks.md against the notebooks' output ($(tail -1 "$tmp/nn.log"))"
echo "all notebook tests passed"
