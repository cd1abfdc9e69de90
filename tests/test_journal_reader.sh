#!/bin/bash
# test_journal_reader.sh GRANWAVE SRCDIR: a sweep's journal held open by a
# reader (a `tail -f`, a viewer) while the sweep runs. Before each row the
# sweep checks its journal's last 4096 bytes, and the whole file when another
# may have written it; any other open file holding the journal (a write lease
# refused) counted as a possible writer, so with a reader holding it every
# row's check read the whole journal: 449 MB read over 2000 cases (224 kB a
# row, quadratic in the rows), 1880 rows/s against 3626 without the reader.
# The holders are now looked up in /proc (their descriptors' flags, their
# shared mappings) once per open of the file the sweep's watch sees, and
# readers alone leave the check at the journal's tail.
#  1 1200 cases of one bead (rk4, t-max 1e-4), one thread, a reader holding
#    the journal from its creation: exit 0, the table of the run without the
#    reader, and (strace) under 12288 bytes pread a row
#  2 the control: a writer that opens the journal (read-write) after the
#    reader, once 200 rows are in, and 200 rows later changes one digit of the
#    first row in place (the length kept, outside the last 4096 bytes),
#    holding the file open: found before the sweep's end, exit 1 naming
#    journal.csv and journal.kept.csv, no table, fewer than 1200 rows kept
#    (the writer's open is seen and the whole file compared from then on)
#  3 a viewer that reopens the journal (opens it, reads it whole, closes it,
#    every 2 ms, as `watch cat` or an editor's reload): each open made the
#    next check compare the whole journal (an open is an event of the watch);
#    an open alone changes no byte, and the check stays at the tail: exit 0,
#    the table of the run without the viewer (at least 50 opens), and the
#    bytes pread beyond part 1's (a reader held throughout) under 16384 an
#    open (a whole compare reads the journal, about 96 kB an open on average
#    over the run: 56 MB over 478 opens before, 13 MB over 920 after);
#    control: with the viewer reopening, a writer that opens the journal
#    read-write once 200 rows are in, maps the bytes then in shared and
#    changes a digit of the first row through the mapping (no event is sent
#    for it), holding the mapping: found before the end, exit 1 naming
#    journal.kept.csv (its open is looked up at the next row)
# SKIP without strace (part 1's count) or in a sanitizer build (part 1's count;
# part 2 runs). Checks that fail on the code before: docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

/usr/bin/python3 - 1200 >c.ini <<'PY'
import sys
n = int(sys.argv[1])
v = ["%.4f" % (0.1 + 1e-4 * i) for i in range(n)]
print("[sweep]\nmodel = chain\n[grid]\nvimp = " + ",\n    ".join(", ".join(v[i:i + 10]) for i in range(0, n, 10)) +
      "\n[params]\nn = 1\nsolver = rk4\nt-max = 1e-4")
PY
"$GW" sweep c.ini --out ref --quiet --jobs 1 || ko "the sweep without a reader"

# held.py MODE DIR CMD...: CMD run; the journal DIR/journal.csv opened for
# reading once it exists; MODE edit: opened read-write too once 200 rows are
# in, and its first row's first digit changed in place 200 rows later; MODE
# reopen: no reader held, the journal opened, read whole and closed every 2
# ms until CMD ends, the opens counted in DIR.opens; MODE mmap: as reopen,
# and once 200 rows are in the journal opened read-write, the bytes then in
# mapped shared and its first row's digit changed through the mapping
cat >held.py <<'PY'
import os, subprocess, sys, time
mode, d, cmd = sys.argv[1], sys.argv[2], sys.argv[3:]
p = subprocess.Popen(cmd)
j = os.path.join(d, "journal.csv")
def rows():
    with open(j, "rb") as f:
        return sum(1 for l in f if not l.startswith(b"#"))
while not os.path.exists(j) and p.poll() is None:
    time.sleep(0.001)
r = open(j, "rb") if os.path.exists(j) and mode not in ("reopen", "mmap") else None
w = None
if mode in ("reopen", "mmap"):
    import mmap
    n, m = 0, None
    while p.poll() is None:
        if mode == "mmap" and m is None and rows() >= 200:
            w = os.open(j, os.O_RDWR)
            m = mmap.mmap(w, os.fstat(w).st_size, mmap.MAP_SHARED, mmap.PROT_READ | mmap.PROT_WRITE)
            at = 0
            while m[at:at + 1] == b"#":  # the head's lines, then the first row
                at = m.find(b"\n", at) + 1
            at = m.find(b",", m.find(b",", at) + 1) + 2  # its third value's second character
            while at < len(m) and not m[at:at + 1].isdigit():
                at += 1
            m[at:at + 1] = b"7" if m[at:at + 1] != b"7" else b"8"
        try:
            with open(j, "rb") as f:
                f.read()
            n += 1
        except OSError:
            pass
        time.sleep(0.002)
    with open(d + ".opens", "w") as f:
        print(n, file=f)
if mode == "edit":
    while p.poll() is None and rows() < 200:
        time.sleep(0.005)
    w = os.open(j, os.O_RDWR)
    while p.poll() is None and rows() < 400:
        time.sleep(0.005)
    text = os.pread(w, 1 << 20, 0)
    at = 0
    while text[at:at + 1] == b"#":  # the head's lines, then the first row
        at = text.index(b"\n", at) + 1
    at = text.index(b",", text.index(b",", at) + 1) + 2  # its third value's second character
    while not text[at:at + 1].isdigit():
        at += 1
    os.pwrite(w, b"7" if text[at:at + 1] != b"7" else b"8", at)
sys.exit(p.wait())
PY

# --- 1 a reader: the check stays at the tail ---
if ! command -v strace >/dev/null || sanitizer_build; then
    echo "SKIP: part 1 needs strace (and no sanitizer build)"
else
    rm -rf r
    /usr/bin/python3 held.py read r strace -qq -e trace=pread64 -o "$tmp/strace" \
        "$GW" sweep c.ini --out r --quiet --jobs 1 2>"$tmp/stderr"; rc=$?
    [ $rc -eq 0 ] && cmp -s r/results.csv ref/results.csv && ok "1 exit 0 with a reader, the table of the run without" ||
        ko "1 with a reader: exit $rc, $(head -c 300 "$tmp/stderr")"
    b=$(awk '/= [0-9]+$/ {s += $NF} END {print s + 0}' "$tmp/strace")
    [ "$b" -lt $((1200 * 12288)) ] && ok "1 $b bytes pread over 1200 rows (under 12288 a row)" ||
        ko "1 $b bytes pread over 1200 rows ($((b / 1200)) a row: the whole journal read per row)"
fi

# --- 2 control: a writer opening after the reader ---
rm -rf e
/usr/bin/python3 held.py edit e "$GW" sweep c.ini --out e --quiet --jobs 1 2>"$tmp/stderr"; rc=$?
[ $rc -eq 1 ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] &&
    grep -q "e/journal.csv was written into while the sweep ran.*kept whole as .*e/journal.kept.csv" "$tmp/stderr" &&
    ok "2 a writer opening after the reader: exit 1, one line naming journal.csv and journal.kept.csv" ||
    ko "2 a writer opening after the reader: exit $rc, $(head -c 300 "$tmp/stderr")"
[ ! -e e/results.csv ] && ok "2 no table" || ko "2 a table written"
n=$(grep -vc '^#' e/journal.kept.csv 2>/dev/null)
[ -n "$n" ] && [ "$n" -lt 1200 ] && ok "2 found before the end ($n rows kept)" || ko "2 ${n:-no} rows kept"

# --- 3 a viewer reopening the journal: the check stays at the tail ---
if ! command -v strace >/dev/null || sanitizer_build; then
    echo "SKIP: part 3 needs strace (and no sanitizer build)"
else
    rm -rf v v.opens
    /usr/bin/python3 held.py reopen v strace -qq -e trace=pread64 -o "$tmp/strace3" \
        "$GW" sweep c.ini --out v --quiet --jobs 1 2>"$tmp/stderr"; rc=$?
    opens=$(cat v.opens 2>/dev/null)
    [ $rc -eq 0 ] && cmp -s v/results.csv ref/results.csv && [ "${opens:-0}" -ge 50 ] &&
        ok "3 exit 0 with a viewer reopening the journal ($opens opens), the table of the run without" ||
        ko "3 with a viewer reopening: exit $rc, ${opens:-no} opens, $(head -c 300 "$tmp/stderr")"
    b3=$(awk '/= [0-9]+$/ {s += $NF} END {print s + 0}' "$tmp/strace3")
    more=$(((b3 - ${b:-0}) / (${opens:-0} > 0 ? opens : 1)))
    [ -n "${b:-}" ] && [ "${opens:-0}" -ge 50 ] && [ "$more" -lt 16384 ] &&
        ok "3 $b3 bytes pread over 1200 rows with $opens reopens ($more an open beyond part 1's $b)" ||
        ko "3 $b3 bytes pread over 1200 rows with ${opens:-no} reopens ($more an open beyond part 1's ${b:-?}: the whole journal read per open)"
fi
rm -rf m
/usr/bin/python3 held.py mmap m "$GW" sweep c.ini --out m --quiet --jobs 1 2>"$tmp/stderr"; rc=$?
n=$(grep -vc '^#' m/journal.kept.csv 2>/dev/null)
[ $rc -eq 1 ] && grep -q "m/journal.csv was written into while the sweep ran.*m/journal.kept.csv" "$tmp/stderr" &&
    [ ! -e m/results.csv ] && [ -n "$n" ] && [ "$n" -lt 1200 ] &&
    ok "3 control: a writer through a shared mapping beside the viewer: found at row $n, exit 1, no table" ||
    ko "3 control, a writer through a shared mapping: exit $rc, ${n:-no} rows kept, $(head -c 300 "$tmp/stderr")"

test_summary test_journal_reader
