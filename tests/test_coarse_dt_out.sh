#!/bin/bash
# test_coarse_dt_out.sh GRANWAVE SRCDIR: a coarse --dt-out thins the written
# series and changes no result; a run that ends before its first impact is
# closed names that end, not the sampling; a sweep config's [grid] values are
# read by the options' table, and a repeated key names its section.
#  1 layer-impact stopped at the first sample after the outcome was decided:
#    on the 40-disc pile of `layer-make --n 40`, --dt-out 0.2 ran the default
#    impact (T_f 0.306 s) to t_end 0.4 s and read energy_error at its samples
#    alone (1.6e-5 against 3.4e-5 at the default 2e-5 s); --until verdict (the
#    verdict at 1.56 ms) ran to 0.2 s. The run now stops at the check after the
#    outcome (every 2e-5 s on the step grid) whatever dt-out: t_end and
#    energy_error are the default's; the outcome itself (events) was already.
#  2 The crowns' warning said "give a smaller --dt-out" where the run ended
#    before the first impact was closed by T_f: --until verdict --dt-out 0.2,
#    and --t-max 0.001 --dt-out 0.2, whose speeds are null at the default
#    sampling too. It now names the run's end (the verdict, t-max). Since the
#    crowns are read at the run's checks (test_wave_speed_dt_out), a coarse
#    --dt-out gives the default's speeds, null here without a warning as the
#    default; rk4 at a step that does not divide --dt-out too, whose samples
#    were its checks until the forty-fourth session (test_dt_out_bitwise).
#  3 A [grid] value was checked only by the check of every case ("case 1:
#    solver: unknown value 'cvod'", no line); now as the config is read
#    ("c.ini:5: [grid] solver: ..."), as a [params] value already was.
#  4 A repeated key names its section and where it was given first, in
#    [sweep], [grid], [params] and across them, either order (refused before
#    too, as "duplicate key 'K'").
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "$0")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C
PY=/usr/bin/python3

cpu_run 120 "$GW" layer-make --n 40 --out s40 --quiet >/dev/null 2>&1 ||
    { ko "layer-make --n 40 (the pile the checks impact)"; test_summary test_coarse_dt_out; exit; }

# impact NAME ARGS...: layer-impact on s40, --json into NAME.json
impact() {
    local name=$1
    shift
    cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json "$@" >"$name.json" 2>"$name.err"
}
# field NAME KEY: the JSON value (None for null)
field() { $PY -c "import json; print(json.load(open('$1.json')).get('$2'))"; }
# same NAME1 NAME2 KEY TOL: the two values within TOL (relative), or both null
same() {
    $PY - "$1.json" "$2.json" "$3" "$4" <<'EOF'
import json, sys
a, b = (json.load(open(f)).get(sys.argv[3]) for f in sys.argv[1:3])
tol = float(sys.argv[4])
sys.exit(0 if (a is None and b is None) or (a is not None and b is not None and abs(a - b) <= tol * abs(b)) else 1)
EOF
}
# warned NAME PREFIX: the --json warnings' line starting PREFIX
warned() { $PY -c "import json; print(''.join(w for w in json.load(open('$1.json'))['warnings'] if w.startswith('$2')))"; }

impact d0 && impact d2 --dt-out 0.2 || ko "layer-impact at the default and --dt-out 0.2 ran (exit $?)"
# 1: the run's end and the energy closure
same d2 d0 t_end 1e-9 && ok "--dt-out 0.2 ends the run where the default does (t_end $(field d0 t_end) s)" ||
    ko "--dt-out 0.2 ends the run at t_end $(field d2 t_end) s, the default at $(field d0 t_end) s"
same d2 d0 energy_error 1e-6 && ok "--dt-out 0.2 gives the default's energy_error ($(field d0 energy_error))" ||
    ko "--dt-out 0.2 gives energy_error $(field d2 energy_error), the default $(field d0 energy_error)"
bad=""
for k in bounced e_n e alpha_r e_n_first t_f penetration dissipated_first_contact t_contact_open dissipated_contact_open; do
    same d2 d0 "$k" 1e-9 || bad="$bad $k ($(field d2 "$k") vs $(field d0 "$k"))"
done
[ -z "$bad" ] && ok "control: --dt-out 0.2 gives the default's outcome (e_n $(field d0 e_n))" ||
    ko "--dt-out 0.2 changes the outcome:$bad"
w=$(warned d2 "dt-out:")
same d2 d0 wave_speed 1e-12 && same d2 d0 wave_speed_kinetic 1e-12 && [ "$(field d0 wave_speed)" != None ] &&
    [ -z "$w" ] && ok "--dt-out 0.2 gives the default's wave speeds, read at the run's checks, no dt-out warning" ||
    ko "--dt-out 0.2: wave_speed $(field d2 wave_speed) (default $(field d0 wave_speed)), warning '$w'"

impact v0 --until verdict && impact v2 --until verdict --dt-out 0.2 || ko "--until verdict runs (exit $?)"
same v2 v0 t_end 1e-9 && ok "--until verdict --dt-out 0.2 stops at the verdict's check (t_end $(field v0 t_end) s)" ||
    ko "--until verdict --dt-out 0.2 ends at $(field v2 t_end) s, the default at $(field v0 t_end) s"
same v2 v0 e_n_first 1e-9 && ok "control: --until verdict --dt-out 0.2 gives the default's e_n_first" ||
    ko "--until verdict --dt-out 0.2: e_n_first $(field v2 e_n_first), the default $(field v0 e_n_first)"

# 2: the reason named (the default sampling of these runs leaves the speeds null
# too; since the fifty-third pass both say the run's end, the wave's strain peaks
# in 1 ring at the verdict: test_hostile_fiftythird)
[ "$(field v0 wave_speed)" = None ] && [ "$(warned v0 '')" = "$(warned v0 'crowns: the run ended at t = ')" ] &&
    [ -n "$(warned v0 '')" ] &&
    ok "control: --until verdict at the default sampling: speeds null, the run's end alone said" ||
    ko "--until verdict at the default sampling: wave_speed $(field v0 wave_speed), warnings '$(warned v0 '')'"
[ "$(field v2 wave_speed)" = None ] && [ "$(warned v2 '')" = "$(warned v0 '')" ] &&
    ok "--until verdict --dt-out 0.2: speeds null, the default sampling's warning alone (no dt-out)" ||
    ko "--until verdict --dt-out 0.2: wave_speed $(field v2 wave_speed), warnings '$(warned v2 '')'"
# rk4 at a step (3e-6 s) that does not divide 0.2 s: its samples were its
# checks, and the until/t-max wording was checked there; since the forty-fourth
# session its checks are every 20 steps whatever --dt-out
# (test_dt_out_bitwise): null speeds and no dt-out warning, as the default's
rk=(--solver rk4 --dt 3e-6)
impact v3 "${rk[@]}" --until verdict --dt-out 0.2 || ko "${rk[*]} --until verdict --dt-out 0.2 runs (exit $?)"
w=$(warned v3 "")
[ "$(field v3 wave_speed)" = None ] && [[ $w != *"dt-out"* ]] &&
    ok "${rk[*]} --until verdict --dt-out 0.2: speeds null, no dt-out warning" ||
    ko "${rk[*]} --until verdict --dt-out 0.2: wave_speed $(field v3 wave_speed), warning '$w'"
impact t3 "${rk[@]}" --t-max 0.001 --dt-out 0.2 || ko "${rk[*]} --t-max 0.001 --dt-out 0.2 runs (exit $?)"
[ "$(field t3 wave_speed)" = None ] && [ -z "$(warned t3 'dt-out:')" ] &&
    ok "${rk[*]} --t-max 0.001 --dt-out 0.2: speeds null, no dt-out warning" ||
    ko "${rk[*]} --t-max 0.001 --dt-out 0.2: warnings '$(warned t3 '')'"

# chain: its outcome from events (a control: it was already)
cpu_run 60 "$GW" chain --n 10 --quiet --json >c0.json 2>/dev/null &&
    cpu_run 60 "$GW" chain --n 10 --dt-out 0.2 --quiet --json >c2.json 2>/dev/null || ko "chain --n 10 ran"
bad=""
for k in f_max tau_max tau_n period eps_eff eps_col t_end n_s; do
    same c2 c0 "$k" 1e-6 || bad="$bad $k ($(field c2 "$k") vs $(field c0 "$k"))"
done
[ -z "$bad" ] && ok "control: chain --n 10 --dt-out 0.2 gives the default's outcome" ||
    ko "chain --n 10 --dt-out 0.2 changes:$bad"

# 3: [grid] values by the options' table, as the config is read
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\nsolver = rk4, cvod\n' >g1.ini
refused "[grid] solver = rk4, cvod" \
    "^granwave sweep: g1\\.ini:5: \\[grid\\] solver: unknown value 'cvod' \\(cvode arkode rk4\\)$" sweep g1.ini --out o
printf '[sweep]\nmodel = chain\n[grid]\nn = 0:2\n' >g2.ini
refused "[grid] n = 0:2" "^granwave sweep: g2\\.ini:4: \\[grid\\] n: 0 is outside \\[1, " sweep g2.ini --check --out o
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\ndamping = none,\n    kq\n' >g3.ini
refused "[grid] a list over two lines, its second misspelt" \
    "^granwave sweep: g3\\.ini:6: \\[grid\\] damping: unknown value 'kq' \\(none kk hc\\)$" sweep g3.ini --out o
printf '[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\nsolver = verlet, rk5\n[params]\nsample = s40\nt-max = 0.002\n' >g4.ini
refused "[grid] solver = verlet, rk5 (layer)" \
    "^granwave sweep: g4\\.ini:5: \\[grid\\] solver: unknown value 'rk5' \\(verlet rk4 cvode arkode\\)$" sweep g4.ini --out o
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\ndamping = kq\n' >p1.ini
refused "control: [params] damping = kq" \
    "^granwave sweep: p1\\.ini:6: \\[params\\] damping: unknown value 'kq' \\(none kk hc\\)$" sweep p1.ini --out o

# 4: a repeated key, every section, both orders; nothing written
dup() { # NAME LINE SECTION FIRST KEY TEXT
    printf "$6" >"$1.ini"
    refused "$1: '$5' repeated in [$3]" \
        "^granwave sweep: $1\\.ini:$2: duplicate key '$5' in \\[$3\\] \\((the option '[a-z-]+', )?given before in \\[$4\\]" sweep "$1.ini"
}
dup k1 4 sweep sweep out '[sweep]\nmodel = chain\nout = o\nout = o2\n[grid]\nn = 1:2\n'
dup k2 3 sweep sweep out '[sweep]\nout = o\nout = o2\nmodel = chain\n[grid]\nn = 1:2\n'
dup k3 4 sweep sweep model '[sweep]\nmodel = chain\nout = o\nmodel = layer\n[grid]\nn = 1:2\n'
dup k4 6 grid grid n '[sweep]\nmodel = chain\nout = o\n[grid]\nn = 1:2\nn = 3\n'
dup k5 8 params params vimp '[sweep]\nmodel = chain\nout = o\n[grid]\nn = 1:2\n[params]\nvimp = 0.1\nvimp = 0.2\n'
dup k6 7 params grid vimp '[sweep]\nmodel = chain\nout = o\n[grid]\nvimp = 0.1, 0.2\n[params]\nvimp = 0.2\n'
dup k7 7 grid params vimp '[sweep]\nmodel = chain\nout = o\n[params]\nvimp = 0.2\n[grid]\nvimp = 0.1, 0.3\n'
dup k8 7 params grid t_max '[sweep]\nmodel = chain\nout = o\n[grid]\nt-max = 1e-3, 2e-3\n[params]\nt_max = 1e-3\n'

test_summary test_coarse_dt_out
