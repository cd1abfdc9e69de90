#!/usr/bin/python3
"""test_option_effect.py GRANWAVE [--full] [--verbose]: every option acts, or is refused.

For every command of `granwave` and every option its --help lists, a small
baseline run and the same run with that option set to a legitimate value other
than the default (and, for the options that act only with another one, the
run with that other option set so that this one cannot act: a damping constant
with no damping model, a solver tolerance with a fixed-step solver, an option
of the column mode of dispersion without --column-n, ...). All outputs are
compared: the JSON on stdout and every file of --out (or the sample file),
without what records the options themselves (the "settings" objects, the
provenance '#' lines, the command line of a VTK header) and without what
differs between two runs of the same baseline (timings). A variant whose
outputs are all the same as the baseline's, with nothing on stderr and exit 0,
is a silent no-op: the test fails, naming it, unless the option is one whose
invariance is its contract (threads, progress lines, FFTW planning, a cap or a
check that the run does not reach: listed in INVARIANT with the reason), which
the test then asserts instead (the outputs must be the same). A variant refused
(exit 2, naming the option) or with a warning on stderr the baseline had not
passes.

Values are chosen to bind: a cap (--dt-max, --t-max) above what the run
reaches, --full on a run that reaches t-max anyway, a value equal to what the run uses anyway
(arkode's default method erk, a sheet's own loss) legitimately changes nothing;
those are the documented cases (INVARIANT, and PAIRS entries with a reason),
not findings.

Default: a representative subset (105 checks, about 40 s); --full: the whole
matrix (335 checks, a few minutes). Exit 0 when every check passes, 1 otherwise.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import synthetic_tables  # the script's own folder is on sys.path

GW = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "build/granwave"
FULL = "--full" in sys.argv
VERBOSE = "--verbose" in sys.argv
TMP = tempfile.mkdtemp(prefix="gw_opt_effect_")

# a tiny settled sample and a layer sweep table, made once
SAMPLE = os.path.join(TMP, "S.txt")
TABLE = os.path.join(TMP, "results.csv")  # a real sweep: no boundary crossing, no B.31 fit
SYN = os.path.join(TMP, "syn.csv")  # a synthetic diagram with a boundary and a fit
SWEEP = os.path.join(TMP, "chain.ini")  # a chain sweep of three cases
SWEEP1 = os.path.join(TMP, "chain1.ini")  # and of one

# the baseline of each command: options (name -> value, None for a flag, False
# to leave out; keys "_..." are the driver's: another table or config, no --out)
BASE = {
    "chain": {"n": "3"},
    "falcon": {"n": "1:3", "vimp": "0.3", "heights": "none", "quiet": None, "jobs": "1"},
    "wavespeed": {"n": "5:8", "vimp": "0.3,0.5", "quiet": None, "jobs": "1"},
    "softwall": {"n": "1:3", "kwall": "1e9", "quiet": None, "jobs": "1"},
    "drop": {"n": "2", "t-max": "2e-4"},
    "dispersion": {"n": "32", "t-samples": "128"},
    "layer-make": {"n": "12", "width-rm": "8", "seed": "2", "ke-threshold": "1e-2", "t-max": "2",
                   "solver": "verlet"},
    # t-max past T_f (0.135 s): the outcome is decided before it (--full acts)
    "layer-impact": {"sample": SAMPLE, "t-max": "0.3", "vi": "5"},
    "layer-stats": {},
    "sweep": {"jobs": "1", "quiet": None},
}

# a legitimate non-default value of each option (per command where it differs)
VALUE = {
    "material": "brass", "radius": "3e-3", "wall-material": "brass", "sheet": "pvc", "radii": None,
    "k": "5e9", "kwall": "5e9", "mass": "2e-3", "gravity": "9.81", "damping": "kk", "gamma": "1e4",
    "alpha": "0.1", "restitution": "0.9", "restitution-v": "0.5", "solver": "arkode", "method": "adams",
    "rtol": "1e-9", "atol": "1e-9", "dt": "5e-9", "dt-max": "2e-8", "max-steps": "1000000",
    "t-max": "5e-5", "dt-out": "1e-7", "energy-tol": "0.5", "sheet-law": "hertz", "sheet-yield": "1e6",
    "sheet-loss": "0.1", "sensor-mass": "0.05", "sensor-stiffness": "1e8", "sensor-damping": "1",
    "guide-friction": "1e-3", "guide-viscous": "0.01", "n": "4", "vimp": "0.4",
    "heights": "2.9", "accuracy": "1e-4", "jobs": "2", "quiet": None, "threshold": "0.2",
    "tol": "0.2", "sheets": None, "height": "3e-3", "gap": "1e-5", "block": None,
    "peak-threshold": "5", "f0": "20", "ends": "fixed", "t-samples": "256", "steps-per-sample": "8",
    "amp": "1e-2", "seed": "3", "min-bins": "4", "fftw-measure": None, "wisdom": "@wisdom",
    "column-n": "3", "friction": "20", "shear-modulus": "30e9", "poisson": "0.3", "density": "2000",
    "skin": "0.05", "mass-law": "sphere", "clump-mass": "union", "rm": "0.3", "volume-ratio": "5",
    "width-rm": "10", "ke-threshold": "5e-2", "modulus-factor": "0.5", "height-rm": "6",
    "clumps": None, "aspect-max": "2", "rb-rm": "2", "vi": "8", "x": "0.1", "ring-width": "0.5",
    "rings": "6", "exact": None, "remove-walls": None, "side-walls": "left", "full": None, "until": "verdict",
    "check": None, "criterion": "0.5", "fit": "beta,a_over_b,offset", "gamma-deg": "0.5", "delta-rm": "0.5",
}
PER_CMD = {
    ("drop", "t-max"): "1e-4", ("drop", "dt-out"): "2e-6", ("drop", "n"): "3", ("drop", "gap"): "1e-5",
    ("drop", "gravity"): "5", ("drop", "mass"): "1e-3",
    ("falcon", "vimp"): "0.4", ("falcon", "n"): "1:4", ("wavespeed", "n"): "5:9", ("softwall", "n"): "1:4",
    ("falcon", "t-max"): "1e-3",
    ("softwall", "kwall"): "5e8", ("softwall", "vimp"): "0.3", ("wavespeed", "vimp"): "0.3,0.4",
    ("dispersion", "n"): "64", ("dispersion", "solver"): "cvode", ("dispersion", "method"): "adams",
    ("dispersion", "rtol"): "1e-9", ("dispersion", "atol"): "1e-9", ("dispersion", "dt-out"): "1e-5",
    ("dispersion", "vimp"): "0.4",
    ("layer-make", "n"): "10", ("layer-make", "t-max"): "1.5", ("layer-make", "dt"): "1e-5",
    ("layer-make", "damping"): "0.5", ("layer-make", "solver"): "rk4", ("layer-make", "height-rm"): "6",
    ("layer-make", "gravity"): "5",
    ("layer-impact", "t-max"): "0.05", ("layer-impact", "dt-out"): "1e-4", ("layer-impact", "dt"): "5e-7",
    ("layer-impact", "solver"): "rk4", ("layer-impact", "method"): "bdf", ("layer-impact", "rtol"): "1e-6",
    ("layer-impact", "atol"): "1e-6", ("layer-impact", "gap"): "1e-3", ("layer-impact", "height-rm"): "4",
    ("layer-impact", "energy-tol"): "0.9", ("layer-impact", "gravity"): "5", ("layer-impact", "alpha"): "20",
}

# options whose contract is that the outputs do not change (asserted the same)
INVARIANT = {
    "jobs": "threads: the tables are the same on any count (one case or many)",
    "quiet": "progress lines on stderr only",
    "fftw-measure": "FFTW planning: the same transform (the planner's time aside)",
    "wisdom": "FFTW wisdom: the same transform",
    "max-steps": "a cap the baseline does not reach",
    "energy-tol": "a check the baseline passes",
    "skin": "the contact list's skin: the same contacts, the same run (only the count of rebuilds differs)",
}
# outputs an invariant option may change: the diagnostics of what it is about
INVARIANT_KEYS = {"skin": {"rebuilds", "rhs_evals", "events"}, "fftw-measure": {"fft_ms"}, "wisdom": {"fft_ms"}}

# runs where an option cannot act, by the help's own words: (command, context
# options, option, value); a silent identical result is a finding.
PAIRS = [
    ("chain", {"solver": "rk4"}, "method", "adams"),
    ("chain", {"solver": "rk4"}, "rtol", "1e-9"),
    ("chain", {"solver": "rk4"}, "atol", "1e-9"),
    ("chain", {}, "gamma", "1e4"),
    ("chain", {"damping": "hc", "alpha": "0.1"}, "gamma", "1e4"),
    ("chain", {}, "alpha", "0.1"),
    ("chain", {}, "restitution-v", "0.5"),
    ("chain", {}, "sheet-law", "hertz"),
    ("chain", {"sheet": "pvc"}, "sheet-yield", "1e6"),
    ("chain", {}, "sensor-stiffness", "1e8"),
    ("chain", {}, "sensor-damping", "1"),
    ("chain", {"kwall": "5e9"}, "wall-material", "brass"),
    ("chain", {"sheet": "pvc"}, "wall-material", "brass"),
    ("chain", {"mass": "2e-3", "k": "5e9", "kwall": "5e9"}, "material", "brass"),
    ("chain", {"n": "2", "radii": "4e-3,3e-3"}, "radius", "3e-3"),
    ("falcon", {"solver": "rk4"}, "accuracy", "1e-4"),
    ("falcon", {"solver": "cvode"}, "rtol", "1e-9"),
    ("softwall", {"kwall": False, "sheets": None, "n": "1:3"}, "sheet-loss", "0.1"),
    ("softwall", {"kwall": False, "sheets": None, "n": "1:3"}, "sheet-yield", "1e6"),
    ("drop", {"block": None}, "gap", "1e-5"),
    ("drop", {"n": "1"}, "gap", "1e-5"),
    ("dispersion", {}, "vimp", "0.4"),
    ("dispersion", {"solver": "cvode"}, "steps-per-sample", "8"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "f0", "20"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "ends", "fixed"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "t-samples", "256"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "steps-per-sample", "8"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "amp", "1e-2"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "seed", "3"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "min-bins", "4"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "dt-out", "1e-7"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3", "solver": "rk4"}, "rtol", "1e-9"),
    ("dispersion", {"solver": "rk4"}, "rtol", "1e-9"),
    ("dispersion", {"solver": "rk4"}, "method", "adams"),
    ("dispersion", {"n": False, "t-samples": False, "column-n": "3"}, "fftw-measure", None),
    ("layer-make", {}, "aspect-max", "2"),
    ("layer-make", {}, "clump-mass", "union"),
    ("layer-make", {"solver": "verlet"}, "method", "bdf"),
    ("layer-impact", {}, "rtol", "1e-6"),
    ("layer-impact", {}, "atol", "1e-6"),
    ("layer-impact", {}, "method", "bdf"),
    ("layer-impact", {"exact": None, "solver": "cvode"}, "dt", "5e-7"),
    ("layer-impact", {"until": "verdict"}, "full", None),
    ("layer-impact", {}, "clump-mass", "union"),
    # the value that holds a parameter, with that parameter fitted (the global
    # fit searches its whole range: no start value; refused)
    ("layer-stats", {"fit": "beta,a_over_b,tan_gamma"}, "gamma-deg", "0.5"),
    ("layer-stats", {"fit": "beta,a_over_b,offset"}, "delta-rm", "0.5"),
    ("layer-stats", {"_table": TABLE}, "gamma-deg", "0.5"),
    ("layer-stats", {"_table": TABLE}, "delta-rm", "0.5"),
    ("layer-stats", {"_table": TABLE}, "fit", "beta,a_over_b,tan_gamma"),
    # tolerances with a fixed-step solver, a fixed step with an adaptive one
    ("drop", {"solver": "rk4"}, "rtol", "1e-9"),
    ("wavespeed", {"solver": "rk4"}, "atol", "1e-9"),
    ("softwall", {"solver": "rk4"}, "rtol", "1e-9"),
    ("falcon", {"solver": "rk4"}, "rtol", "1e-9"),
    ("falcon", {"solver": "cvode"}, "dt", "5e-9"),
    ("drop", {"solver": "cvode"}, "dt", "5e-9"),
    ("layer-impact", {"solver": "cvode"}, "dt", "5e-7"),
    ("layer-impact", {"exact": None}, "rtol", "1e-6"),
    ("layer-impact", {"exact": None}, "method", "bdf"),
    ("layer-impact", {"solver": "rk4"}, "method", "bdf"),
    ("layer-make", {"solver": "rk4"}, "dt", "1e-5"),
    # cadences and crowns with no file asked for: the JSON alone
    ("chain", {"_noout": True}, "dt-out", "1e-7"),
    ("drop", {"_noout": True}, "dt-out", "2e-6"),
    ("falcon", {"_noout": True}, "dt-out", "1e-7"),
    # a coarser dt-out with no file: the results are read at the run's checks
    # (every 2e-5 s) and events, so they are the default's (issue 18's class 6);
    # a finer one reads the crowns from its own samples and changes them
    ("layer-impact", {"_noout": True}, "dt-out", "1e-4",
     "the results are read at the run's checks and events, not at the samples (docs/crowns.md)"),
    ("layer-impact", {"_noout": True}, "dt-out", "1e-5"),
    ("layer-impact", {"_noout": True}, "rings", "6"),
    ("layer-impact", {"_noout": True}, "ring-width", "0.5"),
    # one case on threads: the same outputs (INVARIANT)
    ("sweep", {"_config": SWEEP1}, "jobs", "2"),
]

# more combinations, checked with --full only
PAIRS_FULL = [
    ("softwall", {"kwall": False, "sheets": None}, "tol", "0.2"),
    ("softwall", {"kwall": False, "sheets": None, "sheet-law": "material"}, "wall-material", "brass"),
    ("drop", {"block": None}, "peak-threshold", "5"),
    ("drop", {"n": "1"}, "k", "5e9"),
    ("chain", {"n": "1"}, "k", "5e9"),
    ("chain", {"n": "1"}, "guide-friction", "1e-3"),
    ("falcon", {"solver": "rk4"}, "dt", "5e-9"),
    ("layer-impact", {"until": "verdict"}, "rings", "6"),
    ("layer-impact", {"until": "verdict"}, "dt-out", "1e-4"),
    ("dispersion", {"solver": "cvode", "ends": "fixed"}, "method", "bdf"),
    ("dispersion", {"solver": "cvode"}, "dt-out", "1e-5"),
    ("layer-make", {"clumps": None}, "clump-mass", "union"),
    ("layer-make", {"mass-law": "sphere"}, "clump-mass", "union"),
    ("chain", {"sheet": "pvc", "sheet-law": "hertz"}, "wall-material", "brass"),
    ("chain", {"sensor-mass": "0.05", "sensor-stiffness": "1e8"}, "sensor-damping", "1"),
    ("chain", {"damping": "kk", "restitution": "0.9"}, "restitution-v", "0.5"),
    ("chain", {"solver": "arkode"}, "dt", "5e-9"),
    # a value equal to what the run uses anyway: legitimately the same
    ("chain", {"solver": "arkode"}, "method", "erk", "erk is arkode's default method (--help: [bdf / erk])"),
    ("chain", {"sheet": "rubber", "sheet-law": "material"}, "sheet-loss", "0.1",
     "rubber's own tan(delta) is 0.1 (--help: [the sheet's])"),
]

# the subset the default (fast) run checks: every PAIRS entry and these singles
FAST_SINGLE = {
    ("chain", o) for o in ("material", "radius", "gravity", "dt", "dt-max", "t-max", "dt-out", "guide-viscous",
                           "vimp")
} | {("drop", o) for o in ("height", "peak-threshold", "gap", "dt-out")} | {
    ("dispersion", o) for o in ("f0", "ends", "seed", "amp", "min-bins", "steps-per-sample")
} | {("layer-impact", o) for o in ("vi", "x", "rings", "full", "skin")} | {
    ("falcon", o) for o in ("accuracy", "vimp", "jobs")} | {("softwall", "tol"), ("wavespeed", "threshold")} | {
    ("layer-stats", o) for o in ("criterion", "fit", "gamma-deg", "delta-rm")} | {
    ("sweep", o) for o in ("jobs", "check")} | {("layer-make", o) for o in ("seed", "skin", "clumps")}


def help_options(cmd):
    out = subprocess.run([GW, "help", cmd], capture_output=True, text=True).stdout
    return [m.group(1) for m in re.finditer(r"^  --([a-z0-9-]+)", out, re.M) if m.group(1) != "help"]


def argv(cmd, opts, out_dir):
    a = [GW, cmd]
    if cmd == "layer-stats":
        a.append(opts.get("_table", SYN))
    if cmd == "sweep":
        a.append(opts.get("_config", SWEEP))
    for k, v in opts.items():
        if v is False or k.startswith("_"):
            continue
        a.append("--" + k)
        if v is not None:
            a.append(v.replace("@wisdom", os.path.join(TMP, "wisdom_%d" % id(opts))))
    if cmd == "layer-make":
        a += ["--out", os.path.join(out_dir, "sample.txt"), "--json"]
    elif opts.get("_noout"):  # stdout only: an option that acts on files alone has no effect here
        a += ["--json"]
    elif cmd == "sweep":
        a += ["--out", out_dir]
    else:
        a += ["--json", "--out", out_dir]
    return a


# what records the options (or the run's paths) rather than results: dt_step
# is dispersion's dt-out / steps-per-sample, as its settings' rk4_dt
IGNORED_KEYS = {"settings", "wall_time_ms", "version", "sample_fnv1a64", "command", "sample", "input", "config",
                "input_fnv1a64", "dt_step", "fftw_planner"}


def norm(x, noisy):
    if isinstance(x, dict):
        return {k: norm(v, noisy) for k, v in x.items() if k not in IGNORED_KEYS and k not in noisy}
    if isinstance(x, list):
        return [norm(v, noisy) for v in x]
    return x


def read_outputs(stdout, out_dir, noisy):
    res = {}
    try:
        res["stdout"] = norm(json.loads(stdout), noisy)
    except ValueError:
        res["stdout"] = stdout
    for root, _, files in os.walk(out_dir):
        for f in sorted(files):
            p = os.path.join(root, f)
            rel = os.path.relpath(p, out_dir)
            if f.endswith(".h5"):
                try:
                    import h5py
                    with h5py.File(p, "r") as h:
                        d = {}
                        h.visititems(lambda n, o: d.__setitem__(n, o[()].tobytes())
                                     if isinstance(o, h5py.Dataset) else None)
                    res[rel] = d
                except Exception as e:  # noqa: BLE001
                    res[rel] = "h5 unreadable: %s" % e
                continue
            with open(p, errors="replace") as fh:
                text = fh.read()
            if f.endswith(".json"):
                try:
                    res[rel] = norm(json.loads(text), noisy)
                    continue
                except ValueError:
                    pass
            lines = [ln for ln in text.splitlines()
                     if not ln.startswith("#") and "granwave" not in ln and "of wall time" not in ln]
            if f == "journal.csv":  # a log in the order the cases finished (results.csv is the sorted table)
                lines.sort()
            res[rel] = "\n".join(lines)
    return res


def warnings_of(err):
    """A run's warning lines ("granwave CMD: warning: ..."): the progress display,
    which a run past 2 s of the clock shows on a loaded machine, is no warning
    (its lines made an option that changes nothing look warned of)."""
    return [ln for ln in err.splitlines() if ": warning: " in ln]


def run(cmd, opts, noisy=()):
    d = tempfile.mkdtemp(dir=TMP)
    out = os.path.join(d, "out")
    if cmd == "layer-make":
        os.mkdir(out)
    p = subprocess.run(argv(cmd, opts, out), capture_output=True, text=True, timeout=300)
    res = read_outputs(p.stdout, out, noisy) if p.returncode == 0 else None
    shutil.rmtree(d, ignore_errors=True)
    return p.returncode, p.stderr.strip(), res


def noisy_keys(a, b, path=""):
    """Keys whose values differ between two runs of the same baseline (timings)."""
    keys = set()
    if isinstance(a, dict) and isinstance(b, dict):
        for k in a:
            if k in b:
                if a[k] != b[k] and not isinstance(a[k], (dict, list)):
                    keys.add(k)
                keys |= noisy_keys(a[k], b[k])
    elif isinstance(a, list) and isinstance(b, list):
        for x, y in zip(a, b):
            keys |= noisy_keys(x, y)
    return keys


BASELINES = {}


def baseline(cmd, opts):
    key = (cmd, json.dumps(opts, sort_keys=True))
    if key not in BASELINES:
        rc, err, r1 = run(cmd, opts)
        if rc != 0:
            BASELINES[key] = (rc, err, None, set())
        else:
            _, _, r2 = run(cmd, opts)
            noisy = set()
            for f in r1:
                if isinstance(r1[f], str) and isinstance(r2.get(f), str) and f != "stdout":
                    a, b = r1[f].split("\n"), r2[f].split("\n")
                    noisy |= {(f, i) for i in range(min(len(a), len(b))) if a[i] != b[i]}
                else:
                    noisy |= noisy_keys(r1[f], r2.get(f))
            BASELINES[key] = (rc, err, strip(r1, noisy), noisy)
    return BASELINES[key]


def strip(res, noisy):
    """res without the keys in noisy (JSON) and the lines noisy names by (file, index) (text)."""
    if res is None:
        return None
    out = {}
    for k, v in res.items():
        if isinstance(v, str) and k != "stdout":
            lines = v.split("\n")
            v = "\n".join("<differs run to run>" if (k, i) in noisy else ln for i, ln in enumerate(lines))
        out[k] = norm(v, noisy)
    return out


def make_fixtures():
    subprocess.run([GW, "layer-make", "--n", "40", "--width-rm", "14", "--seed", "2", "--ke-threshold", "1e-2",
                    "--solver", "verlet", "--out", SAMPLE], check=True, capture_output=True)
    ini = os.path.join(TMP, "s.ini")
    with open(ini, "w") as f:
        f.write("[sweep]\nmodel = layer\n[grid]\nrb-rm = 0.8, 2\nheight-rm = 2, 4\npoint = 0:2\n[params]\n"
                "sample = %s\npoints = 3\nt-max = 0.02\n" % SAMPLE)
    subprocess.run([GW, "sweep", ini, "--out", os.path.join(TMP, "sw"), "--quiet", "--jobs", "2"], check=True,
                   capture_output=True)
    shutil.copy(os.path.join(TMP, "sw", "results.csv"), TABLE)
    for path, grid in ((SWEEP, "n = 1:3"), (SWEEP1, "n = 2")):
        with open(path, "w") as f:
            f.write("[sweep]\nmodel = chain\n[grid]\n%s\n[params]\nsolver = rk4\n" % grid)
    # bouncing below H = 3 + 2 R_b/R_m (three points of four; the fourth always bounces)
    synthetic_tables.write_bouncing_diagram(SYN)


fails = passes = 0
findings = []


def check(cmd, ctx, opt, val, same=None):
    global fails, passes
    t0 = time.time()
    base = dict(BASE[cmd])
    for k, v in ctx.items():
        base[k] = v
    if opt in base and base[opt] == val:
        return
    label = "%s %s--%s%s" % (cmd, "".join(("[%s] " % os.path.basename(str(v)) if k in ("_table", "_config") else "[no --out] ")
                                          if k.startswith("_") else "--%s%s " % (k, "" if v is None else " " + str(v))
                                          for k, v in ctx.items() if v is not False),
                             opt, "" if val is None else " " + val)
    var = dict(base)
    var[opt] = val
    rc, err, r = run(cmd, var)
    if rc == 2 and ("--%s:" % opt) in err and not same and not INVARIANT.get(opt):
        r0 = err0 = None  # refused, naming the option: no baseline needed
    else:
        rc0, err0, r0, noisy = baseline(cmd, base)
        if rc0 != 0:
            print("SKIP: %s: baseline exit %d: %s" % (label, rc0, err0[:200]))
            return
        r = strip(r, noisy)
    inv = same or INVARIANT.get(opt)
    if inv and r is not None:
        r, r0 = strip(r, INVARIANT_KEYS.get(opt, ())), strip(r0, INVARIANT_KEYS.get(opt, ()))
    if rc == 2:
        state = "refused: " + err
    elif rc != 0:
        state = "exit %d: %s" % (rc, err[:200])
    elif r == r0:
        extra = "\n".join(warnings_of(err)) if warnings_of(err) != warnings_of(err0) else ""
        state = "SAME" + ((" warned: " + extra) if extra else "")
    else:
        diff = sorted(k for k in set(r) | set(r0) if r.get(k) != r0.get(k))
        state = "changed: " + ",".join(diff)
    silent = state == "SAME"
    if inv:
        ok = state.startswith("SAME")
    else:
        ok = not silent
    if ok:
        passes += 1
        if VERBOSE:
            print("PASS: %s -> %s [%.1f s]" % (label, state, time.time() - t0))
    else:
        fails += 1
        findings.append(label)
        print("FAIL: %s -> %s%s" % (label, state, " (contract: %s)" % inv if inv else " (silent no-op)"))


def main():
    try:
        make_fixtures()
        for cmd in BASE:
            opts = help_options(cmd)
            for o in opts:
                if o in ("json", "out", "sample", "help"):
                    continue
                if not FULL and (cmd, o) not in FAST_SINGLE:
                    continue
                val = PER_CMD.get((cmd, o), VALUE.get(o, "?"))
                if val == "?":
                    print("NOVALUE: %s --%s" % (cmd, o))
                    continue
                if o == "radii":
                    continue
                check(cmd, {}, o, val)
        for cmd, ctx, o, v, *same in PAIRS + (PAIRS_FULL if FULL else []):
            check(cmd, ctx, o, v, same[0] if same else None)
    finally:
        shutil.rmtree(TMP, ignore_errors=True)
    print("%d passed, %d failed" % (passes, fails))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
