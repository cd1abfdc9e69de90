#!/bin/bash
# bench/bench_layer.sh [BUILD_DIR]: cost of layer impacts (docs/physics.md 2.3) and of
# `granwave sweep` over them. Never a pass/fail test: prints measurements.
#   1. the default 300-disc sample (granwave layer-make, made once and kept in
#      BUILD_DIR/bench-layer/sample300.txt);
#   2. cases/s of the default impact (R_b = R_m, V_i = 20 m/s, rk4, dt 1e-6 s,
#      t-max 0.05 s, given explicitly: the default is 2 s since issue 18, so
#      that the numbers stay comparable) on one core: a sweep of NPT impact
#      points with --jobs 1;
#   3. the same cases with 2 threads, with 2 MPI ranks (rank 0 is a pure master
#      in sweep_cmd.c, so 1 worker) and with 3 ranks (2 workers + the master,
#      oversubscribed on 2 cores), the last also with mpi_yield_when_idle;
#      speed-ups against item 2;
#   4. the per-case cost against R_b and H (layer-impact, wall and CPU time) on
#      a 3 x 3 grid, and from it the projected time of the paper's diagram
#      (10 R_b x 8 H x 100 points) on one core, one 2-core machine (threads) and
#      64 MPI ranks (63 workers);
#   5. the check pass of an 8000-case config (`sweep --check`: every case parsed,
#      its sample read and checked), i.e. the cost of reading the sample per case.
# Environment: NPT (impact points in 2-3, default 4); ONLY=speed runs items 1-3 only.
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 1 "$@"
bench_build_dir "${1-$bench_checkout/build}"
cd "$bench_checkout"
GW=$B/granwave
PY=/usr/bin/python3
W=$B/bench-layer
NPT=${NPT:-4}
posint NPT "$NPT"
case "${ONLY:-}" in '' | speed) ;; *) bench_refuse "ONLY must be empty or 'speed', got '$ONLY'" ;; esac
mkdir -p "$W"
cmake --build "$B" --target granwave >/dev/null
now() { date +%s.%N; }
# run NAME CMD...: wall time into $W/NAME.t (s), CPU (user + sys of the children) into $W/NAME.cpu
run() {
    local name=$1; shift
    local t0; t0=$(now)
    /usr/bin/time -f "%U %S" -o "$W/$name.rus" "$@" >"$W/$name.log" 2>&1
    $PY -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$t0" "$(now)" >"$W/$name.t"
    awk '{print $1 + $2}' "$W/$name.rus" >"$W/$name.cpu"
}

echo "# bench_layer: $(date -u +%Y-%m-%dT%H:%MZ) on $(hostname), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "# granwave $("$GW" version | cut -d' ' -f2), $(mpirun --version 2>/dev/null | head -1)"
echo "# load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

# 1. sample
if [ ! -s "$W/sample300.txt" ]; then
    run make "$GW" layer-make --out "$W/sample300.txt"
    echo "sample: 300 discs made in $(cat "$W/make.t") s"
fi
grep -E '^(width|rm|n) ' "$W/sample300.txt" | tr '\n' ' '; echo

# 2-3. one core, threads, MPI
cat >"$W/speed.ini" <<CFG
[sweep]
model = layer
[grid]
point = 0:$((NPT - 1))
[params]
sample = $W/sample300.txt
points = $NPT
t-max = 0.05
CFG
mpi="mpirun --allow-run-as-root --oversubscribe"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$W"/sw_*
run serial "$GW" sweep "$W/speed.ini" --out "$W/sw_serial" --jobs 1 --quiet
run threads2 "$GW" sweep "$W/speed.ini" --out "$W/sw_threads2" --jobs 2 --quiet
run mpi2 $mpi -n 2 "$GW" sweep "$W/speed.ini" --out "$W/sw_mpi2" --quiet
run mpi3 $mpi -n 3 "$GW" sweep "$W/speed.ini" --out "$W/sw_mpi3" --quiet
run mpi3y $mpi --mca mpi_yield_when_idle 1 -n 3 "$GW" sweep "$W/speed.ini" --out "$W/sw_mpi3y" --quiet
for v in threads2 mpi2 mpi3 mpi3y; do
    cmp -s "$W/sw_serial/results.csv" "$W/sw_$v/results.csv" || echo "WARNING: $v table differs from the serial one"
done
$PY - "$W" "$NPT" <<'PY'
import sys
w, n = sys.argv[1], int(sys.argv[2])
t = {k: float(open("%s/%s.t" % (w, k)).read()) for k in ("serial", "threads2", "mpi2", "mpi3", "mpi3y")}
c = {k: float(open("%s/%s.cpu" % (w, k)).read()) for k in t}
label = {"serial": "1 thread", "threads2": "2 threads", "mpi2": "MPI 2 ranks (1 worker)",
         "mpi3": "MPI 3 ranks (2 workers)", "mpi3y": "MPI 3 ranks, yield_when_idle"}
print("default impact (R_b = R_m, V_i = 20 m/s, rk4), %d cases per run:" % n)
for k in t:
    print("  %-30s %7.2f s wall %7.2f s CPU  %6.3f cases/s  speed-up %.2f" % (label[k], t[k], c[k], n / t[k], t["serial"] / t[k]))
PY

if [ "${ONLY:-}" = speed ]; then echo "# load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"; exit 0; fi

# 4. per-case cost against R_b and H
echo "per-case cost (layer-impact, one core), wall s / CPU s / t_end s / bounced / mobile particles:"
for h in 4 12 25; do
    for rb in 0.5 3 10; do
        run "c_${rb}_$h" "$GW" layer-impact --sample "$W/sample300.txt" --rb-rm "$rb" --height-rm "$h" --t-max 0.05 --json
        $PY - "$W/c_${rb}_$h" "$rb" "$h" <<'PY'
import json, sys
p = sys.argv[1]
j = json.loads(open(p + ".log").read())
print("  R_b %4s R_m  H %3s R_m: %7.2f s  %7.2f s  t_end %.4f  bounced %d  mobile %3d  (%d steps)" % (
    sys.argv[2], sys.argv[3], float(open(p + ".t").read()), float(open(p + ".cpu").read()), j["t_end"],
    j["bounced"], j["n_mobile"], j["steps"]))
PY
    done
done

# 5. check pass of the full diagram's config
cat >"$W/diagram.ini" <<CFG
[sweep]
model = layer
[grid]
rb-rm = 0.5, 1, 1.5, 2, 3, 4, 6, 8, 10, 12
height-rm = 4, 6, 8, 10, 12, 15, 20, 25
point = 0:99
[params]
sample = $W/sample300.txt
points = 100
t-max = 0.05
CFG
run check "$GW" sweep "$W/diagram.ini" --out "$W/sw_diagram" --check
echo "sweep --check of the 8000-case diagram config: $(cat "$W/check.t") s ($(cat "$W/check.log"))"

# projections (bilinear interpolation of the measured cost in R_b and H)
$PY - "$W" <<'PY'
import sys
w = sys.argv[1]
rbs, hs = [0.5, 3, 10], [4, 12, 25]
cost = {(rb, h): float(open("%s/c_%s_%s.cpu" % (w, rb, h)).read()) for rb in rbs for h in hs}
def interp(x, xs):
    x = min(max(x, xs[0]), xs[-1])
    for i in range(len(xs) - 1):
        if x <= xs[i + 1]:
            return i, (x - xs[i]) / (xs[i + 1] - xs[i])
def c(rb, h):
    i, a = interp(rb, rbs)
    j, b = interp(h, hs)
    return ((1 - a) * (1 - b) * cost[rbs[i], hs[j]] + a * (1 - b) * cost[rbs[i + 1], hs[j]] +
            (1 - a) * b * cost[rbs[i], hs[j + 1]] + a * b * cost[rbs[i + 1], hs[j + 1]])
grid_rb = [0.5, 1, 1.5, 2, 3, 4, 6, 8, 10, 12]
grid_h = [4, 6, 8, 10, 12, 15, 20, 25]
per_point = sum(c(rb, h) for rb in grid_rb for h in grid_h)
total = 100 * per_point
t = {k: float(open("%s/%s.t" % (w, k)).read()) for k in ("serial", "threads2", "mpi2", "mpi3", "mpi3y")}
cpu = {k: float(open("%s/%s.cpu" % (w, k)).read()) for k in ("serial", "threads2")}
s_thr = t["serial"] / t["threads2"]
work = cpu["threads2"] / cpu["serial"]  # CPU time of the same cases, 2 threads against 1
cmax = max(c(rb, h) for rb in grid_rb for h in grid_h)
print("projection, paper's diagram (10 R_b in 0.5-12 R_m x 8 H in 4-25 R_m x 100 points = 8000 cases):")
print("  mean cost per case %.2f s CPU (interpolated), largest %.1f s" % (total / 8000, cmax))
print("  one core:                           %8.0f s = %6.1f h" % (total, total / 3600))
print("  2-core machine, 2 threads, idle:    %8.0f s = %6.1f h  (2 x one core; 2 threads used %.2f x the CPU time of 1)" % (total * work / 2, total * work / 2 / 3600, work))
print("  2-core machine, as measured now:    %8.0f s = %6.1f h  (measured 2-thread speed-up %.2f)" % (total / s_thr, total / s_thr / 3600, s_thr))
t64 = total / 63 + cmax
print("  64 MPI ranks (63 workers, 1 core each): %5.0f s = %6.2f h  (greedy bound: total/63 + largest case)" % (t64, t64 / 3600))
PY
echo "# load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
