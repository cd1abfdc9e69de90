#!/bin/bash
# test_afile_moved.sh GRANWAVE SRCDIR SIGNAL_SHIM: a single output file written
# outside an output set (layer-make --out D/s.txt, dispersion --wisdom
# D/w.wis) whose directory D is moved or replaced while it is being written
# (issue 18; the twenty-sixth session left it). Its temporary was known by its
# path alone: a SIGTERM taken by another thread then removed whatever had that
# name in the new D (a decoy) and left the temporary in D.old, and the commit
# failed with "No such file or directory" and left it there too. The file now
# holds its directory from the open to the commit (common/gw_io_afile.c):
# the handler removes the temporary in the held directory, and the commit
# places the file only when D still names it.
# Deterministic: tests/signal_shim.c runs GW_SIGNAL_RUN (the move) just before
# the run's 1st fsync (the file's), then raises the signal, if any, on a thread
# of its own with the signals unblocked.
#  1 layer-make, D moved and SIGTERM: 143, D.old and the new D empty;
#  2 the same with decoys in the new D under the temporary's own name: kept
#    byte for byte, D.old empty;
#  3 layer-make, D moved, no signal: exit 1, one line naming D/s.txt and the
#    move, D.old and the new D empty;
#  4 dispersion --wisdom, W moved (the user's wisdom in it), no signal: the
#    run's result stands (exit 0), the wisdom "not saved" with the move named,
#    W.old holds the user's file only;
#  5 controls: no move and SIGTERM: D empty; no move, no signal: the sample is
#    written and layer-impact runs on it.
# 13 checks; on the code before, 6 fail (every D.old and W.old holding the
# temporary, the decoys removed, the commit's "No such file or directory").
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
SHIM=$(shim_path "${3:-}" signal) || { echo "SKIP: no signal shim (not built here)"; exit 0; }
cd "$tmp" || exit 1
export LC_ALL=C
MAKE="layer-make --n 40 --quiet --out D/s.txt" # (--quiet: its stderr lines are counted, and past 3 s the progress display writes there)

# run SIG MOVE ARGS...: ARGS with D (or W) made empty, MOVE run and SIG (0:
# none) raised before the first fsync; sets rc
run() {
    local sig=$1 move=$2
    shift 2
    rm -rf D D.old W W.old
    mkdir D W
    GW_SIGNAL_FSYNC="1:$sig" GW_SIGNAL_RUN="$move" LD_PRELOAD="$SHIM" \
        env --default-signal=INT,TERM,HUP "$GW" "$@" >/dev/null 2>err.txt
    rc=$?
}
empty() { [ -d "$1" ] && [ -z "$(ls -A "$1")" ]; }
listing() { ls -A "$1" 2>/dev/null | tr '\n' ' '; }

# 1 D moved, SIGTERM
# shellcheck disable=SC2086
run 15 'mv D D.old && mkdir D' $MAKE
[ $rc -eq 143 ] && ok "layer-make, D moved, SIGTERM: killed by it (143)" || ko "layer-make, D moved, SIGTERM: exit $rc"
empty D.old && ok "  D.old is empty (the temporary removed there)" || ko "  D.old holds $(listing D.old)"
empty D && ok "  the new D is empty" || ko "  the new D holds $(listing D)"

# 2 decoys under the temporary's name in the new D
# shellcheck disable=SC2086
run 15 'mv D D.old && mkdir D && for f in D.old/*.tmp.*; do echo decoy >"D/${f##*/}"; done' $MAKE
n=$(ls -A D | wc -l)
kept=$(cat D/* 2>/dev/null | grep -c '^decoy$')
[ $rc -eq 143 ] && [ "$n" -eq 1 ] && [ "$kept" -eq 1 ] && ok "decoy in the new D, SIGTERM: 143, the decoy kept" ||
    ko "decoy in the new D, SIGTERM: exit $rc, the new D holds $n files, $kept decoys"
empty D.old && ok "  D.old is empty" || ko "  D.old holds $(listing D.old)"

# 3 D moved, no signal: the commit refuses to place the file
# shellcheck disable=SC2086
run 0 'mv D D.old && mkdir D' $MAKE
[ $rc -eq 1 ] && empty D && empty D.old && ok "layer-make, D moved, no signal: exit 1, nothing in D or D.old" ||
    ko "layer-make, D moved, no signal: exit $rc, D: $(listing D), D.old: $(listing D.old)"
last=$(tail -n 1 err.txt)
case $last in *"D/s.txt"*moved*) ok "  its last line names D/s.txt and the move" ;;
    *) ko "  its last line: $last" ;; esac
[ "$(grep -c . err.txt)" -eq 1 ] && ok "  and no other line" || ko "  $(grep -c . err.txt) lines"

# 4 the wisdom file, W moved with the user's wisdom in it
"$GW" dispersion --n 64 --wisdom w0.wis >/dev/null 2>&1 || ko "dispersion --wisdom w0.wis"
run 0 'cp w0.wis W/w.wis.keep && mv W W.old && mkdir W' dispersion --n 64 --wisdom W/w.wis
[ $rc -eq 0 ] && [ "$(listing W.old)" = "w.wis.keep " ] && empty W && grep -q "W/w.wis.*moved.*not saved" err.txt &&
    ok "dispersion --wisdom, W moved: exit 0, wisdom not saved and saying why, W.old holds the user's file only" ||
    ko "dispersion --wisdom, W moved: exit $rc, W.old: $(listing W.old), W: $(listing W)"
cmp -s w0.wis W.old/w.wis.keep && ok "  and it is unchanged" || ko "  the user's wisdom changed"

# 5 controls
# shellcheck disable=SC2086
run 15 true $MAKE
[ $rc -eq 143 ] && empty D && ok "no move, SIGTERM: 143, D empty" || ko "no move, SIGTERM: exit $rc, D holds $(listing D)"
# shellcheck disable=SC2086
run 0 true $MAKE
[ $rc -eq 0 ] && [ "$(listing D)" = "s.txt " ] && ok "no move, no signal: exit 0, D/s.txt written" ||
    ko "no move, no signal: exit $rc, D holds $(listing D)"
"$GW" layer-impact --sample D/s.txt --t-max 0.01 >/dev/null 2>err.txt
r=$?
[ $r -eq 0 ] && ok "  and layer-impact runs on it (exit 0)" ||
    ko "  layer-impact on it: exit $r, $(head -c 200 err.txt)"

test_summary test_afile_moved
