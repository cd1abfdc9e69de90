#!/bin/bash
# test_hostile_fortysixth.sh GRANWAVE SRCDIR: what the forty-sixth hostile pass
# found, fixed at its root and asserted here.
#  1 The crowns of a run that goes on past T_f. layer-impact --full (or a
#    sweep's full = 1, Python's full=True) runs on after the block's rebound
#    is over; the block falls back and hits the layer again. The crown
#    analysis (layer_crowns.c) took each ring's arrival as the first maximum
#    reaching a quarter of the ring's largest value over the whole record, so
#    the second impact's wave set the outer rings' largest values: on the
#    40-disc pile of `layer-make --n 40` the strain arrivals of rings 8 to 11
#    moved from 8.6-11.2 ms to 0.582-0.588 s and the wave speed from
#    98 +- 45 m/s to 6.2 +- 1.3 m/s (exit 0, below the 20 m/s of the block).
#    Arrivals, delays and spectra are now read over the first impact's
#    samples (up to the first at or after T_f when the block bounced), where
#    a run without --full stops: the program, a sweep and Python give the
#    same crowns with and without it. Control: a run whose block has not
#    reached T_f (t-max 0.05) keeps its whole record.
#  2 A pile hit without gravity. `layer-impact --gravity 0` on a settled pile
#    was refused saying its contacts "carry inf times the weight they carried
#    at rest" and to give "other-settling to run it anyway"; with
#    --other-settling the floor check then refused it whatever the flag. The
#    settling check (the program, sweeps, Python) now says that without
#    gravity the contacts hold their settling's forces with no weight to
#    carry, names the gravity the pile was made with, and offers
#    other-settling only for a pile whose floor carries nothing (which it
#    runs: test_hostile_thirtyfifth).
#  3 The long-wave speed undecided in silence. `dispersion --n 128
#    --t-samples 512 --dt-out 1e-6` (the ridge resolved from qa = 1.47 only)
#    or `--n 8` (no wavenumber at qa <= 0.5) printed "long-wave fit nan m/s"
#    and wrote c0_measured and c0_rel_err null, exit 0, with no warning
#    (the only dispersion warning was for no ridge at all). The study's
#    warnings (stderr, --json, dispersion.json, Python) now say that c0 is
#    undecided and why: too few wavenumbers at qa <= 0.5 in the chain (give
#    more beads) or a ridge resolved from qa = X up (a longer record, a lower
#    --min-bins). The no-ridge warning names --min-bins too. Control: a run
#    that measures c0 says nothing.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=refusal_lib.sh
. "$2/tests/refusal_lib.sh"
hostile_setup "$@"
export LC_ALL=C

# --- 1 the crowns of a run that goes on past T_f ---
make_sample s40.txt --n 40
if runs_json "layer-impact (default)" a.json layer-impact --sample s40.txt --quiet &&
    runs_json "layer-impact --full --t-max 0.7" b.json layer-impact --sample s40.txt --full --t-max 0.7 --quiet; then
    # the second impact comes at about 0.58 s, inside the --full run
    res=$(/usr/bin/python3 - a.json b.json <<'PYEOF'
import json, math, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
def same(x, y):
    return x == y or (x is None and y is None)
keys = ["wave_speed", "wave_speed_err", "wave_speed_kinetic", "wave_speed_kinetic_err", "wave_rings",
        "wave_speed_xcorr", "wave_speed_xcorr_err", "wave_xcorr_gaps"]
print(("PASS" if all(same(a[k], b[k]) for k in keys) else "FAIL") +
      ": --full gives the default's crown speeds: %s" % [(k, a[k], b[k]) for k in keys if not same(a[k], b[k])])
ca, cb = a["crowns"], b["crowns"]
print(("PASS" if ca["peak_strain_t"] == cb["peak_strain_t"] and ca["peak_kinetic_t"] == cb["peak_kinetic_t"]
       else "FAIL") + ": --full gives the default's ring arrivals: %s against %s" %
      (cb["peak_strain_t"], ca["peak_strain_t"]))
tf = b["t_f"]
late = [t for t in cb["peak_strain_t"] + cb["peak_kinetic_t"] if t is not None and t > tf]
print(("PASS" if tf and b["t_end"] > 0.6 and not late else "FAIL") +
      ": --full's arrivals are the first impact's (before T_f = %s s; run to %s s): %s" % (tf, b["t_end"], late))
ws = b["wave_speed"]
print(("PASS" if ws is None or ws > b["v_ni"] else "FAIL") +
      ": --full's wave speed %s m/s is not below the block's %s m/s" % (ws, b["v_ni"]))
PYEOF
)
    while IFS= read -r line; do
        case $line in PASS:*) ok "${line#PASS: }" ;; *) ko "${line#FAIL: }" ;; esac
    done <<<"$res"
fi
# control: a run that ends before T_f keeps its whole record, --full or not
if runs_json "layer-impact --t-max 0.05" c.json layer-impact --sample s40.txt --t-max 0.05 --quiet &&
    runs_json "layer-impact --full --t-max 0.05" d.json layer-impact --sample s40.txt --t-max 0.05 --full --quiet; then
    [ "$(jq_py c.json 'd["crowns"]["peak_strain_t"], d["wave_speed"]')" = \
        "$(jq_py d.json 'd["crowns"]["peak_strain_t"], d["wave_speed"]')" ] &&
        [ "$(jq_py c.json 'd["t_f"]')" = None ] &&
        ok "control: cut before T_f, --full or not, the same crowns" ||
        ko "control: cut before T_f: $(jq_py c.json 'd["wave_speed"]') against $(jq_py d.json 'd["wave_speed"]')"
fi
# a sweep over full: both rows one wave speed
cat >sw.ini <<'INI'
[sweep]
model = layer
out = swo
[grid]
full = 0, 1
[params]
sample = s40.txt
t-max = 0.7
INI
if timeout -s KILL 120 "$GW" sweep sw.ini --quiet --jobs 1 >/dev/null 2>"$tmp/stderr"; then
    ws=$(/usr/bin/python3 -c "
import csv
rows = list(csv.DictReader(l for l in open('swo/results.csv') if not l.startswith('#')))
print(' '.join(r['wave_speed'] for r in rows))")
    set -- $ws
    [ $# -eq 2 ] && [ "$1" = "$2" ] && ok "sweep full = 0, 1: one wave speed ($1)" ||
        ko "sweep full = 0, 1: wave speeds $ws"
else
    ko "sweep full = 0, 1: exit $? ($(head -c 200 "$tmp/stderr"))"
fi
py_checks 2 <<'PYEOF'
a = granwave.layer_impact(sample="s40.txt")
b = granwave.layer_impact(sample="s40.txt", full=True, t_max=0.7)
check(a.wave_speed == b.wave_speed and a.wave_speed_kinetic == b.wave_speed_kinetic,
      "Python full=True: the default's wave speeds (%r, %r against %r, %r)"
      % (b.wave_speed, b.wave_speed_kinetic, a.wave_speed, a.wave_speed_kinetic))
same = lambda x, y: x == y or (x != x and y != y)  # NaN: a ring without an arrival
check(len(a.peak_strain_t) == len(b.peak_strain_t) and all(same(x, y) for x, y in zip(a.peak_strain_t, b.peak_strain_t)),
      "Python full=True: the default's ring arrivals")
PYEOF

# --- 2 a pile hit without gravity ---
g0="without gravity in the impact its contacts hold the forces of its settling with no weight to carry.*give the gravity it was made with \\(9\\.81 m/s\\^2\\) \\(other-settling does not run a pile whose floor carries a load"
refused "layer-impact --gravity 0: names the settling's gravity, offers no other-settling" \
    "^granwave layer-impact: sample 's40\\.txt': it settled with gravity 9\\.81 m/s\\^2 against the impact's 0 .*$g0" \
    layer-impact --sample s40.txt --gravity 0 --out o
grep -q "inf times" "$tmp/stderr" && ko "layer-impact --gravity 0: says 'inf times'" || ok "layer-impact --gravity 0: no 'inf times'"
printf '[sweep]\nmodel = layer\nout = o\n[grid]\nvi = 10, 20\n[params]\nsample = s40.txt\ngravity = 0\n' >g0.ini
refused "sweep --check, gravity = 0: the same" "g0\\.ini: case 0: sample .*$g0" sweep g0.ini --check
py_checks 1 <<'PYEOF'
refused("Python layer_impact(gravity=0): the same", ["without gravity in the impact", "give the gravity it was made with",
        "does not run a pile whose floor carries a load"], granwave.layer_impact, sample="s40.txt",
        gravity=0)
PYEOF
# control: the floor check's own line under other-settling, as before
refused "layer-impact --gravity 0 --other-settling: the floor check's line" \
    "^granwave layer-impact: sample 's40\\.txt': its floor contacts hold .* and gravity is 0" \
    layer-impact --sample s40.txt --gravity 0 --other-settling --out o

# --- 3 the long-wave speed undecided in silence ---
c0w="the long-wave speed c0 is undecided \\(c0_measured and c0_rel_err null\\): its fit needs 3 resolved wavenumbers at qa <= 0\\.5"
# warned_c0 WHAT PATTERN ARGS...: exit 0, c0_measured null, the warning on
# stderr and in the JSON's warnings
warned_c0() {
    local what=$1 pat=$2; shift 2
    rm -rf o
    if runs_json "$what" c0.json dispersion "$@" --quiet --out o; then
        [ "$(jq_py c0.json 'd["c0_measured"]')" = None ] || ko "$what: c0_measured $(jq_py c0.json 'd["c0_measured"]')"
        grep -qE -- "^granwave dispersion: warning: $c0w, $pat" "$tmp/stderr" && ok "$what: warned on stderr" ||
            ko "$what: stderr: $(head -c 300 "$tmp/stderr")"
        [ "$(jq_py c0.json 'sum("the long-wave speed c0 is undecided" in w for w in d["warnings"])')" = 1 ] &&
            [ "$(jq_py o/dispersion.json 'sum("the long-wave speed c0 is undecided" in w for w in d["warnings"])')" = 1 ] &&
            ok "$what: warned in --json and dispersion.json" || ko "$what: warnings $(jq_py c0.json 'd["warnings"]')"
    fi
}
warned_c0 "dispersion --dt-out 1e-6 (ridge from qa = 1.47)" \
    "and the ridge is resolved from qa = 1\\.473 up; give a longer record .*--min-bins" \
    --n 128 --t-samples 512 --dt-out 1e-6
warned_c0 "dispersion --n 8" "and the chain's wavenumbers hold 0 there; give more beads \\(--n\\)" --n 8 --t-samples 64
warned_c0 "dispersion --n 16 --ends fixed" "and the chain's wavenumbers hold 2 there" --n 16 --ends fixed --t-samples 64
if runs_json "dispersion --n 128 --t-samples 512 (c0 measured)" c1.json dispersion --n 128 --t-samples 512 --quiet; then
    [ "$(jq_py c1.json 'd["c0_measured"] is not None and abs(d["c0_rel_err"]) < 1e-3 and d["warnings"] == []')" = True ] &&
        [ ! -s "$tmp/stderr" ] && ok "control: c0 measured (within 1e-3 of theory), nothing said" ||
        ko "control: c0 $(jq_py c1.json 'd["c0_measured"], d["warnings"]')"
fi
if runs_json "dispersion --min-bins 126" nb.json dispersion --n 64 --t-samples 256 --min-bins 126 --quiet; then
    grep -q "no wavenumber resolved: .* or a --min-bins near half of --t-samples)" "$tmp/stderr" &&
        ok "dispersion --min-bins 126: the no-ridge warning names --min-bins" || ko "no-ridge warning: $(cat "$tmp/stderr")"
fi
py_checks 1 <<'PYEOF'
r, w = caught(granwave.dispersion, n=8, t_samples=64)
check(r.c0_measured != r.c0_measured and any("the long-wave speed c0 is undecided" in x for x in w),
      "Python dispersion(n=8): c0 NaN and warned: %s" % w)
PYEOF

test_summary test_hostile_fortysixth
