#!/bin/bash
# test_layer_stats_rows.sh GRANWAVE SRCDIR: layer-stats against rows no run
# writes, by the definitions of e_n, e, alpha_r (docs/physics.md 2.3, B.16-B.18)
# and the energy ledger (2.4), and against the other odd forms a sweep table
# takes (issue 18). A real layer sweep (2 R_b x 2 H x 2 incidences x 3 points
# on a 40-disc sample) gives the table; one cell at a time is edited:
#  - refused (exit 2, one line naming the table, the line and the column,
#    nothing written, nothing on stdout): e_n 1.5 with e 0.23 at normal
#    incidence (e_n cos(alpha_i) > e: V_nr > V_r), alpha_r 120 deg in a
#    bouncing row (V_nr > 0 makes it < 90), alpha_r nan beside numbers, a
#    bouncing row's bounced set to 0 (its e_n_first left), a block loss of 1.5,
#    v_nr above v_r, alpha_r 200 deg in a non-bouncing row of a table before
#    e_n_first; lines ending in CR alone ("no header line (an empty table)"
#    before), cells separated by ';', e_n_first removed with e_first kept
#    ("case 0 bounced but its e_n is nan" before);
#  - warned of (exit 0, the statistics written, one warning naming the case
#    and line): e 1.6 at normal incidence, above what the incident energy and
#    gravity's work over the penetration give;
#  - read (exit 0, no such warning): e_n 1.2 at 40 deg of incidence with e
#    1.0 (oblique impacts turn tangential momentum into normal), a block loss
#    of -5.1e-6 (the block gains energy falling the gap), a row that did
#    not bounce as the model writes it (nan at the rebound columns), the
#    measured 8000-case diagram (before e_n_first: its non-bouncing rows carry
#    e_n), the table with CR LF line ends (the same statistics); a duplicated
#    header column and a units line after the header are refused as before.
# 12 of the 20 checks fail on the code before (the eight that pass: the six
# tables read without a warning, the duplicated column, the units line).
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

"$GW" layer-make --n 40 --width-rm 14 --seed 2 --out S.txt >/dev/null 2>&1 || { echo "FAIL: layer-make"; exit 1; }
printf '[sweep]\nmodel = layer\n[grid]\nrb-rm = 1, 2\nheight-rm = 3, 6\nalpha = 0, 40\npoint = 0:2\n[params]\nsample = %s/S.txt\npoints = 3\nvi = 10\nt-max = 0.3\n' "$tmp" >s.ini
timeout 120 "$GW" sweep s.ini --out sw --quiet --jobs 2 >/dev/null 2>err.txt || { echo "FAIL: the sweep: $(cat err.txt)"; exit 1; }
T=sw/results.csv

# edit OUT CASE COL=VALUE ...: the table with case CASE's cells changed (VALUE
# "acos:X" is arccos(X) in degrees); prints the edited row's line number
edit() {
    $PY - "$T" "$@" <<'PY'
import math, sys
src, out, case = sys.argv[1], sys.argv[2], sys.argv[3]
lines = open(src).read().split("\n")
head = next(i for i, l in enumerate(lines) if l.startswith("case,"))
cols = lines[head].split(",")
for i in range(head + 1, len(lines)):
    cells = lines[i].split(",")
    if cells[0] != case:
        continue
    for a in sys.argv[4:]:
        k, v = a.split("=", 1)
        if v.startswith("acos:"):
            v = repr(math.degrees(math.acos(float(v[5:]))))
        cells[cols.index(k)] = v
    lines[i] = ",".join(cells)
    print(i + 1)
open(out, "w").write("\n".join(lines))
PY
}
# a row of the table: case number of the first bouncing row with finite e_n at
# incidence ALPHA, and its column COL
pick() {
    $PY - "$T" "$1" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
for r in rows:
    if r["alpha"] == sys.argv[2] and r["bounced"] == "1" and not math.isnan(float(r["e_n"])):
        print(r["case"], r["v_ni"]); break
PY
}
col() { $PY -c "import csv,sys; print(next(r for r in csv.DictReader(l for l in open('$T') if not l.startswith('#')) if r['case']=='$1')['$2'])"; }

# refused WHAT FILE PATTERN: exit 2, one stderr line matching PATTERN, no --out
# directory, nothing on stdout
refused() {
    local what=$1 f=$2 pat=$3
    rm -rf o_ref
    timeout 60 "$GW" layer-stats "$f" --out o_ref --json >out.txt 2>err.txt </dev/null
    local rc=$?
    if [ $rc -ne 2 ]; then ko "$what: exit $rc, expected 2 ($(head -c 300 err.txt))"; return; fi
    if [ "$(wc -l <err.txt)" -ne 1 ]; then ko "$what: $(wc -l <err.txt) stderr lines"; return; fi
    if ! grep -qE -- "$pat" err.txt; then ko "$what: message does not match '$pat': $(cat err.txt)"; return; fi
    if [ -e o_ref ]; then ko "$what: --out was written"; rm -rf o_ref; return; fi
    if [ -s out.txt ]; then ko "$what: printed on stdout"; return; fi
    ok "$what"
}
# read WHAT FILE [WARNING-PATTERN]: exit 0, the --out files written; with a
# pattern, one warning line on stderr matching it; without, no warning of the
# bounds ("more kinetic energy")
read_ok() {
    local what=$1 f=$2 pat=${3:-}
    rm -rf o_ok
    timeout 60 "$GW" layer-stats "$f" --out o_ok >out.txt 2>err.txt </dev/null
    local rc=$?
    if [ $rc -ne 0 ]; then ko "$what: exit $rc ($(head -c 300 err.txt))"; return; fi
    if [ ! -s o_ok/groups.csv ]; then ko "$what: no groups.csv"; return; fi
    if [ -n "$pat" ]; then
        if [ "$(grep -cE -- "$pat" err.txt)" -ne 1 ]; then ko "$what: no warning matching '$pat': $(cat err.txt)"; return; fi
    elif grep -q "more kinetic energy" err.txt; then
        ko "$what: warned: $(cat err.txt)"; return
    fi
    ok "$what"
}

read -r c0 vni0 <<<"$(pick 0)"
read -r c40 vni40 <<<"$(pick 40)"
[ -n "$c0" ] && [ -n "$c40" ] || { echo "FAIL: the sweep has no bouncing row with e_n at 0 and 40 deg"; exit 1; }
e0=$(col "$c0" e)

# 1 e_n above e at normal incidence: V_nr > V_r
ln=$(edit a.csv "$c0" e_n=1.5)
refused "e_n 1.5 with e $e0 at normal incidence" a.csv "a\.csv:$ln: column e_n: 1\.5 exceeds e / cos\(alpha_i\)"
# 2 e_n 1.5 and e 1.6 at normal incidence (consistent alpha_r, v_nr, v_r): warned
ln=$(edit b.csv "$c0" e_n=1.5 e=1.6 alpha_r=acos:0.9375 v_nr=15 v_r=16)
read_ok "e 1.6 at normal incidence: warned" b.csv \
    "warning: 1 bouncing point\(s\) left with more kinetic energy .*first: b\.csv:$ln, case $c0, e = 1\.6 >"
# 3 e_n 1.2 with e 1.0 at 40 deg: an oblique rebound's e_n above 1, read without a warning
vnr=$($PY -c "print(repr(1.2 * $vni40))")
edit c.csv "$c40" e_n=1.2 e=1.0 "alpha_r=acos:$($PY -c "import math; print(1.2 * math.cos(math.radians(40)))")" \
    v_nr="$vnr" v_r=10 >/dev/null
read_ok "e_n 1.2, e 1.0 at 40 deg of incidence: read" c.csv
# 4 alpha_r 120 deg in a bouncing row
ln=$(edit d.csv "$c0" alpha_r=120)
refused "alpha_r 120 deg in a bouncing row" d.csv "d\.csv:$ln: column alpha_r: 120 deg in a bouncing row"
# 5 alpha_r nan beside e_n and e
ln=$(edit e.csv "$c0" alpha_r=nan)
refused "alpha_r nan beside e_n and e" e.csv "e\.csv:$ln: column alpha_r: nan where e_n is"
# 6 a bouncing row's bounced set to 0
ln=$(edit f.csv 0 bounced=0)
refused "bounced 0 on a row with e_n_first" f.csv "f\.csv:$ln: column e_n_first: .* in a row that did not bounce \(bounced 0\)"
# 7 a row that did not bounce, as the model writes it
edit g.csv 0 bounced=0 e_n_first=nan e_first=nan alpha_r_first=nan v_nr_first=nan v_r_first=nan t_leave=nan >/dev/null
read_ok "a row that did not bounce, nan at its rebound columns: read" g.csv
# 8 a block loss of 1.5
ln=$(edit h.csv "$c0" block_loss_first_contact=1.5)
refused "block_loss_first_contact 1.5" h.csv "h\.csv:$ln: column block_loss_first_contact: 1\.5 is above 1"
# 9b a block loss below 0 (the block gained energy falling the gap: a run wrote -5.1e-6)
edit h2.csv "$c0" block_loss_first_contact=-5.0776792151664117e-06 >/dev/null
read_ok "block_loss_first_contact -5.1e-6: read" h2.csv
# 9 v_nr above v_r
ln=$(edit i.csv "$c0" v_nr=1e3)
refused "v_nr above v_r" i.csv "i\.csv:$ln: column v_nr: 1000 m/s exceeds v_r"

# 10, 11 the measured diagram (before e_n_first): read; alpha_r 200 in a non-bouncing row refused
M="$SRC/data/measured/layer_diagram_8000/results.csv"
cp "$M" m.csv
read_ok "the measured 8000-case diagram: read, no warning of the bounds" m.csv
$PY - "$M" <<'PY' >m2.csv
import sys
out, done = [], False
for l in open(sys.argv[1]).read().split("\n"):
    c = l.split(",")
    if not done and len(c) > 9 and c[5] == "0":
        c[8] = "200"; done = True; l = ",".join(c)
    out.append(l)
print("\n".join(out), end="")
PY
ln=$(grep -n '^[0-9]*,[^,]*,[^,]*,[^,]*,[^,]*,0,[^,]*,[^,]*,200,' m2.csv | head -1 | cut -d: -f1)
refused "alpha_r 200 deg in a non-bouncing row" m2.csv "m2\.csv:$ln: column alpha_r: 200 deg is outside arccos' range"

# 12 lines ending in CR alone
tr '\n' '\r' <"$T" >cr.csv
refused "lines ending in CR alone" cr.csv "cr\.csv:1: lines end in CR alone"
# 13 cells separated by ';'
sed 's/,/;/g' "$T" >semi.csv
refused "cells separated by ';'" semi.csv "semi\.csv:[0-9]+: the header's cells are separated by ';'"
# 14 e_n_first removed (e_first, alpha_r_first kept)
$PY - "$T" <<'PY' >nofirst.csv
import sys
lines = open(sys.argv[1]).read().split("\n")
k = None
for i, l in enumerate(lines):
    if l.startswith("case,"):
        k = l.split(",").index("e_n_first")
    if k is not None and l and not l.startswith("#"):
        c = l.split(","); del c[k]; lines[i] = ",".join(c)
print("\n".join(lines), end="")
PY
refused "e_n_first removed, e_first kept" nofirst.csv "nofirst\.csv: the header has 2 of the columns e_n_first, e_first, alpha_r_first"
# 15 CR LF line ends: the same statistics
sed 's/$/\r/' "$T" >crlf.csv
# (the sweep's warnings, which layer-stats says naming the table: the name set apart)
timeout 60 "$GW" layer-stats "$T" --json 2>/dev/null | grep -v '"input\|"command' | sed "s#$T: #TABLE: #g" >lf.json
timeout 60 "$GW" layer-stats crlf.csv --json 2>/dev/null | grep -v '"input\|"command' | sed "s#crlf\.csv: #TABLE: #g" >crlf.json
[ -s lf.json ] && cmp -s lf.json crlf.json && ok "CR LF line ends: the same statistics" || ko "CR LF: $(diff lf.json crlf.json | head -3)"
# 16 a duplicated header column, 17 a units line after the header: refused
sed '/^case,/s/,e_first,/,e_n,/' "$T" >dup.csv
refused "a duplicated header column" dup.csv "dup\.csv:[0-9]+: header column 'e_n' appears twice"
hl=$(grep -n '^case,' "$T" | cut -d: -f1)
sed "/^case,/a ,,,,,m,,,,deg,m/s,m/s,m/s,m" "$T" >units.csv
refused "a units line after the header" units.csv "units\.csv:$((hl + 1)): "
# 18, 19 the table as written: read, no warning of the bounds; and e_n 1.5 at
# 40 deg within e / cos(alpha_i) refused only above it
read_ok "the sweep's table as written" "$T"
ln=$(edit j.csv "$c40" e_n="$($PY -c "e = float('$(col "$c40" e)'); import math; print(repr(1.01 * e / math.cos(math.radians(40))))")")
refused "e_n 1 % above e / cos(40 deg)" j.csv "j\.csv:$ln: column e_n: .* exceeds e / cos\(alpha_i\) .*alpha_i 40 deg"

test_summary
