#!/bin/bash
# test_hostile_fortyfirst.sh GRANWAVE SRCDIR: what the forty-first hostile
# pass found, fixed at its root and asserted here, and the strongest of its
# checks that held (regressions).
#  1 An --out path that walks through a directory still to make. --out o/../o2
#    with no o: gw_mkdir_p made o (mkdir -p's way), then o/.. (there), then o2,
#    and left o behind, empty, on success and on refusal alike; gw_out_check
#    passed it, walking up from o/../o2 to the current directory. The path
#    names o2 only through a directory that does not exist (o/.. cannot be
#    opened while o is missing), so it is now refused before anything is
#    made, by gw_out_check (the commands' check before any work) and by
#    gw_mkdir_p itself: "--out: 'o/../o2': 'o' does not exist and '..'
#    follows it", exit 2, nothing made (neither o nor o2). Every command with
#    an --out directory (chain, falcon, wavespeed, softwall, drop, dispersion,
#    layer-impact, layer-stats, sweep's --out and its config's out), deeper
#    forms (a/b/../../c, o/p/.., whose p was left inside the o it names);
#    controls: a '..' after a directory that exists (x/../o2) runs and makes
#    o2 alone, as does ./o3/./; layer-make's --out file under d/.. is refused
#    as before (its directory must exist).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 an --out path through a missing directory and '..' ---
# stray WHAT: nothing but the fixtures in the scratch directory (no o, o2, a,
# c, ...); what is there is removed after, for the next case to start clean
stray() {
    local left
    left=$(ls -A "$tmp" | grep -vxE 'stdout|stderr|x|s20\.txt|results\.csv|sweep\.ini|sweep_out\.ini' | tr '\n' ' ')
    [ -z "$left" ] && ok "$1: nothing made" || ko "$1: left behind: $left"
    # shellcheck disable=SC2086
    [ -z "$left" ] || (cd "$tmp" && rm -rf $left)
}
mkdir x
make_sample s20.txt --n 20 --width-rm 8
cp "$SRC/data/measured/layer_walls/results.csv" results.csv
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nsolver = rk4\n' >sweep.ini
printf '[sweep]\nmodel = chain\nout = q/../r\n[grid]\nn = 1:2\n[params]\nsolver = rk4\n' >sweep_out.ini
dotdot="'o/\\.\\./o2': 'o' does not exist and '\\.\\.' follows it"
for cmd in "chain --n 2" "falcon --n 1:2 --heights none --quiet --jobs 1" "wavespeed --n 6:8 --vimp 0.3 --quiet --jobs 1" \
    "softwall --n 1:3 --quiet --jobs 1" "drop --n 2 --t-max 2e-4" "dispersion --n 16 --t-samples 64" \
    "layer-impact --sample s20.txt --t-max 0.001 --quiet" "layer-stats results.csv" "sweep sweep.ini --quiet"; do
    c=${cmd%% *}
    # shellcheck disable=SC2086
    refused "$c --out o/../o2 (no o)" "^granwave $c --out: $dotdot; give the path without" $cmd --out o/../o2
    stray "$c --out o/../o2"
done
refused "chain --out a/b/../../c (no a)" "^granwave chain --out: 'a/b/\\.\\./\\.\\./c': 'a' does not exist and" \
    chain --n 2 --out a/b/../../c
stray "chain --out a/b/../../c"
refused "chain --out x/p/.. (x there, no p)" "^granwave chain --out: 'x/p/\\.\\.': 'x/p' does not exist and" \
    chain --n 2 --out x/p/..
[ -z "$(ls -A x)" ] && ok "chain --out x/p/..: x left empty" || ko "chain --out x/p/..: x holds $(ls -A x | tr '\n' ' ')"
rm -rf x && mkdir x
stray "chain --out x/p/.."
refused "sweep config out = q/../r (no q)" \
    "^granwave sweep: .*sweep_out\\.ini: \\[sweep\\] out: '.*/q/\\.\\./r': '.*/q' does not exist and" sweep sweep_out.ini --quiet
stray "sweep config out = q/../r"
# a refusal by another input, the --out through a missing directory: nothing either
refused "chain --vimp nan --out o/../o2" "^granwave chain --" chain --n 2 --vimp nan --out o/../o2
stray "chain --vimp nan --out o/../o2"
# controls: '..' after a directory that exists, '.' components
timeout -s KILL 60 "$GW" chain --n 2 --quiet --out x/../o2 >/dev/null 2>"$tmp/stderr" </dev/null &&
    [ -f o2/chain.json ] && [ -z "$(ls -A x)" ] && ok "chain --out x/../o2 (x there): runs, o2 made alone" ||
    ko "chain --out x/../o2: $(head -c 300 "$tmp/stderr")"
rm -rf o2
timeout -s KILL 60 "$GW" chain --n 2 --quiet --out ./o3/./ >/dev/null 2>"$tmp/stderr" </dev/null &&
    [ -f o3/chain.json ] && ok "chain --out ./o3/./: runs into o3" || ko "chain --out ./o3/./: $(head -c 300 "$tmp/stderr")"
rm -rf o3
refused "layer-make --out d/../s.txt (no d): its directory must exist, as before" \
    "^granwave layer-make --out: directory 'd/\\.\\.' of 'd/\\.\\./s\\.txt'" layer-make --n 10 --out d/../s.txt
stray "layer-make --out d/../s.txt"

test_summary test_hostile_fortyfirst
