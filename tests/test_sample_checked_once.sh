#!/bin/bash
# test_sample_checked_once.sh GRANWAVE SRCDIR: a layer impact takes the
# shared sample check once (issue 18). Every call that takes a sample holds
# it to the reader's limits through one O(n) check (layer_sample_limits_check,
# or layer_sample_shape_check, its GW_EINVAL form; its overlap grid built each
# time). The run took it through each public check it called:
# gw_layer_impact_check, gw_layer_impact_gap_check, gw_layer_impact_dem_dt
# (which took gw_layer_impact_check again) and the settling's check, in the
# plan (the setup's resolution) and again in the run, besides the reader's:
# 7 times a layer-impact run, 12 a sweep's check pass of 5 impact points on
# one sample (each case's resolution 2), 52 a sweep of those 5 cases. The
# rules of those checks now have internal forms that take a checked sample
# (layer_impl.h); the public calls still check first. A plan's sample is the
# reader's, checked when read; gw_layer_impact checks once. Observed from
# outside: the times the program enters the check, counted by valgrind's
# callgrind (no counter in the library; SKIP without valgrind, in a
# sanitizer build, or where the calls cannot be counted):
#  1 a layer-impact run: 1 (the reader's), 7 before;
#  2 sweep --check over 5 and 10 impact points on one sample: 2 each (the
#    reader's and the pile's hash), 12 and 22 before;
#  3 a sweep of the 5 cases on one thread: only the reader's (one a case, and
#    the check pass's and the scheduler's reads) and the pile hash's: 8, 52
#    before.
# That the check still refuses what it refused, with the same message from
# every call, is test_library_hostile43's (the walls' 0.01 r and 0.03 r rows).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"

make_sample s.txt --n 40 --seed 1

# checks CMD...: "TOTAL CALLER:N ..." the times CMD enters the shared check
# (from outside it: layer_sample_shape_check calls layer_sample_limits_check),
# by caller; empty when valgrind could not run it
checks() {
    local e
    e=$(callgrind_edges "$@") || return
    awk '$2 ~ /^layer_sample_(limits|shape)_check$/ && $1 !~ /^layer_sample_(limits|shape)_check$/ { c[$1] += $3; t += $3 }
         END { s = t + 0; for (k in c) s = s " " k ":" c[k]; print s }' <<<"$e"
}
# ini FILE POINTS: a layer sweep over POINTS impact points on s.txt
ini() {
    printf '[sweep]\nmodel = layer\n[grid]\nsample = s.txt\npoint = 0:%d\n[params]\nt-max = 1e-4\npoints = %d\nspacing = 0.05\n' \
        $(($2 - 1)) "$2" >"$1"
}
ini p5.ini 5
ini p10.ini 10

base=""
command -v valgrind >/dev/null 2>&1 && ! sanitizer_build &&
    base=$(checks layer-impact --sample s.txt --t-max 1e-4 --out "$tmp/li")
if [ -z "$base" ] || [ "${base%% *}" -lt 1 ]; then
    echo "SKIP: the calls cannot be counted here (valgrind: ${base:-absent, or it could not run the program})"
else
    # --- 1 a layer-impact run
    [ "${base%% *}" = 1 ] && ok "layer-impact: the sample checked once ($base)" ||
        ko "layer-impact: the sample checked ${base%% *} times, want 1 ($base)"
    # --- 2 the check pass: no more checks for more cases
    for c in "p5.ini|5" "p10.ini|10"; do
        f=${c%%|*} n=${c#*|}
        rm -rf "$tmp/o"
        got=$(checks sweep "$f" --out "$tmp/o" --check)
        [ "${got%% *}" = 2 ] && ok "sweep --check, $n points: the sample checked twice, read and hashed ($got)" ||
            ko "sweep --check, $n points: the sample checked ${got%% *} times, want 2 ($got)"
    done
    # --- 3 the sweep: the reads and the pile's hash only
    rm -rf "$tmp/o"
    got=$(checks sweep p5.ini --out "$tmp/o" --jobs 1)
    other=$(tr ' ' '\n' <<<"${got#* }" | grep -vE '^(gw_layer_sample_read|layer_sample_pile_hash):' | tr '\n' ' ')
    [ -n "$got" ] && [ -z "${other// /}" ] && [ "${got%% *}" -le 8 ] &&
        ok "sweep, 5 cases: the sample checked ${got%% *} times, by its reads and its hash ($got)" ||
        ko "sweep, 5 cases: the sample checked ${got%% *} times, want the reads (7) and the hash (1) alone ($got)"
fi

test_summary test_sample_checked_once
