#!/bin/bash
# test_hardening.sh GRANWAVE SRCDIR: outputs are atomic and runs are memory-clean.
#  - A falcon run interrupted by SIGINT while writing into a directory that holds
#    a previous report leaves either the previous files or complete new ones,
#    never a temporary or truncated file. The SIGINTs land at 5, 25, 50 and 75 %
#    of the CPU time the same run took uninterrupted (1.8 s here: 40 columns by
#    cvode), whatever the machine's load, and must stop it (exit 130). They were sent after 0.2 to
#    1.5 s of wall time to a run of 0.28 s that ignored SIGINT (a script's
#    background job): no check ever interrupted a run.
#    A SIGINT once the first staged file appears (the writing has begun)
#    stops the run with the previous set intact and no temporary (the
#    program's handler removes the staged ones: before, they were left until
#    the next write of their names, as after kill -9), or, when it came while
#    the set was placed (SIGINT held there), after the complete new set.
#  - valgrind memcheck (when installed) finds no errors and no definite or
#    indirect leaks in a short chain run with --out and a short falcon run, and
#    in the 2D layer: layer-make --n 30 --width-rm 12 (stopped at 0.5 s of
#    settling to stay short), layer-impact --t-max 0.002 --out on a settled
#    sample of the same size made without valgrind, the same two for a sample of
#    12 clumps (type B), and, when the build writes
#    HDF5 samples, the same impact read from an .h5 sample (~10 s in all).
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"

"$GW" falcon --n 1:6 --heights none --quiet --out "$tmp/f" >/dev/null || ko "first falcon run"
cp "$tmp/f/report.md" "$tmp/report.before"
full=$(cpu_of "$GW" falcon --n 1:40 --solver cvode --heights none --quiet --out "$tmp/fref")
for pc in 5 25 50 75; do
    cpu=$(awk -v f="$full" -v p=$pc 'BEGIN { printf "%.2f", f * p / 100 }')
    env --default-signal=INT "$GW" falcon --n 1:40 --solver cvode --heights none --quiet --out "$tmp/f" >/dev/null 2>&1 & pid=$!
    wait_cpu $pid $cpu; kill -INT $pid 2>/dev/null; wait $pid 2>/dev/null; rc=$?
    if [ $rc -ne 130 ]; then ko "SIGINT at $cpu s of CPU: exit $rc, not stopped by it (130)"; continue; fi
    leftovers=$(ls "$tmp/f" | grep -c '\.tmp' || true)
    if [ "$leftovers" -ne 0 ]; then ko "SIGINT at $cpu s of CPU: $leftovers temporary file(s) left"; continue; fi
    if cmp -s "$tmp/f/report.md" "$tmp/report.before" || grep -q "E_rel/E_K increases" "$tmp/f/report.md"; then
        ok "SIGINT at $cpu s of CPU stopped the run: report.md is the previous one or a complete new one, no temporaries"
    else
        ko "SIGINT at $cpu s of CPU: report.md is truncated"
    fi
done

# the staging: SIGINT once a temporary is seen (the writing, from the first
# temporary to the end, took 28-170 ms at a load of 8-11), a run that ended
# first tried again (five attempts)
for attempt in 1 2 3 4 5; do
    env --default-signal=INT "$GW" falcon --n 1:40 --solver cvode --heights none --quiet --out "$tmp/f" >/dev/null 2>&1 & pid=$!
    wait_file $pid "$tmp/f/*.tmp.*"
    kill -INT $pid 2>/dev/null; wait $pid 2>/dev/null; rc=$?
    [ $rc -eq 130 ] && break
done
left=$(ls "$tmp/f" | grep '\.tmp\.' | tr '\n' ' ')
if [ $rc -ne 130 ]; then
    ko "SIGINT while the files are written: exit $rc in 5 attempts, not stopped by it (130)"
elif [ -n "$left" ]; then
    ko "SIGINT while the files are written: temporaries left: $left"
elif cmp -s "$tmp/f/report.md" "$tmp/report.before" && grep -q 'Solver: rk4' "$tmp/f/report.md"; then
    ok "SIGINT while the files are written (attempt $attempt): the previous set intact, no temporaries"
elif ! ls "$tmp/f" | grep -q '\.tmp\.' && grep -q 'Solver: cvode' "$tmp/f/report.md"; then
    ok "SIGINT while the files are placed (attempt $attempt): the complete new set, no temporaries"
else
    ko "SIGINT while the files are written: a mixed set: $(ls "$tmp/f" | tr '\n' ' ')"
fi
"$GW" falcon --n 1:40 --solver cvode --heights none --quiet --out "$tmp/f" >/dev/null 2>&1 &&
    ! ls "$tmp/f" | grep -q '\.tmp\.' && grep -q "Solver: cvode" "$tmp/f/report.md" &&
    ok "the same run again places its set, nothing else left" ||
    ko "the next run: $(ls "$tmp/f" | tr '\n' ' ')"

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
test_summary
