"""The layer's checks from Python (session 46): granwave.layer_impact_check
(gw_layer_impact_setup_check: the sample's form and limits of
gw_layer_impact_check, the side walls under the run's material of
gw_layer_impact_check_with, the rest, settled, gap and step checks),
granwave.layer_make_check (gw_layer_make_plan) and granwave.sweep_case_check
(the sweep's check pass over one case, gw_sweep_case_check_pass). Before, Python bound none of them: a
caller learnt of a refusal only by running.

Each refusal is compared three ways on the same inputs: the check raises what
the run raises (the same class, the same text), and that text is the
program's refusal (exit 2, one line "granwave CMD --FLAG: MSG" or "granwave
CMD: MSG"), the library's MSG byte for byte with the inputs named by their
keywords (keyword_text: the program's --t-max is Python's t_max). An input
that passes returns None, runs nothing and writes nothing. Last, the rows a
setup's _init leaves "not given" are those docs/library.md's table states,
with the values they hold (layer-impact's rtol and atol NaN, side_walls -1).
"""
import inspect
import math
import subprocess
from pathlib import Path

import pytest

import granwave
from granwave import _core

REPO = Path(__file__).resolve().parents[2]
SAMPLE = str(REPO / "data" / "measured" / "restitution_full" / "sample.txt")


def _flags(kwargs):
    args = []
    for k, v in kwargs.items():
        if v is True:
            args.append("--" + k.replace("_", "-"))
        else:
            args += ["--" + k.replace("_", "-"), str(v)]
    return args


def _program_message(program, cmd, args):
    """The library's message of the program's refusal: exit 2, one line on
    stderr, nothing on stdout."""
    r = subprocess.run([program, cmd, *args], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2, (r.returncode, r.stderr)
    assert r.stdout == "" and r.stderr.count("\n") == 1, r.stderr
    line = r.stderr[:-1]
    head = "granwave " + cmd
    assert line.startswith(head), line
    rest = line[len(head):]
    if rest.startswith(" --"):  # "granwave CMD --NAME: reason": the library's "NAME: reason"
        return rest[3:]
    assert rest.startswith(": "), line
    return rest[2:]


def _expected(study, msg, kwargs):
    st = granwave._study(study)
    return f"{st.func}: {_core.keyword_text(msg, st.names, _core._texts(kwargs.values()))}"


def _raised(f, **kwargs):
    with pytest.raises(granwave.GranwaveError) as e:
        f(**kwargs)
    return e.value


@pytest.fixture(scope="module")
def row(tmp_path_factory):
    """5 discs in a row on the floor pressed between the walls with twice the
    row's weight (test_layer_side_walls.sh, 7): run with both walls, refused
    with side_walls left (the right wall pushes it with 2 of its weight)."""
    G, nu, rho, g, r, n = 40e9, 0.25, 2650.0, 9.81, 0.1, 5
    kn, mg = 2 * math.sqrt(2 * r) * G / (3 * (1 - nu)), rho * math.pi * r * r * g
    uf, uw = (mg / kn) ** (2 / 3), (2 * n * mg / kn) ** (2 / 3)
    x = [r - uw + i * (2 * r - uw) for i in range(n)]
    path = tmp_path_factory.mktemp("checks") / "row.txt"
    with open(path, "w") as f:
        f.write("granwave-layer-sample 1\n# units: metres; lines after 'n' are: x y r\n")
        f.write(f"width {x[-1] + r - uw!r}\nrm {r!r}\nvolume_ratio 1\nseed 0\nmass_law disc\nn {n}\n")
        for xi in x:
            f.write(f"{xi!r} {r - uf!r} {r!r}\n")
    return str(path)


@pytest.fixture(scope="module")
def overlapping(tmp_path_factory):
    """Two discs at one place: the sample's form check (the reader) refuses it."""
    path = tmp_path_factory.mktemp("checks") / "twice.txt"
    path.write_text("granwave-layer-sample 1\nwidth 2\nrm 0.1\nvolume_ratio 1\nseed 0\nmass_law disc\nn 2\n"
                    "0.5 0.1 0.1\n0.5 0.1 0.1\n")
    return str(path)


IMPACT_REFUSALS = [
    {"gap": 1},                                  # the fall changes the normal speed by 2.4 %
    {"vi": 0.001},                               # too slow for the default gap
    {"alpha": 60, "gap": 0.5},                   # the fall at an incidence
    {"t_max": 1e-9},                             # ends before the block reaches the layer
    {"rtol": 1e-6},                              # no effect under verlet
    {"solver": "cvode", "dt": 1e-6},             # no effect under cvode
    {"density": 100},                            # the pile not at rest under this material
    {"mass_law": "sphere"},                      # nor under this mass law
    {"clump_mass": "union"},                     # no clumps in the sample
    {"side_walls": "left", "remove_walls": True},
    {"x": 1e3},                                  # the block outside the box
    {"rb_rm": 1e3},                              # wider than the box
    {"gravity": 1e300},                          # the row's range
]


@pytest.mark.parametrize("kwargs", IMPACT_REFUSALS, ids=lambda k: ",".join(k))
def test_layer_impact_check_refuses_as_the_run_and_the_program(program, kwargs):
    kw = dict(sample=SAMPLE, **kwargs)
    checked = _raised(granwave.layer_impact_check, **kw)
    ran = _raised(granwave.layer_impact, **kw)
    assert type(checked) is type(ran) and checked.status == ran.status
    assert str(checked) == str(ran)
    assert str(checked) == _expected("layer-impact", _program_message(program, "layer-impact", _flags(kw)), kw)


def test_layer_impact_check_with_the_runs_material(program, row):
    # gw_layer_impact_check_with's side-walls rule, under the setup's material:
    # both walls pass, the right wall taken away is refused naming its push
    assert granwave.layer_impact_check(sample=row) is None
    kw = {"sample": row, "side_walls": "left"}
    checked = _raised(granwave.layer_impact_check, **kw)
    assert isinstance(checked, granwave.GranwaveValueError)
    assert str(checked).startswith("layer_impact: side_walls: left: the sample's pile leans on its right wall "
                                   "(at t = 0 it pushes the pile with 2 of its weight"), str(checked)
    assert str(checked) == str(_raised(granwave.layer_impact, **kw))
    assert str(checked) == _expected("layer-impact", _program_message(program, "layer-impact", _flags(kw)), kw)


def test_layer_impact_check_sample_form_and_file(program, overlapping, tmp_path):
    # the sample's form (gw_layer_impact_check's, the reader's): two discs at one place
    kw = {"sample": overlapping}
    checked = _raised(granwave.layer_impact_check, **kw)
    assert isinstance(checked, granwave.GranwaveValueError) and checked.status == _core.GW_EFORMAT
    assert str(checked) == str(_raised(granwave.layer_impact, **kw))
    assert str(checked) == _expected("layer-impact", _program_message(program, "layer-impact", _flags(kw)), kw)
    # a file that is not there: an OSError naming it
    kw = {"sample": str(tmp_path / "none.txt")}
    checked = _raised(granwave.layer_impact_check, **kw)
    assert isinstance(checked, granwave.GranwaveIOError) and str(tmp_path / "none.txt") in str(checked)
    assert str(checked) == str(_raised(granwave.layer_impact, **kw))
    assert str(checked) == _expected("layer-impact", _program_message(program, "layer-impact", _flags(kw)), kw)


# the single run's refusals of two flags of no effect on the sample (session
# 48: layer_impact_check passed them, gw_layer_impact_setup_check had them
# not, and layer_impact and the program refused them)
IDLE_FLAGS = [
    ("restitution", {"other_settling": True}),  # no settings line to compare with
    ("restitution", {"zero_springs": True}),    # no springs
    ("made", {"other_settling": True}),         # settled under the impact's own material
]


@pytest.mark.parametrize("which,flags", IDLE_FLAGS, ids=lambda x: x if isinstance(x, str) else ",".join(x))
def test_layer_impact_check_single_run_flags(program, sample, which, flags):
    kw = dict(sample=SAMPLE if which == "restitution" else str(sample), t_max=1e-5, **flags)
    checked = _raised(granwave.layer_impact_check, **kw)
    assert isinstance(checked, granwave.GranwaveValueError) and "has no effect" in str(checked)
    ran = _raised(granwave.layer_impact, **kw)
    assert type(ran) is type(checked) and str(ran) == str(checked)
    assert str(checked) == _expected("layer-impact", _program_message(program, "layer-impact", _flags(kw)), kw)
    # a sweep's case keeps them (a grid's key acts on its other samples)
    assert granwave.sweep_case_check("layer", **kw) is None


def test_layer_impact_check_single_run_flags_acting(sample):
    # where the flags act, the check passes: the made pile carries springs,
    # and under another shear modulus its recorded settling differs
    assert granwave.layer_impact_check(sample=str(sample), zero_springs=True) is None
    assert granwave.layer_impact_check(sample=str(sample), other_settling=True, shear_modulus=4e9) is None


def _run_warning(**kw):
    """The settling warning layer_impact's result lists (None: none)."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = granwave.layer_impact(t_max=1e-4, **kw)
    said = [w for w in r["warnings"] if w.startswith("the sample settled") or "not settled" in w]
    return said[0] if said else None


def test_layer_impact_settling(sample):
    # session 48: the settling verdict the run takes (gw_layer_impact_settled_check's
    # load ratio and warning), bound without a run; q = [G/(1 - nu)]_impact /
    # [G/(1 - nu)]_settled x W_settled / W_impact (gw_layer.h), the made pile
    # settled at G = 40 GPa, rho = 2650 kg/m^3
    made = str(sample)
    cases = [({}, 1.0), ({"shear_modulus": 3e10}, 0.75), ({"density": 2120}, 2650 / 2120),
             ({"shear_modulus": 4e9, "other_settling": True}, 0.1)]
    for kw, q in cases:
        got = granwave.layer_impact_settling(sample=made, **kw)
        assert got["load_ratio"] == pytest.approx(q, rel=1e-12), (kw, got)
        assert got["warning"] == _run_warning(sample=made, **kw), (kw, got)
        assert (got["warning"] is None) == (not kw)
    # nothing recorded: NaN, no warning
    got = granwave.layer_impact_settling(sample=SAMPLE)
    assert math.isnan(got["load_ratio"]) and got["warning"] is None
    # the refusals are layer_impact_check's (a pile far from rest, a flag of no effect)
    for kw in ({"shear_modulus": 4e9}, {"other_settling": True}):
        checked = _raised(granwave.layer_impact_check, sample=made, **kw)
        got = _raised(granwave.layer_impact_settling, sample=made, **kw)
        assert type(got) is type(checked) and str(got) == str(checked)


def test_layer_impact_check_passes_and_keywords():
    assert granwave.layer_impact_check(sample=SAMPLE) is None
    assert granwave.layer_impact_check(sample=SAMPLE, solver="cvode", rtol=1e-6) is None
    with pytest.raises(TypeError, match="unexpected keyword argument 'vimp'"):
        granwave.layer_impact_check(sample=SAMPLE, vimp=1)
    with pytest.raises(granwave.GranwaveValueError, match=r"^layer_impact: vi: -1 is outside"):
        granwave.layer_impact_check(sample=SAMPLE, vi=-1)
    # the same keywords as layer_impact (but progress)
    run = [p for p in inspect.signature(granwave.layer_impact).parameters if p != "progress"]
    assert list(inspect.signature(granwave.layer_impact_check).parameters) == run
    assert {"layer_impact_check", "layer_make_check", "sweep_case_check", "layer_impact_settling",
            "sweep_check"} <= set(granwave.__all__)


MAKE_REFUSALS = [
    {"gravity": 0},
    {"aspect_max": 2},
    {"clump_mass": "sum"},
    {"clumps": True, "aspect_max": 1, "clump_mass": "union"},
    {"n": 0},
    {"modulus_factor": 1e-12},
]


@pytest.mark.parametrize("kwargs", MAKE_REFUSALS, ids=lambda k: ",".join(k))
def test_layer_make_check_refuses_as_the_run_and_the_program(program, tmp_path, kwargs):
    out = tmp_path / "m.txt"
    kw = dict(out=str(out), **kwargs)
    checked = _raised(granwave.layer_make_check, **kw)
    ran = _raised(granwave.layer_make, **kw)
    assert type(checked) is type(ran) and str(checked) == str(ran)
    assert str(checked) == _expected("layer-make", _program_message(program, "layer-make", _flags(kw)), kw)
    assert not out.exists()


def test_layer_make_check_out(program, tmp_path):
    for out in (tmp_path / "no" / "a.txt", tmp_path):  # a missing directory, a directory
        kw = {"out": str(out), "n": 60}
        checked = _raised(granwave.layer_make_check, **kw)
        assert isinstance(checked, granwave.GranwaveValueError)
        assert str(checked) == str(_raised(granwave.layer_make, **kw))
        assert str(checked) == _expected("layer-make", _program_message(program, "layer-make", _flags(kw)), kw)
    # a run that would start: None, and nothing pluviated or written
    out = tmp_path / "a.txt"
    assert granwave.layer_make_check(n=60, width_rm=16, out=str(out)) is None
    assert not out.exists() and granwave.layer_make_check() is None


SWEEP_REFUSALS = [
    {"point": 5, "points": 2},
    {"vi": 0.001},
    {"gap": 1},
    {"rtol": 1e-6},
]


@pytest.mark.parametrize("kwargs", SWEEP_REFUSALS, ids=lambda k: ",".join(k))
def test_sweep_case_check_refuses_as_the_sweep_and_the_program(program, tmp_path, kwargs):
    kw = dict(sample=SAMPLE, **kwargs)
    checked = _raised(granwave.sweep_case_check, model="layer", **kw)
    assert isinstance(checked, granwave.GranwaveValueError)
    grid = {"vi": [kw.pop("vi", 20)]}
    ran = _raised(granwave.sweep, model="layer", grid=grid, **kw)
    assert type(ran) is type(checked) and str(ran) == str(checked)  # a one-case sweep's text (session 48)
    cfg = tmp_path / "c.ini"
    cfg.write_text("[sweep]\nmodel = layer\nout = " + str(tmp_path / "o") + "\n[grid]\n"
                   f"vi = {grid['vi'][0]}\n[params]\n" + "".join(f"{k.replace('_', '-')} = {v}\n"
                                                               for k, v in kw.items()))
    r = subprocess.run([program, "sweep", str(cfg), "--check"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    prefix = f"granwave sweep: {cfg}: case 0: "
    assert r.stderr.startswith(prefix), r.stderr
    msg = r.stderr[len(prefix):-1]
    names = granwave._sweep._sweep_names("layer", granwave._sweep.sweep_models()["layer"])
    assert str(checked) == "sweep: case 0: " + _core.keyword_text(msg, names, _core._texts(kw.values()))
    assert not (tmp_path / "o").exists()


def test_sweep_case_check_passes_and_keywords():
    assert granwave.sweep_case_check("layer", sample=SAMPLE, vi=20, point=1, points=2) is None
    assert granwave.sweep_case_check("chain", n=3, vimp=0.3) is None
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep: case 0: vimp: 0 is outside"):
        granwave.sweep_case_check("chain", n=3, vimp=0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'vimp' .not a parameter of model layer"):
        granwave.sweep_case_check("layer", sample=SAMPLE, vimp=1)
    with pytest.raises(granwave.GranwaveValueError, match="unknown model 'lay'"):
        granwave.sweep_case_check("lay", sample=SAMPLE)


# ---- docs/library.md's "Not given after _init" table against the setups ----

_SETUPS = {"chain": "gw_chain_setup", "falcon": "gw_chain_falcon_setup", "wavespeed": "gw_chain_wavespeed_setup",
           "softwall": "gw_chain_softwall_setup", "dispersion": "gw_chain_dispersion_setup",
           "drop": "gw_chain_drop_setup", "layer-impact": "gw_layer_impact_setup",
           "layer-make": "gw_layer_make_setup", "layer-stats": "gw_stats_setup"}
_COLUMN = {"chain", "falcon", "wavespeed", "softwall", "drop"}  # their column rows: gw_chain_setup's
_LONG_MIN = -(2 ** 63)


def _not_given_doc():
    """{setup struct: {field: the value the page states}} from the table."""
    import re
    text = (REPO / "docs" / "library.md").read_text()
    start = text.index("**Not given after `_init`.**")
    table, setup = {}, None
    for line in text[start:].split("\n")[1:]:
        if line.startswith("| setup") or line.startswith("|---"):
            continue
        if not line.startswith("|"):
            if table:
                break
            continue
        cells = [c.strip() for c in line.strip("|").split("|")]
        if cells[0]:
            setup = re.match(r"`(\w+)`", cells[0]).group(1)
        for names, value in re.findall(r"((?:`\w+`(?:, )?)+) \(([^)]*)\)", cells[1]):
            for name in re.findall(r"`(\w+)`", names):
                table.setdefault(setup, {})[name.split(".")[-1]] = value
    return table


def _raw(row, buf):
    """A row's value in a setup buffer as the page states it."""
    import ctypes
    at = ctypes.addressof(buf) + row.offset
    t = row.type
    if t in (0, 11):  # double, count
        v = ctypes.c_double.from_address(at).value
        return "NaN" if math.isnan(v) else repr(v)
    if t in (1, 3, 4):  # int, flag, choice
        return str(ctypes.c_int.from_address(at).value)
    if t == 2:
        v = ctypes.c_long.from_address(at).value
        return "`GW_PARAM_UNSET_LONG`" if v == _LONG_MIN else str(v)
    if t == 5:
        return "NULL" if not ctypes.c_void_p.from_address(at).value else "text"
    if t == 6:  # gw_param_list {double *v; int n;}
        return "empty" if ctypes.c_int.from_address(at + ctypes.sizeof(ctypes.c_void_p)).value == 0 else "list"
    return "?"


def test_not_given_rows_are_documented():
    # every row a setup's _init leaves not given (gw_param_format ""), with the
    # value it holds, is stated in the table (layer-impact's rtol, atol NaN and
    # side_walls -1 were not); and the table states no other row
    import ctypes
    from granwave._lib import lib
    lib.gw_param_format.restype = ctypes.c_int
    lib.gw_param_format.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t]
    doc = _not_given_doc()
    assert doc.get("gw_layer_impact_setup", {}).get("rtol") == "NaN"
    assert doc["gw_layer_impact_setup"].get("side_walls") == "-1"
    stated = set()
    for study, setup in _SETUPS.items():
        st = granwave._study(study)
        buf = st.setup({})
        try:
            for i, row in enumerate(st.params):
                out = ctypes.create_string_buffer(256)
                lib.gw_param_format(ctypes.addressof(st.table[i]), buf, out, 256)
                if out.value:
                    continue
                field = row.name.replace("-", "_")
                where = setup if field in doc.get(setup, {}) or study not in _COLUMN else "gw_chain_setup"
                assert field in doc.get(where, {}), f"{study}: {field} not given after init, not in the table"
                assert doc[where][field] == _raw(row, buf), (study, field, doc[where][field], _raw(row, buf))
                stated.add((where, field))
        finally:
            st.st.clear(buf)
    every = {(s, f) for s, rows in doc.items() for f in rows}
    assert every <= stated, f"stated but given after init: {sorted(every - stated)}"
