"""One source for each warning (issue 18, the seventeenth hostile pass).

Every study's warning text was written twice: in the program (app/, on stderr
as "granwave CMD: warning: TEXT") and, copied, in python/granwave/__init__.py
(only layer_impact's came from the library). The copies had drifted (the
program said "raise --t-max", Python "raise t_max"; drop's "null" against
"NaN"), and a C caller of the library got no text at all. The library now
builds each text once (chain/chain_warnings.c, layer/layer_warnings.c,
common/stats/gw_stats_run.c) and gives it with the result (the outcomes'
`warnings`, gw_study_warnings); the program prints those texts and Python
issues them with its inputs named by their keywords (t_max where the program
says --t-max: _core.keyword_text, the nineteenth session of stage 2).

For each study that can warn, a run that does: the texts of the program's
stderr and of a C caller of the library (tests/gw_warnings_probe.c,
gw_study_warnings) are the same, one by one, and Python's GranwaveWarning
(and the result's `warnings` list) is that text with each input of the study
named by its keyword. A run that does not warn gives no warning anywhere. No
warning prose is left in the Python module: no call to issue a warning outside
_core.Study.run, and no run of five words of any warning text in its strings.
"""
import ast
import os
import re
import subprocess
import warnings
from pathlib import Path

import pytest

import granwave

REPO = Path(__file__).resolve().parents[2]
PROGRAM = os.environ.get("GRANWAVE_PROGRAM") or str(REPO / "build" / "granwave")
# built beside the program (tests/CMakeLists.txt: gw_warnings_probe)
PROBE = os.environ.get("GW_WARNINGS_PROBE") or str(Path(PROGRAM).parent / "tests" / "gw_warnings_probe")
TABLE = REPO / "data" / "measured" / "rebound_tf" / "sizes" / "results.csv"
PACKAGE = REPO / "python" / "granwave"

pytestmark = pytest.mark.skipif(not Path(PROGRAM).exists(), reason=f"no granwave program at {PROGRAM}")


def _table(path):
    """TABLE with one undecided point (bounced nan) and one bouncing point whose
    run ended before T_f (e_n, e, alpha_r nan): both layer-stats warnings."""
    lines = TABLE.read_text().splitlines(True)
    body = [ln for ln in lines if not ln.startswith("#")]
    hdr = body[0].rstrip("\n").split(",")
    rows = [ln.rstrip("\n").split(",") for ln in body[1:]]
    b = hdr.index("bounced")
    und = next(i for i, r in enumerate(rows) if r[b] in ("0", "1"))
    for c in ("bounced", "e_n", "e", "alpha_r", "v_nr", "v_r", "e_n_first", "e_first", "alpha_r_first"):
        rows[und][hdr.index(c)] = "nan"
    cut = next(i for i, r in enumerate(rows) if r[b] == "1" and i != und)
    for c in ("e_n", "e", "alpha_r", "v_nr", "v_r"):
        rows[cut][hdr.index(c)] = "nan"
    for i in (und, cut):
        lines[lines.index(body[1 + i])] = ",".join(rows[i]) + "\n"
    Path(path).write_text("".join(lines))


# study, its inputs as {flag: value} (the program's --flag, the probe's NAME=,
# Python's keyword with '-' as '_'), the warnings expected
WARNING_CASES = [
    ("chain", {"n": "7", "t-max": "1.94e-4"}, 1),  # the wall done, the column's contacts busy
    ("chain", {"n": "3", "sensor-mass": "1", "sensor-stiffness": "1e3", "t-max": "2.2e-3"}, 1),  # the sensor still rising
    ("falcon", {"n": "6:7", "vimp": "0.3", "heights": "none", "t-max": "1.94e-4"}, 1),
    ("wavespeed", {"vimp": "0.3,0.5", "n": "8:10", "t-max": "2.8e-4"}, 1),  # columns to 10 beads: the period measured
    ("softwall", {"n": "1:3", "sensor-mass": "1", "sensor-stiffness": "1e3", "t-max": "1e-3"}, 1),
    ("dispersion", {"n": "64", "f0": "1e-300"}, 1),
    ("drop", {"n": "10", "t-max": "2.2e-4"}, 1),  # cut inside the first collision, bead 1 on the sensor
    ("drop", {"n": "10", "t-max": "2.8e-4"}, 1),  # the first collision cut, bead 1 off the sensor
    ("drop", {"n": "3", "t-max": "0.03303"}, 1),  # bead 1 back on the sensor at t_max
    ("layer-make", {"n": "60", "width-rm": "16", "seed": "3", "t-max": "0.05", "out": "m1.txt"}, 1),  # < t_judge
    ("layer-make", {"n": "60", "width-rm": "16", "seed": "3", "t-max": "0.3", "out": "m2.txt"}, 1),  # E_k high
    ("layer-make", {"n": "60", "width-rm": "16", "seed": "3", "t-max": "0.05", "out": "m\nx.txt"}, 1),
    ("layer-impact", {"sample": "s.txt", "t-max": "0.005"}, 1),
    # the default impact: wave_speed_xcorr 17.55 +- 13.3 m/s nulled by its scatter
    # (standard error above half the speed), a warning since session 46
    ("layer-impact", {"sample": "s.txt"}, 1),
    ("layer-stats", {"input": "t.csv"}, 2),
]

QUIET = {"falcon", "wavespeed", "softwall"}  # their progress lines on a terminal; --quiet as a habit


def _program(study, flags):
    args = [PROGRAM, study]
    for k, v in flags.items():
        args += [v] if k == "input" else [f"--{k}", v]
    args += ["--quiet"] if study in QUIET else []
    p = subprocess.run(args, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    lines = p.stderr.splitlines()
    prefix = f"granwave {study}: warning: "
    assert all(ln.startswith(prefix) for ln in lines if "warning" in ln), p.stderr
    return [ln[len(prefix):] for ln in lines if ln.startswith(prefix)]


def _python(study, flags):
    kw = {}
    for k, v in flags.items():
        key = k.replace("-", "_")
        if key == "n" and ":" in v:
            a, b = v.split(":")
            kw[key] = (int(a), int(b))
        elif key in ("vimp", "heights") and study != "chain":
            kw[key] = [] if v == "none" else [float(x) for x in v.split(",")]
        elif key in ("sample", "out", "input"):
            kw[key] = v
        else:
            kw[key] = float(v) if any(c in v for c in ".e") else int(v)
    fn = getattr(granwave, study.replace("-", "_"))
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = fn(**kw)
    got = [x for x in w if issubclass(x.category, granwave.GranwaveWarning)]
    what = fn.__name__ + ": "
    assert all(str(x.message).startswith(what) for x in got), [str(x.message) for x in got]
    assert all(x.filename == __file__ for x in got)  # shown at the caller's line
    texts = [str(x.message)[len(what):] for x in got]
    assert r.warnings == texts  # the result lists what was issued
    return texts


_C_TEXTS = {}  # (study, flags): the texts a C caller got, for the prose check


def _c_caller(study, flags):
    key = (study, tuple(flags.items()))
    if key not in _C_TEXTS:
        assert Path(PROBE).exists(), f"the C caller {PROBE} is not built (tests/CMakeLists.txt: gw_warnings_probe)"
        p = subprocess.run([PROBE, study] + [f"{k}={v}" for k, v in flags.items()], capture_output=True,
                           text=True, timeout=300)
        assert p.returncode == 0, p.stderr
        _C_TEXTS[key] = p.stdout.split("\n")[:-1] if p.stdout else []
    return _C_TEXTS[key]


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    d = tmp_path_factory.mktemp("warn")
    here = os.getcwd()
    os.chdir(d)
    subprocess.run([PROGRAM, "layer-make", "--n", "60", "--width-rm", "16", "--seed", "3", "--out", "s.txt"],
                   check=True, capture_output=True)
    _table(d / "t.csv")
    # a name with a newline is refused where the run would make it (session 42);
    # one the user made is written to, and named on one line
    (d / "m\nx.txt").write_text("")
    yield d
    os.chdir(here)


def _in_python(study, text):
    """The program's text as Python words it: each input of the study named by
    its keyword, as a flag ("raise --t-max": "raise t_max") or by its row's
    name ("t-max = 0.05 s": "t_max = 0.05 s"); a quoted command line of the
    program and a flag the function does not take stay."""
    names = {p["name"] for p in granwave.params(study)}
    keep = re.findall(r"granwave [a-z-]+(?: --[a-z0-9-]+(?: [^\s,;()]+)?)+", text)
    for i, k in enumerate(keep):
        text = text.replace(k, f"\0{i}\0")
    for n in sorted(names, key=len, reverse=True):
        text = re.sub(r"(?<![\w./-])(--)?" + re.escape(n) + r"(?![\w/-]|\.\w)", n.replace("-", "_"), text)
    for i, k in enumerate(keep):
        text = text.replace(f"\0{i}\0", k)
    return text


@pytest.mark.parametrize("study, flags, count", WARNING_CASES,
                         ids=[f"{s}-{i}" for i, (s, _, _) in enumerate(WARNING_CASES)])
def test_one_text_in_every_caller(workdir, study, flags, count):
    # one text, worded for each caller: the program's flags (--t-max) for the
    # program and a C caller, Python's keywords (t_max) in Python
    prog = _program(study, flags)
    assert len(prog) == count, prog
    py = _python(study, flags)
    assert py == [_in_python(study, t) for t in prog]
    names = {p["name"] for p in granwave.params(study)}
    assert not [t for t in py for n in names if "--" + n in t or ("-" in n and n in t)], py
    assert _c_caller(study, flags) == prog


def test_a_file_name_with_a_newline_stays_one_line(workdir):
    # the layer-make text names the file written: a newline in its name split the
    # program's warning over two lines; the library's text is one line (as its
    # error messages: \n written out), the same for every caller
    flags = {"n": "60", "width-rm": "16", "seed": "3", "t-max": "0.05", "out": "m\nx.txt"}
    (text,) = _program("layer-make", flags)
    assert text.endswith("; written to m\\nx.txt with 'converged 0'"), text


def test_without_out_no_file_is_named(workdir):
    # Python and a C caller may pluviate without writing the sample (the program
    # always writes it): the same text, without "written to"
    flags = {"n": "60", "width-rm": "16", "seed": "3", "t-max": "0.05"}
    (text,) = _python("layer-make", flags)
    assert [_in_python("layer-make", t) for t in _c_caller("layer-make", flags)] == [text]
    assert text.startswith("the sample did not settle: t_max = 0.05 s ends before the settling is judged")
    assert "written to" not in text


QUIET_CASES = [
    ("chain", {"n": "7"}),
    ("falcon", {"n": "6:7", "vimp": "0.3", "heights": "none"}),
    ("wavespeed", {"vimp": "0.3,0.5", "n": "8:10"}),  # under 10 beads the period is not measured, said
    ("softwall", {"n": "1:3"}),
    ("dispersion", {"n": "64"}),
    ("dispersion", {"column-n": "5"}),
    ("drop", {"n": "3", "t-max": "3e-3"}),
    ("layer-make", {"n": "20", "width-rm": "8", "seed": "3", "out": "q.txt"}),  # settles in 0.3 s
    ("layer-stats", {"input": str(TABLE)}),
]


@pytest.mark.parametrize("study, flags", QUIET_CASES, ids=[f"{s}-{i}" for i, (s, _) in enumerate(QUIET_CASES)])
def test_a_final_result_warns_nowhere(workdir, study, flags):
    assert _program(study, flags) == []
    assert _python(study, flags) == []
    assert _c_caller(study, flags) == []


def _strings(tree):
    """Every string literal of a module (an f-string's fixed parts joined by a blank)."""
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            yield node.value
        elif isinstance(node, ast.JoinedStr):
            yield " ".join(v.value for v in node.values if isinstance(v, ast.Constant))


def _words(text):
    return [w for w in re.split(r"[\s(),;:]+", text) if w and not re.search(r"\d", w)]


class _WarnCalls(ast.NodeVisitor):
    """The functions that call warn() or _warn() (warnings.warn included), but for
    a DeprecationWarning (the layer_stats columns' names before: Python's own)."""

    def __init__(self, name):
        self.name, self.where, self.calls = name, [], []

    def visit_FunctionDef(self, node):
        self.where.append(node.name)
        self.generic_visit(node)
        self.where.pop()

    def visit_Call(self, node):
        f = node.func
        if (getattr(f, "id", None) or getattr(f, "attr", None)) in ("warn", "_warn") and \
                "DeprecationWarning" not in ast.unparse(node):
            self.calls.append(f"{self.name}:{self.where[-1] if self.where else '<module>'}")
        self.generic_visit(node)


def test_no_warning_prose_in_the_python_module(workdir):
    # (1) warnings are issued in one place: _core.issue, with the library's texts
    # (a study's result from Study.run, a sweep's lines from run_sweep)
    calls = []
    for f in sorted(PACKAGE.glob("*.py")):
        v = _WarnCalls(f.name)
        v.visit(ast.parse(f.read_text()))
        calls += v.calls
    assert sorted(calls) == ["_core.py:issue", "_core.py:warn"], calls
    # (2) no run of five words of any text the library gave in the cases above
    texts = []
    for study, flags, _ in WARNING_CASES:
        texts += _c_caller(study, flags)
    shingles = set()
    for t in texts:
        w = _words(t)
        shingles |= {" ".join(w[i:i + 5]) for i in range(len(w) - 4)}
    assert len(shingles) > 100  # the texts were read
    found = []
    for f in sorted(PACKAGE.glob("*.py")):
        for s in _strings(ast.parse(f.read_text())):
            w = " ".join(_words(s))
            found += [(f.name, sh) for sh in shingles if sh in w]
    assert not found, found[:10]
