#!/bin/bash
# Sample-to-sample spread at R_b = 3 R_m, H = 8 and 16 R_m, 5 points 0.05 m apart, 20 m/s:
# type A (layer-make --seed S) against one-disc grains (layer-make --clumps --aspect-max 1 --seed S),
# seeds 1-4. Writes KIND_seedS.ini, KIND_seedS.csv (the sweep table) and make_KIND_seedS.json here;
# then /usr/bin/python3 summ.py > summary.txt. GW names the binary (default ../../../../build/granwave).
set -e
cd "$(dirname "$0")"
gw=${GW:-../../../../build/granwave}
for seed in 1 2 3 4; do
  for kind in A a1; do
    s=sample_${kind}_s$seed.txt
    if [ ! -e $s ]; then
      if [ $kind = A ]; then $gw layer-make --seed $seed --out $s --json > make_${kind}_seed$seed.json
      else $gw layer-make --clumps --aspect-max 1 --seed $seed --out $s --json > make_${kind}_seed$seed.json; fi
    fi
    printf '[sweep]\nmodel = layer\nout = res_%s_s%s\n[grid]\nrb-rm = 3\nheight-rm = 8, 16\npoint = 0:4\n[params]\nsample = %s\npoints = 5\nvi = 20\n' $kind $seed $s > ${kind}_seed$seed.ini
    $gw sweep ${kind}_seed$seed.ini --quiet > /dev/null
    cp res_${kind}_s$seed/results.csv ${kind}_seed$seed.csv
    echo "$kind seed $seed done"
  done
done
