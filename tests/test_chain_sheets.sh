#!/bin/bash
# test_chain_sheets.sh GRANWAVE SRCDIR: the sheet laws, the sensor body and guide
# friction on the command line (issue 19, parts 2-3).
#   - bad values and options without effect exit 2 with one stderr line naming
#     the flag, nothing on stdout, no output directory;
#   - chain --sheet pvc --sheet-law layer/material runs and records the law;
#     the layer (a 1 mm sheet on a steel base) is stiffer than the Hertz
#     half-space of the same material: shorter tau_max, larger F_max;
#   - a stiff light sensor body leaves chain's F_max within 1e-4 of the rigid
#     sensor's; the sensor settings are recorded;
#   - softwall --sheets --sheet-law material --json lists every sheet of Table 2
#     with n_d_model, n_d_measured, tau_max_1_model/measured, tau_max_nd_*; the
#     fitted mode keeps its walls[] keys and gains the same list.
# shellcheck source=tests/test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
PY=/usr/bin/python3

bad() { # expected-word args...
    local word=$1; shift
    "$GW" "$@" --out "$tmp/never" >"$tmp/out" 2>"$tmp/err"; local rc=$?
    local lines; lines=$(wc -l <"$tmp/err")
    if [ $rc -eq 2 ] && [ "$lines" -eq 1 ] && grep -q -- "$word" "$tmp/err" && [ ! -s "$tmp/out" ] && [ ! -e "$tmp/never" ]; then
        ok "bad input '$*' -> exit 2: $(cat "$tmp/err")"
    else
        ko "bad input '$*' -> exit $rc, $lines line(s): $(cat "$tmp/err")"
    fi
    rm -rf "$tmp/never"
}
bad "--sheet-law" chain --sheet pvc --sheet-law foam
bad "--sheet-law" chain --sheet-law layer
bad "--sheet-law" softwall --sheet-law material
bad "--sheet-yield" chain --sheet brass --sheet-yield 2e8
bad "--sheet-yield" chain --sheet brass --sheet-law layer --sheet-yield 2e8
bad "--sheet-yield" chain --sheet brass --sheet-law material --sheet-yield 10
bad "--sheet-yield" chain --sheet brass --sheet-law material --sheet-yield -1
bad "--sheet-loss" chain --sheet pvc --sheet-law material --sheet-loss 0.9
bad "--sheet-loss" chain --sheet pvc --sheet-law material --sheet-loss nan
bad "--sheet-loss" chain --sheet pvc --sheet-loss 0.1
bad "--sensor-mass" chain --sensor-mass 3e-3
bad "--sensor-mass" chain --sensor-mass 0 --sensor-stiffness 1e9
bad "--sensor-mass" chain --sensor-mass -1 --sensor-stiffness 1e9
bad "--sensor-stiffness" chain --sensor-stiffness 1e9
bad "--sensor-stiffness" chain --sensor-mass 3e-3 --sensor-stiffness 0
bad "--sensor-damping" chain --sensor-damping 1
bad "--sensor-damping" falcon --sensor-mass 3e-3 --sensor-stiffness 1e9 --sensor-damping -2
bad "--guide-friction" chain --guide-friction -0.1
bad "--guide-friction" chain --guide-friction inf
bad "--guide-viscous" softwall --guide-viscous 1e9
bad "--sheet" softwall --sheets --sheet brass --sheet-law material
bad "--sheet-yield" softwall --sheets --sheet-law material --sheet-yield 2e8

jget() { $PY -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

"$GW" chain --n 1 --vimp 0.2385 --sheet pvc --sheet-law hertz --json >"$tmp/h.json" 2>"$tmp/err" &&
"$GW" chain --n 1 --vimp 0.2385 --sheet pvc --sheet-law layer --json >"$tmp/l.json" 2>>"$tmp/err" &&
"$GW" chain --n 3 --vimp 0.2385 --sheet pvc --sheet-law material --json >"$tmp/m.json" 2>>"$tmp/err" || ko "chain with sheet laws: $(cat "$tmp/err")"
if [ -s "$tmp/m.json" ]; then
    th=$(jget "$tmp/h.json" "d['tau_max']"); tl=$(jget "$tmp/l.json" "d['tau_max']")
    fh=$(jget "$tmp/h.json" "d['f_max']"); fl=$(jget "$tmp/l.json" "d['f_max']")
    $PY -c "import sys; sys.exit(0 if $tl < $th and $fl > $fh else 1)" &&
        ok "pvc layer stiffer than its half-space: tau_max $tl < $th s, F_max $fl > $fh N" ||
        ko "pvc layer vs half-space: tau_max $tl / $th, F_max $fl / $fh"
    law=$(jget "$tmp/m.json" "d['settings']['model']['sheet_law'], d['settings']['model']['wall_loss']")
    [ "$law" = "('material', 0.02)" ] && ok "chain records sheet_law material and the loss: $law" || ko "chain settings: $law"
    ee=$(jget "$tmp/m.json" "d['energy_error'] < 1e-7 and d['eps_eff'] < 1")
    [ "$ee" = "True" ] && ok "viscoelastic pvc: energy ledger closed, eps_eff < 1" || ko "viscoelastic pvc ledger/eps: $ee"
fi

"$GW" chain --n 4 --json >"$tmp/r.json" 2>"$tmp/err" &&
"$GW" chain --n 4 --sensor-mass 1e-7 --sensor-stiffness 1e14 --sensor-damping 6 --json >"$tmp/s.json" 2>>"$tmp/err" || ko "chain with a sensor body: $(cat "$tmp/err")"
if [ -s "$tmp/s.json" ]; then
    rel=$($PY -c "import json; a=json.load(open('$tmp/r.json')); b=json.load(open('$tmp/s.json')); print(abs(b['f_max']/a['f_max']-1))")
    $PY -c "import sys; sys.exit(0 if $rel < 1e-4 else 1)" && ok "stiff light sensor body: F_max within $rel of the rigid sensor's" || ko "sensor body F_max off by $rel"
    sn=$(jget "$tmp/s.json" "d['settings']['model']['sensor']['stiffness']")
    [ "$($PY -c "print(float($sn) == 1e14)")" = "True" ] && ok "chain records the sensor body" || ko "sensor settings: $sn"
fi

"$GW" softwall --sheets --sheet-law material --n 1:3 --jobs 1 --quiet --json >"$tmp/sw.json" 2>"$tmp/err" || ko "softwall material: $(cat "$tmp/err")"
"$GW" softwall --sheets --n 1:3 --jobs 1 --quiet --json >"$tmp/sf.json" 2>"$tmp/err" || ko "softwall fitted: $(cat "$tmp/err")"
for f in sw sf; do
    [ -s "$tmp/$f.json" ] || continue
    chk=$($PY - "$tmp/$f.json" <<'PYEOF'
import json, sys
d = json.load(open(sys.argv[1]))
keys = ["name", "n_d_model", "n_d_measured", "tau_max_1_model", "tau_max_1_measured",
        "tau_max_nd_model", "tau_max_nd_measured"]
s = d["sheets"]
names = [e["name"] for e in s]
ok = len(s) == 9 and all(all(k in e for k in keys) for e in s) and names[1] == "brass"
ok = ok and all(e["tau_max_1_model"] > 0 for e in s) and len(d["walls"]) == 9 and "kwall" in d["walls"][0]
print("ok" if ok else "bad: %s" % names)
PYEOF
)
    [ "$chk" = "ok" ] && ok "softwall --sheets ($f) JSON sheets[] with model and measured keys" || ko "softwall $f sheets: $chk"
done
[ -s "$tmp/sw.json" ] && [ "$(jget "$tmp/sw.json" "d['sheet_law']")" = "material" ] && ok "softwall records sheet_law" || ko "softwall sheet_law"

test_summary
