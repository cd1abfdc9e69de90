#!/bin/bash
# test_drop_overdamped.sh GRANWAVE SRCDIR: a drop whose first impact a contact
# damping far above critical holds.
#  - drop --damping kk --gamma 1e14 (hc --alpha 1e8, a block, N = 5) ran to
#    t_max, exit 0, and warned "the run was cut at t_max ...; raise --t-max",
#    naming nothing, though no t-max ends that impact. Now, as granwave chain
#    fails on the same collision: exit 1, one stderr line naming the damping
#    model, its constant and value ("lower gamma"), no "raise --t-max",
#    nothing on stdout (--json) and no --out directory.
#  - The drop fails exactly where chain at v_imp = sqrt(2 g h) under the same
#    gravity fails (hc alpha 1e4, kk gamma 1e7: the damping holds bead 1), and
#    runs where chain says gravity holds the column (hc alpha 1e3: exit 0).
#    Under arkode dirk (kk gamma 1e14) chain said "gravity holds the column"
#    (exit 0) where cvode failed naming the damping: the stopped bead's
#    momentum crossed 0 by 1e-12 of its scale, solver noise read as a fall
#    back; a fall back now needs the momentum to have turned away beyond a
#    thousandth of the column's (chain_fell_back), and both fail under dirk.
#  - A bead that came to rest on the sensor (kk gamma 1e6 after one bounce;
#    hc alpha 1e3, which gravity turned back in its first impact) was told
#    "raise --t-max" too: its warning (stderr and the JSON's) now says bead 1
#    is at rest, held by its weight, names the damping, and advises no
#    t-max; Python's sensor force at the end is then the column's weight
#    n m g (static equilibrium, to 1e-9). Control: a t-max inside the first
#    collision (2e-5 s) keeps "raise --t-max".
#  - Controls: a calibrated kk drop (restitution 0.5) runs, its first
#    collision's eps_eff 0.5 to 0.02, bead 1 back on the sensor; Python's drop
#    raises GranwaveRunError naming the damping, and runs hc alpha 100.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

held="^granwave drop: bead 1 still on the sensor at t_max = 0\\.01 s: the contact damping"
# held_fails WHAT PATTERN ARGS...: drop ARGS --out o --json exits 1 within 60 s,
# one stderr line matching PATTERN and not advising --t-max, nothing on stdout, no o
held_fails() {
    local what=$1 pat=$2; shift 2
    rm -rf o
    timeout -s KILL 60 "$GW" drop "$@" --out o --json --quiet >stdout 2>stderr </dev/null
    local rc=$?
    if [ $rc -ne 1 ]; then ko "$what: exit $rc, expected 1 ($(head -c 300 stderr))"; return; fi
    if [ "$(wc -l <stderr)" -ne 1 ]; then ko "$what: $(wc -l <stderr) stderr lines: $(head -c 300 stderr)"; return; fi
    grep -qE -- "$pat" stderr || { ko "$what: message does not match '$pat': $(cat stderr)"; return; }
    grep -q -- "--t-max" stderr && { ko "$what: still advises --t-max: $(cat stderr)"; return; }
    [ -s stdout ] && { ko "$what: printed on stdout"; return; }
    [ -e o ] && { ko "$what: wrote o ($(ls o | tr '\n' ' '))"; return; }
    ok "$what"
}
held_fails "drop --damping kk --gamma 1e14: fails naming the damping" \
    "$held \\(damping kk, gamma 1e\\+14 N s/m\\^1\\.5\\) stopped it inside its overlap.*: lower gamma\$" \
    --damping kk --gamma 1e14
held_fails "drop --damping hc --alpha 1e8 --n 5: fails naming the damping" \
    "$held \\(damping hc, alpha 1e\\+08 s/m\\) stopped it inside its overlap.*: lower alpha\$" \
    --damping hc --alpha 1e8 --n 5
held_fails "drop --damping kk --gamma 1e14 --solver arkode --method dirk: fails as under cvode" \
    "$held \\(damping kk, gamma 1e\\+14 N s/m\\^1\\.5\\)" --damping kk --gamma 1e14 --solver arkode --method dirk
held_fails "drop --damping kk --gamma 1e14 --block --n 3: fails naming the damping" \
    "$held \\(damping kk, gamma 1e\\+14 N s/m\\^1\\.5\\)" --damping kk --gamma 1e14 --block --n 3

# the drop's status is chain's on the same collision (v_imp = sqrt(2 g h), the same gravity)
v=$(/usr/bin/python3 -c "import math; print(repr(math.sqrt(2 * 9.81 * 5.1e-3)))")
for d in "hc --alpha 1e3" "hc --alpha 1e4" "kk --gamma 1e7" "kk --gamma 1e14 --solver arkode --method dirk"; do
    # shellcheck disable=SC2086
    timeout -s KILL 60 "$GW" chain --damping $d --vimp "$v" --gravity 9.81 --t-max 0.01 --quiet >/dev/null 2>chain.err
    crc=$?
    # shellcheck disable=SC2086
    timeout -s KILL 60 "$GW" drop --damping $d --quiet >/dev/null 2>drop.err
    drc=$?
    [ "$crc" -le 1 ] && [ "$drc" -eq "$crc" ] && ok "drop --damping $d: exit $drc, as chain's on its first collision" ||
        ko "drop --damping $d: exit $drc, chain's $crc ($(head -c 200 drop.err) / $(head -c 200 chain.err))"
done

# control: a calibrated damping bounces and runs
if runs_json "drop --damping kk --restitution 0.5 --t-max 0.05" r.json drop --damping kk --restitution 0.5 --t-max 0.05 --quiet; then
    [ "$(jq_py r.json "abs(d['first_collision']['eps_eff'] - 0.5) < 0.02 and d['n_contact_episodes'] > 1")" = True ] &&
        ok "drop --damping kk --restitution 0.5: eps_eff 0.5 to 0.02, several contact episodes" ||
        ko "drop --restitution 0.5: eps_eff $(jq_py r.json "d['first_collision']['eps_eff']"), $(jq_py r.json "d['n_contact_episodes']") episodes"
fi

# at rest on the sensor: said so, the damping named, no t-max advised
rest="bead 1 was at rest on the sensor at t_max = 0.01 s, the contact damping"
rest_warned() { # WHAT NEEDLE ARGS...
    local what=$1 needle=$2; shift 2
    runs_json "$what" w.json drop "$@" --quiet || return
    grep -qF -- "warning: $rest" "$tmp/stderr" && grep -qF -- "$needle" "$tmp/stderr" &&
        ! grep -q -- "--t-max" "$tmp/stderr" && ok "$what: at rest, on stderr" ||
        ko "$what: stderr $(head -c 300 "$tmp/stderr")"
    [ "$(jq_py w.json "any('''$rest''' in x and '''$needle''' in x for x in d['warnings']) and not any('raise --t-max' in x for x in d['warnings'])")" = True ] &&
        ok "$what: at rest, in the JSON warnings" || ko "$what: JSON warnings $(jq_py w.json "d['warnings']")"
}
rest_warned "drop --damping kk --gamma 1e6" "(damping kk, gamma 1e+06 N s/m^1.5) having taken its rebound" \
    --damping kk --gamma 1e6
rest_warned "drop --damping hc --alpha 1e3 --n 3" "the first collision never ended" --damping hc --alpha 1e3 --n 3
if runs_json "drop --t-max 2e-5 (inside the first collision)" c.json drop --t-max 2e-5 --quiet; then
    grep -q "warning: the run was cut at t_max = 2e-05 s: the first collision had not ended.*; raise --t-max\$" \
        "$tmp/stderr" && ok "drop --t-max 2e-5: cut, raise --t-max kept" || ko "drop --t-max 2e-5: $(cat "$tmp/stderr")"
fi

py_checks 3 <<'PYEOF'
try:
    granwave.drop(damping="kk", gamma=1e14)
    print("FAIL: Python drop(damping='kk', gamma=1e14): ran")
except granwave.GranwaveRunError as e:
    check("damping kk, gamma 1e+14" in str(e) and "raise" not in str(e),
          "Python drop(damping='kk', gamma=1e14): names the damping: %s" % str(e)[:200])
except Exception as e:  # noqa: BLE001
    print("FAIL: Python drop(gamma=1e14): raised %s: %s" % (type(e).__name__, str(e)[:160]))
try:
    r, _ = caught(granwave.drop, damping="hc", alpha=100)
    check(r["first_collision"]["eps_eff"] < 0.1 and r["n_contact_episodes"] >= 2,
          "Python drop(damping='hc', alpha=100): runs, bead 1 rebounds (eps_eff %.3g)" % r["first_collision"]["eps_eff"])
except Exception as e:  # noqa: BLE001
    print("FAIL: Python drop(damping='hc', alpha=100): raised %s: %s" % (type(e).__name__, str(e)[:160]))
r, ws = caught(granwave.drop, n=3, damping="hc", alpha=1e3)
w = r["n"] * r["mass"] * r["gravity"]
check(abs(r["f_wall"][-1] / w - 1) < 1e-9 and any("at rest on the sensor" in m and "alpha 1000" in m for m in ws),
      "Python drop(n=3, hc alpha 1e3): at rest, the sensor reads the column's weight (%.12g N of %.12g), "
      "warned %s" % (r["f_wall"][-1], w, [m[:80] for m in ws]))
PYEOF

test_summary test_drop_overdamped
