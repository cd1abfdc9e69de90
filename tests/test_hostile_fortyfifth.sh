#!/bin/bash
# test_hostile_fortyfifth.sh GRANWAVE SRCDIR: what the forty-fourth pass left
# and the forty-fifth hostile pass found, fixed at their root and asserted here.
#  1 --out into the file system's root. As root, `chain --out /` wrote its
#    four files into "/" (and a later run's output set would have removed its
#    names there). The one output check of every command (gw_out_check) and
#    the library's output sets (gw_outset_begin) now refuse the root by any
#    spelling ("/", "//", "/tmp/..", a link to it), naming the flag, exit 2,
#    nothing written. The refusals are first checked on runs the code before
#    refuses later for another reason (nothing written then): the plain runs,
#    which the code before ran into "/" as root, follow only when those passed.
#    Controls: an ordinary directory runs; layer-make --out FILE names a file.
#  2 A damping model with a constant of 0. `chain --damping kk --gamma 0` (or
#    hc with --alpha 0) ran the elastic column, recorded damping kk and said
#    nothing. chain, drop, falcon, wavespeed, softwall, Python's chain and a
#    chain sweep (once, counting its cases) now warn that it is no damping, on
#    stderr and in the warnings; it still runs (a sweep over gamma from 0).
#    Controls: a gamma above 0 and restitution say nothing of it.
#  3 The first contact of an impact cut at t-max. layer-impact --t-max 6e-8
#    (1e-8 s into the contact) gave under rk4, cvode and arkode the touch
#    itself as the first contact's end (t_first_contact 5e-8 s, a block loss
#    of -4.9e-8): it is now null as undecided; the text said "lower --dt"
#    (verlet), which cannot help: it says "raise --t-max". Under cvode and
#    arkode, which refuse --dt, the fewer-than-3-steps advice names their
#    tolerances (not reached here: their root evaluations fill the contact).
#    Control: verlet's step above the contact still says "lower --dt".
#  4 The --dt and --dt-max rule (controls: one rule under rk4, cvode and
#    arkode, for chain, drop, falcon and a sweep: a --dt above a --dt-max
#    given is refused naming --dt; above the automatic one it runs, warned).
#  5 The solver's step limit named. A --max-steps too small for the run
#    failed (exit 1) with the backend's text alone ("mxstep steps taken
#    before reaching tout", "rk4: more than 5 steps before ..."), naming no
#    input, in chain, drop, falcon and Python: the message now adds "the step
#    limit max-steps = N steps between two outputs or events: raise
#    --max-steps". Control: a run cut at --t-max keeps its own line.
#  6 A bead an overdamped contact holds on the wall. chain --damping hc
#    --alpha 1e8 (or kk --gamma 1e14) failed with "bead 1 still on the wall
#    at t_max = ... s" alone, naming no input, as a stopping guide did before
#    the forty-fourth pass: the run's end (chain, the studies, Python) now
#    names the damping and its constant when the bead has stopped in its
#    overlap. Controls: a t-max that cuts a moving bead keeps the plain line.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 --out into the file system's root ---
root_msg="is the file system's root directory: give a directory of the run's own"
make_sample s20.txt --n 20 --width-rm 8
printf 'vi,penetration\n' >bad.csv
# refused_root WHAT FLAGNAME OUTPATH ARGS...: refused, naming FLAGNAME and the root
refused_root() {
    local what=$1 flag=$2 path=$3; shift 3
    refused "$what" "^granwave $flag: '$(printf '%s' "$path" | sed 's/[.]/\\./g')' $root_msg" "$@"
}
safe_fails=$fails
# these runs are refused later by the code before (nothing written): a dt-out
# too fine for the samples, a sample that is not there, a table with no rows
refused_root "chain --out / (refused before the run's own bounds)" "chain --out" / \
    chain --out / --dt-out 1e-15 --quiet
refused_root "drop --out / (before its dt-out range)" "drop --out" / drop --out / --dt-out 1e-13 --quiet
refused_root "falcon --out //" "falcon --out" // falcon --out // --n 1:3 --dt-out 1e-15 --quiet
refused_root "layer-impact --out /tmp/.. (before the sample is read)" "layer-impact --out" /tmp/.. \
    layer-impact --out /tmp/.. --sample nosuch.txt --quiet
ln -s / rootlink
refused_root "layer-stats --out LINK-TO-ROOT (before the table is read)" "layer-stats --out" rootlink \
    layer-stats --out rootlink bad.csv
refused_root "dispersion --out /. (before --wisdom is read)" "dispersion --out" /. \
    dispersion --out /. --wisdom bad.csv --quiet
printf '[sweep]\nmodel = chain\nout = /\n[grid]\nvimp = 0.1, 0.2\n[params]\ndt-out = 1e-15\n' >root.ini
refused "sweep: [sweep] out = / (before the cases' checks)" "^granwave sweep: root\\.ini: \\[sweep\\] out: '/' $root_msg" \
    sweep root.ini --check
if [ "$fails" -eq "$safe_fails" ]; then
    refused_root "chain --out /" "chain --out" / chain --out / --quiet
    refused_root "wavespeed --out /" "wavespeed --out" / wavespeed --out / --n 2:8 --vimp 0.3 --quiet
    refused_root "softwall --out /" "softwall --out" / softwall --out / --n 1:3 --quiet
    refused_root "drop --out /" "drop --out" / drop --out / --quiet
    refused_root "layer-impact --out /" "layer-impact --out" / layer-impact --out / --sample s20.txt --quiet
    printf '[sweep]\nmodel = chain\nout = o2\n[grid]\nvimp = 0.1, 0.2\n' >sw.ini
    refused_root "sweep --out /" "sweep --out" / sweep sw.ini --out / --quiet
else
    ko "the plain --out / runs not run: the refusals above failed (as root they would write into /)"
fi
runs_quiet "chain --out o3 (an ordinary directory) runs" chain --n 2 --out o3
[ -s o3/chain.json ] && ok "chain --out o3 wrote chain.json" || ko "chain --out o3 wrote no chain.json"
runs_quiet "layer-make --out FILE (a file named in full) runs" layer-make --n 5 --out "$tmp/s5.txt"

# --- 2 a damping model with a constant of 0 ---
zero_kk="--damping kk with --gamma 0 is no damping: the results are those of --damping none"
zero_hc="--damping hc with --alpha 0 is no damping"
# warned_json WHAT NEEDLE CMD...: runs (exit 0), NEEDLE on stderr and in the --json warnings
warned_json() {
    local what=$1 needle=$2; shift 2
    if runs_json "$what" w.json "$@" --quiet; then
        grep -qF -- "warning: $needle" "$tmp/stderr" && ok "$what: warned on stderr" ||
            ko "$what: no warning on stderr ($(head -c 300 "$tmp/stderr"))"
        [ "$(jq_py w.json "any('''$needle''' in x for x in d['warnings'])")" = True ] &&
            ok "$what: in the JSON warnings" || ko "$what: not in the JSON warnings ($(jq_py w.json "d['warnings']"))"
    fi
}
warned_json "chain --damping kk --gamma 0" "$zero_kk" chain --n 3 --damping kk --gamma 0
warned_json "chain --damping hc --alpha 0" "$zero_hc" chain --n 3 --damping hc --alpha 0
warned_json "drop --damping kk --gamma 0" "$zero_kk" drop --n 3 --damping kk --gamma 0
warned_json "falcon --damping hc --alpha 0" "$zero_hc" falcon --n 1:3 --damping hc --alpha 0
warned_json "wavespeed --damping kk --gamma 0" "$zero_kk" wavespeed --n 2:8 --vimp 0.3 --damping kk --gamma 0
warned_json "softwall --damping kk --gamma 0" "$zero_kk" softwall --n 1:3 --damping kk --gamma 0
printf '[sweep]\nmodel = chain\nout = swg\n[params]\nn = 3\ndamping = kk\n[grid]\ngamma = 0, 1e3, 1e4\n' >swg.ini
timeout -s KILL 60 "$GW" sweep swg.ini --check >/dev/null 2>stderr
grep -qF "warning: damping kk with gamma 0, or hc with alpha 0, is no damping: 1 of 3 cases" stderr &&
    ok "sweep --check over gamma = 0, 1e3, 1e4: one warning counting the case" || ko "sweep --check: $(cat stderr)"
# controls: damping that damps, and none, say nothing of it
for args in "--damping kk --gamma 1e3" "--damping kk --restitution 0.9" "--damping none"; do
    # shellcheck disable=SC2086
    if runs_json "chain $args" w.json chain --n 3 $args --quiet; then
        grep -q "no damping" "$tmp/stderr" w.json && ko "chain $args: warned of no damping" ||
            ok "chain $args: no warning of no damping"
    fi
done
py_checks 2 <<'PYEOF'
warned("Python chain(damping='kk', gamma=0)", "damping kk with gamma 0 is no damping", granwave.chain, n=3,
       damping="kk", gamma=0)
r, ws = caught(granwave.chain, n=3, damping="kk", gamma=1e3)
check(not any("no damping" in m for m in ws), "Python chain(damping='kk', gamma=1e3): no such warning (%s)" % ws)
PYEOF

# --- 3 the first contact of an impact cut at t-max ---
for s in rk4 cvode; do
    if runs_json "layer-impact --solver $s --t-max 6e-8" w.json layer-impact --sample s20.txt --solver $s \
        --t-max 6e-8 --quiet; then
        v=$(jq_py w.json "[d[k] for k in ('t_first_contact', 'block_loss_first_contact', 'dissipated_first_contact')]")
        [ "$v" = "[None, None, None]" ] && ok "layer-impact --solver $s --t-max 6e-8: the first contact undecided" ||
            ko "layer-impact --solver $s --t-max 6e-8: the first contact given as ended: $v"
    fi
done
for s in verlet rk4; do
    timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --solver "$s" --t-max 6e-8 --quiet >out.txt 2>/dev/null
    grep -qF "first contact: unresolved (the run ended at t-max inside it: raise --t-max)" out.txt &&
        ok "layer-impact --solver $s --t-max 6e-8: the text says raise --t-max" ||
        ko "layer-impact --solver $s --t-max 6e-8: $(grep 'first contact' out.txt)"
done
# control: a verlet step above the contact is still told to lower --dt
timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --dt 5e-4 --dt-out 5e-4 --quiet >out.txt 2>/dev/null
grep -qF "first contact: unresolved (fewer than 3 step ends in it: lower --dt)" out.txt &&
    ok "layer-impact --dt 5e-4 (verlet): lower --dt" || ko "layer-impact --dt 5e-4: $(grep 'first contact' out.txt)"
# control: a run to its end keeps its first contact
if runs_json "layer-impact (default)" w.json layer-impact --sample s20.txt --quiet; then
    [ "$(jq_py w.json "d['t_first_contact'] is not None")" = True ] && ok "layer-impact: the first contact kept" ||
        ko "layer-impact: the first contact null"
fi

# --- 4 the --dt and --dt-max rule, one for every method (controls) ---
above="--dt: 1e-05 s is above dt-max = 1e-06 s, the largest step"
for s in rk4 cvode arkode; do
    refused "chain --solver $s --dt 1e-5 --dt-max 1e-6" "^granwave chain $above" \
        chain --n 3 --solver "$s" --dt 1e-5 --dt-max 1e-6 --quiet
    if runs_json "chain --solver $s --dt 1e-3 (above the automatic dt-max)" w.json chain --n 3 --solver "$s" \
        --dt 1e-3 --quiet; then
        grep -q "warning: --dt 0.001 s is above" "$tmp/stderr" && ok "chain --solver $s --dt 1e-3: warned" ||
            ko "chain --solver $s --dt 1e-3: not warned"
    fi
done
refused "drop --solver rk4 --dt 1e-5 --dt-max 1e-6" "^granwave drop $above" drop --solver rk4 --dt 1e-5 --dt-max 1e-6 --quiet
refused "falcon --dt 1e-5 --dt-max 1e-6" "^granwave falcon $above" falcon --dt 1e-5 --dt-max 1e-6 --quiet
printf '[sweep]\nmodel = chain\nout = o\n[params]\nn = 3\nsolver = cvode\ndt-max = 1e-6\n[grid]\ndt = 1e-7, 1e-5\n' >dt.ini
refused "sweep over dt = 1e-7, 1e-5 at dt-max = 1e-6 (cvode)" "^granwave sweep: dt\\.ini: case 1: dt: 1e-05 s is above dt-max" \
    sweep dt.ini --check

# --- 5 the solver's step limit named ---
named="\\(the step limit max-steps = 5 steps between two outputs or events: raise --max-steps\\)\$"
# failed_with WHAT PATTERN CMD...: exit 1 within 60 s, one stderr line matching PATTERN
failed_with() {
    local what=$1 pat=$2; shift 2
    timeout -s KILL 60 "$GW" "$@" >/dev/null 2>stderr </dev/null
    local rc=$?
    if [ $rc -ne 1 ]; then ko "$what: exit $rc, expected 1 ($(head -c 300 stderr))"; return; fi
    if [ "$(wc -l <stderr)" -ne 1 ]; then ko "$what: $(wc -l <stderr) stderr lines"; return; fi
    grep -qE -- "$pat" stderr && ok "$what" || ko "$what: message does not match '$pat': $(cat stderr)"
}
failed_with "chain --max-steps 5 (cvode)" "^granwave chain: cvode failed at t = .*mxstep.* $named" \
    chain --n 3 --max-steps 5 --quiet
failed_with "chain --max-steps 5 --solver arkode" "^granwave chain: arkode failed at t = .* $named" \
    chain --n 3 --max-steps 5 --solver arkode --quiet
failed_with "drop --max-steps 5 --solver rk4" "^granwave drop: rk4: more than 5 steps before .* $named" \
    drop --n 3 --max-steps 5 --solver rk4 --quiet
failed_with "falcon --max-steps 5" "^granwave falcon: N = 1, v_imp = 0\\.3 m/s: rk4: more than 5 steps .* $named" \
    falcon --n 1:3 --max-steps 5 --quiet
failed_with "chain --t-max 1e-12: the run's own line, kept" "^granwave chain: bead 1 still on the wall at t_max = 1e-12 s\$" \
    chain --n 3 --t-max 1e-12 --quiet
py_checks 1 <<'PYEOF'
try:
    granwave.chain(n=3, max_steps=5)
    print("FAIL: Python chain(max_steps=5): ran")
except RuntimeError as e:
    check("raise max_steps" in str(e) or "raise --max-steps" in str(e) or "max-steps" in str(e),
          "Python chain(max_steps=5): names max-steps: %s" % str(e)[:200])
PYEOF

# --- 6 a bead an overdamped contact holds on the wall ---
held="^granwave chain: bead 1 still on the wall at t_max = [0-9.e+-]+ s: the contact damping"
failed_with "chain --damping hc --alpha 1e8: names the damping" \
    "$held \\(damping hc, alpha 1e\\+08 s/m\\) stopped it inside its overlap.*lower alpha" \
    chain --n 3 --damping hc --alpha 1e8 --quiet
failed_with "chain --damping kk --gamma 1e14: names the damping" \
    "$held \\(damping kk, gamma 1e\\+14 N s/m\\^1\\.5\\).*lower gamma" chain --n 3 --damping kk --gamma 1e14 --quiet
failed_with "falcon --damping kk --gamma 1e14: names the damping" \
    "^granwave falcon: N = 1, v_imp = 0\\.3 m/s: chain: bead 1 still on the wall .*the contact damping \\(damping kk" \
    falcon --n 1:3 --damping kk --gamma 1e14 --quiet
failed_with "chain --damping kk --gamma 1e3 --t-max 1e-6 (cut moving): the plain line" \
    "^granwave chain: bead 1 still on the wall at t_max = 1e-06 s\$" chain --n 3 --damping kk --gamma 1e3 --t-max 1e-6 --quiet

test_summary test_hostile_fortyfifth
