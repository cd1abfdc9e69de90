#!/bin/bash
# test_layer_stats_text.sh GRANWAVE SRCDIR: layer-stats' text says how many
# points each mean rests on when it rests on some but not all of the group's
# (issue 18): "e_n 0.149 +- n/a" read as the group's when e_n was decided on
# 1 of its 2 points; the JSON's n said so, the text did not.
# Three made-up tables (the columns a layer sweep writes):
#  - one bouncing point and one undecided (bounced nan): e_n, e and alpha_r
#    "(1 of 2 points)", e_n_first n/a without a count (no column), the
#    penetration (over every point) without one;
#  - four points of which two bounce, one group per R_b/R_m: the rebound means
#    "(2 of 4 points)" in the first group, none in the second where all four
#    bounce;
#  - every count printed is the JSON's n of that mean over its n_points, and
#    every mean of the JSON whose n is between 0 and n_points has its count in
#    the text (e_n, e, alpha_r, e_n_first, penetration_rm).
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

COLS="x_impact,bounced,e_n,e,alpha_r,v_ni,v_nr,v_r,penetration,penetration_rm,dissipated_first_contact,block_loss_first_contact,energy_error,wave_speed,t_end,steps"
# a bouncing row (e_n, e, alpha_r consistent: V_nr = e_n V_ni, cos(alpha_r) = V_nr / V_r)
BOUNCE="1,0.149,0.2,41.84,20,2.98,4,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100"
NOBOUNCE="0,nan,nan,nan,20,nan,nan,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100"
UNDECIDED="nan,nan,nan,nan,20,nan,nan,0.1,0.3,0.001,0.6,1e-6,nan,0.01,100"
printf 'case,point,%s\n0,0,0,%s\n1,1,0.05,%s\n' "$COLS" "$BOUNCE" "$UNDECIDED" >"$tmp/undecided.csv"
{
    printf 'case,rb-rm,point,%s\n' "$COLS"
    printf '0,1,0,0,%s\n1,1,1,0.05,%s\n2,1,2,0.1,%s\n3,1,3,0.15,%s\n' "$BOUNCE" "$NOBOUNCE" "$BOUNCE" "$NOBOUNCE"
    printf '4,2,0,0,%s\n5,2,1,0.05,%s\n6,2,2,0.1,%s\n7,2,3,0.15,%s\n' "$BOUNCE" "$BOUNCE" "$BOUNCE" "$BOUNCE"
} >"$tmp/half.csv"

# check TABLE: the text's counts against the JSON's; then EXTRA python asserting on text (t) and groups (G)
check() {
    local name=$1 extra=$2
    "$GW" layer-stats "$tmp/$name.csv" >"$tmp/$name.txt" 2>"$tmp/$name.err"; local rc1=$?
    "$GW" layer-stats "$tmp/$name.csv" --json >"$tmp/$name.json" 2>/dev/null; local rc2=$?
    if [ $rc1 -ne 0 ] || [ $rc2 -ne 0 ]; then
        ko "$name: exit $rc1 / $rc2: $(head -2 "$tmp/$name.err")"
        return
    fi
    $PY - "$tmp/$name.txt" "$tmp/$name.json" "$extra" <<'EOF' >"$tmp/$name.out" 2>&1
import json, re, sys
text = open(sys.argv[1]).read()
G = json.load(open(sys.argv[2]))["groups"]
lines = [l for l in text.splitlines() if l.startswith("  ") and ": n " in l]
def check(cond, what):
    print(("PASS: " if cond else "FAIL: ") + what)
check(len(lines) == len(G), "%d group lines for %d groups" % (len(lines), len(G)))
# the text's name of each mean and the JSON's
names = {"e_n": "e_n", "e": "e", "alpha_r": "alpha_r", "e_n_first": "e_n_first", "penetration": "penetration_rm"}
for l, g in zip(lines, G):
    N = g["n_points"]
    for tn, jn in names.items():
        m = re.search(r"[ ,]%s ([^,]*)" % tn, l)
        if not m:
            check(False, "%s in %r" % (tn, l))
            continue
        cnt = re.search(r"\((\d+) of (\d+) points\)$", m.group(1))
        n = g[jn]["n"]
        want = 0 < n < N
        check((cnt is not None) == want and (not cnt or (int(cnt.group(1)), int(cnt.group(2))) == (n, N)),
              "%s %r: count %s, the JSON's n %d of %d points" % (tn, m.group(1), cnt and cnt.group(0), n, N))
t = text
exec(sys.argv[3])
EOF
    while IFS= read -r l; do
        case $l in PASS:*) ok "$name: ${l#PASS: }" ;; FAIL:*) ko "$name: ${l#FAIL: }" ;; *) ko "$name: checker: $l" ;; esac
    done <"$tmp/$name.out"
}

check undecided '
check("e_n 0.149 +- n/a (1 of 2 points)," in t, "e_n 0.149 +- n/a (1 of 2 points)")
check("alpha_r 41.8 +- n/a deg (1 of 2 points)," in t, "alpha_r 41.8 +- n/a deg (1 of 2 points)")
check("e_n_first n/a +- n/a," in t, "e_n_first n/a, no count (no such column)")
check(G[0]["n_points"] == 2 and G[0]["e_n"]["n"] == 1, "the JSON: e_n on 1 of 2 points")'
check half '
check(t.count("(2 of 4 points)") == 3, "the rebound means of rb-rm=1: (2 of 4 points) three times")
l2 = [l for l in t.splitlines() if "rb-rm=2" in l]
check(len(l2) == 1 and " points)" not in l2[0], "rb-rm=2, every point bounced: no count")'

test_summary test_layer_stats_text
