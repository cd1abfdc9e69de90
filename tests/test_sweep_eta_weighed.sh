#!/usr/bin/env bash
# test_sweep_eta_weighed.sh: `granwave sweep`'s time left weighs its cases by
# their cost (issue 18). The part of the work on a sweep's progress line
# counted its cases alike: a chain sweep of 25 short columns (n = 1 to 25)
# then a long one (n = 250, most of the sweep's time) said 96 % or more of
# the work done, and a time left of a twenty-fifth of the time elapsed, for
# the whole run of its last case. Each case is now weighed before it runs
# (a chain case by its beads times its steps and samples over its expected
# length, as a study's collisions are), the part is the weight done over the
# whole (on one thread), and under mpirun rank 0 counts the cases its ranks
# report done by the same weights (it took the rate at which cases ended).
# On --jobs 1: the first line while the long case runs (25/26 cases, 1 under
# way) says under 90 % of the work (about 20 to 60 % now); under mpirun -np 2
# (where installed; not in a sanitizer build) the first line with 25 cases
# ended gives a time left above a quarter of the time elapsed (0.04 before).
# The table is the same either way. The runs read a clock that counts its
# reads (tests/clock_shim.c, the test's third argument; GW_CLOCK_STEP_MS=20000:
# 20 s a read, so that every case's end is past the line's gap, at most 30 s),
# so the line with 25 cases ended comes as the 25th case ends, on any
# machine, and the long case need not outlast the display's 2 s: n = 100
# (n = 250 and the wall's clock without the shim: with 150 the sweep ended in
# 1.6 s on an idle machine, before its first progress line at 2 s, and the
# test failed there). About 2 s with the shim (10 s without); 2 of its 3
# checks fail on the code before (1 of 1 without mpirun).
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

# the clock that counts its reads (tests/clock_shim.c), when given: clock
# runs a command under it (env alone without it)
clock_shim=$(shim_path "${3:-}" clock) || clock_shim=
long=250
clock=(env)
if [ -n "$clock_shim" ]; then
    long=100
    clock=(env GW_CLOCK_STEP_MS=20000 LD_PRELOAD="$(preload_list "$clock_shim")")
else
    echo "NOTE: no clock shim: the progress lines waited for by the wall's clock"
fi
cat >s.ini <<EOF
[sweep]
model = chain
[grid]
n = 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, $long
[params]
vimp = 0.3
EOF

# the first line with 25 of the 26 cases ended: "P E L" (L empty: none)
first_line() {
    awk 'match($0, /^sweep: 25\/26 cases/) {
             p = ""; e = ""; l = ""
             if (match($0, /[0-9.]+% of the work/)) p = substr($0, RSTART, RLENGTH - 13)
             if (match($0, /[0-9.]+ s elapsed/)) e = substr($0, RSTART, RLENGTH - 10)
             if (match($0, /~[0-9.]+ s left/)) l = substr($0, RSTART + 1, RLENGTH - 8)
             print p, e, l; exit
         }' "$1"
}

"${clock[@]}" "$GW" sweep s.ini --out o1 --jobs 1 >/dev/null 2>e1.txt
rc=$?
read -r p e l <<<"$(first_line e1.txt)"
if [ $rc -eq 0 ] && [ -n "$p" ] && awk -v p="$p" 'BEGIN { exit !(p < 90) }'; then
    ok "--jobs 1: the first line while the long case runs says $p % of the work (below 90 %: weighed)"
else
    ko "--jobs 1: exit $rc, the first line with 25/26 cases ended: '$(grep -m1 '^sweep: 25/26' e1.txt)' (96 % or more: the cases alike)"
fi

if ! command -v mpirun >/dev/null; then
    echo "SKIP: mpirun not installed"
elif ! (ulimit -v 1700000; "$GW" --help >/dev/null 2>&1); then
    echo "SKIP: mpirun checks in a sanitizer build"
else
    timeout -s KILL 120 mpirun --allow-run-as-root --oversubscribe -np 2 "${clock[@]}" "$GW" sweep s.ini --out o2 >/dev/null 2>e2.txt </dev/null
    rc=$?
    read -r p e l <<<"$(first_line e2.txt)"
    if [ $rc -eq 0 ] && [ -n "$l" ] && [ -n "$e" ] && awk -v e="$e" -v l="$l" 'BEGIN { exit !(l > 0.25 * e) }'; then
        ok "under mpirun -np 2: the first line with 25 cases ended gives $l s left at $e s elapsed (above a quarter: weighed)"
    else
        ko "under mpirun -np 2: exit $rc, '$(grep -m1 '^sweep: 25/26' e2.txt)' (a twenty-fifth of the time elapsed: the rate of the cases)"
    fi
    if [ $rc -eq 0 ] && cmp -s o1/results.csv o2/results.csv; then
        ok "under mpirun -np 2: the table is the one of --jobs 1"
    else
        ko "under mpirun -np 2: the tables differ (exit $rc)"
    fi
fi

test_summary
