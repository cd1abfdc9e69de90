#!/bin/bash
# test_hostile_fortythird.sh GRANWAVE SRCDIR: what the forty-third hostile
# pass found in the program's number handling, fixed at its root and asserted
# here.
#  1 A number below the normal double range (a subnormal: 1e-310, 1e-320,
#    4.9e-324, and negative ones) given to a numeric flag was refused by the
#    number parser before any range check, in words of its own: "nonzero
#    values lie at or above 2.2251e-308 ... (give 0 or a larger value)", of
#    flags that do not take 0 (--vimp in [1e-09, 1000], --k in [1000,
#    1e+14]), naming no range. The parser is now given the range of what it
#    reads (gw_parse_double_in, gw_number_impl.h): the option table's, the
#    parameter table's (a sweep's values, the Python module's keywords, a
#    value written into a struct) and the lists' (--vimp, --heights, --radii,
#    --gap), and the refusal gives the values the input takes ("give a value
#    in [1e-09, 1000]", "give 0 or a value in [2.2251e-308, 1]"). Every
#    numeric flag of every command, found from its --help: exit 2, one line
#    naming the flag, nothing written to --out; a real-number flag's words
#    agree with the range its refusal of 1e300 names (the same bounds, 0 when
#    the range takes it, 2.2251e-308 in place of an open or closed 0); a
#    list's second item too; integer flags (refused as no integer) are the
#    controls. A sweep's grid and params values name the same range as the
#    flag.
#  2 layer-impact with a small --vi and the default gap (1 um, no --gap) was
#    refused as "--gap: falling 1e-06 m ... lower gap to ..." of a gap the
#    user never gave, and the gap it named could be the failing one (--vi
#    0.099: "lower gap to 1e-06 m"; --vi 1 --gap 1: "lower gap to 0.000102
#    m", which fails too). Now "--vi: V m/s is too slow for the default gap
#    of 1e-06 m: ... give vi at least 0.0991 m/s with the default gap, or a
#    gap of at most G m", both values printed so that they run as given
#    (checked here by running them), and a gap given keeps its "--gap:"
#    refusal with a gap that runs and the speed that would.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# shellcheck source=flags_lib.sh
. "$2/tests/flags_lib.sh"
flags_setup
M=2.2251e-308

# ere TEXT: TEXT as an extended regular expression matching it literally
ere() { printf '%s' "$1" | sed 's/[][().*^$+?{}|\\]/\\&/g'; }

# allowed RANGE: the values a range of a refusal ("outside [A, B]", "(A, B]",
# "... (or 0)") takes that are 0 or normal doubles, in the words the refusal
# of a subnormal gives them; status 1 for a RANGE not of that form
allowed() {
    local re='^outside ([[(])([^,]+), ([^])]+)([])])( \(or 0\))?$'
    [[ $1 =~ $re ]] || return 1
    local ob=${BASH_REMATCH[1]} a=${BASH_REMATCH[2]} b=${BASH_REMATCH[3]} cb=${BASH_REMATCH[4]} or0=${BASH_REMATCH[5]}
    local zero=
    [ -n "$or0" ] && zero="0 or "
    case $a in
        -*) echo "0 or a value in $ob$a, $b$cb of magnitude at least $M" ;;
        0) { [ "$ob" = "[" ] && zero="0 or "; echo "${zero}a value in [$M, $b$cb"; } ;;
        *) echo "${zero}a value in $ob$a, $b$cb" ;;
    esac
}

# --- 1 a subnormal given to every numeric flag of every command ---
declare -A hint
# the flags that take a value other than a name, a file or a directory (flags_lib.sh)
numeric_flags >"$tmp/flags"
while read -r c f list; do
    mapfile -t b < <(flag_base "$c")
    mapfile -t args < <(flag_without "$f" "${b[@]}")
    # the flag's range, from its refusal of 1e300
    cpu_run 20 "$GW" "${args[@]}" "$f" 1e300 >/dev/null 2>"$tmp/big" </dev/null
    range=$(grep -oE 'outside [][(][^],)]+, [^])]+[])]( \(or 0\))?' "$tmp/big")
    if want=$(allowed "$range"); then
        hint["$c $f"]=$want
        pat="^granwave $c $f: '-?[0-9.e-]+' is too small in magnitude: .*\\(give $(ere "$want")\\)$"
    elif grep -qE "^granwave $c $f: '1e300' is not an integer" "$tmp/big"; then
        pat="^granwave $c $f: '-?[0-9.e-]+' is not an integer" # the controls
    else
        ko "$c $f: no range found in its refusal of 1e300: $(head -c 200 "$tmp/big")"
        continue
    fi
    for v in 1e-310 -1e-310; do
        refused "$c $f $v" "$pat" "${args[@]}" "$f" "$v"
    done
    re_ab='([^][(, ]+), ([^])]+)]$'
    if [ $list = 1 ] && [[ $range =~ $re_ab ]]; then # a list's second item (its first 1, or the upper bound)
        first=$(awk -v a="${BASH_REMATCH[1]}" -v b="${BASH_REMATCH[2]}" 'BEGIN { print (a <= 1 && 1 <= b) ? 1 : b }')
        refused "$c $f $first,-1e-320" "$pat" "${args[@]}" "$f" "$first,-1e-320"
        refused "$c $f 4.9e-324" "$pat" "${args[@]}" "$f" 4.9e-324
    fi
done <"$tmp/flags"
[ ${#hint[@]} -gt 80 ] && ok "real-number flags found: ${#hint[@]}" || ko "only ${#hint[@]} real-number flags found"

# a sweep's values: the same words as the flag's
# (a [params] value is checked when the config is read since the forty-first
# session: its refusal names the line, "sv.ini:7: [params] t-max:"; a grid value since the forty-second,
# "sv.ini:5: [grid] vimp:")
s_chain() { printf '[sweep]\nmodel = chain\n[grid]\n%s\n[params]\nsolver = rk4\n%s\n' "$1" "$2" >sv.ini; }
for kv in "vimp|n = 1:2\nvimp = 0.3, 1e-310|chain --vimp" "t-max|n = 1:2|chain --t-max|t-max = -1e-310" \
    "guide-friction|n = 2\nguide-friction = 0, 4.9e-324|chain --guide-friction"; do
    IFS='|' read -r key grid flag params <<<"$kv"
    s_chain "$(printf "$grid")" "${params:-}"
    refused "sweep (chain): $key subnormal" \
        "^granwave sweep: .*sv\\.ini:[0-9]+: \\[(grid|params)\\] $key: '-?[0-9.e-]+' is too small in magnitude: .*\\(give $(ere "${hint[$flag]:-?}")\\)$" \
        sweep sv.ini --check --out o
done
printf '[sweep]\nmodel = layer\n[grid]\nvi = 20, 1e-320\n[params]\nsample = s20.txt\nt-max = 1e-3\n' >sv.ini
refused "sweep (layer): vi = 20, 1e-320" \
    "^granwave sweep: .*sv\\.ini:4: \\[grid\\] vi: '1e-320' is too small in magnitude: .*\\(give $(ere "${hint[layer-impact --vi]:-?}")\\)$" \
    sweep sv.ini --check --out o
printf '[sweep]\nmodel = layer\n[grid]\nx = 0, -1e-310\n[params]\nsample = s20.txt\nt-max = 1e-3\n' >sv.ini
refused "sweep (layer): x = 0, -1e-310" \
    "^granwave sweep: .*sv\\.ini:4: \\[grid\\] x: '-1e-310' is too small in magnitude: .*\\(give $(ere "${hint[layer-impact --x]:-?}")\\)$" \
    sweep sv.ini --check --out o

# the Python module (the library's tables, a keyword's value as a double and
# in a list): the same words as the flag's
export H_VIMP="${hint[chain --vimp]:-?}" H_FVIMP="${hint[falcon --vimp]:-?}" H_X="${hint[layer-impact --x]:-?}"
py_checks 3 <<'EOF'
import os
refused("Python chain(vimp=1e-310)", ["vimp", "too small in magnitude", "(give %s)" % os.environ["H_VIMP"]],
        granwave.chain, vimp=1e-310, t_max=1e-3)
refused("Python falcon(vimp=[0.3, -1e-320])", ["vimp", "too small in magnitude", "(give %s)" % os.environ["H_FVIMP"]],
        granwave.falcon, n="1:2", heights="none", vimp=[0.3, -1e-320])
refused("Python layer_impact(x=-5e-324)", ["x", "too small in magnitude", "(give %s)" % os.environ["H_X"]],
        granwave.layer_impact, sample="s20.txt", x=-5e-324, t_max=1e-3)
EOF

# --- 2 layer-impact: a small --vi with the default gap ---
# runs_ok WHAT ARGS...: layer-impact on s20.txt exits 0 (a short run; t-max 20 ms: the block at the gaps and speeds named reaches the layer before it)
runs_ok() {
    local what=$1
    shift
    timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --t-max 0.02 --quiet "$@" >/dev/null 2>"$tmp/stderr" </dev/null &&
        ok "$what" || ko "$what: exit $? ($(head -c 300 "$tmp/stderr"))"
}
for vi in 1e-6 1e-3 0.01 0.05 0.099; do
    refused "layer-impact --vi $vi, default gap" \
        "^granwave layer-impact --vi: [0-9.e-]+ m/s is too slow for the default gap of 1e-06 m: .* give vi at least [0-9.e-]+ m/s with the default gap, or a gap of at most [0-9.e-]+ m" \
        layer-impact --sample s20.txt --t-max 1e-3 --vi "$vi" --out o
    vmin=$(sed -nE 's/.* give vi at least ([0-9.e-]+) m\/s .*/\1/p' "$tmp/stderr")
    gmax=$(sed -nE 's/.* a gap of at most ([0-9.e-]+) m .*/\1/p' "$tmp/stderr")
    [ -n "$vmin" ] && runs_ok "--vi $vmin (the smallest named for --vi $vi) runs with the default gap" --vi "$vmin"
    [ -n "$gmax" ] && runs_ok "--vi $vi --gap $gmax (the gap named) runs" --vi "$vi" --gap "$gmax"
    [ -n "$vmin" ] && refused "--vi $vmin/1.01 with the default gap: still refused (the named speed is the smallest)" \
        "^granwave layer-impact --vi: .* too slow for the default gap" \
        layer-impact --sample s20.txt --t-max 1e-3 --vi "$(awk "BEGIN{printf \"%.6g\", $vmin/1.01}")" --out o
done
# the same at an incidence: the speed named is the incident one
refused "layer-impact --vi 0.05 --alpha 60, default gap" \
    "^granwave layer-impact --vi: 0\\.05 m/s at incidence alpha 60 deg is too slow for the default gap of 1e-06 m: .* give vi at least [0-9.e-]+ m/s" \
    layer-impact --sample s20.txt --t-max 1e-3 --vi 0.05 --alpha 60 --out o
vmin=$(sed -nE 's/.* give vi at least ([0-9.e-]+) m\/s .*/\1/p' "$tmp/stderr")
[ -n "$vmin" ] && runs_ok "--vi $vmin --alpha 60 (named) runs" --vi "$vmin" --alpha 60
# a gap given: refused naming --gap, and the gap it names runs (0.000102 did not)
refused "layer-impact --vi 1 --gap 1" \
    "^granwave layer-impact --gap: falling 1 m .* lower gap to [0-9.e-]+ m, or give vi the speed at contact \\(at least [0-9.e-]+ m/s with this gap\\)$" \
    layer-impact --sample s20.txt --t-max 1e-3 --vi 1 --gap 1 --out o
gmax=$(sed -nE 's/.* lower gap to ([0-9.e-]+) m.*/\1/p' "$tmp/stderr")
vmin=$(sed -nE 's/.* at least ([0-9.e-]+) m\/s with this gap.*/\1/p' "$tmp/stderr")
[ -n "$gmax" ] && runs_ok "--vi 1 --gap $gmax (the gap named) runs" --vi 1 --gap "$gmax"
[ -n "$vmin" ] && runs_ok "--vi $vmin --gap 1 (the speed named) runs" --vi "$vmin" --gap 1
# a sweep case at the default gap: the same words, naming vi
printf '[sweep]\nmodel = layer\n[grid]\nvi = 20, 0.05\n[params]\nsample = s20.txt\nt-max = 1e-3\n' >sv.ini
refused "sweep --check: vi 0.05 at the default gap" \
    "sv\\.ini: case 1: vi: 0\\.05 m/s is too slow for the default gap of 1e-06 m: .* give vi at least" sweep sv.ini --out o --check

test_summary test_hostile_fortythird
