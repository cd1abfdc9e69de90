#!/bin/bash
# test_fiftythird_left.sh GRANWAVE SRCDIR: what the fifty-third hostile pass
# found and the forty-sixth session fixed at its root, asserted here.
#  1 falcon's settings recorded the rows' cvode tolerances (rtol 1e-12, atol
#    1e-12) beside "name": "rk4" when --accuracy ran rk4: `falcon --n 1:2
#    --heights none --json`, and the header of every file under --out. rk4
#    has no error test: rtol and atol are now null wherever the solver run is
#    rk4 (every study's settings, chain_cli_settings_json), with its steps
#    per contact time and dt as before; report.md says rk4's fixed step.
#    Control: --solver cvode records its tolerances.
#  2 layer-make --n 1 reported porosity 1: the measuring window (x in [0.1,
#    0.9] W, y in [0.1, 0.8] h) holds no disc. The porosity is now NaN (null
#    in --json, "not measured" in the text, absent from the sample's header,
#    NaN in Python) with a warning; layer-impact reads such a sample as
#    before. Control: --n 30 measures a porosity in (0, 1) with no warning.
#  3 wavespeed --n 3:8 --vimp 0.3,0.4 --k 1000 ran every column (13.7 s of
#    CPU) and then exited 1, "no front fit": no contact can carry more than
#    the column's kinetic energy stored in one Hertz contact, F <= (5/2
#    k^(2/3) n m v^2 / 2)^(3/5) = 0.37 N, under the threshold 6.6 N. Refused
#    now before any run (exit 2 naming --threshold, k and kwall); --kwall
#    1e14 likewise. Control: the defaults run.
#  4 drop --n 1500 was refused as held on the wall (naming --gravity) after
#    the whole drop to t_max, about 27 s of CPU: its first collision's t_max
#    is at least the end of bead 1's first contact, so the drop now stops with
#    the same refusal once bead 1 is still on the sensor past the t_max the
#    plan admits (0.0011 s here; 2.8 s of CPU). Not before the run: a held
#    column bounces (drop --n 100 --height 2e-5 --t-max 0.02: 39 impacts),
#    its first collision then cut short and run. Control: a held column
#    within the bound runs.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# 1 falcon's solver settings under --accuracy
cpu_run 60 "$GW" falcon --n 1:2 --heights none --json >f.json 2>f.err </dev/null ||
    ko "1 falcon --json: $(head -c 300 f.err)"
got=$(jq_py f.json "d['settings']['solver']['name'], d['settings']['solver']['rtol'], d['settings']['solver']['atol'], d['settings']['solver']['steps_per_tc']" 2>&1)
[ "$got" = "rk4 None None 37" ] && ok "1 falcon --json under --accuracy: solver rk4, rtol and atol null, 37 steps per T_c" ||
    ko "1 falcon --json under --accuracy: solver $got"
rm -rf fo
cpu_run 60 "$GW" falcon --n 1:2 --heights none --quiet --out fo >/dev/null 2>fo.err </dev/null ||
    ko "1 falcon --out: $(head -c 300 fo.err)"
if head -1 fo/falcon_runs.csv | grep -q '"name":"rk4"' && head -1 fo/falcon_runs.csv | grep -q '"rtol":null,"atol":null' &&
    ! grep -q "rtol" fo/report.md; then
    ok "1 falcon --out: the runs table's header and report.md record rk4 without tolerances"
else
    ko "1 falcon --out: $(head -1 fo/falcon_runs.csv | grep -o '"solver":{[^}]*}' | head -c 300); $(grep Solver fo/report.md)"
fi
cpu_run 60 "$GW" falcon --n 1:2 --heights none --solver cvode --json >fc.json 2>fc.err </dev/null
got=$(jq_py fc.json "d['settings']['solver']['name'], d['settings']['solver']['rtol']" 2>&1)
[ "$got" = "cvode 1e-12" ] && ok "control: falcon --solver cvode records rtol 1e-12" || ko "control: falcon --solver cvode: $got"

# 2 layer-make's porosity of an empty window
cpu_run 60 "$GW" layer-make --n 1 --out one.txt --json >l1.json 2>l1.err </dev/null ||
    ko "2 layer-make --n 1: $(head -c 300 l1.err)"
got=$(jq_py l1.json "d['porosity'], any('porosity is not measured' in w for w in d.get('warnings', []))" 2>&1)
if [ "$got" = "None True" ] && grep -q "porosity is not measured" l1.err && ! grep -q "^porosity" one.txt; then
    ok "2 layer-make --n 1 --json: porosity null, warned, none in the sample's header"
else
    ko "2 layer-make --n 1 --json: $got; header: $(grep '^porosity' one.txt)"
fi
cpu_run 60 "$GW" layer-make --n 1 --out one2.txt >l1.txt 2>l1t.err </dev/null
grep -q "porosity not measured" l1.txt && ! grep -q "porosity 1" l1.txt &&
    ok "2 layer-make --n 1: the text says the porosity is not measured" || ko "2 layer-make --n 1: $(head -1 l1.txt)"
got=$(pyenv /usr/bin/python3 -W ignore -c "
import math, granwave
r = granwave.layer_make(n=1)
print(math.isnan(r['porosity']), any('porosity is not measured' in w for w in r['warnings']))" 2>&1)
[ "$got" = "True True" ] && ok "2 Python: layer_make(n=1) porosity NaN, warned" || ko "2 Python: layer_make(n=1): $got"
cpu_run 60 "$GW" layer-make --n 30 --out thirty.txt --json >l30.json 2>l30.err </dev/null
got=$(jq_py l30.json "0 < d['porosity'] < 1 and not any('porosity' in w for w in d.get('warnings', []))" 2>&1)
[ "$got" = "True" ] && ok "control: layer-make --n 30 measures its porosity, no warning" || ko "control: layer-make --n 30: $got"

# 3 wavespeed's front threshold no contact can reach, refused before the run
REFUSE_TIMEOUT=3 refused "3 wavespeed --k 1000: the threshold above any contact's reach, before the run" \
    "^granwave wavespeed --threshold: 0.1 of F_max\(1\) is 6.639 N at v_imp = 0.3 m/s .* 0.3685 N .* raise k or lower kwall" \
    wavespeed --n 3:8 --vimp 0.3,0.4 --k 1000 --out "$tmp/o"
REFUSE_TIMEOUT=3 refused "3 wavespeed --kwall 1e14: likewise" \
    "^granwave wavespeed --threshold: .*above the largest force any contact of the 8-bead front column can carry" \
    wavespeed --n 3:8 --vimp 0.3,0.4 --kwall 1e14 --out "$tmp/o"
runs_quiet "control: wavespeed --n 3:8 --vimp 0.3,0.4 runs" wavespeed --n 3:8 --vimp 0.3,0.4

# 4 drop's column held on the wall: refused once bead 1 is still on the sensor
# past the time the first collision's plan admits, not after the whole drop
REFUSE_TIMEOUT=12 refused "4 drop --n 1500: held on the wall, refused naming --gravity within 12 s of CPU (was 27 s)" \
    "^granwave drop --gravity: 9.81 m/s\^2 takes back the impact speed .* lower t-max to 0.0011 s or less" \
    drop --n 1500 --quiet --out "$tmp/o"
runs_quiet "control: drop --n 40 --height 1e-6 --t-max 0.005 (held, within the bound) runs" \
    drop --n 40 --height 1e-6 --t-max 0.005

test_summary test_fiftythird_left
