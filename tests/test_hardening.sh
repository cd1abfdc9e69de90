#!/bin/bash
# test_hardening.sh GRANWAVE SRCDIR: outputs are atomic and runs are memory-clean.
#  - A falcon run interrupted by SIGINT while writing into a directory that holds
#    a previous report leaves either the previous files or complete new ones,
#    never a temporary or truncated file.
#  - valgrind memcheck (when installed) finds no errors and no definite or
#    indirect leaks in a short chain run with --out and a short falcon run, and
#    in the 2D layer: layer-make --n 30 --width-rm 12 (stopped at 0.5 s of
#    settling to stay short), layer-impact --t-max 0.002 --out on a settled
#    sample of the same size made without valgrind, the same two for a sample of
#    12 clumps (type B), and, when the build writes
#    HDF5 samples, the same impact read from an .h5 sample (~10 s in all).
set -u
GW=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; passes=0
ok() { echo "PASS: $1"; passes=$((passes+1)); }
ko() { echo "FAIL: $1"; fails=$((fails+1)); }

"$GW" falcon --n 1:6 --heights none --quiet --out "$tmp/f" >/dev/null || ko "first falcon run"
cp "$tmp/f/report.md" "$tmp/report.before"
for delay in 0.2 0.5 1.0 1.5; do
    "$GW" falcon --n 1:40 --quiet --out "$tmp/f" >/dev/null 2>&1 & pid=$!
    sleep $delay; kill -INT $pid 2>/dev/null; wait $pid 2>/dev/null
    leftovers=$(ls "$tmp/f" | grep -c '\.tmp' || true)
    if [ "$leftovers" -ne 0 ]; then ko "SIGINT after $delay s: $leftovers temporary file(s) left"; continue; fi
    if cmp -s "$tmp/f/report.md" "$tmp/report.before" || grep -q "E_rel/E_K increases" "$tmp/f/report.md"; then
        ok "SIGINT after $delay s: report.md is the previous one or a complete new one, no temporaries"
    else
        ko "SIGINT after $delay s: report.md is truncated"
    fi
done

if command -v valgrind >/dev/null; then
    for args in "chain --n 5 --out $tmp/v1" "falcon --n 1:3 --heights none --quiet --jobs 1 --out $tmp/v2" "chain --n 4 --damping hc --restitution 0.8 --json"; do
        if valgrind --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite,indirect -q "$GW" $args >/dev/null 2>"$tmp/vg.log"; then
            ok "valgrind memcheck clean: granwave $args"
        else
            ko "valgrind memcheck: granwave $args"; tail -20 "$tmp/vg.log"
        fi
    done
    layer=()
    if "$GW" layer-make --n 30 --width-rm 12 --out "$tmp/s30.txt" >/dev/null 2>&1; then
        layer+=("layer-make --n 30 --width-rm 12 --t-max 0.5 --out $tmp/vm.txt"
                "layer-impact --sample $tmp/s30.txt --t-max 0.002 --out $tmp/vi")
        # type B: clumps (rigid bodies of several discs) through make and impact
        if "$GW" layer-make --clumps --n 12 --width-rm 12 --t-max 0.5 --out "$tmp/c12.txt" >/dev/null 2>&1; then
            layer+=("layer-make --clumps --n 12 --width-rm 12 --t-max 0.2 --out $tmp/vc.txt"
                    "layer-impact --sample $tmp/c12.txt --t-max 0.002 --json")
        else
            ko "layer-make --clumps failed outside valgrind"
        fi
        if "$GW" layer-make --n 30 --width-rm 12 --out "$tmp/s30.h5" >/dev/null 2>&1; then
            layer+=("layer-impact --sample $tmp/s30.h5 --t-max 0.002 --json")
        else
            echo "SKIP: valgrind on an HDF5 sample: layer-make does not write .h5 in this build"
        fi
    else
        echo "SKIP: valgrind on the layer: layer-make not available"
    fi
    for args in "${layer[@]}"; do
        if valgrind --error-exitcode=9 --leak-check=full --errors-for-leak-kinds=definite,indirect -q "$GW" $args >/dev/null 2>"$tmp/vg.log"; then
            ok "valgrind memcheck clean: granwave $args"
        else
            ko "valgrind memcheck: granwave $args"; tail -20 "$tmp/vg.log"
        fi
    done
    [ -s "$tmp/vi/ledger.csv" ] && [ -s "$tmp/vm.txt" ] || [ ${#layer[@]} -eq 0 ] || ko "layer runs under valgrind wrote no output"
else
    echo "SKIP: valgrind not installed"
fi
echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
