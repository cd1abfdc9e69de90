#!/bin/bash
# bench/falcon_vs_lsoda.sh [BUILD_DIR] [ROUNDS]: CPU time of the falcon main job
# (`granwave falcon --out DIR`: 200 collisions, N = 1..40 at 5 impact velocities,
# tables, traces and report) against 3 SciPy solve_ivp LSODA collisions of the
# 40-bead column (v_imp = 0.3 m/s, rtol 1e-6, atol = rtol x scale), measured
# alternately in the same run, ROUNDS times (default 3); prints each round, the
# medians and the ratio falcon / (3 LSODA). Measurements only, never pass/fail.
# The falcon CPU time is user + sys of the whole process (/usr/bin/time, both
# threads); LSODA's is time.process_time around solve_ivp (bench/peer_lsoda3.py).
# The machine is shared: compare the ratio, not the seconds.
# Environment: FALCON_ARGS (extra arguments, e.g. "--solver cvode --rtol 1e-12").
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 2 "$@"
ROUNDS=${2-3}
posint ROUNDS "$ROUNDS"
bench_build_dir "${1-$bench_checkout/build}"
cd "$bench_checkout"
PY=/usr/bin/python3
cmake --build "$B" --target granwave >/dev/null
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

# the 40-bead column's parameters and reference observables (granwave default
# run; LSODA's errors against it are printed for information)
"$B/granwave" chain --n 40 --json >"$OUT/ref.json"
read -r K KW M V FREF TREF TEND < <("$PY" -c '
import json, sys
j = json.load(open(sys.argv[1]))
m = j["settings"]["model"]
print(m["k"], m["kwall"], m["mass"], j["v_imp"], j["f_max"], j["tau_n"], j["t_end"])' "$OUT/ref.json")

echo "round  falcon_cpu_s  lsoda3_cpu_s  ratio"
for r in $(seq "$ROUNDS"); do
    # shellcheck disable=SC2086
    /usr/bin/time -f "%U %S" -o "$OUT/time.txt" "$B/granwave" falcon --quiet --out "$OUT/falcon" ${FALCON_ARGS:-} >/dev/null
    fc=$(awk '{print $1 + $2}' "$OUT/time.txt")
    "$PY" bench/peer_lsoda3.py --params "$K" "$KW" "$M" "$V" --ref "$FREF" "$TREF" "$TEND" >"$OUT/lsoda.txt"
    ls3=$(awk '$1 == "LSODA3" {print $2}' "$OUT/lsoda.txt")
    echo "$r $fc $ls3" | awk '{printf "%5d %13.3f %13.3f %6.2f\n", $1, $2, $3, $2 / $3}' | tee -a "$OUT/rounds.txt"
done
grep -v LSODA3 "$OUT/lsoda.txt"
sort -n -k2 "$OUT/rounds.txt" | awk '{f[NR] = $2} END {print f[int((NR + 1) / 2)]}' >"$OUT/mf"
sort -n -k3 "$OUT/rounds.txt" | awk '{f[NR] = $3} END {print f[int((NR + 1) / 2)]}' >"$OUT/ml"
awk -v f="$(cat "$OUT/mf")" -v l="$(cat "$OUT/ml")" 'BEGIN {printf "median: falcon %.3f s CPU, 3 LSODA collisions %.3f s CPU, ratio %.2f\n", f, l, f / l}'
