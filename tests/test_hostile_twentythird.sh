#!/bin/bash
# test_hostile_twentythird.sh GRANWAVE SRCDIR: what the twenty-third hostile
# pass found, each fixed at its root and asserted here.
#  1 Output text that was not UTF-8. JSON is UTF-8 text (RFC 8259), but a file
#    name in Latin-1 (a sample s\xff.txt, an --out directory) or a stray byte
#    of a sweep table's comment ("# param note = caf\xe9") went into --json,
#    impact.json, boundary_fit.json and the CSV headers' "# settings:" JSON
#    byte for byte, so that a strict parser (Python's json.loads on the bytes,
#    jq) refused the whole output, exit 0. Every key and string is now printed
#    as UTF-8 by gw_json_string, which every JSON output goes through (a byte
#    that starts no well-formed sequence becomes U+FFFD; valid UTF-8, such as
#    an e-acute, is kept as given), and the recorded command line quotes such
#    a byte as $'\xHH', so that it stays UTF-8 and bash runs it again with the
#    same bytes. The library's validator gw_utf8_len agrees with Python's strict
#    UTF-8 decoder over 20000 random byte strings biased to the edge cases
#    (overlong forms, surrogates, above U+10FFFF, cut sequences).
#  2 dispersion's settings recorded an RK4 step that never ran: under cvode
#    and arkode (which choose their steps) settings.solver held
#    steps_per_sample 16 and rk4_dt = dt_out / 16, in the JSON and in every
#    CSV header. They are now null there; under rk4 they are what ran
#    (rk4_dt x steps_per_sample = dt_out).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
PY=/usr/bin/python3
cd "$tmp" || exit 1

# strict: the file's bytes are UTF-8 and (JSON) parse, NaN and Infinity refused
strict_json() {
    $PY - "$1" <<'EOF'
import json, sys
b = open(sys.argv[1], "rb").read()
def bad(x): raise ValueError("bare " + x)
try:
    json.loads(b.decode("utf-8"), parse_constant=bad)
except Exception as e:
    print(e); sys.exit(1)
EOF
}
utf8_file() { $PY -c "import sys; open(sys.argv[1], 'rb').read().decode('utf-8')" "$1" 2>/dev/null; }

"$GW" layer-make --n 30 --width-rm 12 --seed 3 --t-max 1 --out s.txt >/dev/null 2>&1 || ko "layer-make of the test sample"
LAT=$'s\xff.txt'
cp s.txt "$LAT"

# --- 1a layer-impact --json with a Latin-1 sample name ---
if runs_json "layer-impact --sample s<ff>.txt" li.json layer-impact --sample "$LAT" --t-max 1e-3; then
    if m=$(strict_json li.json); then ok "layer-impact --json with a Latin-1 sample name is UTF-8 JSON"
    else ko "layer-impact --json with a Latin-1 sample name: $m"; fi
    [ "$($PY -c "import json; print(json.loads(open('li.json','rb').read().decode('utf-8','replace'))['settings']['sample'] == 's\ufffd.txt')")" = True ] &&
        ok "its settings.sample reads s U+FFFD .txt" || ko "its settings.sample is not s U+FFFD .txt"
fi

# --- 1b layer-impact --out: every text file UTF-8, the command line runs again ---
"$GW" layer-impact --sample "$LAT" --t-max 1e-3 --out L >/dev/null 2>&1 || ko "layer-impact --out L exit $?"
bad=""
for f in L/*.csv L/*.json L/*.vtk L/*.pvd; do [ -e "$f" ] && { utf8_file "$f" || bad="$bad $f"; }; done
[ -z "$bad" ] && ok "layer-impact --out: every CSV, JSON, VTK and .pvd file is UTF-8" || ko "not UTF-8:$bad"
if strict_json L/impact.json >/dev/null; then ok "impact.json parses strictly"; else ko "impact.json does not parse strictly"; fi
# the ledger's header records the command line; bash reads it back as the same arguments
cmd=$(head -1 L/ledger.csv | $PY -c "import sys; h = sys.stdin.buffer.read().decode('utf-8', 'replace'); print(h.split(';command: ')[1].split(';settings: ')[0])")
got=$(bash -c "set -- ${cmd#granwave }; printf '%s' \"\$3\"" | od -An -tx1 | tr -d ' \n')
[ "$got" = "73ff2e747874" ] && ok "the header's command line gives back the sample's bytes (s ff .txt) through bash" ||
    ko "the header's command line '$cmd' gives back $got, not 73ff2e747874"
# (a warning of the impact, its sample one that did not settle, follows the settings: ';warning: ...')
settings=$(head -1 L/ledger.csv | $PY -c "import sys, json; h = sys.stdin.buffer.read().decode('utf-8'); json.loads(h[h.index(';settings: ') + 11:].split(';warning: ')[0]); print('ok')" 2>&1 | tail -1)
[ "$settings" = ok ] && ok "the ledger header's settings are UTF-8 JSON" || ko "the ledger header's settings: $settings"

# --- 1c layer-stats: a table's Latin-1 comment, a Latin-1 --out ---
PYTHONPATH="$SRC/tests/python" $PY -c "
import conftest
p = conftest.write_synthetic_sweep('syn.csv')
b = open(p, 'rb').read().replace(b'# param vi = 20', b'# param vi = 20\n# param note = caf\xe9 \xc3\xa9')
open('lat.csv', 'wb').write(b)"
if runs_json "layer-stats on a table with a Latin-1 param" ls.json layer-stats lat.csv; then
    if m=$(strict_json ls.json); then ok "layer-stats --json with a Latin-1 param is UTF-8 JSON"
    else ko "layer-stats --json with a Latin-1 param: $m"; fi
    [ "$($PY -c "import json; print(json.loads(open('ls.json','rb').read().decode('utf-8','replace'))['params']['note'] == 'caf\ufffd \u00e9')")" = True ] &&
        ok "the param reads caf U+FFFD and keeps the valid e-acute" || ko "the param is not 'caf U+FFFD e-acute'"
fi
OUTD=$'st\xe9'
"$GW" layer-stats lat.csv --out "$OUTD" --json >ls2.json 2>/dev/null || ko "layer-stats --out st<e9> exit $?"
if strict_json "$OUTD/boundary_fit.json" >/dev/null && strict_json ls2.json >/dev/null; then
    ok "boundary_fit.json and --json of layer-stats --out st<e9> parse strictly"
else ko "boundary_fit.json or --json of layer-stats --out st<e9> do not parse strictly"; fi
c=$($PY -c "import json; print(json.load(open('ls2.json', 'rb'))['command'])" 2>/dev/null)
got=$(bash -c "set -- ${c#granwave }; printf '%s' \"\$4\"" 2>/dev/null | od -An -tx1 | tr -d ' \n')
[ "$got" = "7374e9" ] && ok "the JSON's command line gives back --out's bytes (st e9) through bash" ||
    ko "the JSON's command line '$c' gives back '$got', not 7374e9"
bad=""
for f in "$OUTD"/*; do utf8_file "$f" || bad="$bad $(basename "$f")"; done
[ -z "$bad" ] && ok "every layer-stats output is UTF-8" || ko "layer-stats outputs not UTF-8:$bad"

# valid UTF-8 kept as given (no over-replacement)
rm -rf "é ü"
"$GW" layer-stats syn.csv --out "é ü" --json >ls3.json 2>/dev/null
[ "$($PY -c "import json; print(json.load(open('ls3.json', 'rb'))['command'])" 2>/dev/null)" = "granwave layer-stats syn.csv --out 'é ü' --json" ] &&
    ok "a UTF-8 --out is recorded as given, single-quoted" || ko "a UTF-8 --out is not recorded as given"

# --- 1d the validator against Python's strict decoder ---
before=$((passes + fails))
py_checks <<'EOF'
import ctypes, random
import granwave
from granwave import _lib
lib = ctypes.CDLL(granwave._clib._name)  # the module's library, declared here
try:
    lib.gw_utf8_len.restype = ctypes.c_size_t
    lib.gw_utf8_len.argtypes = [ctypes.c_char_p]
except AttributeError as e:
    print(f"FAIL: the library has no gw_utf8_len ({e})")
    raise SystemExit
def valid_lib(b):
    i = 0
    while i < len(b):
        k = lib.gw_utf8_len(b[i:])
        if k == 0:
            return False
        i += k
    return True
def valid_py(b):
    try:
        b.decode("utf-8"); return True
    except UnicodeDecodeError:
        return False
edge = [0x7f, 0x80, 0xbf, 0xc0, 0xc1, 0xc2, 0xdf, 0xe0, 0xa0, 0x9f, 0xed, 0xef, 0xf0, 0x90, 0x8f, 0xf4, 0xf5, 0xff, 0x41]
rng = random.Random(23)
bad = []
for _ in range(20000):
    b = bytes(rng.choice(edge) if rng.random() < 0.8 else rng.randrange(1, 256) for _ in range(rng.randrange(1, 7)))
    if valid_lib(b) != valid_py(b):
        bad.append(b)
for c in ("é", "€", "😀", "\U0010ffff", "\ud7ff"):
    if not valid_lib(c.encode()):
        bad.append(c.encode())
print(("PASS" if not bad else "FAIL") + ": gw_utf8_len agrees with Python's strict decoder over 20000 edge-biased byte "
      "strings and 5 characters up to U+10FFFF" + ("" if not bad else f" ({len(bad)} disagree, e.g. {bad[:3]})"))
EOF

[ -n "${py_skipped:-}" ] || [ $((passes + fails)) -eq $((before + 1)) ] || ko "the validator check printed no verdict: $(tail -3 "$tmp/py.out")"

# --- 2 dispersion's settings under an adaptive solver record no RK4 step ---
for solver in cvode arkode; do
    rm -rf "d_$solver"
    if runs_json "dispersion --solver $solver" "d_$solver.json" dispersion --n 32 --t-samples 64 --ends fixed --solver "$solver" --out "d_$solver"; then
        r=$(jq_py "d_$solver.json" "d['settings']['solver']['steps_per_sample'] is None and d['settings']['solver']['rk4_dt'] is None")
        [ "$r" = True ] && ok "dispersion --solver $solver: settings record no RK4 step (null)" ||
            ko "dispersion --solver $solver: settings record an RK4 step that never ran"
        h=$(grep -h '^# settings: ' "d_$solver/dispersion_ridge.csv" | $PY -c "import sys, json; s = json.loads(sys.stdin.read()[12:])['solver']; print(s['steps_per_sample'] is None and s['rk4_dt'] is None)")
        [ "$h" = True ] && ok "  and so does dispersion_ridge.csv's header" || ko "  dispersion_ridge.csv's header records an RK4 step"
    fi
done
if runs_json "dispersion --solver rk4" d_rk4.json dispersion --n 32 --t-samples 64 --steps-per-sample 8; then
    r=$(jq_py d_rk4.json "d['settings']['solver']['steps_per_sample'] == 8 and abs(d['settings']['solver']['rk4_dt'] * 8 / d['settings']['spectrum']['dt_out'] - 1) < 1e-15")
    [ "$r" = True ] && ok "dispersion --solver rk4: the RK4 step recorded is dt_out / steps-per-sample" ||
        ko "dispersion --solver rk4: the RK4 step recorded is not dt_out / steps-per-sample"
fi

echo "test_hostile_twentythird: $passes passed, $fails failed"
[ $fails -eq 0 ]
