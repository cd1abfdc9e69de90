#!/bin/bash
# test_hostile_seventeenth_tools.sh GRANWAVE SRCDIR: the seventeenth hostile pass over
# what a new user runs around the program: setup.sh's arguments and the bench scripts'
# BUILD_DIR, arguments and path variables. Each check asserts behaviour (exit code, one
# line naming the input, nothing done); the numbered ones failed on the code before.
#  1 `./setup.sh ""` (an empty job) ran the main job; refused now, exit 2, one line
#    naming '' (JOBS=abc keeps the old code from building: it fails on the message).
#    `--help` printed "unknown mode" (exit 2); it prints the usage, exit 0.
#  2 the bench scripts took a relative BUILD_DIR from the checkout, setup.sh from the
#    caller's directory (since the sixteenth pass). A relative BUILD_DIR is taken from
#    the caller's directory now: falcon_vs_lsoda.sh with a symlink to the build made in
#    a scratch directory, ROUNDS 1 (about 4 s), runs and prints its median line; a
#    missing one is refused naming the caller's path, not cmake's "is not a directory".
#  3 the bench scripts ignored extra arguments, took an empty BUILD_DIR for build/, and
#    took --help for a build directory; bench_layer.sh ran everything on a misspelt
#    ONLY; bench_layer_peer.sh built before it looked for LAMMPS and took a relative LMP
#    from the checkout. Each refused first now (exit 2), --help prints the header.
#  4 the plot scripts (notebooks/plot_*.py) on a stdout that cannot be written (a
#    full disk, a pipe closed by `| head`) gave a 7-line traceback; one line now
#    ("plot_drop.py: stdout: write failed: ..."), exit 1 (gwdata.run_main).
#  5 `granwave help chain` printed the command list and `granwave version extra` the
#    version, the extra words ignored (exit 0); help CMD prints CMD's help now, and an
#    unknown command or anything more is refused (exit 2, one line).
#  6 plot_wave_speed_layer.py plot printed "beta(5-40) = nan +- nan" for a series with
#    fewer than 3 speeds in 5-40 m/s (two stored series) and a matplotlib warning for
#    the single-point error bars (NaN); it says "not fitted (2 speed(s) ..., 3 needed)"
#    now, draws an unknown error as no bar, fit.json byte-identical.
set -u
GW=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$(cd "$2" && pwd)
B=$(cd "$(dirname "$GW")" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; checks=0
ok() { checks=$((checks + 1)); echo "ok   $1"; }
bad() { checks=$((checks + 1)); fails=$((fails + 1)); echo "FAIL $1"; }
# expect NAME RC PATTERN CMD...: exit RC within 20 s, exactly one stderr line matching
# PATTERN (grep -E), run from $tmp/caller
mkdir -p "$tmp/caller"
expect() {
    local name=$1 want=$2 pat=$3; shift 3
    (cd "$tmp/caller" && timeout 20 "$@" >"$tmp/out" 2>"$tmp/err" </dev/null)
    local rc=$? n; n=$(wc -l <"$tmp/err")
    if [ "$rc" = "$want" ] && [ "$n" = 1 ] && grep -qE -- "$pat" "$tmp/err"; then
        ok "$name: exit $rc: $(cat "$tmp/err")"
    else
        bad "$name: exit $rc (want $want), $n stderr lines: $(tail -2 "$tmp/err" | tr '\n' ' ')"
    fi
}

# 1 setup.sh
expect "1 setup.sh ''" 2 "unknown mode ''" env JOBS=abc BUILD_DIR="$tmp/sb" bash "$SRC/setup.sh" ""
[ ! -e "$tmp/sb" ] && ok "1 no build directory made" || bad "1 $tmp/sb made"
(cd "$tmp/caller" && env JOBS=abc bash "$SRC/setup.sh" --help >"$tmp/out" 2>"$tmp/err")
rc=$?
if [ $rc = 0 ] && grep -q "usage: setup.sh \[main|test|build|bench\]" "$tmp/out" && [ ! -s "$tmp/err" ]; then
    ok "1 setup.sh --help: $(cat "$tmp/out")"
else
    bad "1 setup.sh --help: exit $rc, $(head -1 "$tmp/out") $(head -1 "$tmp/err")"
fi
# (checked before: an extra argument, an unknown job, JOBS; the same rules hold for options)
expect "setup.sh -x" 2 "unknown mode '-x'" env JOBS=abc bash "$SRC/setup.sh" -x
expect "setup.sh main ''" 2 "unexpected argument ''" env JOBS=abc bash "$SRC/setup.sh" main ""
expect "setup.sh '' main" 2 "unexpected argument 'main'" env JOBS=abc bash "$SRC/setup.sh" "" main

# 2 a relative BUILD_DIR from the caller's directory
ln -s "$B" "$tmp/caller/mybuild"
rel=mybuild
(cd "$tmp/caller" && timeout 120 bash "$SRC/bench/falcon_vs_lsoda.sh" "$rel" 1 >"$tmp/out" 2>"$tmp/err")
rc=$?
if [ $rc = 0 ] && grep -q "^median: falcon" "$tmp/out"; then
    ok "2 falcon_vs_lsoda.sh $rel 1 from the caller's directory: $(tail -1 "$tmp/out")"
else
    bad "2 falcon_vs_lsoda.sh $rel 1: exit $rc: $(tail -2 "$tmp/err" | tr '\n' ' ')"
fi
for s in run.sh run_peers.sh bench_layer.sh bench_layer_peer.sh falcon_vs_lsoda.sh; do
    expect "2 $s nobuild" 2 "$s: BUILD_DIR '$tmp/caller/nobuild' is not a configured build directory" \
        bash "$SRC/bench/$s" nobuild
done
expect "2 rhs_vs_v01.sh 3 nobuild" 2 "BUILD_DIR '$tmp/caller/nobuild'" bash "$SRC/bench/rhs_vs_v01.sh" 3 nobuild
expect "2 bench_layer_peer.sh, a relative LMP" 2 "LMP '$tmp/caller/bin/lmp' is not an executable" \
    env LMP=bin/lmp bash "$SRC/bench/bench_layer_peer.sh" "$rel"

# 3 arguments and variables
for s in run.sh run_peers.sh bench_layer.sh bench_layer_peer.sh; do
    expect "3 $s, an extra argument" 2 "$s: unexpected argument 'extra'" bash "$SRC/bench/$s" "$rel" extra
    expect "3 $s ''" 2 "$s: BUILD_DIR is empty" bash "$SRC/bench/$s" ""
done
expect "3 falcon_vs_lsoda.sh, a third argument" 2 "unexpected argument 'extra'" \
    bash "$SRC/bench/falcon_vs_lsoda.sh" "$rel" 1 extra
expect "3 rhs_vs_v01.sh, a third argument" 2 "unexpected argument 'extra'" \
    bash "$SRC/bench/rhs_vs_v01.sh" 3 "$rel" extra
expect "3 bench_layer.sh ONLY=sped" 2 "ONLY must be empty or 'speed', got 'sped'" \
    env ONLY=sped bash "$SRC/bench/bench_layer.sh" "$rel"
for s in run.sh rhs_vs_v01.sh falcon_vs_lsoda.sh run_peers.sh bench_layer.sh bench_layer_peer.sh; do
    (cd "$tmp/caller" && timeout 20 bash "$SRC/bench/$s" --help >"$tmp/out" 2>"$tmp/err")
    rc=$?
    if [ $rc = 0 ] && head -1 "$tmp/out" | grep -q "^bench/$s \[" && [ ! -s "$tmp/err" ]; then
        ok "3 $s --help: $(head -1 "$tmp/out")"
    else
        bad "3 $s --help: exit $rc, $(head -1 "$tmp/err")"
    fi
done

# 4 the plot scripts on a stdout that cannot be written
for s in plot_falcon plot_drop plot_sheets plot_wave_speed_layer; do
    (cd "$tmp/caller" && timeout 20 /usr/bin/python3 "$SRC/notebooks/$s.py" --help >/dev/full 2>"$tmp/err")
    rc=$?
    if [ $rc = 1 ] && [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q "^$s.py: stdout: write failed" "$tmp/err"; then
        ok "4 $s.py --help >/dev/full: $(cat "$tmp/err")"
    else
        bad "4 $s.py --help >/dev/full: exit $rc, $(wc -l <"$tmp/err") stderr lines: $(tail -1 "$tmp/err")"
    fi
done

# 5 the program's own help and version
(cd "$tmp/caller" && timeout 20 "$GW" help layer-stats >"$tmp/out" 2>"$tmp/err")
rc=$?
if [ $rc = 0 ] && head -1 "$tmp/out" | grep -q "^usage: granwave layer-stats" && [ ! -s "$tmp/err" ]; then
    ok "5 granwave help layer-stats: $(head -1 "$tmp/out")"
else
    bad "5 granwave help layer-stats: exit $rc, $(head -1 "$tmp/out") $(head -1 "$tmp/err")"
fi
expect "5 granwave help bogus" 2 "unknown command 'bogus'" "$GW" help bogus
expect "5 granwave help chain extra" 2 "granwave help: unexpected argument 'extra'" "$GW" help chain extra
expect "5 granwave version extra" 2 "granwave version: unexpected argument 'extra'" "$GW" version extra
expect "5 granwave --version extra" 2 "granwave --version: unexpected argument 'extra'" "$GW" --version extra

# 6 plot_wave_speed_layer.py plot on the stored series: fits a series cannot give said so
cp -r "$SRC/data/measured/layer_wave_speed" "$tmp/lws"; rm -rf "$tmp/lws/figures" "$tmp/lws/fit.json"
(cd "$tmp/caller" && MPLBACKEND=Agg timeout 60 /usr/bin/python3 "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/lws" \
    >"$tmp/out" 2>"$tmp/err")
rc=$?
if [ $rc = 0 ] && ! grep -qi nan "$tmp/out" && grep -q "^seed2_r7: beta(5-40) not fitted (2 speed(s) in 5-40 m/s, 3 needed)" "$tmp/out"; then
    ok "6 plot_wave_speed_layer.py: $(grep '^seed2_r7' "$tmp/out")"
else
    bad "6 plot_wave_speed_layer.py: exit $rc, $(grep -i nan "$tmp/out" | head -1)"
fi
cmp -s "$tmp/lws/fit.json" "$SRC/data/measured/layer_wave_speed/fit.json" && ok "6 fit.json unchanged" \
    || bad "6 fit.json differs from the stored one"
# one impact (the first stored one): no fit, one-point error bars
mkdir "$tmp/lws1"
awk -F, '/^#/ || /^tag,/ { print; next } $1 == "disc" && !done { print; done = 1 }' \
    "$SRC/data/measured/layer_wave_speed/impacts.csv" >"$tmp/lws1/impacts.csv"
read -r vi x < <(awk -F, '!/^#/ && !/^tag,/ { print $6, $7 }' "$tmp/lws1/impacts.csv")
awk -F, -v vi="$vi" -v x="$x" '/^#/ || /^tag,/ || ($1 == "disc" && $2 == vi && $3 == x)' \
    "$SRC/data/measured/layer_wave_speed/delays.csv" >"$tmp/lws1/delays.csv"
(cd "$tmp/caller" && MPLBACKEND=Agg timeout 60 /usr/bin/python3 "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/lws1" \
    >"$tmp/out" 2>"$tmp/err")
rc=$?
if [ $rc = 0 ] && ! grep -qi nan "$tmp/out" && [ ! -s "$tmp/err" ] && grep -q "not fitted (1 speed(s)" "$tmp/out"; then
    ok "6 plot_wave_speed_layer.py, one impact: $(cat "$tmp/out")"
else
    bad "6 plot_wave_speed_layer.py, one impact: exit $rc, $(head -1 "$tmp/out"); $(wc -l <"$tmp/err") stderr lines $(head -1 "$tmp/err")"
fi

echo "$((checks - fails)) of $checks checks passed"
[ "$fails" = 0 ]
