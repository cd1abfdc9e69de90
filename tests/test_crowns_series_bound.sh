#!/bin/bash
# test_crowns_series_bound.sh GRANWAVE SRCDIR: the rings' series at the run's
# checks, from which layer-impact reads its crowns when --dt-out is coarser
# than the checks (every 2e-5 s), holds at most 2^22 values at every ring
# count, every other check dropped when it fills.
#  1 It held up to 2^24 values (134 MB), and the crowns' analysis (the
#    spectra, the correlation's FFTs) as much again: on the 40-disc pile of
#    `layer-make --n 40`, `--rings 1000 --dt-out 1e-2` (T_f 0.306 s, 15,300
#    checks of 2001 values) peaked at 262 MB, then 134 MB (2^22 values, but
#    4096 checks above 511 rings: 8.2e6 values, and the spectra beside them);
#    now 43 MB (2096 checks, the spectra written over the series). The
#    check: under 64 MB (the series alone at 4096 checks is 65.6 MB).
#    Control: its speeds within 5 % of their errors of 98.18 +- 44.76 and
#    372.33 +- 59.49 m/s (4096 checks; 98.04 and 370.38 now, 0.3 and 3.3 %).
#  2 `--rings 150 --dt-out 1e-2 --out D`: the spectra's bins per ring bound
#    the series' length (n <= M/2 + 1, M >= 2n - 1 the FFT's length), so
#    bins x (1 + 2 rings) bounds its values: 4.6e6 before (every check
#    kept), 2.3e6 now (every other one, the top frequency 12.5 kHz: an
#    interval of 4e-5 s); the check: at most 2^22, the interval 2^k 2e-5 s.
#    Control: its three speeds within their stated errors of the same run's
#    at the default --dt-out (read from every sample).
#  Control: a first impact within 2^22 values keeps every check: the pile
#  under --gravity 0.5 (--other-settling; T_f 2.6 s, 130,000 checks of 12
#  rings) gives at --dt-out 1e-2 the default --dt-out's speeds and arrivals
#  bit for bit (at 2^21 values it would have been thinned); its three
#  speeds are null in both (pairs and peaks locked, as in 3).
#  3 A cross-correlation locked onto the pile's slow motion is no speed: the
#    40-disc pile at `--vi 40 --gravity 1 --other-settling --t-max 20
#    --dt-out 1e-2` (T_f 1.30 s) gave 15.99 +- 0.03 m/s from ring pairs
#    0.041 s apart, 30 times the block's first contact (open at 1.36 ms);
#    the 300-disc pile of `layer-make --n 300 --seed 1` 11.10 +- 2.55 m/s
#    against the strain peaks' 755.5. Now wave_speed_xcorr is null and a
#    warning names the pairs' delay and the contact. Control: the default
#    impact's 609.50 m/s (pairs 0.6 of its contact) is kept.
# Checks that fail on the code before: see docs/tests.md.
# shellcheck source=test_lib.sh
. "$(dirname "${BASH_SOURCE[0]}")/test_lib.sh"
test_setup "$@"
export LC_ALL=C
cd "$tmp" || exit 1
PY=/usr/bin/python3

cpu_run 120 "$GW" layer-make --n 40 --out s40 --quiet >/dev/null 2>&1 ||
    { ko "layer-make --n 40"; test_summary test_crowns_series_bound; exit; }

# --- 1 peak memory at 1000 rings (not under the sanitizer, whose shadow and
# quarantine hold more than the run) ---
if [ -n "$(sanitizer_runtime)" ]; then
    echo "SKIP: the peak memory under the sanitizer"
else
got=$($PY - "$GW" <<'EOF'
import resource, subprocess, sys
p = subprocess.run([sys.argv[1], "layer-impact", "--sample", "s40", "--quiet", "--json", "--rings", "1000",
                    "--dt-out", "1e-2"], capture_output=True, timeout=600)
print(p.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024)
EOF
)
read -r code mb <<<"$got"
[ "${code:-x}" = 0 ] && [ "${mb:-999999}" -lt 64 ] &&
    ok "--rings 1000 --dt-out 1e-2: peak memory $mb MB, under 64 MB (262, then 134 before)" ||
    ko "--rings 1000 --dt-out 1e-2: exit ${code:-?}, peak memory ${mb:-?} MB (at most 64 MB)"
fi
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json --rings 1000 --dt-out 1e-2 >r1000.json 2>r1000.err
got=$($PY - <<'EOF'
import json
a = json.load(open("r1000.json"))
ref = {"wave_speed": (98.175, 44.76), "wave_speed_kinetic": (372.33, 59.49)}
bad = [f"{k} {a[k]} (4096 checks: {c} +- {e})" for k, (c, e) in ref.items()
       if a[k] is None or abs(a[k] - c) > 0.05 * e]
print("ok" if not bad else "; ".join(bad))
EOF
)
[ "$got" = ok ] && ok "control: --rings 1000 thinned to 2096 checks: its speeds within 5 % of their errors of 4096 checks'" ||
    ko "--rings 1000 --dt-out 1e-2: $got $(head -c 200 r1000.err)"

# --- 2 the series' length at 150 rings, read from its spectra ---
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json --rings 150 --dt-out 1e-2 --out o150 >o150.json 2>o150.err
rc=$?
got=$($PY - <<'EOF'
import collections
bins, fmax = collections.Counter(), 0.0
for line in open("o150/crowns_spectra.csv"):
    if line[0].isdigit():
        f, ring = line.split(",", 2)[:2]
        bins[ring] += 1
        fmax = max(fmax, float(f))
nf = max(bins.values())
print(len(bins), nf, nf * 301, "%.6g" % (1 / (2 * fmax)))
EOF
)
read -r rings _ values dt <<<"$got"
rings=${rings:-0} values=${values:-0} dt=${dt:-0}
[ $rc -eq 0 ] && [ "$rings" = 150 ] || ko "--rings 150 --out: exit $rc, $rings rings in crowns_spectra.csv: $(head -c 300 o150.err)"
[ "$values" -gt 0 ] && [ "$values" -le $((1 << 22)) ] &&
    ok "--rings 150: the checks' series holds at most $values values, not above 2^22" ||
    ko "--rings 150: the checks' series holds up to $values values (its spectra's bins x 301), above 2^22"
$PY -c "import math, sys; k = math.log2(float(sys.argv[1]) / 2e-5); sys.exit(0 if abs(k - round(k)) < 1e-6 and k >= 1 else 1)" "$dt" &&
    ok "--rings 150: the series thinned evenly (interval $dt s, a power of two times 2e-5 s)" ||
    ko "--rings 150: the series' interval $dt s, not thinned to 2, 4, 8 ... times 2e-5 s"
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json --rings 150 >ref150.json 2>ref150.err
got=$($PY - <<'EOF'
import json
a, b = json.load(open("o150.json")), json.load(open("ref150.json"))
n, bad = 0, []
for k in ("wave_speed", "wave_speed_kinetic", "wave_speed_xcorr"):
    if a[k] is None or b[k] is None:
        if (a[k] is None) != (b[k] is None):
            bad.append(f"{k} {a[k]} vs {b[k]}")
        continue
    n += 1
    if abs(a[k] - b[k]) > min(a[k + "_err"], b[k + "_err"]):
        bad.append(f"{k} {a[k]:.6g} vs {b[k]:.6g} +- {b[k + '_err']:.3g}")
print("ok" if n and not bad else f"{n} speeds; " + "; ".join(bad))
EOF
)
[ "$got" = ok ] && ok "control: --rings 150 thinned: its speeds within their errors of the default --dt-out's" ||
    ko "--rings 150 thinned against the default --dt-out: $got"

# --- control: a long first impact of 12 rings kept whole ---
long=(--gravity 0.5 --other-settling --t-max 10)
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json "${long[@]}" --dt-out 1e-2 >g2.json 2>g2.err
rc1=$?
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json "${long[@]}" >g0.json 2>g0.err
rc2=$?
got=$($PY - <<'EOF'
import json
a, b = json.load(open("g2.json")), json.load(open("g0.json"))
keys = ("wave_speed", "wave_speed_kinetic", "wave_speed_xcorr", "wave_speed_err")
# (the cross-correlation's pairs lock onto the pile's motion over this long
# first impact, 0.082 s apart: its speed is null in both, 7.9 m/s before; so
# do its strain and kinetic peaks, 11.87 and 7.32 m/s, 35 and 57 times its
# first contact: null in both, test_crowns_peaks_locked; the arrivals compared)
bad = [k for k in keys if a[k] != b[k]]
bad += [k for k in ("peak_strain_t", "peak_kinetic_t", "xcorr_delay") if a["crowns"][k] != b["crowns"][k]]
print("ok" if not bad and b["t_f"] > 2 else f"T_f {b['t_f']}, differ: {bad}")
EOF
)
[ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] && [ "$got" = ok ] &&
    ok "control: T_f 2.6 s at 12 rings: --dt-out 1e-2 gives the default's speeds and arrivals bit for bit" ||
    ko "T_f 2.6 s at 12 rings: exit $rc1, $rc2: $got $(head -c 200 g2.err)"

# --- 4 --out's peak memory against --json's on that run (not under the
# sanitizer): impact.h5 is built in memory, a second copy of the series (the
# HDF5 image, 90 MB here), and the program kept the series whole while it
# was built, with the ledger copied once more: 197 MB against --json's
# 113 MB, 1.74 times. The series are now freed as the image takes them:
# 150 MB, 1.32 times; the check: under 1.5 times. Control: impact.h5's
# series are the run's (its t and ledger against ledger.csv, its spectra
# against crowns_spectra.csv) ---
if [ -n "$(sanitizer_runtime)" ]; then
    echo "SKIP: the peak memory of --out under the sanitizer"
else
got=$($PY - "$GW" "${long[@]}" <<'EOF'
import os, subprocess, sys
def peak(extra):
    p = subprocess.Popen([sys.argv[1], "layer-impact", "--sample", "s40", "--quiet", "--json"] + sys.argv[2:] + extra,
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, ru = os.wait4(p.pid, 0)
    return os.waitstatus_to_exitcode(status), ru.ru_maxrss / 1024
cj, mj = peak([])
co, mo = peak(["--out", "g4"])
print(cj, co, "%.0f" % mj, "%.0f" % mo, "%.2f" % (mo / mj))
EOF
)
read -r cj co mj mo ratio <<<"$got"
[ "${cj:-x}" = 0 ] && [ "${co:-x}" = 0 ] && $PY -c "import sys; sys.exit(0 if float(sys.argv[1]) < 1.5 else 1)" "${ratio:-9}" &&
    ok "--out peaks at $mo MB against --json's $mj MB, $ratio times (under 1.5; 1.74 before)" ||
    ko "--out against --json: exit ${co:-?} and ${cj:-?}, $mo MB against $mj MB, ${ratio:-?} times (at most 1.5)"
if $PY -c "import h5py" 2>/dev/null && [ -f g4/impact.h5 ]; then
    got=$($PY - <<'EOF'
import h5py, numpy as np
f = h5py.File("g4/impact.h5", "r")
rows = [l for l in open("g4/ledger.csv") if l[0].isdigit()]
led = np.array([[float(x) for x in l.split(",")[1:9]] for l in rows])
t = np.array([float(l.split(",", 1)[0]) for l in rows])
sp = [l.split(",") for l in open("g4/crowns_spectra.csv") if l[0].isdigit()]
nr = f["ring_r"].shape[0]
bad = []
if f["t"].shape[0] != len(rows) or np.max(np.abs(f["t"][()] - t)) > 1e-8 * max(1, t[-1]):
    bad.append("t")
if f["ledger"].shape != led.shape or not np.allclose(f["ledger"][()], led, rtol=1e-8, atol=0):
    bad.append("ledger")
if f["ring_strain"].shape != (len(rows), nr) or f["spec_strain"].shape[0] * nr != len(sp) or \
        not np.allclose(f["spec_strain"][()].ravel(), [float(r[2]) for r in sp], rtol=1e-8, atol=0):
    bad.append("spectra")
print("ok" if not bad else "differ: %s" % bad)
EOF
)
    [ "$got" = ok ] && ok "control: impact.h5's t, ledger and spectra are ledger.csv's and crowns_spectra.csv's" ||
        ko "impact.h5 against the CSVs: $got"
else
    echo "SKIP: impact.h5 against the CSVs (no h5py, or a build without HDF5)"
fi
fi

# --- 3 the cross-correlation locked onto the pile's slow motion ---
cpu_run 120 "$GW" layer-impact --sample s40 --quiet --json --vi 40 --gravity 1 --other-settling --t-max 20 \
    --dt-out 1e-2 >lock.json 2>lock.err
rc=$?
got=$($PY - <<'EOF'
import json
a = json.load(open("lock.json"))
w = [x for x in a["warnings"] if "cross-correlation" in x]
ok = a["wave_speed_xcorr"] is None and a["wave_speed_xcorr_err"] is None and len(w) == 1 and \
    "wave_speed_xcorr is null" in w[0] and "first contact" in w[0] and "0.0406 s apart" in w[0]
print("ok" if ok else f"xcorr {a['wave_speed_xcorr']}, warnings {w}")
EOF
)
[ $rc -eq 0 ] && [ "$got" = ok ] &&
    ok "xcorr locked on the pile's motion (pairs 0.041 s apart, contact 1.36 ms): null, and a warning says why" ||
    ko "--vi 40 --gravity 1 --t-max 20 --dt-out 1e-2: exit $rc, $got"
grep -q "warning: crowns: the cross-correlation's ring pairs are 0.0406 s apart" lock.err &&
    ok "the program's stderr names the pairs' delay" || ko "stderr: $(head -c 300 lock.err)"
cpu_run 120 "$GW" layer-impact --sample "$SRC/data/measured/restitution_full/sample.txt" --quiet --json \
    >def.json 2>def.err
got=$($PY -c "import json; a = json.load(open('def.json')); print('%.2f' % a['wave_speed_xcorr'], \
    any('cross-correlation' in w for w in a['warnings']))" 2>&1)
[ "$got" = "609.50 False" ] && ok "control: the default impact's xcorr 609.50 m/s kept, no warning" ||
    ko "default impact: xcorr, cross-correlation warning: $got"

test_summary test_crowns_series_bound
