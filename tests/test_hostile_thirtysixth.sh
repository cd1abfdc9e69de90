#!/bin/bash
# test_hostile_thirtysixth.sh GRANWAVE SRCDIR: what the thirty-sixth hostile
# pass found, fixed at its root and asserted here.
#  1 Contact damping with nothing to act on. kk and hc act on bead contacts and
#    on a Hertz wall, not on a sheet's layer, plastic or viscoelastic wall
#    (gw_chain.h): one bead (or a drop's block) against such a wall ran as if
#    undamped, with exit 0. chain --damping kk --gamma 1e5 --sheet brass
#    --sheet-law layer gave eps_eff 1.000 (as without damping), and
#    --restitution 0.5 under sheet-law material 0.615, the sheet's own, where
#    the help promises "one bead on the wall rebounds with E". Refused naming
#    --damping by chain, drop, a chain sweep's check and Python; two beads (a
#    bead contact) and a Hertz sheet (hertz law) still run, damped.
#  2 Warnings missing from JSON. chain, drop, falcon, wavespeed, softwall,
#    dispersion and layer-make said their warnings on stderr only (an overlap
#    of 6.87e4 bead radii, a dt above the step taken, a run cut at t-max, a
#    pile that did not settle), where layer-impact's and layer-stats' JSON and
#    Python's results list them: a script reading --json took such a result for
#    a clean one. Their --json and --out JSON now carry "warnings", the texts
#    stderr gives ([] when none).
#  3 A value refused just outside a bound was printed rounded onto the bound:
#    "drop --height: 1 is outside [1e-06, 1]" for 1.0000000001, "layer-impact
#    --gap: 1000 is outside [0, 1000]", "falcon --vimp: item 1 is 1000, outside
#    [1e-09, 1000]". The value is now shown with the digits that read back.
#  4 A drop in which no peak reaches --peak-threshold reported f_max 0 (t_fmax
#    null): drop --n 2 --peak-threshold 1e9 said "f_max": 0 of a sensor whose
#    first collision peaked at 72.5 N, a number a script reads as measured. Now
#    null (Python: nan), as t_fmax; a drop with peaks gives impacts[0]'s.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 damping with nothing to act on ---
DAMP='^granwave (chain|drop) --damping: has no effect on one bead against a sheet'
refused "chain --damping kk --gamma 1e5 on one bead against brass under sheet-law layer: refused naming --damping" \
    "$DAMP" chain --damping kk --gamma 1e5 --sheet brass --sheet-law layer --out o
refused "chain --damping hc --restitution 0.5 on one bead against brass under sheet-law material: refused" \
    "$DAMP" chain --damping hc --restitution 0.5 --sheet brass --sheet-law material --out o
refused "chain --damping kk on one bead against an elastic pmma layer (sheet-yield 0): refused" \
    "$DAMP" chain --damping kk --gamma 1e5 --sheet pmma --sheet-law material --sheet-yield 0 --json
refused "drop --damping kk --restitution 0.5 on one bead against brass under sheet-law material: refused" \
    "$DAMP" drop --damping kk --restitution 0.5 --sheet brass --sheet-law material --out o
refused "drop --n 3 --block --damping kk on a brass layer (the block is one body): refused" \
    "$DAMP" drop --n 3 --block --damping kk --gamma 1e5 --sheet brass --sheet-law layer --out o
printf '[sweep]\nmodel = chain\nout = o\n[grid]\nn = 1:2\n[params]\nsheet = brass\nsheet-law = layer\ndamping = kk\ngamma = 1e5\n' >d.ini
refused "sweep --check over n = 1:2 on a brass layer with kk: case 0 refused naming damping" \
    "^granwave sweep: d.ini: case 0: damping: has no effect on one bead" sweep d.ini --check
refused "sweep over n = 1:2 on a brass layer with kk: refused before any case, nothing written" \
    "^granwave sweep: d.ini: case 0: damping: has no effect on one bead" sweep d.ini --quiet

# eps_eff of chain ARGS (empty on a failure)
eps() { timeout -s KILL 60 "$GW" chain "$@" --json 2>/dev/null </dev/null >e.json && jq_py e.json "repr(d['eps_eff'])"; }
# the damping acts where there is something for it: a bead contact (n = 2 on
# the layer: the pair's contact dissipates) and a Hertz sheet (kk on its wall)
e2=$(eps --n 2 --sheet brass --sheet-law layer --damping kk --gamma 1e5)
e2u=$(eps --n 2 --sheet brass --sheet-law layer)
eh=$(eps --sheet brass --sheet-law hertz --damping kk --gamma 1e5)
/usr/bin/python3 -c "
import sys
e2, e2u, eh = float('$e2'), float('$e2u'), float('$eh')
# damping that acted lowers eps_eff (0.78 against the undamped pair's 0.985,
# whose bead-bead vibration keeps some momentum; 0.36 on the Hertz sheet against
# 1.000): one that did not would leave it within rounding of the undamped run's
sys.exit(0 if e2 < e2u - 1e-3 and eh < 0.9 else 1)" 2>/dev/null &&
    ok "damping still acts with a bead contact (n 2 on the brass layer: eps_eff $e2 against $e2u undamped) and on a Hertz sheet ($eh)" ||
    ko "damping where it acts: n 2 layer '$e2' against '$e2u', hertz sheet '$eh'"

py_checks <<'EOF'
refused("Python chain damping='kk' gamma=1e5 on one bead against a brass layer", ["damping"],
        granwave.chain, damping="kk", gamma=1e5, sheet="brass", sheet_law="layer")
refused("Python drop damping='hc' restitution=0.5 against brass under sheet_law material", ["damping"],
        granwave.drop, damping="hc", restitution=0.5, sheet="brass", sheet_law="material")
EOF

# --- 2 warnings in the JSON ---
# json_warns WHAT JSON: the JSON's "warnings" are exactly the texts of the
# stderr lines "granwave CMD: warning: TEXT" in $tmp/stderr, and there is one
json_warns() {
    /usr/bin/python3 - "$2" "$tmp/stderr" <<'EOF' >chk.txt 2>&1
import json, sys
d = json.load(open(sys.argv[1]))
said = [l.split(": warning: ", 1)[1].rstrip("\n") for l in open(sys.argv[2]) if ": warning: " in l]
print(len(said) >= 1 and d.get("warnings") == said, len(said), d.get("warnings", "no key"))
EOF
    case $(cat chk.txt) in
        True*) ok "$1: its JSON's warnings are stderr's" ;;
        *) ko "$1: $(head -c 300 chk.txt)" ;;
    esac
}
# with_warning WHAT CMD...: CMD --json runs (exit 0) with a warning, listed in its JSON
with_warning() {
    local what=$1; shift
    if runs_json "$what" w.json "$@" --quiet; then json_warns "$what" w.json; fi
}
with_warning "chain at an overlap of 6.87e4 radii (--vimp 1000 --mass 1e3 --kwall 1e3)" \
    chain --vimp 1000 --mass 1e3 --kwall 1e3
with_warning "chain --dt 1e-3 (above the step taken)" chain --dt 1e-3
with_warning "drop cut at t-max with bead 1 on the sensor" drop --t-max 1 --damping kk --restitution 0.5
with_warning "falcon --dt 1e-3" falcon --n 1:2 --dt 1e-3
with_warning "wavespeed --dt 1e-3" wavespeed --n 8:10 --dt 1e-3
with_warning "softwall --dt 1e-3" softwall --n 1:3 --dt 1e-3
with_warning "layer-make cut at t-max 0.2 s (the pile did not settle)" layer-make --n 8 --width-rm 6 --seed 1 --t-max 0.2 --out cut.txt
# a clean run: an empty list, not a missing key
for c in "chain" "drop" "dispersion"; do
    if runs_json "$c" c.json $c --quiet; then
        [ "$(jq_py c.json "d.get('warnings')")" = "[]" ] && [ ! -s "$tmp/stderr" ] &&
            ok "$c without a warning: warnings []" || ko "$c without a warning: $(jq_py c.json "d.get('warnings', 'no key')")"
    fi
done
# the --out JSON files carry them too
rm -rf oc od
timeout -s KILL 60 "$GW" chain --dt 1e-3 --out oc >/dev/null 2>"$tmp/stderr" </dev/null &&
    json_warns "chain --dt 1e-3 --out: chain.json" oc/chain.json || ko "chain --dt 1e-3 --out: exit $?"
timeout -s KILL 60 "$GW" drop --dt 1e-3 --out od >/dev/null 2>"$tmp/stderr" </dev/null &&
    json_warns "drop --dt 1e-3 --out: drop.json" od/drop.json || ko "drop --dt 1e-3 --out: exit $?"

# --- 3 a value just outside a bound is shown as given ---
refused "drop --height 1.0000000001: the message shows the value given" \
    "^granwave drop --height: 1\.0000000001 is outside \[1e-06, 1\]" drop --height 1.0000000001 --out o
refused "drop --gap 0.10000001: the item shown as given" \
    "^granwave drop --gap: item 1 is 0\.10000001, outside \[0, 0\.1\]" drop --n 3 --gap 0.10000001 --out o
refused "falcon --vimp 1000.0000001: the item shown as given" \
    "^granwave falcon --vimp: item 1 is 1000\.0000001, outside" falcon --n 1:2 --vimp 1000.0000001 --out o
refused "drop --dt-out 0.0100001: shown as given" \
    "^granwave drop --dt-out: 0\.0100001 s is outside" drop --dt-out 0.0100001 --out o
"$GW" layer-make --n 8 --width-rm 6 --seed 1 --out s.txt >/dev/null 2>&1
refused "layer-impact --gap 1000.0000001: shown as given" \
    "^granwave layer-impact --gap: 1000\.0000001 is outside \[0, 1000\]" layer-impact --sample s.txt --gap 1000.0000001 --out o
refused "layer-impact --t-max 1000.00000001: shown as given" \
    "^granwave layer-impact --t-max: 1000\.00000001 is outside \(0, 1000\]" layer-impact --sample s.txt --t-max 1000.00000001 --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nalpha = 10, 90.0000000001\n[params]\nsample = s.txt\n' >a.ini
refused "sweep --check, alpha = 90.0000000001: shown as given" \
    "^granwave sweep: a.ini:5: \[grid\] alpha: 90\.0000000001 is outside \[0, 90\)" sweep a.ini --check
# and a value of few digits as before
refused "drop --height 2: as before" "^granwave drop --height: 2 is outside \[1e-06, 1\]" drop --height 2 --out o

# --- 4 a drop without a peak at or above the threshold: f_max null ---
if runs_json "drop --n 2 --peak-threshold 1e9" p.json drop --n 2 --peak-threshold 1e9; then
    [ "$(jq_py p.json "(d['n_peaks'], d['f_max'], d['t_fmax'], d['first_collision']['f_max'] > 70)")" = "(0, None, None, True)" ] &&
        ok "drop --n 2 --peak-threshold 1e9: no peak, f_max and t_fmax null (the first collision's 72.5 N kept)" ||
        ko "drop --n 2 --peak-threshold 1e9: $(jq_py p.json "(d['n_peaks'], d['f_max'], d['t_fmax'])")"
fi
if runs_json "drop --n 2" p.json drop --n 2; then
    [ "$(jq_py p.json "d['n_peaks'] > 0 and d['f_max'] == max(i['f_max'] for i in d['impacts'])")" = True ] &&
        ok "drop --n 2: f_max is the largest impact's peak" || ko "drop --n 2: f_max $(jq_py p.json "d['f_max']")"
fi
py_checks <<'EOF'
import math
r = granwave.drop(n=2, peak_threshold=1e9)
check(r["n_peaks"] == 0 and math.isnan(r["f_max"]) and math.isnan(r["t_fmax"]),
      "Python drop peak_threshold=1e9: f_max nan with no peak (%r)" % r["f_max"])
EOF

test_summary test_hostile_thirtysixth
