#!/bin/bash
# test_out_checked_first.sh GRANWAVE SRCDIR: `sweep` and `layer-impact` check
# --out (and a sweep config's [sweep] out) before any work, as the other
# commands do (gw_out_check), and say what is in the way (docs/reliability.md,
# "Outputs before validation"). Before, both made the directory only after the
# work before it (every case of a sweep checked; the layer-impact's sample read
# and planned) and refused whatever was there as "granwave sweep: X: not a
# directory", naming neither --out nor the reason:
#  1 a 90000-case layer sweep with --out naming a file was refused after 25 s
#    (9.8 s of CPU; 40-disc sample) of case checks; now at once (here: within
#    3 s, on a one-disc sample);
#  2 --out naming a file, /dev/null, a symbolic link to nothing, a loop of
#    links or a path under a file: exit 2, one line naming --out and what is
#    there, nothing written, for sweep and layer-impact;
#  3 a config's [sweep] out that is a link to nothing: named with the config;
#    sweep --check refuses it too (it said "is valid");
#  4 what is legitimate still runs: --out through a symbolic link to a
#    directory, a new nested directory.
# 13 of the 16 checks fail on the binary before (the 3 that pass: nothing
# written, the nested directory and the symbolic link to a directory).
set -u
GW=$1
SRC=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=refusal_lib.sh
. "$SRC/tests/refusal_lib.sh"
cd "$tmp" || exit 1

printf 'granwave-layer-sample 1\nwidth 20\nrm 0.325\nvolume_ratio 1\nn 1\n10 0.325 0.325\n' >one.txt
touch afile
ln -s nowhere dangling
ln -s loop2 loop1
ln -s loop1 loop2
mkdir real && ln -s real dirlink

# 1: a large grid is not checked before its --out
{
    echo "[sweep]"; echo "model = layer"; echo "[grid]"; echo "vi = 10:109"; echo "alpha = 0:89"
    echo "x = 0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09"
    echo "[params]"; echo "sample = $tmp/one.txt"; echo "t-max = 0.002"; echo "remove-walls = 1"
} >big.ini
REFUSE_TIMEOUT=3 refused "a 90000-case sweep with --out a file: refused before its cases are checked" \
    "^granwave sweep --out: 'afile' exists and is not a directory$" sweep big.ini --out afile --quiet

# 2: what is in the way, named, for both commands
printf '[sweep]\nmodel = chain\n[grid]\nn = 2, 3\n' >c.ini
imp="layer-impact --sample one.txt --remove-walls --t-max 0.002"
for cmd in "sweep c.ini --quiet" "$imp"; do
    name=${cmd%% *}
    # shellcheck disable=SC2086
    {
    refused "$name --out a file" "^granwave $name --out: 'afile' exists and is not a directory$" $cmd --out afile
    refused "$name --out /dev/null" "^granwave $name --out: '/dev/null' exists and is not a directory$" $cmd --out /dev/null
    refused "$name --out a link to nothing" "^granwave $name --out: 'dangling' is a symbolic link to 'nowhere', which does not exist$" $cmd --out dangling
    refused "$name --out a loop of links" "^granwave $name --out: 'loop1': Too many levels of symbolic links$" $cmd --out loop1
    refused "$name --out under a file" "^granwave $name --out: 'afile/sub': Not a directory$" $cmd --out afile/sub
    }
done

# 3: the config's out, also under --check
printf '[sweep]\nmodel = chain\nout = dangling\n[grid]\nn = 2\n' >d.ini
# (the config's out is taken from the config's directory: named resolved)
refused "[sweep] out a link to nothing" "^granwave sweep: d.ini: \[sweep\] out: '/[^']*/dangling' is a symbolic link" sweep d.ini --quiet
refused "sweep --check with [sweep] out a link to nothing" "^granwave sweep: d.ini: \[sweep\] out: '/[^']*/dangling'" sweep d.ini --check
[ ! -e afile/sub ] && [ ! -s afile ] && [ "$(ls real)" = "" ] && ok "nothing written by the refusals" ||
    ko "the refusals wrote: $(ls -R afile real 2>&1 | tr '\n' ' ')"

# 4: legitimate outputs
"$GW" sweep c.ini --quiet --out dirlink >/dev/null 2>&1 && [ -s real/results.csv ] &&
    ok "sweep --out through a symbolic link to a directory" || ko "sweep --out dirlink"
"$GW" $imp --out n1/n2/n3 >/dev/null 2>&1 && [ -s n1/n2/n3/impact.json ] &&
    ok "layer-impact --out a new nested directory" || ko "layer-impact --out n1/n2/n3"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
