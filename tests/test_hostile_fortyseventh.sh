#!/bin/bash
# test_hostile_fortyseventh.sh GRANWAVE SRCDIR: what the forty-seventh hostile
# pass found, fixed at its root and asserted here.
#  1 An --out directory left by a study that did not finish. falcon,
#    wavespeed and softwall made --out (as mkdir -p) before their runs and
#    took it back only when the run refused an input: a run ended by SIGINT,
#    SIGTERM or SIGHUP (exit 130, 143, 129) or failing (exit 1: `falcon
#    --damping hc --alpha 1e8`, `wavespeed --kwall 1e13`, its front not seen) left the empty
#    directories it made, where chain, drop and dispersion (which make --out
#    only to write) left none. The three now check --out before the work, as
#    before, and make it only to write. Each is stopped once it has used
#    0.3 s of CPU (its run, about 20 to 60 s, well under way: wait_cpu), and
#    must leave neither NEW nor NEW/a; an --out that existed stays with its
#    files; a study that completes still makes NEW/a and writes its files.
#  2 layer-impact, whose run stages its snapshots in --out and so makes it
#    before the run, left the directories it made empty when a signal ended
#    it: the handler that removes the temporaries now also removes the
#    directories the run made, if empty and still the same directory
#    (gw_temps_add_dirs). SIGINT and SIGTERM are sent once the run's first
#    staged snapshot is seen (wait_file); an --out that existed stays. A
#    refusal found by the run (`--dt 1e-12`: too many particle-steps) took
#    back what it made but not the parent of an --out with a trailing slash
#    (`--out N/x/`), and named the option without its dashes ("layer-impact:
#    dt: ..."): now nothing is left and the line says "layer-impact --dt:".
#  3 A wavespeed warning that named the wrong cause. With the sensor as a body
#    (`--sensor-mass 1e-3 --sensor-stiffness 1e6`, N = 8..12) tau_N scatters by
#    0.94 T_q about its line and the estimators disagree by 0.28; the warning
#    put it to "a wall much stiffer than the bead contacts, K/k = 1.41", the
#    default steel wall, whose own scatter is 0.03. It now names the sensor
#    body (--sensor-mass, --sensor-stiffness and its period against T_q), in
#    stderr and --json alike. Control: the rigid wall (K/k = 2.83, no sensor
#    body) still gets the stiff-wall cause.
#  4 `dispersion --column-n` ran its collision without the collision's
#    warnings (chain's: a step above dt-max, an overlap beyond the radius, a
#    collision cut at t_max) and its JSON, --json and dispersion.json, had no
#    "warnings" at all, where every command's has the array ([] when none):
#    a script reading d["warnings"] failed on it. The library's column run
#    now gives the collision's warnings (gw_chain_result_warnings), printed
#    and listed as the study mode's.
#  5 layer-make at a --dt of 1e-9 s or less. Its settling advances in chunks
#    of 0.01 s, each under the solver's default bound of 1e7 steps per call,
#    while the validation bounds the whole settling at 1e9 steps: `--dt 1e-9
#    --t-max 0.0102` (1.02e7 steps) ran 1e7 steps and failed, exit 1, "rk4:
#    more than 10000000 steps before t = 0.01 s", naming no input. A chunk's
#    bound now covers its steps: the run ends (the pile unsettled at that
#    t-max: a warning, 'converged 0') with the porosity of the same run at
#    --dt 1e-8 to 1e-4.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# tree DIR: what DIR holds (recursively), one line; "-" when it does not exist
tree() { if [ -e "$1" ]; then (cd "$1" && find . -mindepth 1 | sort | tr '\n' ' '); else echo -; fi; }

# stopped WHAT SIG OUT CMD...: CMD, writing into OUT, sent SIG once it has
# used 0.3 s of CPU; sets rc (its exit status)
stopped() {
    local sig=$2 pid
    shift 3
    env --default-signal=INT "$GW" "$@" >/dev/null 2>&1 & pid=$!
    wait_cpu $pid 0.3
    kill -"$sig" $pid 2>/dev/null
    wait $pid 2>/dev/null; rc=$?
}

# --- 1 a study's --out after a signal or a failure ---
studies=("falcon --n 1:40 --vimp 0.3 --solver cvode --quiet"
         "wavespeed --n 5:60 --vimp 0.01,0.1,1 --quiet"
         "softwall --sheets --n 1:40 --quiet")
for s in "${studies[@]}"; do
    read -r -a args <<<"$s"
    rm -rf N
    stopped "${args[0]}" INT N "${args[@]}" --out N/a
    [ $rc -eq 130 ] && [ "$(tree N)" = - ] && ok "${args[0]} --out N/a, SIGINT mid-run: exit 130, no N made" ||
        ko "${args[0]} --out N/a, SIGINT mid-run: exit $rc, N holds: $(tree N)"
done
rm -rf N
stopped wavespeed TERM N wavespeed --n 5:60 --vimp 0.01,0.1,1 --quiet --out N/
[ $rc -eq 143 ] && [ "$(tree N)" = - ] && ok "wavespeed --out N/, SIGTERM mid-run: exit 143, no N made" ||
    ko "wavespeed --out N/, SIGTERM mid-run: exit $rc, N holds: $(tree N)"
# an --out that existed keeps what it held
mkdir -p E && echo keep >E/mine.txt
stopped falcon INT E falcon --n 1:40 --vimp 0.3 --solver cvode --quiet --out E
[ $rc -eq 130 ] && [ "$(tree E)" = "./mine.txt " ] && ok "falcon --out E (existing), SIGINT: E as it was" ||
    ko "falcon --out E (existing), SIGINT: exit $rc, E holds: $(tree E)"
# run failures (exit 1)
failing=("falcon --n 1:3 --damping hc --alpha 1e8 --quiet"
       "softwall --n 2:5 --damping hc --alpha 1e8 --quiet"
       "wavespeed --n 6:8 --vimp 0.3 --kwall 1e13 --quiet") # (--kwall 1e14: refused before the run since session 46)
for s in "${failing[@]}"; do
    read -r -a args <<<"$s"
    rm -rf N
    timeout -s KILL 120 "$GW" "${args[@]}" --out N/a >/dev/null 2>"$tmp/stderr"; rc=$?
    [ $rc -eq 1 ] && [ "$(tree N)" = - ] && [ "$(wc -l <"$tmp/stderr")" -eq 1 ] &&
        ok "$s --out N/a: exit 1, one line, no N made" ||
        ko "$s --out N/a: exit $rc, N holds: $(tree N) ($(head -c 200 "$tmp/stderr"))"
done
# control: a study that completes makes N/a and writes its files
rm -rf N
timeout -s KILL 120 "$GW" wavespeed --n 8:10 --vimp 0.1,0.3 --quiet --out N/a >/dev/null 2>&1 &&
    [ "$(tree N)" = "./a ./a/wavespeed.csv ./a/wavespeed.json " ] && ok "control: wavespeed --out N/a writes N/a" ||
    ko "control: wavespeed --out N/a: $(tree N)"
rm -rf N
timeout -s KILL 120 "$GW" softwall --n 2:5 --quiet --out N/a >/dev/null 2>&1 &&
    [ "$(tree N)" = "./a ./a/softwall.json " ] && ok "control: softwall --out N/a writes N/a" ||
    ko "control: softwall --out N/a: $(tree N)"

# --- 2 layer-impact's --out after a signal, and a refusal found by its run ---
"$GW" layer-make --n 20 --width-rm 10 --seed 1 --out s.txt --quiet >/dev/null 2>&1 || ko "layer-make"
# impact_stopped SIG OUT DIR: the long impact into OUT, sent SIG once a staged
# temporary of it is seen in DIR (OUT's directory); sets rc and seen
impact_stopped() {
    local sig=$1 out=$2 dir=$3 pid
    env --default-signal=INT "$GW" layer-impact --sample s.txt --x 0.3 --full --t-max 1 --out "$out" \
        >/dev/null 2>&1 & pid=$!
    wait_file $pid "$dir/*.tmp.*" && seen=1 || seen=0
    kill -"$sig" $pid 2>/dev/null
    wait $pid 2>/dev/null; rc=$?
}
rm -rf N
impact_stopped INT N/a/b N/a/b
[ $seen -eq 1 ] && [ $rc -eq 130 ] && [ "$(tree N)" = - ] &&
    ok "layer-impact --out N/a/b, SIGINT after its first snapshot: exit 130, no N left" ||
    ko "layer-impact --out N/a/b, SIGINT: exit $rc (snapshot seen: $seen), N holds: $(tree N)"
rm -rf N && mkdir N
impact_stopped TERM N/a/ N/a
[ $seen -eq 1 ] && [ $rc -eq 143 ] && [ "$(tree N)" = "" ] &&
    ok "layer-impact --out N/a/ (N existing), SIGTERM: exit 143, N as it was (empty), no N/a" ||
    ko "layer-impact --out N/a/, SIGTERM: exit $rc (snapshot seen: $seen), N holds: $(tree N)"
rm -rf E && mkdir E && echo keep >E/mine.txt
impact_stopped INT E E
[ $seen -eq 1 ] && [ $rc -eq 130 ] && [ "$(tree E)" = "./mine.txt " ] &&
    ok "layer-impact --out E (existing), SIGINT: E as it was" ||
    ko "layer-impact --out E (existing), SIGINT: exit $rc (snapshot seen: $seen), E holds: $(tree E)"
rm -rf N
exits_refused "layer-impact --dt 1e-12 --out N/x/" '^granwave layer-impact --dt: a step of 1e-12 s' 60 \
    "$GW" layer-impact --sample s.txt --dt 1e-12 --out N/x/ &&
    { [ "$(tree N)" = - ] && ok "layer-impact --dt 1e-12 --out N/x/: exit 2 naming --dt, no N left" ||
          ko "layer-impact --dt 1e-12 --out N/x/: N holds: $(tree N)"; }

# --- 3 wavespeed's cause with the sensor as a body ---
if timeout -s KILL 120 "$GW" wavespeed --n 8:12 --vimp 0.1,0.3 --sensor-mass 1e-3 --sensor-stiffness 1e6 --quiet \
    --json >ws.json 2>ws.err; then
    res=$(/usr/bin/python3 - ws.json ws.err <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
err = [l.split("warning: ", 1)[1] for l in open(sys.argv[2]).read().splitlines() if "warning: " in l]
w = [x for x in d["warnings"] if "estimators disagree" in x]
ok = (len(w) == 1 and d["max_disagreement"] > 0.2 and "--sensor-mass 0.001 kg" in w[0]
      and "--sensor-stiffness 1e+06 N/m" in w[0] and "much stiffer" not in w[0])
print(("PASS" if ok else "FAIL") + ": wavespeed with a sensor body: the disagreement (%.3g) put to the sensor "
      "body, not to a stiff wall%s" % (d["max_disagreement"], "" if ok else ": %s" % w))
print(("PASS" if err == d["warnings"] else "FAIL") + ": wavespeed's stderr warnings are its JSON's%s" %
      ("" if err == d["warnings"] else ": %s against %s" % (err, d["warnings"])))
# the body's period, 2 pi sqrt(m/k) = 0.198 ms, against the T_q of the speed named
import math, re
m = re.search(r"at v_imp = ([0-9.e+-]+) m/s", w[0] if w else "")
p = re.search(r"its own period ([0-9.e+-]+) T_q", w[0] if w else "")
if m and p:
    iv = d["v_imp"].index(float(m.group(1)))
    want = 2 * math.pi * math.sqrt(1e-3 / 1e6) / d["t_q"][iv]
    print(("PASS" if abs(float(p.group(1)) / want - 1) < 2e-3 else "FAIL") +
          ": the sensor's period in T_q: %s against %.4g" % (p.group(1), want))
else:
    print("FAIL: the warning gives no sensor period in T_q: %s" % w)
PYEOF
)
    while IFS= read -r line; do
        case $line in PASS:*) ok "${line#PASS: }" ;; *) ko "${line#FAIL: }" ;; esac
    done <<<"$res"
else
    ko "wavespeed --sensor-mass 1e-3 --sensor-stiffness 1e6: exit $? ($(head -c 200 ws.err))"
fi
# control: the rigid wall, no sensor body, keeps the stiff-wall cause
timeout -s KILL 120 "$GW" wavespeed --n 8:12 --vimp 0.1,0.3 --wall-material rigid --quiet --json >wr.json 2>/dev/null &&
    [ "$(jq_py wr.json '[x for x in d["warnings"] if "much stiffer than the bead contacts, K/k = 2.83" in x] != []')" = True ] &&
    ok "control: the rigid wall's warning names the stiff wall" ||
    ko "control: the rigid wall's warning: $(jq_py wr.json 'd["warnings"]' 2>&1 | head -c 300)"

# --- 4 dispersion --column-n's warnings ---
rm -rf N
if timeout -s KILL 120 "$GW" dispersion --column-n 5 --quiet --json --out N >cj.json 2>cj.err; then
    [ "$(jq_py cj.json 'd.get("warnings")')" = "[]" ] && [ "$(jq_py N/dispersion.json 'd.get("warnings")')" = "[]" ] &&
        [ ! -s cj.err ] && ok "dispersion --column-n 5: warnings [] in --json and dispersion.json, none on stderr" ||
        ko "dispersion --column-n 5: warnings $(jq_py cj.json 'd.get("warnings")') / $(jq_py N/dispersion.json 'd.get("warnings")'), stderr: $(head -c 200 cj.err)"
else
    ko "dispersion --column-n 5 --json --out N: exit $? ($(head -c 200 cj.err))"
fi

# --- 5 layer-make at --dt 1e-9 ---
mk=(layer-make --n 2 --width-rm 5 --rm 1e-5 --t-max 0.0102 --quiet)
if timeout -s KILL 120 "$GW" "${mk[@]}" --dt 1e-9 --out p9.txt >/dev/null 2>p9.err &&
    timeout -s KILL 120 "$GW" "${mk[@]}" --dt 1e-8 --out p8.txt >/dev/null 2>/dev/null; then
    res=$(/usr/bin/python3 - p9.txt p8.txt <<'PYEOF'
import sys
def por(f):
    for l in open(f):
        if l.startswith("porosity "):
            return float(l.split()[1])
a, b = por(sys.argv[1]), por(sys.argv[2])
conv = any(l.startswith("# settled:") and "converged 0" in l for l in open(sys.argv[1]))
print(("PASS" if conv and abs(a / b - 1) < 1e-4 else "FAIL") +
      ": layer-make --dt 1e-9: the sample written (converged 0), porosity %r against %r at dt 1e-8" % (a, b))
PYEOF
)
    case $res in PASS:*) ok "${res#PASS: }" ;; *) ko "${res#FAIL: }" ;; esac
else
    ko "layer-make --dt 1e-9 --t-max 0.0102: exit $? ($(head -c 200 p9.err))"
fi

test_summary test_hostile_fortyseventh
