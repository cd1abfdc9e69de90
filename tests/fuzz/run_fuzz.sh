#!/bin/bash
# run_fuzz.sh SRCDIR BUILDDIR [SECONDS]: build the libFuzzer targets with clang
# (ASan + UBSan): sweep config, CLI validation, sweep journal (resume) and the
# table written from it, layer-stats' sweep table reader with the whole
# analysis (fuzz_stats_table), layer sample reader (when the
# layer module is present), the studies' parameter tables (fuzz_params: the
# instrumented gw_param.c over the tables of the build's libgranwave.so, when
# the build has one without a sanitizer); run each for SECONDS (default 10) from its seed corpus in
# tests/fuzz/corpus/<target>/. New inputs go to a temporary directory; crashes
# are written to BUILDDIR/fuzz/ and fail the run. Longer runs: pass more
# seconds, e.g. run_fuzz.sh . build 3600.
set -eu
SRC=$(cd "$1" && pwd); B=$(cd "$2" && pwd); T=${3:-10}
if ! command -v clang >/dev/null; then echo "SKIP: clang not installed"; exit 0; fi
out="$B/fuzz"; mkdir -p "$out"
CF="-g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I$SRC/common -I$SRC/app -I$SRC/common/solver -I$SRC/common/sweep -I$SRC/common/stats -I$B/generated -D_DEFAULT_SOURCE"
# the sweep module's files (common/CMakeLists.txt lists the same)
sweep="$SRC/common/sweep/gw_sweep_config.c $SRC/common/sweep/gw_sweep_inputs.c $SRC/common/sweep/gw_sweep_rows.c
 $SRC/common/sweep/gw_sweep_head.c $SRC/common/sweep/gw_sweep_journal.c $SRC/common/sweep/gw_sweep_build.c
 $SRC/common/sweep/gw_sweep_table.c $SRC/common/sweep/gw_sweep_run.c $SRC/common/gw_pool.c"
# the build a journal records names the numerical libraries' versions
sweeplibs="-lsundials_cvode -lgsl -lgslcblas -lfftw3"
common="$SRC/common/gw_common.c $SRC/common/gw_io_afile.c $SRC/common/gw_io_outset.c $SRC/common/gw_io_temps.c $SRC/common/gw_io_paths.c $SRC/common/gw_io_input.c $SRC/common/gw_io_hash.c $SRC/common/gw_io_hash_memo.c $SRC/app/gw_cli.c $SRC/common/gw_json.c $SRC/common/gw_param.c $SRC/common/gw_locale.c $SRC/common/gw_forklock.c"
clang $CF -o "$out/fuzz_sweep_config" "$SRC/tests/fuzz/fuzz_sweep_config.c" $sweep $common $sweeplibs -linih -lcjson -lm
clang $CF -o "$out/fuzz_cli" "$SRC/tests/fuzz/fuzz_cli.c" $common -lcjson -lm
# the sweep journal a resumed sweep reads back, and the table written from it
clang $CF -o "$out/fuzz_sweep_journal" "$SRC/tests/fuzz/fuzz_sweep_journal.c" $sweep $common \
    $sweeplibs -linih -lcjson -lm
# the sweep table layer-stats reads, and the whole analysis after it (B.31 fit: GSL);
# the sweep module for the models' value rules the table's cells are held to (no
# model is linked here: the rule's absence is the path taken)
clang $CF -o "$out/fuzz_stats_table" "$SRC/tests/fuzz/fuzz_stats_table.c" "$SRC"/common/stats/*.c "$SRC/common/gw_fit.c" \
    $sweep $common $sweeplibs -linih -lcjson -lm
# The layer sample reader (text, and HDF5 when the build has it: inputs up to
# 16 kB so that the seed HDF5 samples fit). Without HDF5 flags for clang the
# target is built text-only, with a gw_version.h that says so.
if [ -f "$SRC/layer/layer_sample.c" ]; then
    H5=""; GEN="$B/generated"
    if grep -q 'GW_HAVE_HDF5 1' "$B/generated/gw_version.h"; then
        H5=$(pkg-config --cflags --libs hdf5-serial 2>/dev/null || pkg-config --cflags --libs hdf5 2>/dev/null) || {
            GEN="$out/gen-nohdf5"; mkdir -p "$GEN"
            sed 's/GW_HAVE_HDF5 1/GW_HAVE_HDF5 0/' "$B/generated/gw_version.h" >"$GEN/gw_version.h"
            echo "NOTE: no pkg-config flags for HDF5: fuzz_layer_sample built text-only"; H5=""; }
    fi
    clang -I"$GEN" -I"$SRC/layer" $CF -o "$out/fuzz_layer_sample" "$SRC/tests/fuzz/fuzz_layer_sample.c" \
        "$SRC/layer/layer_sample.c" "$SRC/layer/layer_sample_check.c" "$SRC/layer/layer_sample_h5.c" \
        "$SRC/layer/layer_sample_porosity.c" "$SRC/layer/layer_sample_settings.c" "$SRC/layer/layer_sample_springs.c" "$SRC/layer/layer_clump_check.c" "$SRC/common/gw_h5.c" \
        $common $H5 -lcjson -lm
    targets="sweep_config cli sweep_journal stats_table layer_sample"
else
    targets="sweep_config cli sweep_journal stats_table"
fi
# The parameter tables of every study (gw_study_get): gw_param.c and the
# validation it calls are compiled here, instrumented, and take precedence over
# the library's copies; the tables themselves come from the build's
# libgranwave.so. A sanitizer build's library carries gcc's ASan runtime, which
# cannot share a process with clang's: skipped there (and without the library).
if [ -f "$B/lib/libgranwave.so" ] && ! grep -q '^GW_SANITIZE:BOOL=ON' "$B/CMakeCache.txt" 2>/dev/null; then
    clang $CF -I"$SRC/app/lib" -I"$SRC/chain" -I"$SRC/layer" -o "$out/fuzz_params" "$SRC/tests/fuzz/fuzz_params.c" \
        "$SRC/common/gw_param.c" "$SRC/common/gw_common.c" "$SRC/common/gw_json.c" "$SRC/common/gw_locale.c" -L"$B/lib" -lgranwave \
        -Wl,-rpath,"$B/lib" -lcjson -lm
    targets="$targets params"
else
    echo "NOTE: fuzz_params skipped (no libgranwave.so in $B/lib, or a sanitizer build)"
fi
# libhdf5 1.10 loses a block when a metadata checksum fails (a leak inside the
# library, see layer_sample_h5_read in layer/layer_sample_h5.c): not ours to fix, so leaks
# whose allocation stack passes through libhdf5 are suppressed; leaks of our own
# allocations are still fatal.
echo "leak:libhdf5" >"$out/lsan.supp"
export LSAN_OPTIONS="suppressions=$out/lsan.supp:print_suppressions=0"
fail=0
for t in $targets; do
    work=$(mktemp -d); len=4096
    [ "$t" = layer_sample ] || [ "$t" = stats_table ] && len=16384
    # in the test command (10 s or less) the targets added in the thirteenth
    # pass replay their corpus only; longer runs fuzz them as the others
    mode="-max_total_time=$T"
    case "$t" in sweep_journal|stats_table) [ "$T" -le 10 ] && mode="-runs=0" ;; esac
    if (cd "$out" && "./fuzz_$t" "$mode" -max_len=$len -print_final_stats=0 "$work" "$SRC/tests/fuzz/corpus/$t" >"$out/fuzz_$t.log" 2>&1); then
        echo "PASS: fuzz_$t ran ${mode#-}: $(grep -Eo 'DONE +cov: [0-9]+|#[0-9]+ +DONE[^$]*' "$out/fuzz_$t.log" | tail -1) $(grep -c . "$out/fuzz_$t.log") log lines"
    else
        echo "FAIL: fuzz_$t: see $out/fuzz_$t.log"; tail -20 "$out/fuzz_$t.log"; fail=1
    fi
    rm -rf "$work"
done
exit $fail
