#!/bin/bash
# granwave set-up: installs the missing Debian packages (non-interactive, only
# what is missing), configures and builds, then runs the chosen job.
#
#   ./setup.sh main   install + build + run the main job (Falcon study, figures)
#   ./setup.sh test   install + build (warnings are errors) + run every test, then
#                     again in an AddressSanitizer + UBSan build
#   ./setup.sh build  install + build only
#   ./setup.sh bench  install (with LAMMPS, the peer) + build + run the benchmarks:
#                     bench/run.sh, bench/rhs_vs_v01.sh, bench/falcon_vs_lsoda.sh,
#                     bench/run_peers.sh (measurements only, a few minutes)
#   ./setup.sh        the main job; ./setup.sh --help prints the usage. Any other
#                     argument (an empty one too) or a second one: exit 2, nothing done.
#
# Environment: BUILD_DIR (default build), RESULTS (default results/falcon),
# JOBS (build parallelism, a positive integer, default nproc). A relative BUILD_DIR
# or RESULTS given by the caller is taken from the caller's working directory (the
# defaults are in the checkout).
set -euo pipefail
usage="usage: setup.sh [main|test|build|bench]"
if [ $# -gt 1 ]; then
    echo "setup.sh: unexpected argument '$2' ($usage)" >&2
    exit 2
fi
# no argument is the main job; an argument given, even an empty one, must name a job
if [ $# -eq 0 ]; then mode=main; else mode=$1; fi
case "$mode" in
main | test | build | bench) ;;
-h | --help)
    echo "$usage (no argument: main); environment BUILD_DIR, RESULTS, JOBS"
    exit 0
    ;;
*)
    echo "setup.sh: unknown mode '$mode' ($usage)" >&2
    exit 2
    ;;
esac
case "${JOBS:-}" in '' ) ;; *[!0-9]* | 0*)
    echo "setup.sh: JOBS='$JOBS' is not a positive integer" >&2
    exit 2
    ;;
esac
caller=$PWD
abs() { case "$1" in /*) printf '%s' "$1" ;; *) printf '%s/%s' "$caller" "$1" ;; esac; }
[ -z "${BUILD_DIR:-}" ] || BUILD_DIR=$(abs "$BUILD_DIR")
[ -z "${RESULTS:-}" ] || RESULTS=$(abs "$RESULTS")
cd "$(dirname "$0")"
BUILD_DIR=${BUILD_DIR:-build}
RESULTS=${RESULTS:-results/falcon}
JOBS=${JOBS:-$(nproc)}

packages=(build-essential cmake pkg-config libsundials-dev libgsl-dev libfftw3-dev
          libhdf5-dev libcjson-dev libinih-dev libopenmpi-dev openmpi-bin python3-numpy python3-scipy python3-matplotlib python3-h5py
          jupyter-nbconvert python3-ipykernel python3-pytest clang libclang-rt-14-dev valgrind strace)

install_missing() {
    local missing=()
    for p in "${packages[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    if [ ${#missing[@]} -eq 0 ]; then
        echo "setup: all ${#packages[@]} Debian packages present"
        return
    fi
    echo "setup: installing ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@"
    cmake --build "$BUILD_DIR" -j "$JOBS"
}
# (a later -DCMAKE_BUILD_TYPE in "$@" overrides the Release default)

case "$mode" in
main)
    install_missing
    build
    "$BUILD_DIR/granwave" falcon --out "$RESULTS"
    # the figures from the Python module (the same study; equal to the files to 1e-10)
    GRANWAVE="$BUILD_DIR/granwave" MPLBACKEND=Agg /usr/bin/python3 notebooks/plot_falcon.py --module "$RESULTS"
    echo "setup: report $RESULTS/report.md, figures $RESULTS/figures/"
    ;;
test)
    install_missing
    build -DGW_WERROR=ON
    (cd "$BUILD_DIR" && ctest --output-on-failure -j 2)
    # the C unit tests (label "unit") again under AddressSanitizer + UBSan,
    # leaks included, plus the program's input-handling tests (the CLI refusals
    # and the CLI property test: no sanitizer report on any hostile value)
    echo "setup: sanitizer build ($BUILD_DIR-asan)"
    BUILD_DIR="$BUILD_DIR-asan" build -DGW_WERROR=ON -DGW_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug
    src=$PWD
    cd "$BUILD_DIR-asan"
    export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    export LSAN_OPTIONS="suppressions=$src/tests/lsan.supp:print_suppressions=0"
    ctest --output-on-failure -j 2 -L unit
    ctest --output-on-failure -R 'test_chain_cli|test_chain_sheets|test_cli_refusals|test_cli_property|test_hostile_layer|test_hostile_chain$|test_hostile_outputs'
    # and the sweep's input, config and journal handling (never in this list
    # before; their mpirun parts skip themselves here, as LeakSanitizer reports
    # Open MPI's own allocations), and test_journal_window (its journal checks
    # inside a row's write, the move shim preloaded after the sanitizer's
    # runtime; its sweeps of 6 to 36 beads since session 43: it took 518 s
    # here with its old 150-bead reference sweep). The long ones stay
    # release-only: the hostile sweep passes (test_hostile_sweeps*, test_sweep,
    # test_layer_sweep, not run here).
    ctest --output-on-failure -R '^(test_sweep_inputs_out|test_sweep_journal_format|test_sweep_journal_build|test_sweep_error_prefix|test_sweep_config_comment|test_sweep_config_paths|test_settling_sweep|test_sweep_check_journal|test_sweep_params_some|test_journal_window)$'
    ;;
build)
    install_missing
    build
    ;;
bench)
    packages+=(lammps)
    install_missing
    build
    LONG_ARGS=${LONG_ARGS:---nmax 100000 --reps 1 --rounds 2 --bdf-max 10000} bench/run.sh "$BUILD_DIR"
    bench/rhs_vs_v01.sh 7 "$BUILD_DIR"
    bench/falcon_vs_lsoda.sh "$BUILD_DIR" 7
    bench/run_peers.sh "$BUILD_DIR"
    ;;
esac
