#!/bin/bash
# test_hostile_sixteenth_tools.sh GRANWAVE SRCDIR: the sixteenth hostile pass, over
# what a new user runs around the program: the plot scripts (notebooks/*.py),
# setup.sh and the bench scripts. Each check asserts behaviour (exit code, one
# line, what is written, no hang); each failed on the code before this pass.
#  1 a FIFO where a plot script expects a JSON or CSV file hung it for good
#    (plot_drop.py, plot_sheets.py, plot_wave_speed_layer.py); gwdata opens
#    regular files only now: exit 2, one line naming the file "a FIFO".
#  2 malformed files of a run (a summary whose v_imp is null, a bead trace with
#    no rows) gave a Python traceback (exit 1) in plot_falcon.py; exit 2 now.
#  3 plot_sheets.py on a directory without runs made DIR/figures before it
#    refused, and ignored a third argument; nothing is made now, exit 2.
#  4 plot_wave_speed_layer.py plot on tables without rows wrote fit.json, then
#    crashed (StopIteration); exit 2 now and nothing written.
#  5 a figure that cannot be written (figures/ a file) gave a traceback in
#    plot_drop.py and plot_wave_speed_layer.py; exit 1, one line now.
#  6 setup.sh with JOBS=abc configured a build, then cmake printed its usage
#    (exit 1); an extra argument was ignored. Both refused first now (exit 2).
#  7 bench_long ignored a lone last option (--bogus, "--reps" without a value)
#    and ran the whole 1e6-bead benchmark; bench_chain took "junk" for 1
#    repetition and a misspelt mode for the full run; the bench scripts' counts
#    (ROUNDS, REPS, NPT, DEM_STEPS) were checked after work or not at all.
set -u
GW=$1
SRC=$2
B=$(dirname "$GW")
PY=/usr/bin/python3
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; checks=0
ok() { checks=$((checks + 1)); echo "ok   $1"; }
bad() { checks=$((checks + 1)); fails=$((fails + 1)); echo "FAIL $1"; }
# expect NAME RC CMD...: exit RC within 20 s, exactly one line on stderr, no traceback
expect() {
    local name=$1 want=$2; shift 2
    timeout 20 "$@" >"$tmp/out" 2>"$tmp/err"
    local rc=$? n; n=$(wc -l <"$tmp/err")
    if [ "$rc" = "$want" ] && [ "$n" = 1 ] && ! grep -q Traceback "$tmp/err"; then
        ok "$name: exit $rc: $(cat "$tmp/err")"
    else
        bad "$name: exit $rc (want $want), $n stderr lines: $(tail -2 "$tmp/err" | tr '\n' ' ')"
    fi
}
P=(env MPLBACKEND=Agg GRANWAVE="$GW" "$PY")

# 1 FIFOs
mkdir -p "$tmp/drop/column_h5.1_10ms"; mkfifo "$tmp/drop/column_h5.1_10ms/drop.json"
expect "1 plot_drop, drop.json a FIFO" 2 "${P[@]}" "$SRC/notebooks/plot_drop.py" "$tmp/drop"
grep -q FIFO "$tmp/err" || bad "1 plot_drop names the FIFO"
mkdir -p "$tmp/sheets"; mkfifo "$tmp/sheets/softwall_fitted_tol05.json"
expect "1 plot_sheets, softwall JSON a FIFO" 2 "${P[@]}" "$SRC/notebooks/plot_sheets.py" "$tmp/sheets"
mkdir -p "$tmp/ws"
printf 'tag,sample,rings,mass_law,gravity,vi,x,wave_speed_xcorr,wave_speed_xcorr_err,wave_xcorr_gaps,wave_speed,wave_speed_err,wave_speed_kinetic,wave_rings,energy_error,t_end,wall_time_ms\n' >"$tmp/ws/impacts.csv"
printf 'tag,vi,x,ring,r_mid,r_next,delay,rho\n' >"$tmp/ws/delays.csv"
cp -r "$tmp/ws" "$tmp/ws_fifo"; echo 'disc,s,7,x,0,1,0,500,1,0,500,1,500,7,0,0.01,1' >>"$tmp/ws_fifo/impacts.csv"
rm "$tmp/ws_fifo/delays.csv"; mkfifo "$tmp/ws_fifo/delays.csv"
expect "1 plot_wave_speed_layer, delays.csv a FIFO" 2 "${P[@]}" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/ws_fifo"

# 2 malformed falcon run
"$GW" falcon --n 1:8 --out "$tmp/fal" --quiet >/dev/null 2>&1 || bad "2 granwave falcon --n 1:8 ran"
cp -r "$tmp/fal" "$tmp/fal_null"
"$PY" -c "import json,sys;p=sys.argv[1];d=json.load(open(p));d['velocities'][0]['v_imp']=None;json.dump(d,open(p,'w'))" \
    "$tmp/fal_null/falcon_summary.json"
expect "2 plot_falcon, summary v_imp null" 2 "${P[@]}" "$SRC/notebooks/plot_falcon.py" "$tmp/fal_null"
cp -r "$tmp/fal" "$tmp/fal_rows"; grep -v '^[0-9-]' "$tmp/fal/trace_n7_beads.csv" >"$tmp/fal_rows/trace_n7_beads.csv"
expect "2 plot_falcon, bead trace without rows" 2 "${P[@]}" "$SRC/notebooks/plot_falcon.py" "$tmp/fal_rows"
for d in fal_null fal_rows; do [ ! -e "$tmp/$d/figures" ] || bad "2 $d: figures made on a refused run"; done

# 3 plot_sheets writes nothing on a refusal, refuses a third argument
mkdir "$tmp/empty"
expect "3 plot_sheets, no runs" 2 "${P[@]}" "$SRC/notebooks/plot_sheets.py" "$tmp/empty"
[ ! -e "$tmp/empty/figures" ] && ok "3 plot_sheets made no figures/" || bad "3 plot_sheets made $tmp/empty/figures"
expect "3 plot_sheets, a third argument" 2 "${P[@]}" "$SRC/notebooks/plot_sheets.py" "$SRC/data/measured/sheets" "$tmp/sheets_out" junk
[ ! -e "$tmp/sheets_out" ] && ok "3 nothing made" || bad "3 $tmp/sheets_out made"

# 4 wave-speed tables without rows
expect "4 plot_wave_speed_layer, no rows" 2 "${P[@]}" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/ws"
[ ! -e "$tmp/ws/fit.json" ] && [ ! -e "$tmp/ws/figures" ] && ok "4 nothing written" || bad "4 fit.json or figures/ written"

# 5 figures that cannot be written
cp -r "$SRC/data/measured/layer_wave_speed" "$tmp/ws_ro"; rm -rf "$tmp/ws_ro/figures" "$tmp/ws_ro/fit.json"; touch "$tmp/ws_ro/figures"
expect "5 plot_wave_speed_layer, figures/ a file" 1 "${P[@]}" "$SRC/notebooks/plot_wave_speed_layer.py" plot "$tmp/ws_ro"
[ ! -e "$tmp/ws_ro/fit.json" ] && ok "5 no fit.json without its figures" || bad "5 fit.json written without figures"
mkdir -p "$tmp/dr"; for c in column_h5.1_10ms column_h1.9_10ms bead_h5.1_300ms block_h5.1_300ms; do
    cp -r "$SRC/data/measured/drop/$c" "$tmp/dr/" 2>/dev/null; done
if [ -f "$tmp/dr/column_h5.1_10ms/drop.json" ] && [ -f "$tmp/dr/block_h5.1_300ms/drop.json" ]; then
    touch "$tmp/dr/figures"
    expect "5 plot_drop, figures/ a file" 1 "${P[@]}" "$SRC/notebooks/plot_drop.py" "$tmp/dr"
fi

# 6 setup.sh
expect "6 setup.sh JOBS=abc" 2 env JOBS=abc BUILD_DIR="$tmp/sb" bash "$SRC/setup.sh" build
[ ! -e "$tmp/sb" ] && ok "6 no build directory made" || bad "6 $tmp/sb made before the refusal"
expect "6 setup.sh, an extra argument" 2 env JOBS=abc BUILD_DIR="$tmp/sb2" bash "$SRC/setup.sh" build extra
expect "6 setup.sh, unknown mode" 2 bash "$SRC/setup.sh" bogus

# 7 bench
expect "7 bench_long --bogus" 2 "$B/bench/bench_long" --bogus
expect "7 bench_long --reps without a value" 2 "$B/bench/bench_long" --nmax 1000 --reps
expect "7 bench_long --nmax 1e5 (not an integer count)" 2 "$B/bench/bench_long" --nmax 1e5x
expect "7 bench_chain junk" 2 "$B/bench/bench_chain" junk
expect "7 bench_chain, misspelt mode" 2 "$B/bench/bench_chain" 10 rsh
expect "7 falcon_vs_lsoda.sh ROUNDS=0" 2 bash "$SRC/bench/falcon_vs_lsoda.sh" "$(dirname "$B")/$(basename "$B")" 0
expect "7 run_peers.sh REPS=x" 2 env REPS=x bash "$SRC/bench/run_peers.sh" "$B"
expect "7 bench_layer.sh NPT=x" 2 env NPT=x bash "$SRC/bench/bench_layer.sh" "$B"
expect "7 bench_layer_peer.sh DEM_STEPS=1e3" 2 env DEM_STEPS=1e3 LMP=/bin/false bash "$SRC/bench/bench_layer_peer.sh" "$B"

echo "$((checks - fails)) of $checks checks passed"
[ "$fails" = 0 ]
