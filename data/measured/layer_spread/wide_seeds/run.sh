#!/bin/bash
# Sample-to-sample spread of the wide R_b = 3 R_m column: 7 heights, 5 points 1.25 m apart
# (the paper's 5 m span), V_i = 20 m/s, on type A (layer-make --seed S) and type B
# (layer-make --clumps --seed S) samples, S = 2..4 (seed 1 is ../wide/). Writes
# wide_KIND_seedS.ini, wide_KIND_seedS.csv (the sweep table) and make_KIND_seedS.json here,
# and make_B_seed1.json for seed 1's porosity; then /usr/bin/python3 summ.py > summary.txt.
# GW names the binary (default ../../../../build/granwave). Sweeps resume from their journals.
set -e
cd "$(dirname "$0")"
gw=${GW:-../../../../build/granwave}
[ -e make_B_seed1.json ] || $gw layer-make --clumps --seed 1 --out sample_B_s1.txt --json > make_B_seed1.json
for seed in 2 3 4; do
  for kind in A B; do
    s=sample_${kind}_s$seed.txt
    if [ ! -e $s ]; then
      if [ $kind = A ]; then $gw layer-make --seed $seed --out $s --json > make_${kind}_seed$seed.json
      else $gw layer-make --clumps --seed $seed --out $s --json > make_${kind}_seed$seed.json; fi
    fi
    printf '[sweep]\nmodel = layer\nout = res_%s_s%s\n[grid]\nrb-rm = 3\nheight-rm = 4, 6, 8, 10, 12, 16, 20\npoint = 0:4\n[params]\nsample = %s\npoints = 5\nspacing = 1.25\nvi = 20\n' $kind $seed $s > wide_${kind}_seed$seed.ini
    T0=$(date +%s)
    $gw sweep wide_${kind}_seed$seed.ini --quiet > /dev/null
    cp res_${kind}_s$seed/results.csv wide_${kind}_seed$seed.csv
    echo "$kind seed $seed done $(( $(date +%s) - T0 )) s"
  done
done
