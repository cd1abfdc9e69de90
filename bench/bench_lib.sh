#!/bin/bash
# bench_lib.sh: sourced by the bench scripts, first thing, before they change to the
# checkout (`. "$(dirname "$0")/bench_lib.sh"`), so that it sees the caller's directory.
# Each refusal is one line naming the script, exit 2, before any work.
#   bench_args MAX "$@": -h or --help prints the script's usage line (its second
#     line) and exits 0; more than MAX arguments are refused.
#   bench_build_dir VALUE: sets B to the build directory, absolute. A relative VALUE
#     is taken from the caller's working directory, as setup.sh takes BUILD_DIR; the
#     scripts' default is the checkout's build/. Refused: an empty VALUE, a directory
#     without CMakeCache.txt (not configured: ./setup.sh build).
#   bench_path_var NAME: a relative path in the variable NAME (one with a '/', e.g.
#     LMP=./lmp) is made absolute from the caller's directory; a bare command name
#     is left to the PATH.
#   posint NAME VALUE: refuse anything but a positive integer.
bench_caller=$PWD
# shellcheck disable=SC2034 # (used by the scripts that source this file)
bench_checkout=$(cd "$(dirname "$0")/.." && pwd)
bench_refuse() {
    echo "$(basename "$0"): $*" >&2
    exit 2
}
bench_args() {
    local max=$1
    shift
    case "${1:-}" in -h | --help)
        awk 'NR > 1 { if (!/^#/) exit; sub(/^# ?/, ""); print }' "$0"
        exit 0
        ;;
    esac
    if [ $# -gt "$max" ]; then
        shift "$max"
        bench_refuse "unexpected argument '$1' (usage: $(sed -n '2s/^# \([^:]*\):.*/\1/p' "$0"))"
    fi
}
bench_build_dir() {
    local d=$1
    case "$d" in
    '') bench_refuse "BUILD_DIR is empty" ;;
    /*) ;;
    *) d=$bench_caller/$d ;;
    esac
    [ -f "$d/CMakeCache.txt" ] ||
        bench_refuse "BUILD_DIR '$d' is not a configured build directory (no CMakeCache.txt; ./setup.sh build makes one)"
    # shellcheck disable=SC2034 # (B is the sourcing script's)
    B=$(cd "$d" && pwd -P)
}
bench_path_var() {
    local v=${!1:-}
    case "$v" in /* | '') ;; */*) printf -v "$1" '%s/%s' "$bench_caller" "$v" ;; esac
}
posint() {
    case "$2" in '' | *[!0-9]* | 0*)
        bench_refuse "$1 must be a positive integer, got '$2'"
        ;;
    esac
}
