#!/usr/bin/python3
"""test_frontend_parity.py GRANWAVE [--full] [--verbose] [--only CMD]: one rule in the three front-ends.

granwave is used through the program (`granwave CMD --flag V`), the Python
module (granwave.CMD(keyword=V)) and the C library (a setup struct from the
study's _init, its fields set, the study's run); the library's parameter table
holds the rule. For every study of the library's index and every number,
integer, range, list or choice row of its table that is also an option of the
command, the same values go to the front-ends, each over a small baseline run:

  the row's documented min and max (from the table) and just outside each end,
  0, nan and 1.5 (integer rows; every count row, a whole number the library
  holds as a double, also its whole minimum written as a real, 1.0); with --full also -1, 1e308, -1e308, 1e-308
  (subnormal), 3e-308, inf, -inf, 2^63 and -0.5; every name of a choice row
  and an unknown one; an optional text row (granwave.params "optional") at its
  default's text, given (layer-stats' fit, on a table without a diagram where
  a given fit has no effect: refused by all three, as none given runs).

Asserted:
  - the program and Python both refuse (the program: exit 2 with exactly one
    line on stderr naming --flag, or naming it as a word in a rule over it and
    the sample; Python: a ValueError or TypeError naming the keyword), or both
    accept (the program exits 0, or 1 for a run that failed, and Python returns,
    or raises GranwaveRunError for the same failure); a refusal over another
    option (t-samples x n) must be the same in both;
  - where both ran to the end, the results agree: every number of the
    program's --json (top level, and lists of numbers) that the Python result
    holds under the same name is the same to 1e-12 (timings aside);
  - a C caller that writes the value into the setup's field (an index past the
    names for an unknown choice; NaN is "not given" in a field, so not tried)
    is refused or runs as Python is (by default where Python refuses; --full:
    every value), with the same results.
A run still going after the time limit counts as accepted; where one side
refused and the other was still going, the other is run to its end.

The Python and C calls run in a worker process, interrupted by SIGINT at the
time limit (as Ctrl-C), so a long run cannot hang the test. By default a row
shared by several studies (the column's material ... guide-viscous, the layer's
material) is tried in the first that has it with the same range, nan and 1.5 in
the first row of each study: 460 checks, about 20 s of CPU (2 minutes of wall
time at a load of 12 on two cores). --full: every row in every study, every
value, a 20 s limit. Exit 0 when every check passes, 1 otherwise.
"""
import json
import math
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import synthetic_tables  # the script's own folder is on sys.path

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(HERE)
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
GW = os.path.abspath(ARGS[0]) if ARGS else os.path.join(SRC, "build", "granwave")
FULL = "--full" in sys.argv
VERBOSE = "--verbose" in sys.argv
ONLY = sys.argv[sys.argv.index("--only") + 1] if "--only" in sys.argv else None
# seconds a run may take before it counts as running (accepted): a refusal comes
# before any work, in milliseconds; results are compared for the runs done by then
TIMEOUT = 20.0 if FULL else 0.4
LONG_TIMEOUT = 120.0  # where one side refused and the other was still running at TIMEOUT
TMP = tempfile.mkdtemp(prefix="gw_parity_")
SAMPLE = os.path.join(TMP, "S.txt")
TABLE = os.path.join(TMP, "syn.csv")
NODIA = os.path.join(TMP, "nodia.csv")  # a table without a bouncing diagram

ENV = dict(os.environ)
ENV.setdefault("PYTHONPATH", os.path.join(SRC, "python"))
if "GRANWAVE_LIB" not in ENV:  # the build tree's library beside the program
    lib = os.path.join(os.path.dirname(GW), "lib", "libgranwave.so")
    if os.path.exists(lib):
        ENV["GRANWAVE_LIB"] = lib
ENV["PYTHONDONTWRITEBYTECODE"] = "1"

# the small baseline of each command (flag -> text), the same for both front-ends
BASE = {
    "chain": {"n": "3"},
    "falcon": {"n": "1:3", "vimp": "0.3", "heights": "none", "jobs": "1"},
    "wavespeed": {"n": "6:8", "vimp": "0.3,0.5", "jobs": "1"},
    "softwall": {"n": "1:3", "kwall": "1e9", "jobs": "1"},
    "drop": {"n": "2", "t-max": "2e-4"},
    "dispersion": {"n": "32", "t-samples": "128"},
    "layer-impact": {"sample": SAMPLE, "t-max": "0.01", "vi": "5"},
    "layer-make": {"n": "12", "width-rm": "8", "seed": "2", "ke-threshold": "1e-2", "t-max": "2",
                   "solver": "verlet"},
    "layer-stats": {"input": TABLE},
}
# options of the program that are not rows of a study's table (the driver's own)
PROGRAM_ONLY = {"jobs", "quiet", "json", "out", "help", "wisdom", "fftw-measure"}
# baseline options that must not reach the table run as the row under test
# (the row replaces them); rows whose base options conflict are run without them
DROP_WITH = {("dispersion", "column-n"): ("n", "t-samples"), ("dispersion", "vimp"): ("n", "t-samples"),
             ("softwall", "sheets"): ("kwall",)}
# context that lets a row act (else it is refused as having no effect, whatever
# its value, and its range would go unchecked)
CONTEXT = {
    ("chain", "gamma"): {"damping": "kk"}, ("chain", "alpha"): {"damping": "hc"},
    ("chain", "restitution-v"): {"damping": "kk", "restitution": "0.9"},
    ("chain", "sheet-yield"): {"sheet": "pvc", "sheet-law": "material"},
    ("chain", "sheet-loss"): {"sheet": "pvc", "sheet-law": "material"},
    ("chain", "sensor-stiffness"): {"sensor-mass": "0.05"}, ("chain", "sensor-damping"): {"sensor-mass": "0.05", "sensor-stiffness": "1e8"},
    ("chain", "rtol"): {"solver": "cvode"}, ("chain", "atol"): {"solver": "cvode"},
    ("chain", "method"): {"solver": "cvode"}, ("chain", "dt"): {"solver": "rk4"},
    ("dispersion", "rtol"): {"solver": "cvode"}, ("dispersion", "atol"): {"solver": "cvode"},
    ("dispersion", "method"): {"solver": "cvode"},
    ("dispersion", "vimp"): {"column-n": "3"},
    ("drop", "gap"): {"n": "3"},
    ("layer-impact", "rtol"): {"exact": None, "solver": "cvode"},
    ("layer-impact", "atol"): {"exact": None, "solver": "cvode"},
    ("layer-impact", "method"): {"exact": None, "solver": "cvode"},
    ("layer-make", "aspect-max"): {"clumps": None}, ("layer-make", "clump-mass"): {"clumps": None},
    ("layer-stats", "gamma-deg"): {"fit": "beta,a_over_b"}, ("layer-stats", "delta-rm"): {"fit": "beta,a_over_b"},
    # an optional text row is tried at its default's text, where being given
    # decides a refusal: fit on a table without a diagram has no effect
    ("layer-stats", "fit"): {"input": NODIA},
}

WORKER = r'''
import json, math, sys, warnings
import numpy as np
import granwave
warnings.simplefilter("ignore")
def num(v):
    if isinstance(v, (bool, np.bool_)):
        return None
    if isinstance(v, (int, float, np.integer, np.floating)):
        return float(v)
    if isinstance(v, np.ndarray) and v.ndim == 1 and v.dtype.kind in "iuf" and v.size <= 100000:
        return [float(x) for x in v]
    if isinstance(v, (list, tuple)) and v and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v):
        return [float(x) for x in v]
    return None
import ctypes
from granwave import _core, _lib
C_TYPES = {_core.DOUBLE: ctypes.c_double, _core.COUNT: ctypes.c_double, _core.LONG: ctypes.c_long,
           _core.INT: ctypes.c_int}
def c_value(p, value):
    """value as a C caller writes it into the struct field of row p; None where
    no C value is that one (1.5 into a long)."""
    if p.type == _core.CHOICE:
        return p.choices.index(value) if value in p.choices else len(p.choices)  # an index past the names
    if p.type == _core.TEXT:
        return value if isinstance(value, str) else None
    if isinstance(value, list) or isinstance(value, str):
        return None
    if p.type in (_core.DOUBLE, _core.COUNT):  # a count is a double field (1.5 written as it is)
        return float(value)
    if p.type in (_core.LONG, _core.INT, _core.RANGE):
        v = float(value)
        lim = 2 ** 31 if p.type == _core.INT else 2 ** 63
        return int(v) if v == v and abs(v) < lim and v == int(v) else None
    return None
def c_call(func, kwargs, key):
    """The study as a C caller runs it: the setup from its _init, the other
    parameters set by name (gw_param_set), the one under test written into its
    field, then the study's run (which checks the struct, gw_param_check)."""
    st = granwave._study(func.replace("_", "-") if func != "layer_stats" else "layer-stats")
    p = st.by_keyword[key]
    v = c_value(p, kwargs.pop(key))
    if v is None:
        return {"kind": "na"}
    buf = st.setup(kwargs)
    out = ctypes.create_string_buffer(st.st.fields_size)
    err = _lib.GwErr()
    try:
        addr = ctypes.addressof(buf) + p.offset
        if p.type == _core.RANGE:
            (ctypes.c_long * 2).from_address(addr)[:] = [v, v]
        elif p.type == _core.TEXT:  # an owned copy, as the struct's clear frees it
            libc = ctypes.CDLL(None)
            libc.strdup.restype, libc.strdup.argtypes = ctypes.c_void_p, [ctypes.c_char_p]
            libc.free.argtypes = [ctypes.c_void_p]
            cell = ctypes.c_void_p.from_address(addr)
            libc.free(cell.value)
            cell.value = libc.strdup(v.encode())
        else:
            (ctypes.c_int if p.type == _core.CHOICE else C_TYPES[p.type]).from_address(addr).value = v
        with _core.Interruptible():
            rc = st.st.run(buf, out, _lib.PROGRESS(), None, ctypes.byref(err))
        msg = err.msg.decode(errors="replace")
        if rc == 0:
            r = _core.read_result(st.fields, ctypes.addressof(out))
            return {"kind": "ok", "nums": {k: num(x) for k, x in r.items() if num(x) is not None}}
        if rc in (_core.GW_EINVAL, _core.GW_EFORMAT, _core.GW_EUNSUPPORTED):
            return {"kind": "refused", "etype": "status %d" % rc, "msg": msg}
        if rc in (_core.GW_ESOLVER, _core.GW_ELIMIT, _core.GW_EENERGY):
            return {"kind": "runfail", "msg": msg}
        if rc == _core.GW_ECANCELED:
            return {"kind": "running"}
        return {"kind": "error", "etype": "status %d" % rc, "msg": msg}
    finally:
        st.st.free_out(out)
        st.st.clear(buf)
def serve():
    while True:
        try:
            line = sys.stdin.readline()
        except KeyboardInterrupt:  # a late interrupt after the answer went out
            continue
        if not line:
            return
        q = json.loads(line)
        fn = getattr(granwave, q["func"])
        try:
            try:
                if q.get("c_key"):
                    out = c_call(q["func"], q["kwargs"], q["c_key"])
                else:
                    r = fn(**q["kwargs"])
                    out = {"kind": "ok", "nums": {k: num(v) for k, v in r.items() if num(v) is not None}}
            except KeyboardInterrupt:  # the driver's time limit: the run was going (accepted)
                out = {"kind": "running"}
            except granwave.GranwaveRunError as e:
                out = {"kind": "runfail", "msg": str(e)}
            except (ValueError, TypeError, granwave.GranwaveUnsupported) as e:  # the program's exit 2
                out = {"kind": "refused", "etype": type(e).__name__, "msg": str(e)}
            except Exception as e:
                out = {"kind": "error", "etype": type(e).__name__, "msg": str(e)}
        except KeyboardInterrupt:
            out = {"kind": "running"}
        sys.stdout.write(json.dumps(out) + "\n")
        sys.stdout.flush()
sys.stdout.write("ready\n")
sys.stdout.flush()
serve()
'''


class Worker:
    def __init__(self):
        self.p = None

    def start(self):
        self.p = subprocess.Popen([sys.executable, "-c", WORKER], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, env=ENV, text=True)
        if self.p.stdout.readline() != "ready\n":
            raise SystemExit("the Python worker did not start (PYTHONPATH, GRANWAVE_LIB?)")

    def call(self, func, kwargs, c_key=None):
        if self.p is None or self.p.poll() is not None:
            self.start()
        self.p.stdin.write(json.dumps({"func": func, "kwargs": kwargs, "c_key": c_key}) + "\n")
        self.p.stdin.flush()
        r, _, _ = select.select([self.p.stdout], [], [], TIMEOUT)
        interrupted = not r
        if not r:  # interrupted as Ctrl-C would (the module stops the library's run), else ended
            self.p.send_signal(signal.SIGINT)
            r, _, _ = select.select([self.p.stdout], [], [], 30)
            if not r:
                self.stop()
                return {"kind": "running"}
        line = self.p.stdout.readline()
        if not line and interrupted and self.p.wait() == -signal.SIGINT:  # ended by the driver's SIGINT
            self.p = None
            return {"kind": "running"}
        if not line:  # the interpreter died: a crash in the library
            rc = self.p.wait()
            self.p = None
            return {"kind": "error", "etype": "crash", "msg": "worker ended with %s" % rc}
        return json.loads(line)

    def stop(self):
        if self.p is not None:
            self.p.kill()
            self.p.wait()
            self.p = None


WORK = Worker()


# the module's type names (granwave.params) as the driver's
TYPES = {"float": "double", "int": "int", "bool": "flag", "choice": "choice", "str": "text",
         "list of float": "list", "range A:B": "range", "count": "count"}


def py_value(text, ptype):
    """The Python value a user would pass for the program's text."""
    if ptype == "choice" or ptype == "text":
        return text
    if ptype == "range" and ":" in text:
        a, b = text.split(":")
        return [int(a), int(b)]
    if ptype == "list" and "," in text:
        return [float(x) for x in text.split(",")]
    if text == "none":
        return []
    try:
        return int(text)
    except ValueError:
        return float(text)


def text_of(v):
    return str(v) if isinstance(v, int) else repr(v)


GENERIC = set()
CURRENT = [None]


def values(p):
    """The values tried for row p: (value, why). Numbers as Python numbers
    (the program gets their repr)."""
    integer = p["type"] in ("int", "long", "range", "count")  # a count: a whole number held as a double
    lo, hi = p["min"], p["max"]
    out = []

    def add(v, why, real=False):
        if not real and isinstance(v, float) and integer and math.isfinite(v) and v == int(v) and abs(v) < 2 ** 63:
            v = int(v)
        if all(not (type(v) is type(w) and (v == w or (v != v and w != w))) for w, _ in out):
            out.append((v, why))

    # at and just outside the ends of the table's range
    for end, sign, name in ((lo, -1, "min"), (hi, 1, "max")):
        if not math.isfinite(end):
            continue
        add(end, name)
        if integer:
            add(end + sign, "just outside " + name)
        else:
            add(end + sign * max(abs(end) * 1e-9, 1e-300), "just outside " + name)
    add(0, "zero")
    # nan and 1.5 go through the one number parser of every row: by default in
    # the first row of each kind of a study (--full: every row)
    if FULL or ("nan", CURRENT[0]) not in GENERIC:
        GENERIC.add(("nan", CURRENT[0]))
        add(float("nan"), "nan")
    if integer and (FULL or (p["type"] == "count" or ("int", CURRENT[0]) not in GENERIC)):
        GENERIC.add(("int", CURRENT[0]))
        add(1.5, "not an integer")  # every count row: its own rule of whole numbers
    if p["type"] == "count":  # a whole number written as a real: taken by all three (Python's 30.0)
        add(float(math.ceil(lo)) if math.isfinite(lo) else 1.0, "a whole number as a real", real=True)
    if FULL:
        add(-1, "negative")
        add(1e308, "huge")
        add(1e-308, "subnormal")
        add(float("inf"), "inf")
        add(float("-inf"), "-inf")
        add(-1e308, "huge negative")
        if integer:
            add(2.0 ** 63, "beyond a long")
            add(-0.5, "negative fraction")
        else:
            add(3e-308, "tiny normal")
    return out


def help_options(cmd):
    out = subprocess.run([GW, "help", cmd], capture_output=True, text=True).stdout
    return {m.group(1) for m in re.finditer(r"^  --([a-z0-9-]+)", out, re.M)}


def cli_start(cmd, opts):
    a = [GW, cmd]
    opts = dict(opts)
    if "input" in opts:
        a.append(opts.pop("input"))
    for k, v in opts.items():
        a.append("--" + k)
        if v is not None:
            a.append(v)
    if cmd == "layer-make":
        a += ["--out", os.path.join(TMP, "lm_out.txt")]
    a.append("--json")
    return subprocess.Popen(a, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True), time.time()


def cli_finish(proc, t0):
    """The program's run (started by cli_start, beside the Python call)."""
    try:
        out, err = proc.communicate(timeout=max(TIMEOUT - (time.time() - t0), 0.05))
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        return {"kind": "running"}

    class R:
        pass
    r = R()
    r.returncode, r.stdout, r.stderr = proc.returncode, out, err
    if r.returncode == 2:
        return {"kind": "refused", "msg": r.stderr}
    if r.returncode == 1:
        return {"kind": "runfail", "msg": r.stderr}
    if r.returncode != 0:
        return {"kind": "error", "msg": "exit %d: %s" % (r.returncode, r.stderr[-300:])}
    try:
        js = json.loads(r.stdout)
    except ValueError:
        return {"kind": "error", "msg": "exit 0 without a JSON object on stdout"}
    nums = {}
    for k, v in js.items():
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            nums[k] = float(v)
        elif v is None:
            nums[k] = float("nan")
        elif isinstance(v, list) and v and all(isinstance(x, (int, float)) and not isinstance(x, bool) or x is None
                                               for x in v):
            nums[k] = [float("nan") if x is None else float(x) for x in v]
    return {"kind": "ok", "nums": nums}


def py_run(cmd, opts, types):
    kw = {}
    for k, v in opts.items():
        key = k.replace("-", "_")
        if v is None:  # a flag
            kw[key] = True
        else:
            kw[key] = py_value(v, types.get(k, "double"))
    return WORK.call(cmd.replace("-", "_"), kw), kw


def timing(k):
    return k.endswith("_ms") or k.startswith("wall_time") or k in ("wall_s",)


def same(a, b):
    if isinstance(a, list) and len(a) == 1 and not isinstance(b, list):  # one wall: a scalar in the JSON
        a = a[0]
    if isinstance(b, list) and len(b) == 1 and not isinstance(a, list):
        b = b[0]
    if isinstance(a, list) or isinstance(b, list):
        if not (isinstance(a, list) and isinstance(b, list)) or len(a) != len(b):
            return False
        return all(same(x, y) for x, y in zip(a, b))
    if a != a or b != b:
        return a != a and b != b
    return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b))


def names(text, flag):
    """text names the option: --flag, or flag as a word ("with shear-modulus 1e+15 Pa":
    a rule over the option and the sample)."""
    return re.search(r"(^|[^a-z0-9_-])(--)?%s($|[^a-z0-9_-])" % re.escape(flag), text) is not None


def refusal_ok_cli(res, flag):
    lines = res["msg"].splitlines()
    return len(lines) == 1 and lines[0].startswith("granwave ") and names(lines[0], flag)


def refusal_ok_py(res, key, flag):
    return res.get("etype") in ("ValueError", "TypeError", "GranwaveValueError", "GranwaveUnsupported") and \
        (names(res["msg"], key) or names(res["msg"], flag))


def reason(text, cmd, flag, key):
    """A refusal's reason without the front-end's prefix ("granwave CMD --flag: ",
    "func: keyword: ")."""
    text = text.strip()
    for pre in ("granwave %s --%s: " % (cmd, flag), "granwave %s: " % cmd, "%s: %s: " % (cmd.replace("-", "_"), key),
                "%s: " % cmd.replace("-", "_")):
        if text.startswith(pre):
            return text[len(pre):]
    return text


WORDING = []


def other_option(c, py, names):
    """Both refusals name the same option, one of the study's rows: a rule over two
    options (n with t-samples) refused alike."""
    m = re.match(r"granwave \S+ --([a-z0-9-]+):", c["msg"])
    if not m or m.group(1) not in names or len(c["msg"].splitlines()) != 1:
        return False
    return re.match(r"\w+: %s:" % re.escape(m.group(1).replace("-", "_")), py["msg"]) is not None


ROWS = {}


def rows_of(cmd):
    return ROWS.get(cmd, ())


fails = []
nchecks = 0
ncompared = 0
t_start = time.time()


def check(cmd, p, value, why, types):
    global nchecks, ncompared
    flag, key = p["name"], p["keyword"]
    opts = dict(BASE[cmd])
    for k in DROP_WITH.get((cmd, flag), ()):
        opts.pop(k, None)
    opts.update(CONTEXT.get((cmd, flag), {}))
    opts[flag] = text_of(value) if not isinstance(value, str) else value
    proc, t0 = cli_start(cmd, opts)  # the program and Python at once
    py, kw = py_run(cmd, opts, types)
    t1 = time.time()
    c = cli_finish(proc, t0)
    t2 = time.time()
    global TIMEOUT
    if {c["kind"], py["kind"]} == {"running", "refused"}:  # a refusal after some work: the other side to its end
        short, TIMEOUT = TIMEOUT, LONG_TIMEOUT
        try:
            if c["kind"] == "running":
                c = cli_finish(*cli_start(cmd, opts))
            else:
                py, kw = py_run(cmd, opts, types)
        finally:
            TIMEOUT = short
    nchecks += 1
    label = "%s --%s %s (%s)" % (cmd, flag, opts[flag], why)
    problems = []
    accepted = ("ok", "runfail", "running")
    if c["kind"] == "error":
        problems.append("program: " + c["msg"].strip())
    if py["kind"] == "error":
        problems.append("python: %s %s" % (py.get("etype"), py["msg"]))
    if not problems:
        if c["kind"] == "refused" and py["kind"] in accepted:
            problems.append("the program refuses (%s) where Python %s" % (
                c["msg"].strip(), "runs" if py["kind"] != "runfail" else "runs and fails: " + py["msg"]))
        elif py["kind"] == "refused" and c["kind"] in accepted:
            problems.append("Python refuses (%s: %s) where the program %s" % (
                py["etype"], py["msg"], "runs" if c["kind"] != "runfail" else "runs and fails"))
        elif c["kind"] == "refused" and other_option(c, py, rows_of(cmd)):
            pass  # both refuse by the same rule over another option (t-samples x n)
        elif c["kind"] == "refused":
            if not refusal_ok_cli(c, flag):
                problems.append("the program's refusal is not one line naming --%s: %r" % (flag, c["msg"]))
            if not refusal_ok_py(py, key, flag):
                problems.append("Python's refusal does not name %s: %s: %s" % (key, py.get("etype"), py["msg"]))
            a, b = reason(c["msg"], cmd, flag, key), reason(py["msg"], cmd, flag, key)
            if a != b.replace(key, flag) and a.replace(flag, key) != b:
                WORDING.append("%s: program '%s', python '%s'" % (label, a, b))
        elif {c["kind"], py["kind"]} == {"ok", "runfail"}:
            problems.append("the program %s, Python %s" % (c["kind"], py["kind"]))
        elif c["kind"] == "ok" and py["kind"] == "ok":
            common = [k for k in c["nums"] if k in py["nums"] and not timing(k)]
            ncompared += 1
            if not common:
                problems.append("no result of the same name in both to compare")
            diff = [k for k in common if not same(c["nums"][k], py["nums"][k])]
            if diff:
                k = diff[0]
                problems.append("results differ in %d of %d (%s; %s: program %s, python %s)" % (
                    len(diff), len(common), ", ".join(diff), k, str(c["nums"][k])[:60], str(py["nums"][k])[:60]))
    # the C caller: by default where Python refuses (a struct that runs there is
    # a finding, found within TIMEOUT); --full: every value
    if not problems and (not isinstance(value, str) or p["type"] in ("choice", "text")) and \
            (FULL or py["kind"] == "refused"):
        problems += c_check(cmd, p, kw, py)
    if problems:
        fails.append((label, problems))
        print("FAIL %s\n     %s" % (label, "\n     ".join(problems)), flush=True)
    elif VERBOSE:
        print("ok   %-60s program %-8s %5.2f s python %-8s %5.2f s" % (label, c["kind"], t2 - t0, py["kind"], t1 - t0),
              flush=True)


NC = [0]


def c_check(cmd, p, kw, py):
    """The third front-end: a C caller that writes the value into the setup's
    field and runs the study (the library's gw_param_check), against Python's
    verdict (gw_param_set on the text)."""
    key = p["keyword"]
    v = kw[key]
    if isinstance(v, float) and v != v and p["default"] is None and p["type"] == "double":
        return []  # NaN in a field is "not given" to the library (gw_param.h), the text "nan" is refused
    c = WORK.call(cmd.replace("-", "_"), dict(kw), c_key=key)
    if c["kind"] == "na":
        return []
    NC[0] += 1
    if {c["kind"], py["kind"]} == {"running", "refused"}:
        global TIMEOUT
        short, TIMEOUT = TIMEOUT, LONG_TIMEOUT
        try:
            if c["kind"] == "running":
                c = WORK.call(cmd.replace("-", "_"), dict(kw), c_key=key)
            else:
                py = WORK.call(cmd.replace("-", "_"), dict(kw))
        finally:
            TIMEOUT = short
    accepted = ("ok", "runfail", "running")
    if c["kind"] == "error":
        return ["C caller: %s %s" % (c.get("etype"), c["msg"])]
    if c["kind"] == "refused" and py["kind"] in accepted:
        return ["a C caller's struct is refused (%s) where Python's keyword runs" % c["msg"]]
    if py["kind"] == "refused" and c["kind"] in accepted:
        return ["a C caller's struct runs (%s) where Python refuses (%s)" % (c["kind"], py["msg"])]
    # the same text, Python's naming its inputs by their keywords where the
    # library's (the C caller's) names the program's flags ("raise skin" for
    # "raise --skin": python/granwave/_core.py, keyword_text)
    def plain(t):
        return re.sub(r"(?<![\w./-])--([a-z])", r"\1", t).replace("_", "-")
    same_refusal = c["kind"] == "refused" and plain(reason(py["msg"], cmd, p["name"], key)) == plain(c["msg"])
    if c["kind"] == "refused" and not (names(c["msg"], p["name"]) or names(c["msg"], key) or same_refusal):
        return ["the C caller's refusal does not name %s: %s" % (p["name"], c["msg"])]
    if {c["kind"], py["kind"]} == {"ok", "runfail"}:
        return ["the C caller %s, Python %s" % (c["kind"], py["kind"])]
    if c["kind"] == "ok" and py["kind"] == "ok":
        common = [k for k in c["nums"] if k in py["nums"] and not timing(k)]
        diff = [k for k in common if not same(c["nums"][k], py["nums"][k])]
        if diff:
            return ["C caller and Python differ in %s" % ", ".join(diff)]
    return []


def make_fixtures():
    subprocess.run([GW, "layer-make", "--n", "40", "--width-rm", "14", "--seed", "2", "--ke-threshold", "1e-2",
                    "--solver", "verlet", "--out", SAMPLE], check=True, capture_output=True)
    synthetic_tables.write_bouncing_diagram(TABLE)  # a diagram with a boundary (synthetic_tables.py)
    synthetic_tables.write_no_diagram(NODIA)


# the studies share rows (the column's material ... guide-viscous in chain,
# falcon, wavespeed, softwall and drop; the layer's material in layer-make and
# layer-impact): by default a row is tried in the first study that has it with
# the same type, range, default and choices (--full: in every study)
SEEN = set()


def signature(p):
    return (p["name"], p["type"], repr(p["min"]), repr(p["max"]), p["default"], repr(p["choices"]))


def tables():
    """{study: [row dicts]} of the library's index, read through the module."""
    q = subprocess.run([sys.executable, "-c",
                        "import json, granwave\n"
                        "print(json.dumps({s: granwave.params(s) for s in %r}))" % list(BASE)],
                       capture_output=True, text=True, env=ENV, check=True)
    return json.loads(q.stdout.replace("-Infinity", "-1e999").replace("Infinity", "1e999").replace("NaN", "null"))


def main():
    make_fixtures()
    t = tables()
    missing = []
    for cmd, rows in t.items():
        if ONLY and cmd != ONLY:
            continue
        flags = help_options(cmd)
        CURRENT[0] = cmd
        for p in rows:
            p["type"] = TYPES.get(p["type"], p["type"])
        types = {p["name"]: p["type"] for p in rows}
        ROWS[cmd] = set(types)
        for p in rows:
            if not FULL and signature(p) in SEEN:
                continue  # a row as an earlier study's: tried there (--full: here too)
            SEEN.add(signature(p))
            if p["name"] not in flags:
                missing.append("%s: keyword %s has no option --%s" % (cmd, p["keyword"], p["name"]))
                continue
            if p["type"] == "text" and p.get("optional") and p["default"]:
                # the default's text given: told from none alike (gw_param.optional)
                check(cmd, p, p["default"], "the default's text, given", types)
            if p["type"] in ("text", "flag"):
                continue
            if p["min"] is None:
                p["min"] = float("nan")
            if p["max"] is None:
                p["max"] = float("nan")
            if p["type"] == "choice":
                vals = [(c, "choice") for c in p["choices"]] + [("bogus", "unknown name")]
                if not FULL:
                    vals = vals[-2:]
            else:
                vals = values(p)
            for v, why in vals:
                check(cmd, p, v, why, types)
        for f in sorted(flags - PROGRAM_ONLY - set(types)):
            missing.append("%s: option --%s has no keyword" % (cmd, f))
    WORK.stop()
    for m in missing:
        print("note: " + m)
    for w in WORDING if VERBOSE else ():
        print("wording: " + w)
    print("%d refusals alike in both but worded differently (--verbose lists them)" % len(WORDING))
    print("%d checks (%d with results compared; %d also as a C caller), %d fail, %.0f s" % (
        nchecks, ncompared, NC[0], len(fails), time.time() - t_start))
    shutil.rmtree(TMP, ignore_errors=True)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
