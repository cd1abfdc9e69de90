#!/bin/bash
# test_left48.sh GRANWAVE SRCDIR: what the forty-eighth pass left, asserted
# through the program.
#  3 A range-valued option (falcon, wavespeed, softwall --n A:B) refused
#    '1:3:1' as "'3:1' is not an integer", quoting a fragment: the refusal now
#    quotes the whole value given and the form a range takes (A:B, A <= B),
#    then the end's own reason (gw_parse_int_range, which every range option
#    of the program and of a sweep's configuration reads through).
#  4 `layer-impact --alpha 89.9` (20 m/s) was refused naming --vi only: the
#    incidence is the driver of the normal speed. The refusal names the
#    incidence and the largest one that runs, and that one runs (exit 0) while
#    one 1e-4 deg above it is refused.
#  5 layer-make's text output printed a raw newline of an --out name holding
#    one ("written to s<newline>t.txt"): every path the program echoes goes
#    through gw_one_line (gw_cli_path), the name printed s\nt.txt on one line.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 3 a range option's refusal quotes the whole value and the form A:B ---
refused "falcon --n 1:3:1" "^granwave falcon --n: '1:3:1' is not a range A:B of integers, A <= B" falcon --n 1:3:1
refused "wavespeed --n 1:x" "^granwave wavespeed --n: '1:x' is not a range A:B of integers, A <= B \(its end" wavespeed --n 1:x
refused "softwall --n 0:3" "^granwave softwall --n: '0:3' is not a range A:B of integers, A <= B \(its start: 0 is outside" softwall --n 0:3
# control: a range that is one still runs past the parse (refused later or run: not a range refusal)
"$GW" falcon --n 3:1 >/dev/null 2>"$tmp/stderr"
grep -q "range '3:1' is empty" "$tmp/stderr" && ok "control: falcon --n 3:1 refused as an empty range" ||
    ko "control: falcon --n 3:1: $(cat "$tmp/stderr")"

# --- 4 layer-impact: a steep incidence named with vi, and the largest that runs ---
make_sample pile.txt --n 40 --quiet
rm -rf o
if exits_refused "layer-impact --alpha 89.9" "^granwave layer-impact --vi: 20 m/s at incidence alpha 89.9 deg is too slow" 30 \
    "$GW" layer-impact --sample pile.txt --alpha 89.9; then
    amax=$(grep -o 'an incidence alpha of at most [0-9.]* deg' "$tmp/stderr" | grep -o '[0-9][0-9.]*')
    if [ -n "$amax" ]; then
        ok "layer-impact --alpha 89.9: refused naming vi and the incidence, largest alpha $amax"
        cpu_run 60 "$GW" layer-impact --sample pile.txt --alpha "$amax" --t-max 1e-4 --quiet --json >/dev/null 2>&1
        rc=$?
        above=$(/usr/bin/python3 -c "print($amax + 1e-4)")
        cpu_run 60 "$GW" layer-impact --sample pile.txt --alpha "$above" --t-max 1e-4 --quiet --json >/dev/null 2>&1
        rc2=$?
        [ $rc = 0 ] && [ $rc2 = 2 ] && ok "layer-impact --alpha $amax runs, --alpha $above is refused" ||
            ko "layer-impact --alpha $amax: exit $rc, --alpha $above: exit $rc2 (expected 0, 2)"
    else
        ko "layer-impact --alpha 89.9: no largest incidence named: $(cat "$tmp/stderr")"
    fi
fi

# --- 5 layer-make: an --out name with a newline echoed on one line ---
name=$(printf 's\nt.txt')
cpu_run 60 "$GW" layer-make --n 40 --out "$name" >"$tmp/lm.out" 2>"$tmp/stderr" </dev/null
rc=$?
last=$(tail -n 1 "$tmp/lm.out")
[ $rc = 0 ] && [ -s "$name" ] && [ "$last" = "${last%written to s\\nt.txt}written to s\\nt.txt" ] &&
    ! grep -qx 't.txt' "$tmp/lm.out" &&
    ok "layer-make --out 's<newline>t.txt': written, its name printed s\\nt.txt on one line" ||
    ko "layer-make --out 's<newline>t.txt': exit $rc, output ends: $(tail -n 2 "$tmp/lm.out" | tr '\n' '|')"

test_summary test_left48
