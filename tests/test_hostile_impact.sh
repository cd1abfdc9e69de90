#!/bin/bash
# test_hostile_impact.sh GRANWAVE SRCDIR: the thirteenth hostile pass, over the
# outcomes of layer-impact (and the layer sweep cases built on it) seen several
# ways: --dt-out, --out, snapshots, fast against exact. Each check asserts
# behaviour (values, exit codes) and failed on the binary before this pass
# unless marked "kept".
#  1 the fast mode's trajectory changed with --dt-out in the last bits (the
#    verlet step that landed on a sample was tout - t, a few ulps off dt), and a
#    chaotic impact grew that: R_b = 2 R_m at 5 m/s on a 100-disc sample, which
#    takes off at 0.25 s, gave e_n 0.045331 / 0.045333 / 0.045337 / 0.045345 at
#    dt-out 1e-5 / 2e-5 / 1e-4 / 1e-3. Now every step is dt and the outcome is
#    the same double at every dt-out that is a multiple of the step.
#  2 the first contact's opening was read up to the end of the run, which a
#    decided run reaches at the first sample after the verdict: a block that
#    did not bounce (0.1 m/s) and still rested on its target at the verdict
#    (5.35 ms) gave t_contact_open = t_end and dissipated_contact_open 0.510,
#    0.518 and 0.537 at dt-out 1e-5, 1e-4 and 1e-3, and the true opening (5.53
#    ms) with --full. The first-contact values are now frozen at the verdict:
#    the same at every dt-out and with --full, and an opening that had not come
#    by then is null (it was t_end, also for runs cut by t-max).
set -u
GW=$1
SRC=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# shellcheck source=tests/refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
PY=/usr/bin/python3
S300=$SRC/data/measured/layer_diagram_8000/sample.txt

# the values of KEYS in JSON file F, one line, each as repr (bit for bit)
vals() { $PY -c "
import json, sys
j = json.load(open(sys.argv[1]))
print(' '.join(repr(j[k]) for k in sys.argv[2:]))" "$@"; }
# times of JSON file F, rounded to 1e-12 relative (event times are interpolated
# between step ends whose times are sums of steps: they may differ in the last bit)
times() { $PY -c "
import json, sys
j = json.load(open(sys.argv[1]))
print(' '.join('None' if j[k] is None else '%.12e' % j[k] for k in sys.argv[2:]))" "$@"; }
OUTK="bounced e_n e alpha_r v_nr v_r e_n_first e_first alpha_r_first penetration dissipated_first_contact block_loss_first_contact dissipated_contact_open"
TIMEK="t_leave t_rebound t_rebound_first t_f t_first_contact t_contact_open"

"$GW" layer-make --n 100 --width-rm 20 --seed 5 --out "$tmp/s100.txt" >/dev/null 2>&1 || ko "layer-make of the 100-disc sample"

# --- 1: the fast mode's outcome does not depend on --dt-out -----------------
same_over_dtout() { # WHAT ARGS...: the outcome at dt-out 1e-5, 2e-5, 1e-4, 1e-3
    local what=$1; shift
    local ref="" reft="" d v t bad=""
    for d in 1e-5 2e-5 1e-4 1e-3; do
        "$GW" layer-impact "$@" --dt-out $d --json >"$tmp/j_$d.json" 2>/dev/null || { bad="$bad exit at $d"; continue; }
        v=$(vals "$tmp/j_$d.json" $OUTK); t=$(times "$tmp/j_$d.json" $TIMEK)
        if [ -z "$ref" ]; then ref=$v; reft=$t
        else
            [ "$v" = "$ref" ] || bad="$bad; dt-out $d: $v against $ref"
            [ "$t" = "$reft" ] || bad="$bad; times at dt-out $d: $t against $reft"
        fi
    done
    [ -z "$bad" ] && ok "1: $what: the same outcome bit for bit at dt-out 1e-5, 2e-5, 1e-4, 1e-3" ||
        ko "1: $what:$bad"
}
same_over_dtout "a chaotic late rebound (R_b = 2 R_m, 5 m/s, take-off at 0.25 s)" \
    --sample "$tmp/s100.txt" --rb-rm 2 --vi 5 --x 1 --t-max 0.3
same_over_dtout "a grazing impact on 300 discs (45 deg, take-off at 0.17 s)" \
    --sample "$S300" --vi 20 --alpha 45 --t-max 0.3 --until verdict

# --- 2: the first contact is read up to the verdict ---------------------------
FCK="bounced penetration dissipated_first_contact block_loss_first_contact dissipated_contact_open"
FCT="t_first_contact t_contact_open" # times: to 1e-12, as in 1
ref=""; bad=""
for v in "--dt-out 1e-5" "--dt-out 1e-4" "--dt-out 1e-3" "--full" "--until verdict"; do
    # shellcheck disable=SC2086
    "$GW" layer-impact --sample "$tmp/s100.txt" --vi 0.1 --gap 1e-9 --t-max 0.05 $v --json >"$tmp/fc.json" 2>/dev/null ||
        { bad="$bad exit with $v"; continue; }
    got="$(vals "$tmp/fc.json" $FCK) $(times "$tmp/fc.json" $FCT)"
    [ -z "$ref" ] && ref=$got
    [ "$got" = "$ref" ] || bad="$bad; $v: $got against $ref"
done
[ -z "$bad" ] && ok "2: a block resting on its target (no bounce): the first contact the same at dt-out 1e-5, 1e-4, 1e-3, --full, --until verdict" ||
    ko "2: first contact of a block that stays:$bad"
set -- $ref
[ "$1" = False ] && [ "$7" = None ] && [ "$5" = None ] &&
    ok "2:   no bounce, and the contact that had not opened by the verdict has no opening (null)" ||
    ko "2:   bounced $1, t_contact_open $7, dissipated_contact_open $5 (expected False None None)"
"$GW" layer-impact --sample "$tmp/s100.txt" --vi 0.05 --gap 1e-10 --t-max 0.01 --json >"$tmp/fc.json" 2>/dev/null
got=$(vals "$tmp/fc.json" bounced t_contact_open t_end)
[ "$got" = "None None 0.01" ] && ok "2: a run cut by t-max with the block on its target: t_contact_open null, not t_end" ||
    ko "2: cut run: bounced, t_contact_open, t_end = $got"

echo "$passes passed, $fails failed"
[ $fails -eq 0 ]
