#!/bin/bash
# bench/run.sh [BUILD_DIR]: build and run the benchmarks; prints measurements only.
set -euo pipefail
cd "$(dirname "$0")/.."
B=${1:-build}
cmake --build "$B" --target bench_chain >/dev/null
"$B/bench/bench_chain"
