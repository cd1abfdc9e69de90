#!/bin/bash
# bench/run.sh [BUILD_DIR]: build and run the benchmarks; prints measurements only.
#   bench_chain  RHS cost against a force-only loop and a flop-count bound,
#                per-backend cost on the 40-bead column
#   bench_long   1e3 .. 1e6 beads: ns per bead-step and peak RSS per backend
#                and its ratio to rk4 per step (LONG_ARGS, e.g. "--nmax 100000
#                --reps 1 --rounds 4": backends in turn, best of each)
# Not run here: bench_falcon_accuracy (the convergence study behind the falcon
# main job's RK4 step), bench/falcon_vs_lsoda.sh (falcon main job CPU against
# 3 SciPy LSODA collisions). Peers (SciPy, LAMMPS) and time to solution:
# bench/run_peers.sh. The RHS against v0.1's library, alternating: bench/rhs_vs_v01.sh.
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 1 "$@"
bench_build_dir "${1-$bench_checkout/build}"
cd "$bench_checkout"
cmake --build "$B" --target bench_chain bench_long >/dev/null
"$B/bench/bench_chain"
echo
# shellcheck disable=SC2086
"$B/bench/bench_long" ${LONG_ARGS:-}
