#!/bin/bash
# test_unused_option_combinations.sh GRANWAVE SRCDIR: options that a given
# combination makes act on nothing are refused (or, where that is known only
# after the run, warned of), as issue 18 class 5 asks (the twenty-second
# hostile pass). Before, each of these exited 0 with outputs identical to the
# run without the option:
#  1 a sheet's overrides under --sheet-law material that gw_sheet_apply drops:
#    --sheet-loss on a sheet that yields (brass, beech, or any sheet given a
#    --sheet-yield above 0: Thornton elastic-plastic, the loss is the elastic
#    layer's; `--sheet pvc --sheet-yield 1e10 --sheet-loss 2` even took a loss
#    the Maxwell arms refuse alone), and --sheet-yield or --sheet-loss with
#    --sheet none (the bare sensor). Refused naming the flag by chain, drop, a
#    chain sweep's --check and Python; the combinations that act still run and
#    change the result (--sheet-yield 0 --sheet-loss 0.3 on brass; pvc's loss);
#  2 drop --block with one bead (already one body of the column's mass);
#  3 layer-impact --height-rm above the sample's depth (the lowest particle's
#    centre under the surface): no particle frozen, the run of --height-rm 0.
#    Refused by the program, a layer sweep's --check and Python; just below the
#    depth the run freezes a particle (the refusal follows the freeze rule);
#  4 layer-make --height-rm at or above the settled pile's top took nothing
#    away: now a warning (program: one stderr line; Python: the result's
#    warnings), the sample still written; a height below the top trims, no
#    warning;
#  5 the reverse: softwall --sheets refused --wall-material under every sheet
#    law, where under hertz, layer and material the sheet none among them is
#    the Hertz half-space of the sensor's material (gw_sheet_apply): it now
#    runs and sets that row alone (kwall, and its label "no sheet (brass
#    sensor)"); under fitted it is still refused;
#  7 --clump-mass over grains of one disc each (layer-make --clumps
#    --aspect-max 1, or layer-impact on such a sample): sum and union are the
#    same mass; refused, and taken where a clump has two discs or more.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

# 1: a sheet's overrides that the material law does not take
refused "1a chain: --sheet-loss on brass (yields)" "^granwave chain --sheet-loss: has no effect on sheet brass" \
    chain --sheet brass --sheet-law material --sheet-loss 0.3 --out "$tmp/o"
refused "1b chain: --sheet-loss with --sheet-yield > 0" "^granwave chain --sheet-loss: has no effect on sheet pvc" \
    chain --sheet pvc --sheet-law material --sheet-yield 1e10 --sheet-loss 2
refused "1c chain: --sheet-loss with sheet none" "^granwave chain --sheet-loss: has no effect with sheet none" \
    chain --sheet none --sheet-law material --sheet-loss 0.3
refused "1d chain: --sheet-yield with sheet none" "^granwave chain --sheet-yield: has no effect with sheet none" \
    chain --sheet none --sheet-law material --sheet-yield 1e6
refused "1e drop: --sheet-loss on beech (yields)" "^granwave drop --sheet-loss: has no effect on sheet beech" \
    drop --sheet beech --sheet-law material --sheet-loss 0.1 --out "$tmp/o"
printf '[sweep]\nmodel = chain\nout = %s/o\n[grid]\nn = 1, 2\n[params]\nsheet = brass\nsheet-law = material\nsheet-loss = 0.3\n' \
    "$tmp" >brass.ini
refused "1f sweep --check: sheet-loss on brass" "^granwave sweep: .*brass.ini: case 0: sheet-loss: has no effect" \
    sweep brass.ini --check
# what acts still runs, and acts
fmax() { "$GW" chain "$@" --json 2>/dev/null | $PY -c "import json,sys; print(json.load(sys.stdin)['f_max'])"; }
a=$(fmax --sheet brass --sheet-law material --sheet-yield 0)
b=$(fmax --sheet brass --sheet-law material --sheet-yield 0 --sheet-loss 0.3)
c=$(fmax --sheet pvc --sheet-law material)
d=$(fmax --sheet pvc --sheet-law material --sheet-loss 0.1)
if [ -n "$a" ] && [ -n "$b" ] && [ -n "$c" ] && [ -n "$d" ] && [ "$a" != "$b" ] && [ "$c" != "$d" ]; then
    ok "1g a loss on an elastic sheet runs and changes F_max ($a -> $b N; pvc $c -> $d N)"
else
    ko "1g a loss on an elastic sheet: F_max '$a' '$b', pvc '$c' '$d'"
fi

# 2: drop --block with one bead
refused "2a drop --block --n 1" "^granwave drop --block: has no effect with one bead" drop --block --n 1 --out "$tmp/o"
# (runs_json counts a run that fails; the checks after it, a run that ran)
if runs_json "2b drop --block --n 2" b2.json drop --block --n 2 --t-max 1e-3; then
    [ "$(jq_py b2.json 'd["n"], d["block"]')" = "1 True" ] && ok "2b drop --block --n 2 runs one body" ||
        ko "2b drop --block --n 2 ($(head -c 200 b2.json))"
fi

# 3: layer-impact --height-rm above the sample's depth
"$GW" layer-make --n 12 --width-rm 8 --seed 2 --ke-threshold 1e-2 --t-max 2 --solver verlet --out S.txt \
    >/dev/null 2>&1 || { ko "layer-make of the test sample"; echo "$passes passed, $fails failed"; exit 1; }
depth=$($PY - <<'EOF'
lines = open("S.txt").read().split("\n")
for i, l in enumerate(lines):
    if l.startswith("rm "):
        rm = float(l.split()[1])
    if l.startswith("n "):
        break
pts = [[float(v) for v in l.split()] for l in lines[i + 1:i + 1 + int(lines[i].split()[1])]]
print(repr((max(y + r for _, y, r in pts) - min(y for _, y, _ in pts)) / rm))
EOF
)
above=$($PY -c "print(repr($depth * 1.001))"); below=$($PY -c "print(repr($depth * 0.999))")
LI=(layer-impact --sample S.txt --t-max 2e-3 --vi 5)
refused "3a layer-impact --height-rm 1000" "^granwave layer-impact --height-rm: .*no particle is frozen" \
    "${LI[@]}" --height-rm 1000 --out "$tmp/o"
refused "3b layer-impact --height-rm just above the depth ($above R_m)" "^granwave layer-impact --height-rm: " \
    "${LI[@]}" --height-rm "$above"
if runs_json "3c layer-impact --height-rm just below the depth" h.json "${LI[@]}" --height-rm "$below"; then
    [ "$(jq_py h.json 'd["n_frozen"] >= 1')" = "True" ] &&
        ok "3c just below the depth ($below R_m) freezes $(jq_py h.json 'd["n_frozen"]') particle(s)" ||
        ko "3c just below the depth ($below R_m): nothing frozen"
fi
printf '[sweep]\nmodel = layer\nout = %s/o\n[grid]\nheight-rm = 2, 1000\n[params]\nsample = S.txt\nt-max = 2e-3\n' \
    "$tmp" >h.ini
refused "3d layer sweep --check: height-rm 1000" "^granwave sweep: .*h.ini: case 1: height-rm: .*no particle is frozen" \
    sweep h.ini --check

# 4: layer-make --height-rm that takes nothing away
LM=(layer-make --n 12 --width-rm 8 --seed 2 --ke-threshold 1e-2 --t-max 2 --solver verlet)
"$GW" "${LM[@]}" --height-rm 100 --out T.txt --quiet --json >t.json 2>t.err
rc=$?
if [ $rc -eq 0 ] && [ -s T.txt ] && [ "$(wc -l <t.err)" -eq 1 ] &&
    grep -q "^granwave layer-make: warning: --height-rm took nothing away" t.err &&
    [ "$(jq_py t.json 'd["n_removed_above_height"]')" = "0" ]; then
    ok "4a layer-make --height-rm 100: sample written, one warning"
else
    ko "4a layer-make --height-rm 100: exit $rc, stderr: $(cat t.err)"
fi
"$GW" "${LM[@]}" --height-rm 6 --out U.txt --quiet --json >u.json 2>u.err
rc=$?
if [ $rc -eq 0 ] && [ ! -s u.err ] && [ "$(jq_py u.json 'd["n_removed_above_height"] > 0')" = "True" ]; then
    ok "4b layer-make --height-rm 6 trims $(jq_py u.json 'd["n_removed_above_height"]') particles, no warning"
else
    ko "4b layer-make --height-rm 6: exit $rc, stderr: $(cat u.err)"
fi

# 5: the reverse: softwall --sheets refused --wall-material under every law,
# where under hertz, layer and material the sheet none among them is the Hertz
# half-space of the sensor's material: it now runs and sets that row alone
refused "5a softwall --sheets --wall-material (fitted)" "^granwave softwall --wall-material: has no effect with sheets" \
    softwall --sheets --n 1:3 --jobs 1 --quiet --wall-material brass
SW=(softwall --sheets --n 1:3 --jobs 1 --quiet --sheet-law hertz)
if runs_json "5b softwall --sheets --sheet-law hertz" sw0.json "${SW[@]}" &&
    runs_json "5b softwall --sheets --sheet-law hertz --wall-material brass" sw1.json "${SW[@]}" --wall-material brass; then
    r=$($PY - <<'EOF'
import json
a, b = (json.load(open(f))["sheets"] for f in ("sw0.json", "sw1.json"))
bad = []
if not b[0]["kwall"] < 0.9 * a[0]["kwall"]:  # brass is softer than steel: a lower Hertz coefficient
    bad.append("none: kwall %g -> %g" % (a[0]["kwall"], b[0]["kwall"]))
if b[0]["material"] != "no sheet (brass sensor)":
    bad.append("none labelled %r" % b[0]["material"])
bad += ["%s changed" % x["name"] for x, y in zip(a[1:], b[1:]) if x != y]
print("; ".join(bad) or "ok")
EOF
)
    [ "$r" = "ok" ] && ok "5b --sheets --sheet-law hertz --wall-material brass sets the sheet none row alone" ||
        ko "5b --sheets --sheet-law hertz --wall-material brass: $r"
fi

# 7: --clump-mass over grains of one disc each (aspect-max 1: the sum and the
# union of a clump's discs are the same mass; the sample differed only in its
# header line, the impact not at all)
refused "7a layer-make --clumps --aspect-max 1 --clump-mass union" \
    "^granwave layer-make --clump-mass: has no effect with aspect-max 1" \
    "${LM[@]}" --clumps --aspect-max 1 --clump-mass union --out "$tmp/o"
"$GW" "${LM[@]}" --clumps --aspect-max 1 --out C1.txt >/dev/null 2>&1 || ko "7 layer-make of the one-disc clump sample"
refused "7b layer-impact --clump-mass union on one-disc clumps" \
    "^granwave layer-impact --clump-mass: has no effect: every clump of the sample 'C1.txt' is one disc" \
    layer-impact --sample C1.txt --t-max 2e-3 --vi 5 --clump-mass union --out "$tmp/o"
"$GW" "${LM[@]}" --clumps --aspect-max 1.5 --clump-mass union --out C2.txt >/dev/null 2>c2.err &&
    runs_json "7c" c2.json layer-impact --sample C2.txt --t-max 2e-3 --vi 5 --clump-mass sum &&
    ok "7c clumps of aspect up to 1.5: --clump-mass taken by layer-make and layer-impact" ||
    ko "7c clumps of aspect up to 1.5: $(cat c2.err "$tmp/stderr" | head -c 300)"

# 1-4 and 7 in Python: the same library checks and warning
pyenv $PY - >py.out 2>&1 <<'EOF'
import warnings
import granwave

bad = []
def refused(name, key, **kw):
    fn = getattr(granwave, name)
    try:
        fn(**kw)
        bad.append("%s(%r) ran" % (name, kw))
    except granwave.GranwaveValueError as e:
        if not str(e).startswith("%s: %s:" % (name, key)):
            bad.append("%s(%r): %s" % (name, kw, e))

refused("chain", "sheet_loss", sheet="brass", sheet_law="material", sheet_loss=0.3)
refused("chain", "sheet_yield", sheet="none", sheet_law="material", sheet_yield=1e6)
refused("drop", "block", n=1, block=True)
refused("layer_impact", "height_rm", sample="S.txt", t_max=2e-3, vi=5, height_rm=1000)
refused("layer_make", "clump_mass", n=12, width_rm=8, clumps=True, aspect_max=1, clump_mass="union")
with warnings.catch_warnings(record=True) as w:
    warnings.simplefilter("always")
    r = granwave.layer_make(n=12, width_rm=8, seed=2, ke_threshold=1e-2, t_max=2, solver="verlet", height_rm=100)
ws = list(r["warnings"]) if isinstance(r, dict) else list(r.warnings)
if not any("height_rm took nothing away" in x for x in ws) or not any("height_rm" in str(x.message) for x in w):
    bad.append("layer_make(height_rm=100): warnings %r, issued %r" % (ws, [str(x.message) for x in w]))
print("\n".join(bad) or "ok")
EOF
[ "$(cat py.out)" = "ok" ] && ok "6 Python refuses 1-3 and 7 naming the keyword and warns of 4" || ko "6 Python: $(cat py.out)"

echo "$passes passed, $fails failed"
[ "$fails" -eq 0 ]
