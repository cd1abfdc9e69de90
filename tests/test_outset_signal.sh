#!/bin/bash
# test_outset_signal.sh GRANWAVE SRCDIR SIGNAL_SHIM FAIL_SHIM: a signal handled
# on another thread while an output set is placed leaves --out holding wholly
# the earlier run's set or wholly the new one, never a mix (issue 18). The
# placing thread holds SIGINT, SIGTERM and SIGHUP, but the process's handler
# (gw_temps_on_signals) may run on any thread that does not (an OpenMP or pool
# worker): before, it removed the temporaries not yet renamed and ended the
# process between two renames, leaving some new files, some old ones and the
# earlier files kept aside under their side names. Now the placing is a
# critical section for the handler: it records the signal, and the placer
# sends it again once the set is wholly placed or wholly put back.
# The shim (tests/signal_shim.c) raises the signal on a thread of its own,
# with the signals unblocked, before the K-th rename, and waits for it.
#  1 falcon --n 1:8 --out D over an earlier falcon --n 1:16 (9 renames: 7
#    placed, 2 of the earlier run's moved aside), SIGTERM before every K:
#    killed by SIGTERM (exit 143: the run says it was interrupted), D holds
#    wholly the new set or wholly the earlier one, no temporary, no file kept
#    aside;
#  2 the same with SIGINT (130) and SIGHUP (129) before the middle rename;
#  3 chain --n 6 over chain --n 5 (4 renames), SIGTERM before every K;
#  4 a rollback interrupted: the 4th rename of the falcon run fails (the
#    failure shim, tests/alloc_fail_shim.c) and SIGTERM comes before each
#    rename that puts an earlier file back: exit 143, D wholly the earlier set;
#  5 no signal: the shims change nothing (exit 0, the new set).
# 19 checks. On the code before, 18 fail: every interrupted placing (sections
# 1 to 4) left the temporaries not yet placed, the files kept aside and,
# from K = 2, a mix of the two runs; only the run with no signal passes there.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
SIG_SHIM=$(shim_path "${3:-}" signal) && FAIL_SHIM=$(shim_path "${4:-}" alloc_fail) ||
    { echo "SKIP: no shims (not built here)"; exit 0; }
cd "$tmp" || exit 1
export LC_ALL=C

# same_file A B: A and B hold the same results (the wall time a run took, in
# the summary and the report, left out; an HDF5 file, which records when its
# objects were made, by size)
same_file() {
    case $1 in
    *.h5) [ "$(stat -c %s "$1")" = "$(stat -c %s "$2")" ] ;;
    *) cmp -s <(grep -v 'wall.time' "$1") <(grep -v 'wall.time' "$2") ;;
    esac
}

# holds D WANT: D holds WANT's set (the same names, the same results)
holds() {
    [ "$(ls -A "$1")" = "$(ls -A "$2")" ] || return 1
    local f
    for f in "$2"/*; do same_file "$1/${f##*/}" "$f" || return 1; done
}

# renames ARGS...: how many renames the run ARGS makes into a fresh copy of old
renames() {
    rm -rf d && cp -a old d
    GW_SIGNAL_COUNT="$tmp/cnt" LD_PRELOAD="$SIG_SHIM" "$GW" "$@" >/dev/null 2>&1
    local w
    read -ra w <cnt
    rm -f cnt
    echo "${w[1]}"
}

# interrupted WHAT WANT_RC ARGS...: ARGS (into d, a fresh copy of old; the
# environment is the caller's) end with WANT_RC and d holds wholly old's set
# or wholly new's, with nothing else in it
interrupted() {
    local what=$1 want=$2
    shift 2
    rm -rf d && cp -a old d
    "$GW" "$@" >/dev/null 2>err.txt
    local rc=$? got=mix
    if [ "$(ls -A old)" = "$(ls -A d)" ] && diff -r old d >/dev/null; then
        got=old
    elif holds d new; then
        got=new
    fi
    if [ $rc -eq "$want" ] && [ $got != mix ]; then
        ok "$what: exit $rc, --out wholly the $got set"
    else
        ko "$what: exit $rc (want $want), --out: $(ls -A d | tr '\n' ' ' | head -c 300) ($(head -c 200 err.txt))"
    fi
}

# sweep_k NAME ARGS...: SIGTERM before every rename of ARGS
sweep_k() {
    local name=$1 n k
    shift
    n=$(renames "$@")
    echo "  $name: $n renames"
    for ((k = 1; k <= n; k++)); do
        GW_SIGNAL_AT=$k:15 LD_PRELOAD="$SIG_SHIM" interrupted "$name, SIGTERM on another thread before rename $k of $n" 143 "$@"
    done
}

# 1, 2, 4, 5: falcon over an earlier falcon that wrote more traces
rm -rf old new d
"$GW" falcon --n 1:16 --quiet --out old >/dev/null 2>&1 || ko "falcon --n 1:16 (the earlier run)"
cp -a old d && "$GW" falcon --n 1:8 --quiet --out d >/dev/null 2>&1 && mv d new || ko "falcon --n 1:8 (the new set)"
sweep_k "falcon --n 1:8" falcon --n 1:8 --quiet --out d
GW_SIGNAL_AT=5:2 LD_PRELOAD="$SIG_SHIM" interrupted "falcon --n 1:8, SIGINT on another thread before rename 5" 130 \
    falcon --n 1:8 --quiet --out d
GW_SIGNAL_AT=5:1 LD_PRELOAD="$SIG_SHIM" interrupted "falcon --n 1:8, SIGHUP on another thread before rename 5" 129 \
    falcon --n 1:8 --quiet --out d
# 4: the 4th rename fails; the renames after it put the earlier files back
rm -rf d && cp -a old d
GW_FAIL_IO=rename:4 GW_SIGNAL_COUNT="$tmp/cnt" LD_PRELOAD="$SIG_SHIM $FAIL_SHIM" "$GW" falcon --n 1:8 --quiet --out d \
    >/dev/null 2>&1
read -ra w <cnt
echo "  falcon --n 1:8 with its 4th rename failing: ${w[1]} renames"
[ "${w[1]}" -gt 4 ] || ko "the rollback puts the earlier files back by rename (${w[1]} renames)"
for ((k = 5; k <= w[1]; k++)); do
    GW_FAIL_IO=rename:4 GW_SIGNAL_AT=$k:15 LD_PRELOAD="$SIG_SHIM $FAIL_SHIM" \
        interrupted "falcon --n 1:8, rename 4 failing, SIGTERM before rename $k (putting back)" 143 falcon --n 1:8 --quiet --out d
done
rm -rf d && cp -a old d
LD_PRELOAD="$SIG_SHIM $FAIL_SHIM" "$GW" falcon --n 1:8 --quiet --out d >/dev/null 2>&1
rc=$?
[ $rc -eq 0 ] && holds d new && ok "falcon --n 1:8 under the shims, no signal: exit 0, the new set" ||
    ko "falcon --n 1:8 under the shims, no signal: exit $rc, $(ls -A d | tr '\n' ' ')"

# 3: chain over an earlier chain (the same names)
rm -rf old new d && "$GW" chain --n 5 --out old >/dev/null 2>&1 || ko "chain --n 5 (the earlier run)"
cp -a old d && "$GW" chain --n 6 --out d >/dev/null 2>&1 && mv d new || ko "chain --n 6 (the new set)"
sweep_k "chain --n 6" chain --n 6 --out d

test_summary test_outset_signal
