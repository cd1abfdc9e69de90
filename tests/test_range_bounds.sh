#!/bin/bash
# test_range_bounds.sh GRANWAVE SRCDIR: the bounds a flag's range refusal
# prints are values the flag takes, and an integer flag's refusal of a number
# that is no integer names its range.
#  1 Range messages printed their bounds with %g (6 digits): falcon
#    --heights' upper bound, 5.0968399e7 mm, printed as 5.09684e+07, above
#    it, so that the value the message named was refused too. The bounds are
#    now printed rounded inward when %g would step outside (gw_num_bound).
#    For every numeric flag of every command (flags_lib.sh's enumeration,
#    shared with test_hostile_fortythird.sh), its range is read from its
#    refusal of 1e300 (an integer flag's of 99999999999999999999), and each
#    closed end printed is given back to the flag: it is not refused as
#    outside the range. Flags whose range the option parser checks are given
#    it with --help (parsed, nothing run); the others (the lists, checked
#    after the parse) run their command's quick form, killed after 20 s (a
#    run that lasts is no refusal).
#  2 An integer flag refused 1e-310 as "'1e-310' is not an integer", naming
#    no range, where a real flag names the values it takes: now "... (give
#    an integer in [A, B])" ("0 or an integer" where the row takes 0 besides
#    its range), A and B the range the flag's refusal of a large integer
#    names; a sweep's integer key and the Python module's keyword the same.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
# shellcheck source=flags_lib.sh
. "$2/tests/flags_lib.sh"
flags_setup

# ends RANGE: "LO LO_CLOSED HI HI_CLOSED" of a refusal's range ("outside [A,
# B]", "(A, B]", "must be > A", "must be >= A"; "-" for no end); status 1
# when RANGE is none of these
ends() {
    local re='^outside ([[(])([^,]+), ([^])]+)([])])' re1='^must be (>=?) ([^ ]+)$'
    if [[ $1 =~ $re ]]; then
        echo "${BASH_REMATCH[2]} $([ "${BASH_REMATCH[1]}" = "[" ] && echo 1 || echo 0)" \
            "${BASH_REMATCH[3]} $([ "${BASH_REMATCH[4]}" = "]" ] && echo 1 || echo 0)"
    elif [[ $1 =~ $re1 ]]; then
        echo "${BASH_REMATCH[2]} $([ "${BASH_REMATCH[1]}" = ">=" ] && echo 1 || echo 0) - 0"
    else
        return 1
    fi
}

numeric_flags >"$tmp/flags"
nflags=0 nends=0 nint=0
while read -r c f list; do
    mapfile -t b < <(flag_base "$c")
    mapfile -t args < <(flag_without "$f" "${b[@]}")
    # the range, from the refusal of a large value: with --help first (the
    # option parser's refusal: nothing runs; quick 1), else by a run
    big=1e300 quick=1 int=0
    refusal() {
        [ $quick = 1 ] && set -- --help "$@"
        cpu_run 20 "$GW" "${args[@]}" "$@" >/dev/null 2>"$tmp/big" </dev/null
    }
    refusal "$f" "$big"
    [ $? = 2 ] || { quick=0; refusal "$f" "$big"; }
    if grep -qE "^granwave $c $f: '1e300' is not an integer" "$tmp/big"; then
        int=1 big=99999999999999999999
        refusal "$f" "$big"
    fi
    range=$(grep -oE "(outside [][(][^],)]+, [^])]+[])]|must be >=? [^ ]+$)" "$tmp/big" | head -n 1)
    if ! e=$(ends "$range"); then
        ko "$c $f: no range found in its refusal of $big: $(head -c 200 "$tmp/big")"
        continue
    fi
    read -r lo lo_closed hi hi_closed <<<"$e"
    nflags=$((nflags + 1))
    for end in lo hi; do
        [ "$end" = lo ] && v=$lo closed=$lo_closed || v=$hi closed=$hi_closed
        [ "$closed" = 1 ] && [ "$v" != - ] || continue
        nends=$((nends + 1))
        if [ $quick = 1 ]; then
            cpu_run 20 "$GW" "${args[@]}" --help "$f" "$v" >/dev/null 2>"$tmp/end" </dev/null
        else
            cpu_run 20 "$GW" "${args[@]}" "$f" "$v" >/dev/null 2>"$tmp/end" </dev/null
        fi
        if grep -qE "^granwave $c $f: .*(outside [][(]|must be >)" "$tmp/end"; then
            ko "$c $f $v (its range's printed $end end, $range): refused as outside it: $(head -c 200 "$tmp/end")"
        else
            ok "$c $f $v (the printed $end end of $range) is taken"
        fi
    done
    # 2 an integer flag's refusal of 1e-310: its range named
    if [ $int = 1 ]; then
        nint=$((nint + 1))
        refused "$c $f 1e-310: its range named" \
            "^granwave $c $f: '1e-310' is not an integer \\(give (0 or )?an integer in \\[$lo, $hi\\]\\)$" \
            "${args[@]}" "$f" 1e-310
    fi
done <"$tmp/flags"
[ $nflags -gt 120 ] && ok "flags with a range found: $nflags ($nends closed ends, $nint integer flags)" ||
    ko "only $nflags flags with a range found ($nends closed ends, $nint integer flags)"

# a sweep's integer key and the Python module's keyword: the same words
printf '[sweep]\nmodel = chain\n[grid]\nn = 2, 1e-310\n[params]\nsolver = rk4\n' >sv.ini
refused "sweep (chain): n = 2, 1e-310" \
    "^granwave sweep: .*sv\\.ini:4: \\[grid\\] n: '1e-310' is not an integer \\(give an integer in \\[1, [0-9]+\\]\\)$" \
    sweep sv.ini --check --out o
py_checks 1 <<'EOF'
refused("Python chain(n=1.5)", ["n:", "is not an integer (give an integer in [1, "], granwave.chain, n=1.5, t_max=1e-4)
EOF

test_summary test_range_bounds
