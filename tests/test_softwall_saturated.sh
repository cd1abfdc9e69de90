#!/bin/bash
# test_softwall_saturated.sh GRANWAVE SRCDIR: softwall's `saturated` per wall
# is true when N_d is located (or at most the first size), false when the
# sizes run decided F_max has not reached its plateau, and undecided (JSON
# null, Python masked, text "undecided") when columns held by gravity keep the
# decided ones from locating N_d: the longest column held, or a held one
# ending the walk down the plateau before SATURATION_RUN (6) sizes. It was
# false in both cases, as if the sizes run had decided it. The verdict is
# checked against the rule applied here to the JSON's own F_max and held
# flags, wall by wall, and the walls the warning names are those with null.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

# expected FILE TOL: per wall, what the rule gives from f_max and held:
# True (6 or more sizes on the plateau, or it reaches N = 1), None (held
# columns are why it is not located) or False; printed as a Python list
expected() {
    /usr/bin/python3 - "$1" "$2" <<'EOF'
import json, sys
d, tol = json.load(open(sys.argv[1])), float(sys.argv[2])
walls = d.get("walls") or [d]
out = []
for w in walls:
    f, held, n = w["f_max"], w["held"], len(w["f_max"])
    top = max((i for i in range(n) if not held[i]), default=None)
    if top is None:
        out.append(None)
        continue
    on, i = 0, top
    while i >= 0 and not held[i] and abs(f[i] - f[top]) <= tol * f[top]:
        on, i = on + 1, i - 1
    if i < 0 or on >= 6:
        out.append(True)
    else:
        out.append(None if top < n - 1 or held[i] else False)
print(out)
EOF
}
verdicts() { jq_py "$1" "[w['saturated'] for w in d.get('walls') or [d]]"; }

# one wall, N = 13 and 14 held: undecided
if runs_json "one wall, gravity 30" a.json softwall --n 1:14 --kwall 1e9 --gravity 30 --tol 0.02 --quiet; then
    [ "$(verdicts a.json)" = "[None]" ] && ok "one wall, N = 13, 14 held: saturated null" ||
        ko "one wall held: saturated $(verdicts a.json)"
    [ "$(expected a.json 0.02)" = "[None]" ] && ok "one wall held: the rule over its JSON gives undecided too" ||
        ko "one wall held: the rule gives $(expected a.json 0.02)"
    [ "$(jq_py a.json "d['n_d'] is None and d['n_d_at_most'] is None")" = True ] && ok "one wall held: n_d null" ||
        ko "one wall held: n_d $(jq_py a.json "d['n_d']")"
    grep -q "saturated null" "$tmp/stderr" && ok "one wall held: the warning says saturated is undecided" ||
        ko "one wall held: warning $(cat "$tmp/stderr")"
fi
"$GW" softwall --n 1:14 --kwall 1e9 --gravity 30 --tol 0.02 --quiet >t.txt 2>/dev/null
grep -qE -- '--kwall .* undecided ' t.txt && ok "one wall held: the text says undecided" || ko "text: $(cat t.txt)"
# decided: nothing held
if runs_json "one wall, N = 1..5" b.json softwall --n 1:5 --quiet; then
    [ "$(verdicts b.json)" = "[False]" ] && ok "N = 1..5, nothing held: saturated false (decided)" ||
        ko "N = 1..5: saturated $(verdicts b.json)"
fi
if runs_json "one wall, N = 1..30" c.json softwall --n 1:30 --quiet; then
    [ "$(verdicts c.json)" = "[True]" ] && ok "N = 1..30: saturated true" || ko "N = 1..30: saturated $(verdicts c.json)"
fi
# every sheet, two gravities: each wall's verdict the rule's, held or not
for g in 20 40; do
    if runs_json "sheets gravity $g" "s$g.json" softwall --sheets --n 1:20 --gravity "$g" --tol 0.02 --quiet; then
        got=$(verdicts "s$g.json") want=$(expected "s$g.json" 0.02)
        [ "$got" = "$want" ] && ok "sheets, gravity $g: every wall's saturated is the rule's ($got)" ||
            ko "sheets, gravity $g: saturated $got, the rule gives $want"
        named=$(/usr/bin/python3 -c "
import json, re, sys
d = json.load(open('s$g.json'))
m = re.search(r'N_d \(sheets ([^)]*)\)', open('$tmp/stderr').read())
said = sorted(m.group(1).split(', ')) if m else []
print(said == sorted(w['sheet'] for w in d['walls'] if w['saturated'] is None))")
        [ "$named" = True ] && ok "sheets, gravity $g: the warning names the walls whose saturated is null" ||
            ko "sheets, gravity $g: warning $(cat "$tmp/stderr")"
        # a wall with held columns that is decided (false) is among them: the held ones lie below the walk
        [ "$(jq_py "s$g.json" "any(sum(w['held']) and w['saturated'] is False for w in d['walls'])")" = True ] &&
            ok "sheets, gravity $g: a wall with held columns below its walk is decided false" ||
            ko "sheets, gravity $g: no held wall decided: $(verdicts "s$g.json")"
    fi
done

py_checks <<EOF
import warnings
import numpy as np
import granwave
def check(what, cond):
    print(("PASS: " if cond else "FAIL: ") + what)
with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    s = granwave.softwall(n=(1, 14), kwall=1e9, gravity=30, tol=0.02, jobs=1)
    t = granwave.softwall(n=(1, 14), kwall=1e9, gravity=30, tol=0.02, jobs=1)
check("Python held: saturated masked (tolist None)", np.ma.is_masked(s.saturated) and s.saturated.tolist() == [None])
check("Python held: two runs equal (masked in the same place)", s == t)
u = granwave.softwall(n=(1, 5))
check("Python N = 1..5: saturated False, a plain bool array",
      u.saturated.dtype == bool and not np.ma.isMaskedArray(u.saturated) and u.saturated.tolist() == [False])
EOF

test_summary test_softwall_saturated
