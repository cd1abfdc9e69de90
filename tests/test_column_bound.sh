#!/bin/bash
# test_column_bound.sh GRANWAVE SRCDIR: one column's work bounded before it
# runs, the refusal naming the flag the user gave; falcon's heights within
# chain's impact speeds.
#  1 One column's work was bounded by its memory alone: chain --n 100000 ran
#    for days (its progress said about 653,000 s left), as did drop --n 100000
#    and dispersion --column-n 100000. The studies' bound (N^2 at most 2e6, N =
#    1414 over a whole collision) now holds for one column over the share of
#    its collision the run covers (chain_column_work_check: the plan, so chain,
#    sweeps and Python; the drop's first collision over its t-max;
#    dispersion's column, which names --column-n, not dispersion's own --n),
#    exit 2 and one line before anything is allocated or written. Controls:
#    N = 1414 (the bound) passes a sweep's check, dispersion's column of 1414
#    beads and the drop's of 4650 (its bound over 10 ms: 4690) start to run,
#    100000 beads over the collision's first 1e-5 s run. `chain --help` printed
#    --n's parser range [1, 50000000] alone (session 45): its line names the
#    bound, N = 1414 over a whole collision (that N passes, N + 1 is refused),
#    and dispersion's --column-n line too.
#  2 falcon --heights 5e-17 (the row's lower end) fell at 9.9e-10 m/s, a speed
#    chain --vimp refuses: the row now starts at 5.1e-17 mm (1.0003e-9 m/s), and
#    under another gravity a height's fall is held to chain's speeds [1e-9,
#    1000] m/s (it was [0.99e-9, 1000]).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# 1 one column's work (the code before ran each of these for hours to days;
# cpu_run's limit ends them, a failed check)
work='a column of 100000 beads over the collision \(about 2\.5 s\) is 1e\+10 bead\^2 of work'
refused "chain --n 100000 refused by the column's work, naming --n" "^granwave chain --n: $work" \
    chain --n 100000 --out o --quiet
refused "chain --n 1415 (just above N = 1414) refused" "^granwave chain --n: a column of 1415 beads .*: lower n, or t-max" \
    chain --n 1415 --out o --quiet
refused "dispersion --column-n 100000 refused naming --column-n (not dispersion's --n)" \
    "^granwave dispersion --column-n: $work .*: lower column-n\$" dispersion --column-n 100000 --out o --quiet
refused "dispersion --column-n 1415 refused naming --column-n" "^granwave dispersion --column-n: a column of 1415 beads" \
    dispersion --column-n 1415 --out o --quiet
refused "drop --n 100000 refused over its first collision's t-max, naming --n" \
    "^granwave drop --n: a column of 100000 beads over the first collision \(about 0\.01 s\) is 7\.1e\+07 bead\^2" \
    drop --n 100000 --out o --quiet
printf '[sweep]\nmodel = chain\n[grid]\nn = 1414, 100000\n' >big.ini
refused "a chain sweep's check refuses its 100000-bead case, naming n" "^granwave sweep: big.ini: case 1: n: a column of 100000 beads" \
    sweep big.ini --out o --check
# controls: at the bound (N = 1414 over a whole collision) the checks pass
printf '[sweep]\nmodel = chain\n[grid]\nn = 1414\n' >edge.ini
cpu_run 20 "$GW" sweep edge.ini --out e --check >/dev/null 2>"$tmp/stderr" </dev/null &&
    ok "control: a sweep's check of N = 1414 (the bound) passes" ||
    ko "control: sweep --check of n = 1414: exit $? ($(head -c 300 "$tmp/stderr"))"
cpu_run 20 "$GW" chain --n 100000 --t-max 1e-5 --quiet >/dev/null 2>"$tmp/stderr" </dev/null
rc=$?
[ $rc -eq 1 ] && grep -q "still on the wall at t_max = 1e-05 s" "$tmp/stderr" &&
    ok "control: chain --n 100000 --t-max 1e-5 (the collision's start) runs to its t-max" ||
    ko "control: chain --n 100000 --t-max 1e-5: exit $rc, $(head -c 300 "$tmp/stderr")"
# dispersion's column of 1414 beads and a drop's of 3500 from 0.1 m (its bound
# over its 10 ms lies between 3500 and 3800) get past the checks and run: still
# running, not refused, when their CPU limit of 2 s ends them (SIGXCPU or
# SIGKILL). From the default 5.1 mm the bound is 4690, but gravity holds such a
# column on the wall (g t_col = 1.07 m/s against v_imp 0.32) and the held
# check refuses its 2.8e8 bead-samples to t-max: no N there both passes the
# work bound and runs.
for c in "dispersion --column-n 1414" "drop --n 3500 --height 0.1"; do
    # shellcheck disable=SC2086
    cpu_run 2 "$GW" $c --quiet >/dev/null 2>"$tmp/stderr" </dev/null
    rc=$?
    [ $rc -gt 128 ] && ! grep -q "a column of" "$tmp/stderr" &&
        ok "control: $c (within the bound) runs, ended by its CPU limit (exit $rc)" ||
        ko "control: $c: exit $rc ($(head -c 300 "$tmp/stderr"))"
done

# the help says the real limit (session 45: `chain --help` printed --n's parser
# range [1, 50000000] alone): the N it names over a whole collision is the
# bound's, N passing a sweep's check and N + 1 refused
nh=$("$GW" chain --help | grep -E '^  --n N ' | grep -oE 'at most [0-9]+ over a whole collision' | grep -oE '[0-9]+')
if [ -n "$nh" ] && "$GW" chain --help | grep -E '^  --n N ' | grep -qF 'in [1, 50000000] as parsed'; then
    printf '[sweep]\nmodel = chain\n[grid]\nn = %s\n' "$nh" >nh.ini
    cpu_run 20 "$GW" sweep nh.ini --out nh --check >/dev/null 2>"$tmp/stderr" </dev/null &&
        cpu_run 20 "$GW" chain --n $((nh + 1)) --out o --quiet >/dev/null 2>"$tmp/stderr2" </dev/null
    rc=$?
    [ $rc -eq 2 ] && grep -q "^granwave chain --n: a column of $((nh + 1)) beads" "$tmp/stderr2" &&
        ok "chain --help's --n line names the work bound, N = $nh over a whole collision (N passes, N + 1 refused)" ||
        ko "chain --help's N = $nh: exit $rc, $(head -c 300 "$tmp/stderr" "$tmp/stderr2")"
else
    ko "chain --help's --n line names no work bound: $("$GW" chain --help | grep -E '^  --n N ')"
fi
"$GW" dispersion --help | grep -E '^  --column-n N ' | grep -qF "at most 1414" &&
    ok "dispersion --help's --column-n line names the work bound, 1414" ||
    ko "dispersion --help's --column-n line: $("$GW" dispersion --help | grep -E '^  --column-n N ')"

# 2 falcon's heights within chain's impact speeds
refused "falcon --heights 5e-17 (9.9e-10 m/s) refused naming --heights and the value" \
    '^granwave falcon --heights: item 1 is 5e-17, outside \[5\.1e-17, 5\.09683e\+07\]$' \
    falcon --n 1:3 --heights 5e-17 --out o --quiet
refused "falcon --heights 5.1e-17 --gravity 9.7 (9.95e-10 m/s) refused naming --heights" \
    '^granwave falcon --heights: item 1 is 5\.1e-17 mm: at gravity 9\.7 m/s\^2 it falls to v = sqrt\(2 g h\) = 9\.94[0-9]*e-10 m/s, outside the impact speeds \[1e-09, 1000\] m/s$' \
    falcon --n 1:3 --heights 5.1e-17 --gravity 9.7 --out o --quiet
runs_quiet "control: falcon --heights 5.1e-17 (the row's new lower end, 1.0003e-9 m/s) runs" \
    falcon --n 1:2 --heights 5.1e-17 --jobs 1

# the same refusals through Python (the code before ran the first call for
# hours: the script is killed at 60 s, a failed check)
PY_TIMEOUT=60 py_checks 5 <<'PYEOF'
refused("Python falcon(heights=[5e-17]) refused naming heights", ("falcon: heights: item 1 is 5e-17",),
        granwave.falcon, n=(1, 3), heights=[5e-17])
refused("Python chain(n=100000) refused naming n", ("chain: n: a column of 100000 beads", "bead^2 of work"),
        granwave.chain, n=100000)
refused("Python dispersion(column_n=100000) refused naming column_n",
        ("dispersion: column_n: a column of 100000 beads", "lower column_n"), granwave.dispersion, column_n=100000)
refused("Python drop(n=100000) refused naming n", ("drop: n: a column of 100000 beads over the first collision",),
        granwave.drop, n=100000)
refused("Python sweep over chain n = 100000 refused naming n", ("sweep: case 0: n: a column of 100000 beads",),
        granwave.sweep, model="chain", grid={"n": [100000]})
PYEOF

test_summary test_column_bound
