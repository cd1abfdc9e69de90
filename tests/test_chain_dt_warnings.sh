#!/bin/bash
# test_chain_dt_warnings.sh GRANWAVE SRCDIR: a --dt above the step a run takes
# (the automatic dt-max; rk4's dt-out, where its steps end) runs at that step.
# `chain` and `drop` said so on stderr; falcon, wavespeed, softwall and the
# chain sweeps recorded the dt given beside the steps taken and said nothing.
# Each now gives one warning line per study or sweep, not one per case,
# saying how many of its runs it concerns, and the study's outcome records it
# (its `warnings`, which Python issues as GranwaveWarning):
#  - falcon, its traces too; wavespeed, its front columns too (ncase + nv);
#    softwall, the rigid wall's 20 columns of T_q too (ncase + 20); exit 0,
#    the settings' per-run dt the step taken (below the dt given);
#  - rk4 at a --dt-out below --dt names --dt-out;
#  - a --dt below every step: no warning;
#  - `granwave sweep` of the chain model, a grid over dt: one line counting
#    the cases over their step (the pass of checks that validates them, so
#    --check says it too); a thousand-case grid still one line;
#  - Python: one GranwaveWarning, the outcome's warnings.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
test_setup "$@"
cd "$tmp" || exit 1

# one_warning CMD WHAT PATTERN: exactly one stderr line, "granwave CMD: warning: " and PATTERN
one_warning() {
    local n
    n=$(grep -c "^granwave $1: warning: " "$tmp/stderr")
    if [ "$(wc -l <"$tmp/stderr")" -eq 1 ] && [ "$n" -eq 1 ] && grep -qE -- "$3" "$tmp/stderr"; then
        ok "$2: one warning line, '$3'"
    else
        ko "$2: expected one warning line matching '$3': $(cat "$tmp/stderr")"
    fi
}
# steps_below FILE GIVEN: every run's dt in settings.runs is its dt_max, below GIVEN, and dt_given GIVEN
steps_below() {
    [ "$(jq_py "$1" "all(a == b < $2 for a, b in zip(d['settings']['runs']['dt'], d['settings']['runs']['dt_max'])) and d['settings']['solver']['dt_given'] == $2")" = True ]
}

# --- falcon ---
if runs_json "falcon --dt 1e-3" f.json falcon --n 1:5 --vimp 0.3 --heights none --dt 1e-3 --quiet; then
    one_warning falcon "falcon --dt 1e-3" "--dt 0.001 s is above the longest step that 5 of 5 collisions take \(dt-max = "
    steps_below f.json 1e-3 && ok "falcon --dt 1e-3: the settings' steps the dt-max taken, dt_given 1e-3" ||
        ko "falcon settings: $(jq_py f.json "d['settings']['runs']['dt']")"
fi
# the traces of --out (N = 7, 15, 30) are runs too: 26 sizes and 3 traces
if runs_json "falcon --out (its traces)" ft.json falcon --n 5:30 --vimp 0.3 --heights none --dt 1e-3 --quiet --out fo; then
    one_warning falcon "falcon with traces" "29 of 29 collisions"
fi
if runs_json "falcon rk4" fr.json falcon --n 1:5 --vimp 0.3 --heights none --solver rk4 --dt 1e-6 --dt-out 5e-7 --quiet; then
    one_warning falcon "falcon rk4 --dt above --dt-out" "--dt 1e-06 s is above the longest step that 5 of 5 collisions take \(--dt-out = 5e-07 s"
    [ "$(jq_py fr.json "set(d['settings']['runs']['dt'])")" = "{5e-07}" ] && ok "falcon rk4: the steps taken 5e-7" ||
        ko "falcon rk4 steps: $(jq_py fr.json "d['settings']['runs']['dt']")"
fi
if runs_json "falcon --dt 1e-7" f2.json falcon --n 1:5 --vimp 0.3 --heights none --dt 1e-7 --quiet; then
    [ -s "$tmp/stderr" ] && ko "falcon --dt 1e-7 (below dt-max) warned: $(cat "$tmp/stderr")" ||
        ok "falcon --dt below every step: no warning"
fi

# --- wavespeed: 7 sizes at one speed (the longest of 10 beads, whose period is measured: one warning), and its front column ---
if runs_json "wavespeed --dt 1e-3" w.json wavespeed --n 4:10 --vimp 0.3 --dt 1e-3 --quiet; then
    one_warning wavespeed "wavespeed --dt 1e-3" "--dt 0.001 s is above the longest step that 8 of 8 collisions take"
    steps_below w.json 1e-3 && ok "wavespeed: the settings' steps those taken, dt_given 1e-3" ||
        ko "wavespeed settings: $(jq_py w.json "d['settings']['runs']['dt']")"
fi

# --- softwall: 4 sizes and the rigid wall's 20 columns ---
if runs_json "softwall --dt 1e-3" s.json softwall --n 1:4 --dt 1e-3 --quiet; then
    one_warning softwall "softwall --dt 1e-3" "--dt 0.001 s is above the longest step that 24 of 24 collisions take"
    steps_below s.json 1e-3 && ok "softwall: the settings' steps those taken, dt_given 1e-3" ||
        ko "softwall settings: $(jq_py s.json "d['settings']['runs']['dt']")"
fi
if runs_json "softwall no --dt" s0.json softwall --n 1:4 --quiet; then
    [ -s "$tmp/stderr" ] && ko "softwall without --dt warned: $(cat "$tmp/stderr")" || ok "softwall without --dt: no warning"
fi

# --- granwave sweep, model chain ---
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:4\ndt = 1e-3, 1e-7\n' >sw.ini
if timeout -s KILL 120 "$GW" sweep sw.ini --out so --quiet >"$tmp/stdout" 2>"$tmp/stderr" </dev/null; then
    one_warning sweep "sweep, dt 1e-3 and 1e-7 over N = 1..4" "dt 0.001 s is above the longest step that 4 of 8 cases take \(dt-max = "
    [ "$(grep -vc '^#' so/results.csv)" -eq 9 ] && ok "sweep: the table's 8 rows" || ko "sweep table: $(cat so/results.csv)"
else
    ko "sweep failed: $(cat "$tmp/stderr")"
fi
timeout -s KILL 60 "$GW" sweep sw.ini --out so --check >"$tmp/stdout" 2>"$tmp/stderr" </dev/null &&
    one_warning sweep "sweep --check" "4 of 8 cases" || ko "sweep --check failed: $(cat "$tmp/stderr")"
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:4\ndt = 1e-7, 1e-8\n' >sn.ini
timeout -s KILL 60 "$GW" sweep sn.ini --out sn --check >"$tmp/stdout" 2>"$tmp/stderr" </dev/null
[ $? -eq 0 ] && ! [ -s "$tmp/stderr" ] && ok "sweep --check, every dt below its step: no warning" ||
    ko "sweep with dt below the step: $(cat "$tmp/stderr")"
# a thousand cases: one line, not a thousand
printf '[sweep]\nmodel = chain\n[grid]\nn = 1:500\nvimp = 0.2, 0.3\n[params]\ndt = 1e-3\n' >sk.ini
timeout -s KILL 120 "$GW" sweep sk.ini --out sk --check --quiet >"$tmp/stdout" 2>"$tmp/stderr" </dev/null &&
    one_warning sweep "sweep --check of 1000 cases" "1000 of 1000 cases" || ko "1000-case sweep --check: $(head -c 300 "$tmp/stderr")"

py_checks <<EOF
import warnings
import granwave
def check(what, cond):
    print(("PASS: " if cond else "FAIL: ") + what)
for name, kw, count in (("falcon", dict(n="1:5", vimp=0.3, heights="none"), "5 of 5"),
                        ("wavespeed", dict(n="4:10", vimp=0.3), "8 of 8"),
                        ("softwall", dict(n="1:4"), "24 of 24")):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = getattr(granwave, name)(dt=1e-3, **kw)
    said = [str(x.message) for x in w if "is above the longest step" in str(x.message)]
    check(f"Python {name} dt=1e-3: one warning, {count} collisions", len(said) == 1 and count in said[0])
    check(f"Python {name} dt=1e-3: the outcome's warnings record it",
          any("dt 0.001 s is above the longest step" in x for x in r["warnings"] or []))
    check(f"Python {name} dt=1e-3: every step taken below it", bool((r["dt"] < 1e-3).all()))
EOF

test_summary test_chain_dt_warnings
