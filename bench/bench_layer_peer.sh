#!/bin/bash
# bench/bench_layer_peer.sh [BUILD_DIR]: granwave's layer impact (docs/physics.md 2.3)
# against its LAMMPS peer (bench/peer_lammps_layer.py) and against a minimal
# fixed-list DEM step (bench_dem_min). Measurement only, never pass/fail.
#   a. the default 300-disc sample (granwave layer-make, made once and kept in
#      BUILD_DIR/bench-peer/sample300.txt);
#   b. the LAMMPS force-law verification (binary and wall collisions against
#      the Hertz contact time, tangential stiffness at rest);
#   c. REPS repetitions, alternating granwave / LAMMPS, of two impacts:
#        1. R_b = R_m, 20 m/s, normal, x = 0: granwave's defaults with
#           --t-max 0.05 (the default before issue 18, kept for comparable
#           numbers; the default is 2 s, to T_f); LAMMPS
#           simulates granwave's t_end of the same repetition (plus at most
#           2 ms to settle the outcome with granwave's stopping rule);
#        3. R_b = 3 R_m, both over 0.1 s (granwave --t-max 0.1 --full);
#      CPU time (user + sys) of each process and the processes it waited for,
#      from getrusage(RUSAGE_CHILDREN) in microseconds (cpu_run below;
#      /usr/bin/time's 10 ms steps are 10 % of granwave's 0.1 s runs);
#   d. bench_dem_min (velocity Verlet at 1e-5 s and RK4 at 1e-6 s, ns per
#      disc-step, fixed contact list), once inside each repetition of c (the
#      bound beside its impacts: a load that comes and goes falls on both)
#      and once at the end for its checks;
#   e. a table: median CPU s, ratio granwave / LAMMPS, cost per disc-step
#      (CPU / (discs x steps), discs = sample + block; granwave's steps from
#      its --json "steps") over the bound (of the medians, and the median of
#      each repetition's own ratio), and both codes' e_n, bounced, penetration.
# granwave runs with its program defaults plus GW_FLAGS (e.g. GW_FLAGS="--exact"
# or "--solver rk4"): the script works with any granwave binary.
# Environment: REPS (3), GW_FLAGS (empty), LMP (LAMMPS binary, default lmp),
# DEM_STEPS (bench_dem_min steps per repetition, 1000), DEM_REPS (9).
# The machine may be shared: compare the ratios of this run, not the seconds.
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 1 "$@"
bench_build_dir "${1-$bench_checkout/build}"
bench_path_var LMP
cd "$bench_checkout"
GW=$B/granwave
PY=/usr/bin/python3
W=$B/bench-peer
REPS=${REPS:-3}
GW_FLAGS=${GW_FLAGS:-}
LMP=${LMP:-$(command -v lmp || true)}
DEM_STEPS=${DEM_STEPS:-1000}
DEM_REPS=${DEM_REPS:-9}
posint REPS "$REPS"
posint DEM_STEPS "$DEM_STEPS"
posint DEM_REPS "$DEM_REPS"
[ -n "$LMP" ] || bench_refuse "no LAMMPS binary (Debian package lammps: lmp); set LMP"
command -v "$LMP" >/dev/null || bench_refuse "LMP '$LMP' is not an executable"
mkdir -p "$W"
cmake --build "$B" --target granwave bench_dem_min >/dev/null
S=$W/sample300.txt

echo "# bench_layer_peer: $(date -u +%Y-%m-%dT%H:%MZ) on $(hostname), $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "# granwave $("$GW" version | cut -d' ' -f2) ($B), LAMMPS $("$LMP" -h | sed -n 's/.*Simulator - \(.*\)$/\1/p' | head -1)"
echo "# GW_FLAGS='$GW_FLAGS' REPS=$REPS; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"

# a. sample
if [ ! -s "$S" ]; then
    echo "+ $GW layer-make --out $S"
    "$GW" layer-make --out "$S" >"$W/make.log"
fi
grep -E '^(width|rm|mass_law|n) ' "$S" | tr '\n' ' '; echo

# b. LAMMPS verification
echo
echo "== LAMMPS force law: + $PY bench/peer_lammps_layer.py --lmp $LMP --verify"
"$PY" bench/peer_lammps_layer.py --lmp "$LMP" --verify

# c. impacts, alternating granwave / LAMMPS
# shellcheck disable=SC2206
gwflags=($GW_FLAGS)
# --zero-springs: the LAMMPS data file carries no tangential springs, so
# granwave starts from none either (the sample's springs section, which
# layer-make writes, is skipped by the peer's reader)
gw_args_1=(layer-impact --sample "$S" --t-max 0.05 --zero-springs --json)
gw_args_3=(layer-impact --sample "$S" --rb-rm 3 --t-max 0.1 --full --zero-springs --json)
echo
echo "== impacts, $REPS repetitions, alternating granwave / LAMMPS; commands:"
echo "   granwave case 1: $GW ${gw_args_1[*]} ${gwflags[*]:-}"
echo "   lammps   case 1: $PY bench/peer_lammps_layer.py --lmp $LMP --sample $S --t-end T_END"
echo "                    (T_END = granwave's t_end of the same repetition)"
echo "   granwave case 3: $GW ${gw_args_3[*]} ${gwflags[*]:-}"
echo "   lammps   case 3: $PY bench/peer_lammps_layer.py --lmp $LMP --sample $S --rb-rm 3 --t-end 0.1 --full"
rm -f "$W"/gw_*.json "$W"/lmp_*.txt "$W"/*.rus
# cpu_run FILE CMD...: run CMD (stdout and stderr as given) and write its user
# and system CPU seconds to FILE
cpu_run() {
    "$PY" -c 'import resource, subprocess, sys
rc = subprocess.run(sys.argv[2:]).returncode
u = resource.getrusage(resource.RUSAGE_CHILDREN)
open(sys.argv[1], "w").write("%.6f %.6f\n" % (u.ru_utime, u.ru_stime))
sys.exit(rc)' "$@"
}
for rep in $(seq 1 "$REPS"); do
    for c in 1 3; do
        if [ "$c" = 1 ]; then args=("${gw_args_1[@]}"); else args=("${gw_args_3[@]}"); fi
        cpu_run "$W/gw_${c}_$rep.rus" "$GW" "${args[@]}" "${gwflags[@]}" \
            >"$W/gw_${c}_$rep.json"
        if [ "$c" = 1 ]; then
            tend=$("$PY" -c "import json, sys; print(json.load(open(sys.argv[1]))['t_end'])" "$W/gw_1_$rep.json")
            largs=(--t-end "$tend")
        else
            largs=(--rb-rm 3 --t-end 0.1 --full)
        fi
        cpu_run "$W/lmp_${c}_$rep.rus" "$PY" bench/peer_lammps_layer.py --lmp "$LMP" \
            --sample "$S" "${largs[@]}" >"$W/lmp_${c}_$rep.txt"
        echo "   rep $rep case $c: granwave $(awk '{print $1 + $2}' "$W/gw_${c}_$rep.rus") s CPU," \
             "lammps $(awk '{print $1 + $2}' "$W/lmp_${c}_$rep.rus") s CPU"
    done
    # the bound in the same repetition, so that a load that comes and goes
    # falls on the bound as on the impacts (the x bound of each pair)
    "$B/bench/bench_dem_min" "$S" --steps "$DEM_STEPS" --reps "$DEM_REPS" >"$W/dem_min_$rep.txt"
done

# d. the minimal DEM step
echo
echo "== bound: + $B/bench/bench_dem_min $S --steps $DEM_STEPS --reps $DEM_REPS"
"$B/bench/bench_dem_min" "$S" --steps "$DEM_STEPS" --reps "$DEM_REPS" | tee "$W/dem_min.txt"

# e. table
echo
"$PY" - "$W" "$REPS" <<'PY'
import json, statistics, sys
w, reps = sys.argv[1], int(sys.argv[2])
cpu = lambda p: sum(float(v) for v in open(p).read().split())
def bounds(path):
    b = {}
    for line in open(path):
        if line.startswith("BOUND "):
            b[line.split()[1]] = float(line.split()[2])
    return b
bound = bounds(w + "/dem_min.txt")
# the verlet bound measured inside each repetition, beside its impacts
rep_bound = [bounds("%s/dem_min_%d.txt" % (w, r)).get("verlet", float("nan")) for r in range(1, reps + 1)]
names = {1: "R_b = R_m, 20 m/s", 3: "R_b = 3 R_m, 0.1 s"}
def num(v):  # e_n is null (undecided) when a run ends before T_f (docs/outcomes.md)
    return "%.4f" % v if isinstance(v, (int, float)) else "undecided"
print("impact               code      CPU s (median; all)            ratio gw/lmp  steps    ns/disc-step  x bound (pairs)  e_n        bounced  penetration m")
for c in (1, 3):
    g = [json.load(open("%s/gw_%d_%d.json" % (w, c, r))) for r in range(1, reps + 1)]
    l = []
    for r in range(1, reps + 1):
        for line in open("%s/lmp_%d_%d.txt" % (w, c, r)):
            if line.startswith("OUTCOME "):
                l.append(json.loads(line[8:]))
    gc = [cpu("%s/gw_%d_%d.rus" % (w, c, r)) for r in range(1, reps + 1)]
    lc = [cpu("%s/lmp_%d_%d.rus" % (w, c, r)) for r in range(1, reps + 1)]
    gm, lm = statistics.median(gc), statistics.median(lc)
    discs = l[0]["discs"]  # sample + block, the same for both codes
    gsteps = statistics.median(j["steps"] for j in g)
    lsteps = statistics.median(o["steps"] + o["steps_settle"] for o in l)
    # the ratio of the medians, and the median of the ratios of the alternating pairs
    pairs = statistics.median(a / b for a, b in zip(gc, lc))
    for code, m, allc, steps, o, runs in (("granwave", gm, gc, gsteps, g[-1], [(cc, j["steps"]) for cc, j in zip(gc, g)]),
                                          ("lammps", lm, lc, lsteps, l[-1],
                                           [(cc, q["steps"] + q["steps_settle"]) for cc, q in zip(lc, l)])):
        ns = 1e9 * m / (discs * steps)
        # each repetition's cost per disc-step over the bound measured in that repetition
        xb = statistics.median(1e9 * cc / (discs * st) / rb for (cc, st), rb in zip(runs, rep_bound))
        print("%-20s %-9s %8.3f (%-20s) %12s %8d %12.1f %8.2f (%.2f)  %-9s  %-7s  %.4f" % (
            names[c], code, m, " ".join("%.3g" % v for v in allc),
            "%.2f (%.2f)" % (gm / lm, pairs) if code == "granwave" else "",
            steps, ns, ns / statistics.median(rep_bound), xb, num(o["e_n"]),
            "undecided" if o["bounced"] is None else str(bool(o["bounced"])).lower(),
            o["penetration"]))
print("bench_dem_min bound (fixed list, %s): verlet %.1f ns/disc-step (dt 1e-5 s), rk4 %.1f ns/disc-step (dt 1e-6 s);"
      " verlet in the repetitions: median %.1f (%s)" % (
    "sample + block", bound.get("verlet", float("nan")), bound.get("rk4", float("nan")), statistics.median(rep_bound),
    " ".join("%.1f" % v for v in rep_bound)))
print("ratio: of the medians (median of the %d pairwise ratios); x bound: ns/disc-step over bench_dem_min's verlet"
      " measured in the repetitions (median of each repetition's own ratio)" % reps)
print("granwave's CPU is the whole process (sample read, set-up, solver, recording every 2e-5 s, crowns, JSON);")
print("LAMMPS's is python + lmp (input writing, set-up, run, trace parsing). Steps: granwave's --json 'steps';")
print("LAMMPS's steps include those run past t_end to settle the outcome (case 1).")
PY
echo "# load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
