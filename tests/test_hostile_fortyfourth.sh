#!/bin/bash
# test_hostile_fortyfourth.sh GRANWAVE SRCDIR: what the forty-fourth hostile
# pass found, fixed at its root and asserted here.
#  1 A block that never reaches the layer. layer-impact ran a t-max that ends
#    before the block has crossed its gap (--t-max 1e-8 at the default 1 um
#    gap and 20 m/s, or --gap 0.03 --t-max 0.001: the block needs 1.5 ms)
#    with exit 0: the bounce undecided, but the penetration written 0 (a
#    number, not null), no contact made; a layer sweep over t-max journaled
#    such a case and its row's penetration 0 entered layer-stats' penetration
#    means. The library's gap check (gw_layer_impact_gap_check, run by the
#    command, the sweep's check and run, Python and gw_layer_impact itself)
#    now refuses it naming t-max and the earliest arrival (the gap over the
#    block's whole speed, gravity added: no contact closes faster, whatever
#    the incidence): "--t-max: 1e-08 s ends before the block can reach the
#    layer (its gap of 1e-06 m takes at least 5e-08 s at 20 m/s ...)", exit
#    2, nothing written. Controls: a t-max after the arrival runs (exit 0),
#    an oblique one between gap/v and gap/v_n too (its target off x).
#  2 A bead its guide stops on the wall. chain with a guide friction that
#    stops bead 1 inside its overlap (--guide-friction 1 or --guide-viscous
#    100 at --vimp 1e-3: the drag, the Coulomb term regularised near rest,
#    lets the overlap creep back without end) failed at every t-max with
#    "bead 1 still on the wall at t_max = ... s", naming no input. The run's
#    end (collide_after, shared by chain, the studies, sweeps and Python) now
#    names the guide's friction and its values when the bead has stopped
#    there, exit 1 as before; a t-max that cuts a moving bead short keeps the
#    plain line (a longer t-max does end that one).
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 a t-max that ends before the block reaches the layer ---
make_sample s20.txt --n 20 --width-rm 8
before="ends before the block can reach the layer"
refused "layer-impact --t-max 1e-8 (default gap: the block needs 5e-8 s)" \
    "^granwave layer-impact --t-max: 1e-08 s $before \\(its gap of 1e-06 m takes at least 5e-08 s at 20 m/s" \
    layer-impact --sample s20.txt --t-max 1e-8 --quiet --out o
refused "layer-impact --gap 0.03 --t-max 0.001 (the block needs 1.5 ms)" \
    "^granwave layer-impact --t-max: 0\\.001 s $before \\(its gap of 0\\.03 m takes at least 0\\.001499 s at 20 m/s" \
    layer-impact --sample s20.txt --gap 0.03 --t-max 0.001 --quiet --out o
refused "layer-impact --gap 0.03 --t-max 0.001 --json: nothing on stdout" "^granwave layer-impact --t-max: 0\\.001 s $before" \
    layer-impact --sample s20.txt --gap 0.03 --t-max 0.001 --quiet --json
refused "layer-impact --alpha 60 --gap 1e-5 --t-max 4e-7: the block's whole speed bounds its arrival" \
    "^granwave layer-impact --t-max: 4e-07 s $before \\(its gap of 1e-05 m takes at least 5e-07 s at 20 m/s" \
    layer-impact --sample s20.txt --alpha 60 --gap 1e-5 --t-max 4e-7 --quiet --out o
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nt-max = 1e-8, 0.002\n[params]\nsample = s20.txt\n' >tmax.ini
refused "sweep over t-max = 1e-8, 0.002: case 0 refused before any case runs" \
    "^granwave sweep: tmax\\.ini: case 0: t-max: 1e-08 s $before" sweep tmax.ini --quiet --jobs 1
refused "sweep --check over t-max = 1e-8, 0.002" "^granwave sweep: tmax\\.ini: case 0: t-max: 1e-08 s $before" \
    sweep tmax.ini --check
# controls: a t-max after the arrival runs (undecided, warned)
if timeout -s KILL 60 "$GW" layer-impact --sample s20.txt --gap 0.03 --t-max 0.002 --quiet --json >r.json 2>/dev/null; then
    ok "layer-impact --gap 0.03 --t-max 0.002 (after the arrival) runs"
    pen=$(jq_py r.json "d['penetration']")
    case $pen in 0|0.0|None) ko "layer-impact --gap 0.03 --t-max 0.002: penetration $pen" ;;
        *) ok "layer-impact --gap 0.03 --t-max 0.002: the block touched (penetration $pen m)" ;; esac
else
    ko "layer-impact --gap 0.03 --t-max 0.002: exit $?"
fi
runs_quiet "layer-impact --t-max 1e-6 (default gap) runs" layer-impact --sample s20.txt --t-max 1e-6
# an oblique block whose target lies off x closes its gap faster than its
# normal speed: a t-max between gap/v and gap/v_n still runs (it touches)
runs_quiet "layer-impact --alpha 60 --gap 1e-5 --t-max 6e-7 (past gap/v, before gap/v_n) runs" \
    layer-impact --sample s20.txt --alpha 60 --gap 1e-5 --t-max 6e-7
py_checks 2 <<'PYEOF'
refused("Python layer_impact(t_max=1e-8): before the block reaches the layer",
        ["t_max: 1e-08 s ends before the block can reach the layer"],
        granwave.layer_impact, sample="s20.txt", t_max=1e-8)
refused("Python layer_impact(gap=0.03, t_max=0.001)", ["t_max: 0.001 s ends before the block can reach the layer"],
        granwave.layer_impact, sample="s20.txt", gap=0.03, t_max=0.001)
PYEOF

# --- 2 a bead its guide stops on the wall ---
# failed WHAT PATTERN CMD...: exit 1 within 60 s, one stderr line matching PATTERN
failed() {
    local what=$1 pat=$2; shift 2
    timeout -s KILL 60 "$GW" "$@" >stdout 2>stderr </dev/null
    local rc=$?
    if [ $rc -ne 1 ]; then ko "$what: exit $rc, expected 1 ($(head -c 300 stderr))"; return; fi
    if [ "$(wc -l <stderr)" -ne 1 ]; then ko "$what: $(wc -l <stderr) stderr lines"; return; fi
    grep -qE -- "$pat" stderr && ok "$what" || ko "$what: message does not match '$pat': $(cat stderr)"
}
guide="still on the wall at t_max = [0-9.e+-]+ s: the guide's friction"
failed "chain --n 1 --guide-friction 1 --vimp 1e-3: names the guide" \
    "^granwave chain: bead 1 $guide \\(guide-friction 1 N, guide-viscous 0 N s/m\\) stopped it" \
    chain --n 1 --guide-friction 1 --vimp 1e-3 --quiet
failed "chain --n 1 --guide-viscous 100 --vimp 1e-3 --t-max 0.05: names the guide" \
    "^granwave chain: bead 1 $guide \\(guide-friction 0 N, guide-viscous 100 N s/m\\).*lower guide-friction or guide-viscous" \
    chain --n 1 --guide-viscous 100 --vimp 1e-3 --t-max 0.05 --quiet
failed "chain --n 5 --guide-viscous 100 --vimp 1e-2: names the guide" "^granwave chain: bead 1 $guide" \
    chain --n 5 --guide-viscous 100 --vimp 1e-2 --quiet
# controls: a t-max that cuts a moving bead short keeps the plain line; a
# lighter guide lets the bead leave
failed "chain --n 2 --guide-friction 1e-3 --t-max 1e-5: cut short, the plain line" \
    "^granwave chain: bead 1 still on the wall at t_max = 1e-05 s\$" chain --n 2 --guide-friction 1e-3 --t-max 1e-5 --quiet
runs_quiet "chain --n 1 --guide-viscous 1 --vimp 1e-3 (the bead leaves)" chain --n 1 --guide-viscous 1 --vimp 1e-3

test_summary test_hostile_fortyfourth
