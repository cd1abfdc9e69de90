#!/bin/bash
# test_outset_rollback.sh GRANWAVE SRCDIR [SHIM]: a run whose output set cannot
# be placed whole leaves --out as the earlier run left it (issue 18). The set's
# commit (gw_io_outset.c) keeps every earlier file it replaces or removes aside
# first (a hard link, or a rename where no link can be made) and, when a rename
# fails part-way, puts them back, removes the new files and the temporaries,
# and exits 1 with one line naming the file and the OS error. Before, the
# files renamed before the failing one stayed: --out held a mix of two runs.
#  1 the shim (tests/alloc_fail_shim.c, LD_PRELOAD) fails the K-th rename of
#    falcon --n 1:8 --out D over an earlier falcon --n 1:16 (7 files placed, 2
#    of the earlier run's removed: 9 renames now, 7 before), for every K: exit
#    1, one stderr line naming a file of D and "Input/output error", D the
#    earlier run's files byte for byte (names and contents), no temporary and
#    no file kept aside; past the last rename, the new set (7 files, the two
#    earlier traces of N = 15 gone);
#  2 the same for chain --n 6 over chain --n 5 (4 files, 4 renames);
#  3 chain --n 6 into a directory with no earlier run, every K: exit 1 and D
#    empty;
#  4 as root where chattr works: an earlier file made immutable (chattr +i), one
#    the run replaces (falcon_summary.json) or one it would remove
#    (trace_n15.h5): exit 1 naming it and "Operation not permitted", D as it
#    was;
#  5 section 1 again where no hard link can be made (the shim fails every
#    link with EPERM, GW_FAIL_LINK_ALL): the earlier files are renamed aside
#    instead (16 renames), every K as in 1, and with none failing the new set
#    and nothing left aside.
# 37 checks (35 without chattr). On the code before, which made 7 renames in
# sections 1 and 5 (no removal by rename, no side names), 20 of its 26 checks
# fail: every K from 2 on in sections 1, 2, 3 and 5 and both of section 4; K =
# 1 (nothing placed yet) and the runs with no rename failing pass there.
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
SHIM="${3:-$(dirname "$GW")/tests/libgw_alloc_fail_shim.so}"
[ -f "$SHIM" ] || { echo "SKIP: no shim $SHIM (not built here)"; exit 0; }
SHIM=$(cd "$(dirname "$SHIM")" && pwd)/$(basename "$SHIM")
cd "$tmp" || exit 1
export LC_ALL=C
# chattr'd files must lose the flag before the scratch directory can go
trap 'chattr -R -i "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT

# renames ARGS...: how many renames the run ARGS makes (into a fresh copy of ref)
renames() {
    rm -rf d && cp -a ref d
    GW_FAIL_COUNT="$tmp/cnt" LD_PRELOAD="$SHIM" "$GW" "$@" >/dev/null 2>&1
    local w
    read -ra w <cnt
    rm -f cnt
    for ((i = 0; i < ${#w[@]}; i += 2)); do [ "${w[i]}" = rename ] && echo "${w[i + 1]}"; done
}

# as_before WHAT REASON ARGS...: ARGS (writing into d, a fresh copy of ref) exit
# 1 with one stderr line matching d/REASON (a file of d, the OS error); d is ref byte for byte
# with no other name (no temporary, nothing kept aside). The environment
# (GW_FAIL_IO, LD_PRELOAD) is the caller's.
as_before() {
    local what=$1 reason=$2
    shift 2
    "$GW" "$@" >/dev/null 2>err.txt
    local rc=$? lines extra
    lines=$(wc -l <err.txt)
    extra=$(diff -r ref d 2>&1 | head -c 300)
    if [ $rc -eq 1 ] && [ "$lines" -eq 1 ] && grep -q "d/$reason" err.txt && [ -z "$extra" ]; then
        ok "$what: exit 1, one line ($(cut -c1-110 err.txt)), --out as the earlier run left it"
    else
        ko "$what: exit $rc, $lines lines ($(head -c 200 err.txt)); differences: ${extra:-none}"
    fi
}

# sweep_k NAME ARGS...: as_before for every K from 1 to the run's renames, the
# K-th rename failing; then past the last one, the run's own files
sweep_k() {
    local name=$1 n
    shift
    n=$(renames "$@")
    echo "  $name: $n renames"
    for ((k = 1; k <= n; k++)); do
        rm -rf d && cp -a ref d
        GW_FAIL_IO=rename:$k LD_PRELOAD="$SHIM" as_before "$name, rename $k of $n failing" "[^ ]*: .*Input/output error" "$@"
    done
}

# 1: falcon over an earlier falcon that wrote more traces
"$GW" falcon --n 1:16 --quiet --out ref >/dev/null 2>&1 || ko "falcon --n 1:16 (the earlier run)"
sweep_k "falcon --n 1:8" falcon --n 1:8 --quiet --out d
rm -rf d && cp -a ref d
GW_FAIL_IO=rename:1000 LD_PRELOAD="$SHIM" "$GW" falcon --n 1:8 --quiet --out d >/dev/null 2>err.txt
rc=$?
got=$(ls -A d | tr '\n' ' ')
want="falcon_final_velocities.csv falcon_runs.csv falcon_summary.json report.md trace_n7.h5 trace_n7_beads.csv trace_n7_wall_force.csv "
[ $rc -eq 0 ] && { [ "$got" = "$want" ] || [ "$got" = "${want/trace_n7.h5 /}" ]; } && ! cmp -s ref/falcon_runs.csv d/falcon_runs.csv &&
    ok "falcon --n 1:8 with no rename failing: exit 0, its own files and the N = 15 traces gone" ||
    ko "falcon --n 1:8 with no rename failing: exit $rc, files: $got ($(head -c 200 err.txt))"

# 5 (first, while ref is falcon's): no hard link can be made (the shim fails
# every link, as a file system without them): the earlier files are renamed
# aside instead, and put back the same way
export GW_FAIL_LINK_ALL=1
sweep_k "falcon --n 1:8 without hard links" falcon --n 1:8 --quiet --out d
rm -rf d && cp -a ref d
LD_PRELOAD="$SHIM" "$GW" falcon --n 1:8 --quiet --out d >/dev/null 2>err.txt
rc=$?
got=$(ls -A d | tr '\n' ' ')
[ $rc -eq 0 ] && { [ "$got" = "$want" ] || [ "$got" = "${want/trace_n7.h5 /}" ]; } && ! cmp -s ref/falcon_runs.csv d/falcon_runs.csv &&
    ok "falcon --n 1:8 without hard links, no rename failing: exit 0, its own files, nothing left aside" ||
    ko "falcon --n 1:8 without hard links, no rename failing: exit $rc, files: $got ($(head -c 200 err.txt))"
unset GW_FAIL_LINK_ALL

# 2: chain over an earlier chain
rm -rf ref && "$GW" chain --n 5 --out ref >/dev/null 2>&1 || ko "chain --n 5 (the earlier run)"
sweep_k "chain --n 6" chain --n 6 --quiet --out d

# 3: no earlier run: nothing is left
rm -rf ref && mkdir ref
sweep_k "chain --n 6 into an empty directory" chain --n 6 --quiet --out d

# 4: an immutable earlier file (root, a file system with chattr)
rm -rf ref && "$GW" falcon --n 1:16 --quiet --out ref >/dev/null 2>&1
if [ "$(id -u)" -eq 0 ] && touch probe && chattr +i probe 2>/dev/null; then
    chattr -i probe
    for f in falcon_summary.json trace_n15.h5; do
        rm -rf d && cp -a ref d && chattr +i "d/$f"
        as_before "falcon --n 1:8 with d/$f immutable" "$f: .*Operation not permitted" falcon --n 1:8 --quiet --out d
        chattr -i "d/$f"
    done
else
    echo "SKIP: section 4 (not root, or no chattr +i here)"
fi

test_summary test_outset_rollback
