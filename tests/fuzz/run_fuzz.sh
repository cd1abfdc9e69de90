#!/bin/bash
# run_fuzz.sh SRCDIR BUILDDIR [SECONDS]: build the libFuzzer targets with clang
# (ASan + UBSan) and run each for SECONDS (default 10) from its seed corpus in
# tests/fuzz/corpus/<target>/. New inputs go to a temporary directory; crashes
# are written to BUILDDIR/fuzz/ and fail the run. Longer runs: pass more
# seconds, e.g. run_fuzz.sh . build 3600.
set -eu
SRC=$(cd "$1" && pwd); B=$(cd "$2" && pwd); T=${3:-10}
if ! command -v clang >/dev/null; then echo "SKIP: clang not installed"; exit 0; fi
out="$B/fuzz"; mkdir -p "$out"
CF="-g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I$SRC/common -I$B/generated -D_DEFAULT_SOURCE"
common="$SRC/common/gw_common.c $SRC/common/gw_io.c $SRC/common/gw_cli.c $SRC/common/gw_json.c"
clang $CF -o "$out/fuzz_sweep_config" "$SRC/tests/fuzz/fuzz_sweep_config.c" "$SRC/common/gw_sweep.c" $common -linih -lcjson -lm
clang $CF -o "$out/fuzz_cli" "$SRC/tests/fuzz/fuzz_cli.c" $common -lcjson -lm
fail=0
for t in sweep_config cli; do
    work=$(mktemp -d)
    if (cd "$out" && "./fuzz_$t" -max_total_time="$T" -max_len=4096 -print_final_stats=0 "$work" "$SRC/tests/fuzz/corpus/$t" >"$out/fuzz_$t.log" 2>&1); then
        echo "PASS: fuzz_$t ran $T s: $(grep -Eo 'DONE +cov: [0-9]+|#[0-9]+ +DONE[^$]*' "$out/fuzz_$t.log" | tail -1) $(grep -c . "$out/fuzz_$t.log") log lines"
    else
        echo "FAIL: fuzz_$t: see $out/fuzz_$t.log"; tail -20 "$out/fuzz_$t.log"; fail=1
    fi
    rm -rf "$work"
done
exit $fail
