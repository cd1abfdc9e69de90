#!/bin/bash
# test_out_moved_signal.sh GRANWAVE SRCDIR SIGNAL_SHIM: a SIGINT, SIGTERM or
# SIGHUP that ends a run after its --out directory was moved or replaced
# removes the run's temporaries in the moved directory and nothing at the old
# path (issue 18; the thirtieth pass left it). The signal handler's table of
# temporaries (common/gw_io_temps.c) held paths: it unlinked D/NAME.tmp.* in
# whatever D named by then, and left every staged temporary in D.old. Now a
# temporary of an output set is bound to the directory the set holds open,
# and the handler removes it there by its last name (unlinkat).
# Deterministic: the shim (tests/signal_shim.c) runs GW_SIGNAL_RUN, a shell
# command that moves D, just before the K-th fsync (the K-th file of the run
# made durable: K-1 staged temporaries and the one being written exist), then
# raises the signal on a thread of its own with the signals unblocked.
#  1 layer-impact --full, falcon and chain into D (the user's mine.txt in it),
#    "mv D D.old && mkdir D" and SIGTERM before the 3rd fsync: exit 143, D.old
#    holds the user's file and nothing else, the new D is empty;
#  2 the same with SIGINT (130) and SIGHUP (129) (layer-impact);
#  3 D replaced by a link to another directory T: T empty, D.old as before;
#  4 the new D holds decoys under the very names of the temporaries (copied
#    from D.old before the signal): they stay, byte for byte, and D.old is
#    clean (before, the handler removed the decoys and left the temporaries);
#  5 no move: the temporaries in D removed, as before (a control);
#  6 the last fsync of falcon's set: all its temporaries gone the same way;
#  7 a sweep's journal in the making (a temporary in the sweep's held
#    directory): moved and signalled before its fsync, removed there.
# 25 checks; on the code before the session, 10 fail (every D.old in 1 to 4, 6 and 7, and
# the decoys in 4, which the handler removed); the exit codes, the empty new
# directories and the control pass there. 7's second check fails on the
# session's merge before the journal's temporary was bound to the directory.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
SHIM=$(shim_path "${3:-}" signal) || { echo "SKIP: no signal shim (not built here)"; exit 0; }
cd "$tmp" || exit 1
export LC_ALL=C
"$GW" layer-make --n 60 --out s.txt >/dev/null 2>err.txt || { echo "FAIL: layer-make: $(head -c 200 err.txt)"; exit 1; }
IMPACT="layer-impact --sample s.txt --t-max 0.05 --full --out D"

# run K SIG MOVE ARGS...: ARGS into D (holding the user's mine.txt), MOVE run
# and SIG raised before the K-th fsync; sets rc. The run is started under
# `env --default-signal` (the job of a script ignores SIGINT).
run() {
    local k=$1 sig=$2 move=$3
    shift 3
    rm -rf D D.old T
    mkdir D && echo keep >D/mine.txt
    GW_SIGNAL_FSYNC="$k:$sig" GW_SIGNAL_RUN="$move" LD_PRELOAD="$SHIM" \
        env --default-signal=INT,TERM,HUP "$GW" "$@" >/dev/null 2>err.txt
    rc=$?
}

# only_mine DIR: DIR holds the user's file and nothing else
only_mine() { [ "$(ls -A "$1" 2>/dev/null)" = mine.txt ] && [ "$(cat "$1/mine.txt")" = keep ]; }
listing() { ls -A "$1" 2>/dev/null | tr '\n' ' '; }
MOVE='mv D D.old && mkdir D'

# 1 three commands, SIGTERM
for cmd in "$IMPACT" "falcon --n 1:4 --quiet --out D" "chain --n 5 --out D"; do
    name=${cmd%% *}
    # shellcheck disable=SC2086
    run 3 15 "$MOVE" $cmd
    [ $rc -eq 143 ] && ok "$name, D moved, SIGTERM: killed by it (143)" || ko "$name, D moved, SIGTERM: exit $rc, $(head -c 200 err.txt)"
    only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(listing D.old)"
    [ -z "$(ls -A D)" ] && ok "  the new D is empty" || ko "  the new D holds $(listing D)"
done

# 2 SIGINT and SIGHUP
for s in 2:130:SIGINT 1:129:SIGHUP; do
    IFS=: read -r n want name <<<"$s"
    # shellcheck disable=SC2086
    run 3 "$n" "$MOVE" $IMPACT
    [ "$rc" -eq "$want" ] && ok "layer-impact, D moved, $name: killed by it ($want)" || ko "layer-impact, D moved, $name: exit $rc"
    only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(listing D.old)"
done

# 3 D replaced by a link to another directory
# shellcheck disable=SC2086
run 4 15 'mv D D.old && mkdir T && echo t >T/theirs.txt && ln -s T D' $IMPACT
[ $rc -eq 143 ] && ok "D replaced by a link to T, SIGTERM: 143" || ko "D replaced by a link to T, SIGTERM: exit $rc"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(listing D.old)"
[ "$(listing T)" = "theirs.txt " ] && [ "$(cat T/theirs.txt)" = t ] && ok "  T as it was" || ko "  T holds $(listing T)"

# 4 decoys at the old path under the temporaries' own names
# shellcheck disable=SC2086
run 3 15 'mv D D.old && mkdir D && for f in D.old/*.tmp.*; do echo decoy >"D/${f##*/}"; done' $IMPACT
[ $rc -eq 143 ] && ok "decoys in the new D, SIGTERM: 143" || ko "decoys in the new D, SIGTERM: exit $rc"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(listing D.old)"
n=$(ls -A D | wc -l)
kept=$(cat D/* 2>/dev/null | grep -c '^decoy$')
[ "$n" -ge 2 ] && [ "$kept" -eq "$n" ] && ok "  the $n decoys in the new D kept" || ko "  the new D holds $n files, $kept decoys"

# 5 the control: no move, the temporaries removed in D
# shellcheck disable=SC2086
run 3 15 true $IMPACT
[ $rc -eq 143 ] && only_mine D && ok "no move, SIGTERM: 143, D holds the user's file only" || ko "no move: exit $rc, D holds $(listing D)"

# 6 the last fsync of falcon's set (4 files)
run 4 15 "$MOVE" falcon --n 1:4 --quiet --out D
[ $rc -eq 143 ] && ok "falcon, its 4th file: 143" || ko "falcon, its 4th file: exit $rc"
only_mine D.old && ok "  D.old holds the user's file only" || ko "  D.old holds $(listing D.old)"
[ -z "$(ls -A D)" ] && ok "  the new D is empty" || ko "  the new D holds $(listing D)"

# 7 a sweep's journal, made under a temporary name in the sweep's directory
# (held open since the twenty-sixth session): the directory moved and SIGTERM
# before that temporary's fsync (the run's first): removed in the moved
# directory (the table of temporaries held its path: journal.csv.new.* stayed)
printf '[sweep]\nmodel = chain\nout = SW\n[grid]\nn = 2:3\n[params]\nvimp = 0.1\n' >sw.ini
rm -rf SW SW.old
GW_SIGNAL_FSYNC="1:15" GW_SIGNAL_RUN="mv SW SW.old" LD_PRELOAD="$SHIM" \
    env --default-signal=INT,TERM,HUP "$GW" sweep sw.ini --quiet >/dev/null 2>err.txt
rc=$?
[ $rc -eq 143 ] && ok "a sweep's journal in the making: 143" || ko "a sweep's journal in the making: exit $rc"
[ -d SW.old ] && [ -z "$(ls -A SW.old)" ] && [ ! -e SW ] && ok "  the moved SW.old is empty" ||
    ko "  SW.old holds $(listing SW.old)"

test_summary test_out_moved_signal
