#!/bin/bash
# bench/rhs_vs_v01.sh [PAIRS] [BUILD_DIR]: the chain right-hand side against v0.1's.
#
# Builds bench_chain.c (today's source, public API only) against the library of
# v0.1 (commit V01 below, the last one before the speed work) in a temporary git
# worktree, then runs the old and today's bench_chain alternately PAIRS times
# (default 7) in "rhs" mode and prints, per chain length, the median ns per bead
# of each, the ratio of the medians and the range of the pairwise ratios.
# Same harness, same machine, same run: only the library differs. Prints
# measurements, never a pass/fail verdict. Needs a git clone (for the history).
set -euo pipefail
# shellcheck source=bench/bench_lib.sh
. "$(dirname "$0")/bench_lib.sh" # (before the cd: it records the caller's directory)
bench_args 2 "$@"
PAIRS=${1-7}
posint PAIRS "$PAIRS"
bench_build_dir "${2-$bench_checkout/build}"
cd "$bench_checkout"
V01=024eb8d
if ! git rev-parse --verify -q "$V01^{commit}" >/dev/null 2>&1; then
    echo "rhs_vs_v01.sh: commit $V01 (v0.1) is not in this checkout; run from a git clone" >&2
    exit 2
fi
WT=$(mktemp -d /tmp/gw-v01.XXXXXX)
OUT=$(mktemp /tmp/gw-v01-runs.XXXXXX)
cleanup() {
    git worktree remove --force "$WT" >/dev/null 2>&1 || rm -rf "$WT"
    rm -f "$OUT"
}
trap cleanup EXIT
git worktree add -q --detach "$WT" "$V01"
cp bench/bench_chain.c "$WT/bench/bench_chain.c"
cmake -S "$WT" -B "$WT/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$WT/build" -j2 --target bench_chain >/dev/null
cmake --build "$B" --target bench_chain >/dev/null
OLD="$WT/build/bench/bench_chain"
NEW="$B/bench/bench_chain"
rows() { # label binary: the first table's rows from 1e3 beads up
    "$2" 2000 rhs | awk -v w="$1" '/^3\./ { exit } $1 ~ /^[0-9]+$/ && $1 >= 1000 { print w, $1, $2 }'
}
for _ in $(seq "$PAIRS"); do
    rows old "$OLD" >>"$OUT"
    rows new "$NEW" >>"$OUT"
done
echo "chain RHS, ns per bead per evaluation: v0.1 ($V01) against $(git rev-parse --short HEAD)," \
    "$PAIRS alternating pairs (bench_chain 2000 rhs, thread CPU time), load: $(cut -d' ' -f1-3 /proc/loadavg)"
awk '
{ v[$1, $2, ++k[$1, $2]] = $3; n[$2] = 1 }
function med(a, m,    i, j, t, b) {
    for (i = 1; i <= m; i++) b[i] = a[i]
    for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (b[j] < b[i]) { t = b[i]; b[i] = b[j]; b[j] = t }
    return m % 2 ? b[(m + 1) / 2] : (b[m / 2] + b[m / 2 + 1]) / 2
}
END {
    printf "%10s %10s %10s %9s %15s %18s\n", "beads", "v0.1", "today", "speed-up", "pairwise median", "pairwise min-max"
    for (s in n) sizes[++ns] = s + 0
    for (i = 1; i <= ns; i++) for (j = i + 1; j <= ns; j++) if (sizes[j] < sizes[i]) { t = sizes[i]; sizes[i] = sizes[j]; sizes[j] = t }
    for (i = 1; i <= ns; i++) {
        s = sizes[i]; m = k["old", s]; lo = 1e9; hi = 0
        for (p = 1; p <= m; p++) {
            o[p] = v["old", s, p]; w[p] = v["new", s, p]; r[p] = o[p] / w[p]
            if (r[p] < lo) lo = r[p]
            if (r[p] > hi) hi = r[p]
        }
        printf "%10d %10.3f %10.3f %8.2fx %14.2fx %11.2f-%.2f\n", s, med(o, m), med(w, m), med(o, m) / med(w, m), med(r, m), lo, hi
    }
}' "$OUT"
