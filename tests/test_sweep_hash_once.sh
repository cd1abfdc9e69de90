#!/bin/bash
# test_sweep_hash_once.sh GRANWAVE SRCDIR: a layer sweep hashes its sample
# once, not once for each case, and still finds it changed. The check pass
# read the sample twice for each case (its reader's rules and its hash), and
# the check before each row was journaled twice more (about 1.5 ms per MiB
# each: an HDF5 sample is hashed with the up to 1 MiB its objects do not
# hold); the hashes are now kept while stat finds the file as it was hashed
# (common/gw_io_hash_memo.c). Counted with strace (the opens of the sample,
# a file older than the memo's 2 s settle time):
#  1 `sweep --check` over 2 and over 6 cases opens the sample as many times
#    (before: 2 more for each case);
#  2 the sweep over 6 cases opens it 4 times more than over 2: once for each
#    case, the case's own read (before: 5 times for each case);
#  3 the tables of both sweeps, and the hashes they record, as before: the
#    sample's "# input" hash its content's;
#  4 the sample written in place while the sweep runs (right before case
#    0's row is journaled: one byte of a comment line, its size kept and its
#    modification time set back) still stops the sweep at case 1: exit 2,
#    "sample '...' changed while the sweep ran", case 0's row kept, no table.
# 2 of the 4 checks fail on the code before (1 and 2); 4 is the safety check
# of the memo (it passes before, as every case hashed the file again).
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
if ! command -v strace >/dev/null; then
    echo "SKIP: no strace"
    test_summary
    exit 0
fi

make_sample s.txt --n 40 --seed 1
make_sample e.txt --n 40 --seed 2
sleep 3 # older than the memo's settle time (GW_HASH_MEMO_SETTLE_S, 2 s)
ini() { # NAME SAMPLE N: a sweep of N cases (vi = 10, 11, ...) over SAMPLE
    printf '[sweep]\nmodel = layer\n[grid]\nvi = %s\n[params]\nsample = %s\nt-max = 0.002\n' \
        "$(seq -s ', ' 10 $((9 + $3)))" "$tmp/$2" >"$1.ini"
}
# opens TRACE FILE: how many times TRACE (strace -f -e trace=openat,open) opened FILE
opens() { grep -c "\"$2\"" "$1"; }
traced() { # TRACE ARGS...: the program under strace, its exit code in rc
    cpu_run 300 strace -f -qq -e trace=openat,open -o "$1" "$GW" "${@:2}" >/dev/null 2>"$1.err"; rc=$?
}
ini c2 s.txt 2
ini c6 s.txt 6

# --- 1 the check pass: the sample opened as many times for 2 cases as for 6 ---
traced k2 sweep c2.ini --out k2.out --check --quiet; rc2=$rc
traced k6 sweep c6.ini --out k6.out --check --quiet; rc6=$rc
o2=$(opens k2 "$tmp/s.txt"); o6=$(opens k6 "$tmp/s.txt")
if [ $rc2 -eq 0 ] && [ $rc6 -eq 0 ] && [ "$o2" -gt 0 ] && [ "$o2" -eq "$o6" ]; then
    ok "1 sweep --check over 2 and 6 cases: the sample opened $o2 times each"
else
    ko "1 sweep --check (exit $rc2, $rc6): the sample opened $o2 times for 2 cases, $o6 for 6"
fi

# --- 2 the sweep: once more for each case, its own read ---
traced r2 sweep c2.ini --out r2.out --jobs 1 --quiet; rc2=$rc
traced r6 sweep c6.ini --out r6.out --jobs 1 --quiet; rc6=$rc
o2=$(opens r2 "$tmp/s.txt"); o6=$(opens r6 "$tmp/s.txt")
if [ $rc2 -eq 0 ] && [ $rc6 -eq 0 ] && [ "$((o6 - o2))" -eq 4 ]; then
    ok "2 the sweep over 6 cases opens the sample 4 times more than over 2 ($o6, $o2): once a case"
else
    ko "2 the sweep (exit $rc2, $rc6): the sample opened $o2 times for 2 cases, $o6 for 6 ($(( (o6 - o2) / 4 )) a case)"
fi

# --- 3 the tables as before: the sample's hash its content's ---
h=$(/usr/bin/python3 -c '
import sys
h = 14695981039346656037
for b in open(sys.argv[1], "rb").read():
    h = ((h ^ b) * 1099511628211) % (1 << 64)
print("%016x" % h)' s.txt)
if grep -qx "# input sample = $tmp/s.txt fnv1a64 $h" r2.out/results.csv &&
    grep -qx "# input sample = $tmp/s.txt fnv1a64 $h" r6.out/results.csv &&
    [ "$(journal_rows r6.out/results.csv)" -eq 7 ] && [ "$(cut -d, -f1 r6.out/results.csv | grep -c '^[0-5]$')" -eq 6 ]; then
    ok "3 both tables record the sample's content hash, the 6 cases' table its 6 rows"
else
    ko "3 tables: $(grep -h '^# input' r2.out/results.csv r6.out/results.csv | tr '\n' ' ') (want $h)"
fi

# --- 4 the sample written in place, size and mtime kept: still found changed ---
ini w e.txt 4
edit="/usr/bin/python3 -c 'import os, sys
p = sys.argv[1]; st = os.stat(p); d = open(p, \"rb\").read(); i = d.index(b\"\\n# granwave\") + 3
f = open(p, \"r+b\"); f.seek(i); f.write(b\"G\"); f.close()
os.utime(p, ns=(st.st_atime_ns, st.st_mtime_ns))' '$tmp/e.txt'"
if MOVE_SHIM=$(shim_path "" move); then
    m0=$(stat -c '%s %Y' e.txt)
    cpu_run 300 env GW_MOVE_AT=1 GW_MOVE_RUN="$edit" LD_PRELOAD="$(preload_list "$MOVE_SHIM")" \
        "$GW" sweep w.ini --out w.out --quiet --jobs 1 >w.stdout 2>w.err </dev/null; rc=$?
    nw=$(journal_rows w.out/journal.csv)
    if [ "$(stat -c '%s %Y' e.txt)" = "$m0" ] && grep -q '^# Granwave' e.txt && [ $rc -eq 2 ] && [ "$nw" -eq 1 ] &&
        [ ! -e w.out/results.csv ] && [ "$(wc -l <w.err)" -eq 1 ] &&
        grep -q "^granwave sweep: sample '.*e.txt' changed while the sweep ran" w.err; then
        ok "4 the sample written in place (size and mtime kept) after case 0: exit 2 naming it, 1 row kept, no table"
    else
        ko "4 sample written in place: exit $rc, $nw rows, size/mtime $m0 -> $(stat -c '%s %Y' e.txt), $(head -c 300 w.err)"
    fi
else
    echo "SKIP: 4, the sample written in place mid-sweep (no move shim in this build)"
fi
test_summary
