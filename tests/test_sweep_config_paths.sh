#!/bin/bash
# test_sweep_config_paths.sh GRANWAVE SRCDIR: the paths a sweep config names
# ([sweep] out, a layer `sample`, in [params] or [grid]) are taken from the
# config file's own directory when relative, never from the working directory
# (docs/formats.md, "Sweep configs"; gw_sweep_config_read). Before, the same
# config run from another directory read another file of the same name (here
# a decoy sample of another seed: another table, exit 0) or none ("case 0:
# sample: S.txt: cannot open"), and wrote its table under the working
# directory.
#  1 the config cfg/d.ini (sample = S.txt, out = res) run from its parent,
#    from its own directory and from a sibling holding a decoy S.txt: three
#    tables byte-identical, the first at cfg/res (the config's out), each
#    recording the resolved sample (# param, # input lines) as an absolute
#    path in cfg/;
#  2 a grid of samples (S.txt, ./S2.txt) resolved the same way, from two
#    directories, identical tables;
#  3 an absolute sample stays as written;
#  4 a relative sample that does not exist there: exit 2, one line naming the
#    config, the key and the resolved path, nothing written ([params] and
#    [grid]); a chain sweep's relative out lands beside its config;
#  5 layer-stats reads the table (its case hashes over the resolved values).
set -u
GW=$1
SRC=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=refusal_lib.sh
. "$SRC/tests/refusal_lib.sh"
cd "$tmp" || exit 1
real=$(pwd -P)
mkdir cfg other
"$GW" layer-make --n 40 --width-rm 12 --seed 2 --out cfg/S.txt >/dev/null 2>&1 || ko "layer-make cfg/S.txt"
"$GW" layer-make --n 40 --width-rm 12 --seed 5 --out cfg/S2.txt >/dev/null 2>&1 || ko "layer-make cfg/S2.txt"
cp cfg/S2.txt other/S.txt # the decoy: another sample under the same name
printf '[sweep]\nmodel = layer\nout = res\n[grid]\nvi = 10, 20\n[params]\nsample = S.txt\nt-max = 0.002\n' >cfg/d.ini

# 1: three working directories, one table
"$GW" sweep cfg/d.ini --jobs 1 --quiet >/dev/null 2>"$tmp/e1" && [ -s cfg/res/results.csv ] && [ ! -e res ] &&
    ok "run from the parent: the table at the config's out (cfg/res)" || ko "run from the parent: $(cat "$tmp/e1")"
(cd cfg && "$GW" sweep d.ini --out ../t2 --jobs 1 --quiet >/dev/null 2>"$tmp/e2") || ko "run from cfg: $(cat "$tmp/e2")"
(cd other && "$GW" sweep ../cfg/d.ini --out ../t3 --jobs 1 --quiet >/dev/null 2>"$tmp/e3") ||
    ko "run from other: $(cat "$tmp/e3")"
cmp -s cfg/res/results.csv t2/results.csv && ok "the table from cfg/ is the one from its parent" ||
    ko "the table from cfg/ differs: $(diff cfg/res/results.csv t2/results.csv | head -4)"
cmp -s cfg/res/results.csv t3/results.csv && ok "the table from a directory with a decoy S.txt is the same" ||
    ko "the table from other/ differs: $(diff cfg/res/results.csv t3/results.csv | head -4)"
grep -qx "# param sample = $real/cfg/S.txt" cfg/res/results.csv &&
    grep -q "^# input sample = $real/cfg/S.txt fnv1a64 [0-9a-f]\{16\}$" cfg/res/results.csv &&
    ok "the table records the resolved sample" || ko "the table's settings: $(grep '^#' cfg/res/results.csv | tr '\n' '|')"

# 2: a grid of samples
printf '[sweep]\nmodel = layer\n[grid]\nsample = S.txt, ./S2.txt\n[params]\nt-max = 0.002\nvi = 10\n' >cfg/g.ini
"$GW" sweep cfg/g.ini --out g1 --jobs 1 --quiet >/dev/null 2>"$tmp/e4" &&
    (cd other && "$GW" sweep ../cfg/g.ini --out ../g2 --jobs 1 --quiet >/dev/null 2>"$tmp/e4") &&
    cmp -s g1/results.csv g2/results.csv && grep -q "^1,$real/cfg/./S2.txt," g1/results.csv &&
    ok "a grid of samples: resolved, the same table from two directories" ||
    ko "a grid of samples: $(cat "$tmp/e4") $(grep -v '^#' g1/results.csv 2>/dev/null | cut -c1-60 | tr '\n' '|')"

# 3: an absolute path stays as written
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10\n[params]\nsample = %s\nt-max = 0.002\n' "$tmp/cfg/S.txt" >other/a.ini
"$GW" sweep other/a.ini --out a1 --jobs 1 --quiet >/dev/null 2>"$tmp/e5" &&
    grep -qx "# param sample = $tmp/cfg/S.txt" a1/results.csv && ok "an absolute sample is kept as written" ||
    ko "an absolute sample: $(cat "$tmp/e5") $(grep '^# param sample' a1/results.csv 2>/dev/null)"

# 4: a relative path that names nothing from the config's directory
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = nosuch.txt\n' >cfg/m.ini
refused "[params] sample missing beside the config" \
    "^granwave sweep: cfg/m.ini: \[params\] sample = nosuch.txt: no such file $real/cfg/nosuch.txt \(a relative path in a config is taken from the config's directory\)$" \
    sweep cfg/m.ini --out o
printf '[sweep]\nmodel = layer\n[grid]\nsample = S.txt, sub/x.txt\n' >cfg/m2.ini
refused "[grid] sample missing beside the config (--check)" \
    "^granwave sweep: cfg/m2.ini: \[grid\] sample = sub/x.txt: no such file $real/cfg/sub/x.txt " sweep cfg/m2.ini --out o --check
# the decoy beside the working directory does not make it run
cp other/S.txt nosuch.txt
refused "a file of the name in the working directory is not taken" "no such file $real/cfg/nosuch.txt" \
    sweep cfg/m.ini --out o
printf '[sweep]\nmodel = chain\nout = c/out\n[grid]\nn = 2, 3\n' >cfg/c.ini
(cd other && "$GW" sweep ../cfg/c.ini --quiet >/dev/null 2>"$tmp/e6") && [ -s cfg/c/out/results.csv ] &&
    [ ! -e other/c ] && ok "a chain sweep's relative out lands beside its config" ||
    ko "chain out: $(cat "$tmp/e6") $(ls other cfg | tr '\n' ' ')"

# 5: the table's hashes, recomputed by layer-stats over the resolved values
(cd other && "$GW" layer-stats "$tmp/cfg/res/results.csv" --json >/dev/null 2>"$tmp/e7") &&
    ok "layer-stats reads the table from another directory" || ko "layer-stats: $(cat "$tmp/e7")"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
