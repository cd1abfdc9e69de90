#!/bin/bash
# test_printed_bounds.sh GRANWAVE SRCDIR: the bounds the settling check and
# the sample checks print (gw_num_bound, not %g) are values they take.
#  1 A pile settled at --friction 30.0000001 and run at --friction 20 was
#    refused with "give the settling's friction (30 deg) or more", and
#    --friction 30, as printed, was refused again (its friction coefficient
#    4e-9 below the settling's). The bound given back is now taken: the run
#    exits 0 (with its warning), and the refusal names the settling's own
#    friction (it said "friction 30 deg against the impact's 20").
#  2 The sample checks' bounds (a radius outside [1e-3, 1e3] R_m, rm outside
#    [1e-5, 1000] m): each bound printed, given back in the sample, is taken
#    (the bounds are exact in %g too: controls).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 the settling's friction ---
make_sample f.txt --n 20 --width-rm 8 --friction 30.0000001
if exits_refused "layer-impact: a pile settled at 30.0000001 deg run at 20 deg" \
    "^granwave layer-impact: sample 'f\\.txt': it settled with friction 30\\.0000001 deg against the impact's 20 .*give the settling's friction \\([^ ]+ deg\\) or more" \
    20 "$GW" layer-impact --sample f.txt --friction 20 --out o; then
    ok "layer-impact at 20 deg refused naming the settling's 30.0000001 deg"
fi
bound=$(sed -n "s/.*give the settling's friction (\\([^ ]*\\) deg) or more.*/\\1/p" "$tmp/stderr")
timeout -s KILL 60 "$GW" layer-impact --sample f.txt --friction "$bound" --t-max 0.001 --out o1 \
    >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc = 0 ] && ok "the friction printed as the bound ($bound deg) is taken" ||
    ko "--friction $bound, the printed bound: exit $rc ($(head -c 300 "$tmp/stderr"))"

# --- 2 the sample checks' bounds ---
make_sample s.txt --n 20 --width-rm 8
# the first particle's radius made 1e4 R_m: its range's upper end, given back
rm_line=$(grep -m1 -E '^rm ' s.txt)
rmv=${rm_line#rm }
awk -v big="$(awk -v r="$rmv" 'BEGIN { printf "%.17g", r * 1e4 }')" \
    'done == 0 && NF == 3 && $1 ~ /^[0-9.e+-]+$/ { $3 = big; done = 1 } { print }' s.txt >big.txt
timeout -s KILL 60 "$GW" layer-impact --sample big.txt --out o >/dev/null 2>"$tmp/stderr" </dev/null
hi=$(sed -n 's/.*radius [^ ]* m is outside \[\([^,]*\), \([^]]*\)\] R_m.*/\2/p' "$tmp/stderr")
if [ -n "$hi" ]; then
    ok "a radius of 1e4 R_m refused naming the range's upper end ($hi R_m)"
    awk -v big="$(awk -v r="$rmv" -v h="$hi" 'BEGIN { printf "%.17g", r * h }')" \
        'done == 0 && NF == 3 && $1 ~ /^[0-9.e+-]+$/ { $3 = big; done = 1 } { print }' s.txt >hi.txt
    timeout -s KILL 60 "$GW" layer-impact --sample hi.txt --out o >/dev/null 2>"$tmp/stderr" </dev/null
    grep -q "radius .* is outside" "$tmp/stderr" &&
        ko "a radius of $hi R_m, the printed bound, is refused as outside ($(head -c 300 "$tmp/stderr"))" ||
        ok "a radius of $hi R_m, the printed bound, is not refused by the range"
else
    ko "a radius of 1e4 R_m: no range named ($(head -c 300 "$tmp/stderr"))"
fi

test_summary test_printed_bounds
