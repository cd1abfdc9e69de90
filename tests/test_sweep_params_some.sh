#!/bin/bash
# test_sweep_params_some.sh GRANWAVE SRCDIR: a sweep's [params] key that acts
# on only some of its grid cases (issue 18, class 5, the design question left
# in the thirty-fourth session). [params] hold for every case, and a key of no
# effect in a case is refused, never run as if it acted (the case's row would
# record a tolerance rk4 never used). The refusal now says which case takes
# the key, so the user splits the grid: `rtol` with `solver = rk4, cvode`
# names case 1 (cvode), and the same key over a grid where no case takes it
# (solver = rk4 in [params], n = 1, 2) names none. Each: exit 2, one line,
# nothing written, the same through the program and the Python module
# (gw_sweep_run_text, one helper in the library); the split sweep (the cvode
# case alone) runs. 6 checks (5 without Python, in a sanitizer build); on
# the code before, the 2 that ask for the case named fail.
# shellcheck source=refusal_lib.sh
. "$(dirname "$0")/refusal_lib.sh"
hostile_setup "$@"

printf '[sweep]\nmodel = chain\n[grid]\nsolver = rk4, cvode\nn = 2\n[params]\nrtol = 1e-8\n' >some.ini
refused "rtol acting on only some cases" \
    'case 0: rtol: .*rk4.*\(case 1 takes it: a \[params\] key holds for every case' sweep some.ini --out o
printf '[sweep]\nmodel = chain\n[grid]\nn = 1, 2\n[params]\nsolver = rk4\nrtol = 1e-8\n' >none.ini
refused "rtol acting on no case" 'case 0: rtol: .*rk4' sweep none.ini --out o
grep -q 'takes it' "$tmp/stderr" && ko "  a case named where none takes the key: $(cat "$tmp/stderr")" ||
    ok "  no case named where none takes the key"
# a key of the grid that fails is not a [params] key: no case named (its
# value is refused as the config is read, naming the line)
printf '[sweep]\nmodel = chain\n[grid]\nn = 2, -1\n' >grid.ini
refused "a bad grid value" 'grid.ini:4: \[grid\] n: ' sweep grid.ini --out o
printf '[sweep]\nmodel = chain\n[grid]\nsolver = cvode\nn = 2\n[params]\nrtol = 1e-8\n' >split.ini
runs_quiet "the split sweep (cvode alone)" sweep split.ini --out split

py_checks 1 <<'PY'
refused("the module's sweep: rtol acting on only some cases", ["case 0: rtol", "case 1 takes it"],
        granwave.sweep, "chain", {"solver": ["rk4", "cvode"], "n": [2]}, rtol=1e-8)
PY
test_summary
