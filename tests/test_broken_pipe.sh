#!/bin/bash
# test_broken_pipe.sh GRANWAVE SRCDIR: a reader that leaves early does not end
# a run (issue 18). `granwave sweep CONFIG 2>&1 | head -1` made the sweep's
# next progress line kill it by SIGPIPE: exit 141, its journal part-written and
# no results.csv (a rerun resumed it). The program now ignores SIGPIPE: a write
# to the closed pipe fails with EPIPE, progress lines are dropped, the sweep
# runs every case and writes its table, and the failed stdout is the run's
# failure (exit 1, as a full disk is). Each run is started with SIGPIPE at its
# default action (env --default-signal=PIPE), whatever the test's parent set.
#  1 a chain sweep of four 300-bead cases on one thread (several seconds, so a
#    progress line comes while cases run) into a pipe that `head -1` closes:
#    not killed by a signal, exit 0 (a sweep's lines are all on stderr, and a
#    lost progress line is no failure), results.csv byte for byte the table of
#    the same sweep run --quiet with nothing closed, no temporary left;
#  2 chain --json --out D with its stdout a pipe whose reader is gone before
#    it starts: not killed, exit 1 naming stdout and the broken pipe, D's
#    chain.json written and whole.
# 5 of the 8 checks fail on the code before (killed: exit 141 and no table;
# killed by SIGPIPE at the JSON).
# shellcheck source=test_lib.sh
. "$(dirname "$0")/test_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

cfg() { # cfg OUT: the sweep's config into OUT
    printf '[sweep]\nmodel = chain\nout = %s\n[params]\nn = 300\n[grid]\nvimp = 0.1, 0.2, 0.3, 0.4\n' "$1"
}
cfg ref > ref.ini
cfg piped > piped.ini

if ! "$GW" sweep ref.ini --jobs 1 --quiet > ref.log 2>&1; then
    ko "the reference sweep ran (exit $?): $(head -c 300 ref.log)"
    test_summary test_broken_pipe
    exit 1
fi

env --default-signal=PIPE "$GW" sweep piped.ini --jobs 1 2>&1 | head -1 > head.txt
rc=${PIPESTATUS[0]}
if [ "$rc" -lt 128 ]; then ok "sweep | head -1: not killed by a signal (exit $rc)"; else ko "sweep | head -1: killed by signal $((rc - 128)) (exit $rc)"; fi
if [ "$rc" -eq 0 ]; then ok "sweep | head -1: exit 0 (its lines are on stderr)"; else ko "sweep | head -1: exit $rc, not 0"; fi
if [ -f piped/results.csv ] && cmp -s ref/results.csv piped/results.csv; then
    ok "sweep | head -1: results.csv written, byte for byte the --quiet run's"
else
    if [ -f piped/results.csv ]; then ko "sweep | head -1: results.csv differs from the --quiet run's"; else ko "sweep | head -1: no results.csv"; fi
fi
if grep -q '^sweep: 4 cases' head.txt; then ok "sweep | head -1: its first line reached the reader"; else ko "sweep | head -1: first line '$(cat head.txt)'"; fi
left=$(ls -A piped | grep '\.tmp\.' | tr '\n' ' ')
if [ -z "$left" ]; then ok "sweep | head -1: no temporary left"; else ko "sweep | head -1: temporaries left: $left"; fi

# closed_stdout CMD...: CMD run with SIGPIPE at its default action and its
# stdout a pipe whose read end is closed before it starts; prints its exit
# code (128 + the signal when one ended it), its stderr into closed.err
closed_stdout() {
    /usr/bin/python3 -c '
import os, subprocess, sys
r, w = os.pipe()
os.close(r)
with open("closed.err", "wb") as err:
    p = subprocess.run(sys.argv[1:], stdout=w, stderr=err, restore_signals=True)
print(p.returncode if p.returncode >= 0 else 128 - p.returncode)
' "$@"
}
rc=$(closed_stdout "$GW" chain --n 10 --json --out D)
if [ "$rc" -lt 128 ]; then ok "chain --json into a closed pipe: not killed by a signal (exit $rc)"; else ko "chain --json into a closed pipe: killed by signal $((rc - 128))"; fi
if [ "$rc" -eq 1 ] && grep -q '^granwave chain: stdout: write failed: Broken pipe$' closed.err; then
    ok "chain --json into a closed pipe: exit 1 naming stdout and the broken pipe"
else
    ko "chain --json into a closed pipe: exit $rc, stderr '$(head -c 300 closed.err)'"
fi
if /usr/bin/python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if "f_max" in json.dumps(d) else 1)' D/chain.json 2>/dev/null; then
    ok "chain --json into a closed pipe: D/chain.json written and whole"
else
    ko "chain --json into a closed pipe: D/chain.json missing or not whole"
fi

test_summary test_broken_pipe
