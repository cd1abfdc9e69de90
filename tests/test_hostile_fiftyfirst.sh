#!/bin/bash
# test_hostile_fiftyfirst.sh GRANWAVE SRCDIR: what the fifty-first hostile
# pass found, fixed at its root and asserted here.
#  1 An output the run would replace that is the file its standard output or
#    standard error is written to (`chain --out d > d/chain.json`,
#    `layer-make --out /dev/stdout > s.txt`, `--out /proc/self/fd/2 2> e.txt`,
#    a hard link to it): the run renamed its file over it, and the summary and
#    warnings it printed after went to the replaced file, lost, with exit 0.
#    The output checks (gw_out_file_check: layer-make's --out, dispersion's
#    --wisdom; gw_out_names_check: every --out set, sweep's journal and
#    table) refuse it before the run, naming the file and the stream, exit 2,
#    nothing written (a sweep's rerun `>> d/journal.csv` lost its lines with
#    the journal it rewrote). Controls: a file of --out that is not one of the run's
#    outputs (d/log.txt) takes the summary, and the run writes its files.
#  2 A signal that ends the program by default other than SIGINT, SIGTERM and
#    SIGHUP (SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU) left
#    layer-impact's staged snapshot_0.vtk.tmp.HOST.PID.XXXXXX and the --out
#    NEW/a it had made. One list of these signals (gw_io_end_signals) is held
#    while files are placed and handled to remove the temporaries and the
#    directories made, the process still ending by the signal. Controls:
#    SIGTERM (handled before) leaves nothing, and a run left alone writes.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

make_sample s40 --n 40 --quiet
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n' >c.ini

# 1 an output that is the file standard output or standard error writes to
# std_refused WHAT STREAM FILE CMD...: CMD (its stdout, or stderr, sent to
# FILE, made empty first) exits 2 with one line naming FILE's stream, and FILE
# and the directory it is in hold nothing else afterwards
std_refused() {
    local what=$1 stream=$2 file=$3; shift 3
    local dir
    dir=$(dirname "$file")
    rm -rf "$dir" && mkdir -p "$dir" && : >"$file"
    local rc left
    if [ "$stream" = output ]; then
        cpu_run 60 "$GW" "$@" >"$file" 2>std.err </dev/null
        rc=$?
    else
        cpu_run 60 "$GW" "$@" 2>"$file" >std.out </dev/null
        rc=$?
        cp "$file" std.err
    fi
    left=$(find "$dir" -mindepth 1 ! -path "$file" | tr '\n' ' ')
    [ $rc -eq 2 ] && [ "$(wc -l <std.err)" -eq 1 ] &&
        grep -q "is the file this run's standard $stream is written to" std.err && [ -z "$left" ] &&
        { [ "$stream" = error ] || [ ! -s "$file" ]; } &&
        ok "$what: refused naming standard $stream, nothing written" ||
        ko "$what: exit $rc, left '$left', $(head -c 300 std.err)"
}
std_refused "chain --out d > d/chain.json" output d/chain.json chain --n 2 --out d
std_refused "chain --out d 2> d/chain_beads.csv" error d/chain_beads.csv chain --n 2 --out d
std_refused "layer-impact --out d > d/impact.json" output d/impact.json layer-impact --sample s40 --out d --quiet
std_refused "falcon --out d > d/falcon_summary.json" output d/falcon_summary.json \
    falcon --n 1:3 --heights none --jobs 1 --quiet --out d
# a sweep's rerun appending its lines to the journal it reads and rewrites
rm -rf sj
cpu_run 60 "$GW" sweep c.ini --out sj --jobs 1 --quiet >/dev/null 2>&1 && [ -s sj/results.csv ] ||
    ko "the sweep into sj"
sum=$(md5sum <sj/journal.csv)
cpu_run 60 "$GW" sweep c.ini --out sj --jobs 1 >>sj/journal.csv 2>sj.err </dev/null
rc=$?
[ $rc -eq 2 ] && [ "$(wc -l <sj.err)" -eq 1 ] && grep -q "'sj/journal.csv' is the file this run's standard output" sj.err &&
    [ "$(md5sum <sj/journal.csv)" = "$sum" ] &&
    ok "sweep --out d >> d/journal.csv (a rerun): refused naming standard output, the journal as it was" ||
    ko "sweep --out d >> d/journal.csv: exit $rc, $(head -c 300 sj.err)"
std_refused "layer-make --out /dev/stdout > ls/s.txt" output ls/s.txt layer-make --n 20 --t-max 0.01 --quiet --out /dev/stdout
std_refused "layer-make --out /proc/self/fd/2 2> le/s.txt" error le/s.txt layer-make --n 20 --t-max 0.01 --quiet \
    --out /proc/self/fd/2
std_refused "dispersion --wisdom w/w > w/w" output w/w dispersion --n 64 --t-samples 4096 --quiet --wisdom w/w
# a hard link to an output, under another name
rm -rf hl && mkdir hl && : >hl/chain.json && ln hl/chain.json hl/log
cpu_run 60 "$GW" chain --n 2 --out hl >hl/log 2>hl.err </dev/null
rc=$?
[ $rc -eq 2 ] && grep -q "'hl/chain.json' is the file this run's standard output" hl.err && [ ! -s hl/log ] &&
    ok "chain --out d > d/log, a hard link to d/chain.json: refused" || ko "the hard link: exit $rc, $(head -c 300 hl.err)"
# controls: a file in --out that the run does not write takes what it prints
rm -rf c1 && mkdir c1
cpu_run 60 "$GW" chain --n 2 --out c1 >c1/log.txt 2>c1.err </dev/null &&
    grep -q "^granwave .* chain: n = 2" c1/log.txt && [ -s c1/chain.json ] &&
    ok "control: chain --out d > d/log.txt prints its summary there and writes d/chain.json" ||
    ko "control: chain --out d > d/log.txt: $(head -c 300 c1.err)"
cpu_run 60 "$GW" layer-make --n 20 --t-max 0.01 --out c1/s.txt >c1/make.txt 2>c1/make.err </dev/null &&
    grep -q "^granwave-layer-sample 1" c1/s.txt && grep -q "layer-make: 20 particles" c1/make.txt &&
    grep -q "did not settle" c1/make.err &&
    ok "control: layer-make --out s.txt > make.txt 2> make.err: the sample, the summary and the warning apart" ||
    ko "control: layer-make with its streams in files"

# 2 signals other than SIGINT, SIGTERM and SIGHUP
# stopped SIG: layer-impact --out NEW/a signalled once its first snapshot is
# staged; its exit status printed, what it left in $tmp/sig_left
stopped() {
    rm -rf NEW
    "$GW" layer-impact --sample s40 --t-max 2 --full --out NEW/a --quiet >/dev/null 2>sig.err </dev/null &
    local pid=$! k
    for k in $(seq 1 400); do
        compgen -G 'NEW/a/snapshot_0.vtk.tmp.*' >/dev/null && break
        sleep 0.025
    done
    kill -s "$1" "$pid"
    wait "$pid"
    local rc=$?
    find NEW 2>/dev/null | tr '\n' ' ' >sig_left
    echo $rc
}
for sig in USR1 USR2 ALRM VTALRM PROF XCPU; do
    num=$(kill -l "$sig")
    rc=$(stopped "$sig")
    [ "$rc" -eq $((128 + num)) ] && [ ! -s sig_left ] &&
        ok "SIG$sig mid-run: ended by it ($rc), no temporary and no --out NEW left" ||
        ko "SIG$sig mid-run: exit $rc, left: $(cat sig_left)"
done
rc=$(stopped TERM)
[ "$rc" -eq 143 ] && [ ! -s sig_left ] && ok "control: SIGTERM mid-run leaves nothing" ||
    ko "control: SIGTERM: exit $rc, left: $(cat sig_left)"
rm -rf NEW
cpu_run 60 "$GW" layer-impact --sample s40 --out NEW/a --quiet >/dev/null 2>&1 && [ -s NEW/a/snapshot_0.vtk ] &&
    [ -z "$(compgen -G 'NEW/a/*.tmp.*')" ] && ok "control: the run left alone writes NEW/a" ||
    ko "control: layer-impact --out NEW/a"

test_summary test_hostile_fiftyfirst
