#!/usr/bin/env bash
# test_sensor_late_contact.sh: a default run goes on to the collision's end, and
# a cut run's warning names the contact that still acts (the forty-first session).
#
# The default t-max is 20 times the collision's expected length, a fixed
# estimate. On a soft sensor spring the beads leave the ride out of order and
# meet again long after it: chain --n 10 --sensor-mass 0.03 --sensor-stiffness
# 1e4 was cut at the default 0.148 s (its beads 5 and 6 meet at 0.278 s), --n 5
# --sensor-mass 0.01 --sensor-stiffness 1e4 at 0.093 s (it ends at 1.36 s, 291
# expected lengths); so was a light bead between heavy ones on the rigid wall
# (--n 3 --radii 4e-3,1e-3,4e-3: cut at 2.5 ms, ends at 4.8 ms). A default run
# now goes on past its t-max while contacts act, up to a stated bound
# (chain_extend_bound: 50 default t-max, 5e6 samples at dt_max past it). The
# cut's warning said "bead 1 still at the wall" with bead 1 12 mm beyond the
# sensor body's swing (the body swinging toward it), or "the column's own
# contacts still closed or closing"; it now names the contact.
#
# Asserted:
#   1 the three columns end by default: exit 0, no warning, converged; their
#     last contact (the latest detach time) is that of a run with a t-max 20
#     times longer within 1e-9 s, their final velocities within 1e-9 m/s
#     (they run the same events), t_end at or past it; the momentum
#     restitution -sum m v_f / sum m v_0 is eps_eff (equal beads) and the
#     energy ledger closes within 1e-6; the sensor column's beads 5 and 6
#     leave in order (v_6 < v_5: the pair parted);
#   2 a run cut by --t-max names its state: --n 10 on the sensor at 0.2 s
#     "beads 5 and 6 closing, to meet at about t = 0.278 s" (the meeting
#     within 1e-3 s of the default run's detach time of bead 5) and not "bead
#     1 still at the wall", wall_done true; at 5 ms bead 1 is back on the
#     sensor (wall_done false, a later wall contact) and the text says so, with
#     beads 3 and 4 closing; the light bead cut at 2.5 ms:
#     "beads 2 and 3 closing"; the same warnings from Python;
#   3 rigid defaults untouched: chain, chain --n 10, --n 40, falcon --out,
#     drop and softwall end before their t-max (the run never goes on), chain's
#     t_max 20 (n T_q + tau_1) to 1e-14; with GW_BASE_PROGRAM (the code
#     before) their outputs are compared byte for byte, timing lines aside.
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

# --- 1 the default runs end where a long run's last contact is
SENSOR="--n 10 --sensor-mass 0.03 --sensor-stiffness 1e4"
for a in "$SENSOR" "--n 5 --sensor-mass 0.01 --sensor-stiffness 1e4" "--n 3 --radii 4e-3,1e-3,4e-3"; do
    # shellcheck disable=SC2086
    runs_json "1: chain $a" "$tmp/d.json" chain $a --quiet || continue
    # nothing on stderr but a chatter on the sensor body (--n 5 on 0.01 kg: its
    # wall contact closes 10 times, too costly to run again: test_chatter_warned)
    ! grep -v "^granwave chain: warning: bead 1 chattered on the sensor body" "$tmp/stderr" | grep -q . &&
        ok "1: chain $a: nothing on stderr but a chatter" || ko "1: chain $a: stderr $(head -c 300 "$tmp/stderr")"
    tm=$(jq_py "$tmp/d.json" "20 * d['settings']['solver']['t_max']")
    # shellcheck disable=SC2086
    runs_json "1: chain $a --t-max $tm" "$tmp/r.json" chain $a --quiet --t-max "$tm" || continue
    v=$($PY - "$tmp/d.json" "$tmp/r.json" <<'EOF'
import json, sys
d, r = (json.load(open(f)) for f in sys.argv[1:3])
why = []
if not (d["converged"] and d["wall_done"] and [w for w in d["warnings"] if not w.startswith("bead 1 chattered")] == []):
    why.append("not ended: converged %s, %s" % (d["converged"], d["warnings"]))
if not r["converged"]:
    why.append("the long run did not end")
last_d, last_r = max(d["detach_times"]), max(r["detach_times"])
if not abs(last_d - last_r) < 1e-9 or not d["t_end"] >= last_d:
    why.append("last contact %.12g against the long run's %.12g, t_end %.12g" % (last_d, last_r, d["t_end"]))
dv = max(abs(a - b) for a, b in zip(d["final_velocities"], r["final_velocities"]))
if not dv < 1e-9:
    why.append("final velocities %.3g m/s from the long run's" % dv)
if not d["energy_error"] < 1e-6:
    why.append("energy error %.3g" % d["energy_error"])
print("True" if not why else "False: " + "; ".join(why))
print(last_d, d["t_end"], d["settings"]["solver"]["t_max"])
EOF
)
    [ "$(head -1 <<<"$v")" = True ] &&
        ok "1: chain $a ends by default at its last contact $(sed -n 2p <<<"$v" | cut -d' ' -f1) s, as a run to $tm s" ||
        ko "1: chain $a: $(head -1 <<<"$v")"
done
# the sensor column: equal beads, so eps_eff is -sum v_f / (n v_0); beads 5 and 6 parted
runs_json "1: chain $SENSOR" "$tmp/s.json" chain $SENSOR --quiet &&
    [ "$(jq_py "$tmp/s.json" "abs(-sum(d['final_velocities']) / (10 * d['v_imp']) - d['eps_eff']) < 1e-12 and d['final_velocities'][5] < d['final_velocities'][4] and all(v < 0 for v in d['final_velocities'])")" = True ] &&
    ok "1: the sensor column: eps_eff $(jq_py "$tmp/s.json" "d['eps_eff']") from its final velocities, beads 5 and 6 parted, every bead leaving" ||
    ko "1: the sensor column: $(jq_py "$tmp/s.json" "(d['eps_eff'], d['final_velocities'])" 2>/dev/null)"
t56=$(jq_py "$tmp/s.json" "d['detach_times'][4]" 2>/dev/null)

# --- 2 the warning of a cut run names the contact
# cut CASE ARGS...: exit 0, one warning line on stderr, the JSON in $tmp/c.json
cut() {
    local what=$1
    shift
    cpu_run 60 "$GW" chain "$@" --quiet --json >"$tmp/c.json" 2>"$tmp/c.err" </dev/null
    local rc=$?
    [ $rc -eq 0 ] && [ "$(wc -l <"$tmp/c.err")" -eq 1 ] && return 0
    ko "2: $what: exit $rc, $(head -c 300 "$tmp/c.err")"
    return 1
}
# shellcheck disable=SC2086
if cut "the sensor column at 0.2 s" $SENSOR --t-max 0.2; then
    meet=$(sed -n 's/.*(beads 5 and 6 closing, to meet at about t = \([0-9.e-]*\) s).*/\1/p' "$tmp/c.err")
    [ -n "$meet" ] && ! grep -q "bead 1 still at the wall" "$tmp/c.err" &&
        [ "$(jq_py "$tmp/c.json" "d['converged'] is False and d['wall_done'] is True and abs($meet - ${t56:-0}) < 1e-3")" = True ] &&
        ok "2: cut at 0.2 s: names beads 5 and 6 closing, meeting at about $meet s (they part at ${t56:-?} s)" ||
        ko "2: cut at 0.2 s: $(cat "$tmp/c.err")"
fi
# shellcheck disable=SC2086
if cut "the sensor column at 5 ms" $SENSOR --t-max 5e-3; then
    grep -q "(bead 1 still at the wall; beads 3 and 4 closing" "$tmp/c.err" &&
        [ "$(jq_py "$tmp/c.json" "d['wall_done'] is False and d['wall_contacts'] > 1")" = True ] &&
        ok "2: cut at 5 ms, bead 1 back on the sensor: bead 1 still at the wall, beads 3 and 4 closing" ||
        ko "2: cut at 5 ms: $(cat "$tmp/c.err")"
fi
if cut "the light bead at 2.5 ms" --n 3 --radii 4e-3,1e-3,4e-3 --t-max 2.5e-3; then
    grep -q "(beads 2 and 3 closing, to meet at about t = " "$tmp/c.err" &&
        [ "$(jq_py "$tmp/c.json" "d['converged'] is False and d['wall_done'] is True")" = True ] &&
        ok "2: the light bead cut at 2.5 ms: beads 2 and 3 closing" || ko "2: the light bead: $(cat "$tmp/c.err")"
fi
py_checks 3 <<EOF
r = granwave.chain(n=10, sensor_mass=0.03, sensor_stiffness=1e4)
check(r.converged and not r.warnings and abs(max(r.detach_times) - $t56) < 1e-9,
      "Python: the sensor column ends by default at its last contact (%s, %s)" % (r.converged, r.warnings))
r, said = caught(granwave.chain, n=10, sensor_mass=0.03, sensor_stiffness=1e4, t_max=0.2)
check(any("beads 5 and 6 closing" in w for w in said) and not any("bead 1 still at the wall" in w for w in said),
      "Python: cut at 0.2 s, warned naming beads 5 and 6 (%s)" % said)
check(r.converged is False and r.wall_done is True, "Python: cut, the wall's side done")
EOF

# --- 3 rigid defaults: the run never goes on past its t-max
for a in "" "--n 10" "--n 40"; do
    # shellcheck disable=SC2086
    runs_json "3: chain $a" "$tmp/g.json" chain $a --quiet || continue
    [ "$(jq_py "$tmp/g.json" "d['converged'] and d['t_end'] < d['settings']['solver']['t_max'] and abs(d['settings']['solver']['t_max'] / (20 * (d['n'] * d['closed_forms']['t_q'] + d['closed_forms']['tau_1'])) - 1) < 1e-14")" = True ] &&
        ok "3: chain $a: ends before its t-max 20 (n T_q + tau_1)" ||
        ko "3: chain $a: $(jq_py "$tmp/g.json" "(d['converged'], d['t_end'], d['settings']['solver']['t_max'])")"
done
if cpu_run 120 "$GW" falcon --quiet --out "$tmp/fa" >/dev/null 2>"$tmp/fa.err" </dev/null; then
    # every collision ended (unfinished 0), and each t_max is 20 (n T_q + tau_1):
    # linear in n at each speed (a run that went on records where it stopped)
    v=$($PY - "$tmp/fa" <<'EOF'
import csv, json, sys
rows = list(csv.DictReader(l for l in open(sys.argv[1] + "/falcon_runs.csv") if not l.startswith("#")))
s = json.load(open(sys.argv[1] + "/falcon_summary.json"))
bad = []
by_v = {}
for r in rows:
    by_v.setdefault(r["v_imp_m_s"], {})[int(r["n"])] = float(r["t_max_s"])
for v, t in by_v.items():
    step = t[2] - t[1]
    bad += [(v, n) for n in t if n > 1 and abs(t[n] - t[n - 1] - step) > 1e-9 * t[n]]
print("True" if s["unfinished"] == 0 and len(rows) == 200 and not bad else
      "False: unfinished %s, %d rows, t_max off its line at %s" % (s["unfinished"], len(rows), bad[:5]))
EOF
)
    [ "$v" = True ] && ok "3: falcon --out: every collision ended, t_max linear in n (none went on)" || ko "3: falcon: $v"
else
    ko "3: falcon --out: $(head -c 300 "$tmp/fa.err")"
fi
# byte for byte against the code before, when given (timing lines and values aside)
if [ -n "${GW_BASE_PROGRAM:-}" ] && [ -x "$GW_BASE_PROGRAM" ]; then
    strip() { grep -v -E 'wall_time|collisions in|of wall time|\([0-9.]+ s\)$|^# (command|granwave)'; }
    for c in "chain" "chain --n 10 --json" "drop" "softwall" "falcon --out OUT"; do
        # shellcheck disable=SC2086
        a=$(cd "$tmp" && rm -rf OUT && cpu_run 300 "$GW" ${c} --quiet 2>&1 | strip; cat OUT/*.csv 2>/dev/null | strip)
        # shellcheck disable=SC2086
        b=$(cd "$tmp" && rm -rf OUT && cpu_run 300 "$GW_BASE_PROGRAM" ${c} --quiet 2>&1 | strip; cat OUT/*.csv 2>/dev/null | strip)
        [ "$a" = "$b" ] && [ -n "$a" ] && ok "3: $c: the output of the code before, byte for byte" ||
            ko "3: $c: differs from the code before"
    done
else
    echo "SKIP: the byte-for-byte comparison (GW_BASE_PROGRAM not given)"
fi

test_summary
