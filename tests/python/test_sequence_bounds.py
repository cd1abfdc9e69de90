"""What the module takes from a caller's sequence is bounded (issue 18, the
twentieth session of stage 2), and layer-stats' per-diagram texts name
Python's keywords.

1. A generator that never ends, given where a sequence goes, ran on for good,
   taking memory as it went: radii=itertools.count(1), vimp or heights of
   (0.3 for _ in iter(int, 1)), a drop's gap, layer_impact's snapshots, a
   sweep grid's values, a falcon n=(A, B) whose iteration does not end. Every
   list row of the library's tables now gives the most items it takes
   (gw_param.rows: a number, or the integer row it is counted against: radii
   and gap at most n), gw_param_set and gw_param_check refuse more, and the
   module takes at most that many + 1 items from any sequence (one helper,
   _core._items): refused at once, naming the keyword and the bound. A grid
   key takes at most the values a sweep config holds (1 MiB, the library's
   bound of a config file, now of a config given as text too). Each call runs
   in a child process under a timeout and a 2 GiB address-space limit, so a
   regression fails instead of hanging. Lists, arrays and finite generators
   run as before, to the last digit.
2. layer_stats' diagrams had no offset_source and fit_reason (the JSON's
   fit.offset_source and fit_reason); they are now columns of r.diagrams,
   naming the input as Python does ('delta_rm' where the program writes
   '--delta-rm'), and the program's JSON is unchanged.
3. A hostile pass: text given as bytes (bytes, bytearray) where numbers go ran
   as the bytes' values (radii=bytearray([1]) a bead of 1 m; falcon
   n=bytearray([1, 3]) the range 1:3; grid={"n": b"12"} the columns of 49 and
   50 beads); a str subclass decided what the module checked (its own
   __contains__ hid a NUL: the library opened the file named by the text up
   to it; its own split ran other grid values); a path object whose
   __fspath__ gives no path, and a sweep model that is no str, were refused
   naming nothing.
4. The falcon and wavespeed studies compared every pair of their speeds
   (n^2 / 2): 220 s before the first collision with 320000 speeds; now sorted.
On the code before this session (the module and the library), 26 of the 28
tests fail (the 10 generators with the module before: it is what takes them).
"""
import ctypes
import itertools
import json
import math
import re
import resource
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import granwave
from conftest import write_synthetic_sweep
from granwave import _core, _lib

GEN = "(0.3 for _ in iter(int, 1))"  # a generator that never ends
NEVER = {
    "chain radii count": ("granwave.chain(n=3, radii=itertools.count(1))", r"^chain: radii: more than 3 items \(n = 3\)"),
    "chain radii, n not given": ("granwave.chain(radii=(1e-3 for _ in iter(int, 1)))",
                                 r"^chain: radii: more than 1 item \(n = 1, its default\)"),
    "falcon vimp": (f"granwave.falcon(n=(1, 2), vimp={GEN})", r"^falcon: vimp: more than 2000000 items"),
    "falcon heights": (f"granwave.falcon(n=(1, 2), heights=(2.0 for _ in iter(int, 1)))",
                       r"^falcon: heights: more than 2000000 items"),
    "wavespeed vimp": (f"granwave.wavespeed(n=(2, 3), vimp={GEN})", r"^wavespeed: vimp: more than 2000000 items"),
    "drop gap": ("granwave.drop(n=4, gap=(1e-3 for _ in iter(int, 1)))", r"^drop: gap: more than 4 items \(n = 4\)"),
    "layer_impact snapshots": ("granwave.layer_impact(sample='none.txt', snapshots=(0.01 for _ in iter(int, 1)))",
                               r"^layer_impact: snapshots: more than 10000 items"),
    "sweep grid count": ("granwave.sweep('chain', grid={'n': itertools.count(1)})",
                         r"^sweep\(\) grid: 'n': more than 524288 items"),
    "sweep grid floats": (f"granwave.sweep('chain', grid={{'vimp': {GEN}}})",
                          r"^sweep\(\) grid: 'vimp': more than 524288 items"),
    "falcon n of two that never ends": ("granwave.falcon(n=Two(), vimp=[0.3], heights=[])",
                                        r"^falcon: n: more than 2 items"),
}

CHILD = textwrap.dedent("""
    import itertools, json, sys
    import granwave

    class Two:  # says it holds two items, and never stops giving them
        def __len__(self):
            return 2

        def __iter__(self):
            return itertools.count(1)

    try:
        eval(sys.argv[1])
        print(json.dumps(["ran", ""]))
    except BaseException as e:
        print(json.dumps([type(e).__name__, str(e)]))
""")


def _limit():
    resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))


@pytest.mark.parametrize("case", sorted(NEVER))
def test_a_sequence_that_never_ends_is_refused_at_once(case):
    call, message = NEVER[case]
    try:
        p = subprocess.run([sys.executable, "-c", CHILD, call], capture_output=True, text=True, timeout=30,
                           preexec_fn=_limit)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{call} still running after 30 s")
    kind, text = json.loads(p.stdout.strip().splitlines()[-1]) if p.stdout.strip() else ("no output", p.stderr)
    assert kind == "GranwaveValueError", (call, kind, text)
    assert re.search(message, text), (call, text)


def test_many_speeds_are_checked_distinct_at_once():
    """The falcon and wavespeed studies check their speeds distinct. Every pair
    was compared: falcon(n=(1, 2)) with 320000 speeds (its work bound takes
    4e5) spent 220 s before its first collision; now sorted (8 s, most of it
    the conversion of the speeds). Here 400000, under a 60 s timeout. The first speed given twice is named as
    before: the first item with an earlier equal, and the first of those."""
    call = ("granwave.falcon(n=(1, 2), heights=[], vimp=[*__import__('numpy').linspace(0.01, 1, 399998), "
            "float(__import__('numpy').linspace(0.01, 1, 399998)[7]), 0.01])")
    p = subprocess.run([sys.executable, "-c", CHILD, call], capture_output=True, text=True, timeout=60,
                       preexec_fn=_limit)
    kind, text = json.loads(p.stdout.strip().splitlines()[-1])
    assert kind == "GranwaveValueError" and text.startswith(
        "falcon: vimp: item 399999 gives the impact velocity 0.01001732513 m/s of item 8: "), text
    for vimp, heights, message in (([0.3, 0.2, 0.3, 0.2], [], "vimp: item 3 gives the impact velocity 0.3 m/s of item 1:"),
                                   ([0.2, 0.25], [2.0, 2.0], "heights: item 2 gives the impact velocity 0.1980908882 "
                                                             "m/s of item 1:"),
                                   ([math.sqrt(2 * 9.81 * 2e-3)], [2.0], "heights: item 1 gives the impact velocity "
                                                                         "0.1980908882 m/s of item 1 of vimp:")):
        with pytest.raises(granwave.GranwaveValueError, match="^falcon: " + re.escape(message)):
            granwave.falcon(n=(1, 2), vimp=vimp, heights=heights)


def test_lists_arrays_and_finite_generators_run_as_before():
    a = granwave.chain(n=3, radii=[1e-3, 2e-3, 3e-3])
    assert granwave.chain(n=3, radii=np.array([1e-3, 2e-3, 3e-3])) == a
    assert granwave.chain(n=3, radii=(r * 1e-3 for r in (1, 2, 3))) == a
    assert granwave.chain(n=3, radii=iter([1e-3, 2e-3, 3e-3])) == a
    f = granwave.falcon(n=(1, 3), vimp=[0.2, 0.3], heights=[])
    assert granwave.falcon(n=(1, 3), vimp=np.array([0.2, 0.3]), heights=()) == f
    assert granwave.falcon(n=range(1, 4), vimp=(v for v in (0.2, 0.3)), heights=iter([])) == f
    s = granwave.sweep("chain", grid={"vimp": [0.2, 0.3], "n": [2, 3]}, jobs=1)
    t = granwave.sweep("chain", grid={"vimp": (v for v in (0.2, 0.3)), "n": iter([2, 3])}, jobs=1)
    assert s == t and s.ncases == 4


def test_a_sized_sequence_above_the_bound_is_refused_by_its_length():
    class Long(list):  # its length is read, no item is taken
        def __iter__(self):
            raise AssertionError("items taken")

    with pytest.raises(granwave.GranwaveValueError, match=r"^layer_impact: snapshots: 10001 items, at most 10000$"):
        granwave.layer_impact(sample="none.txt", snapshots=Long([0.01] * 10001))
    with pytest.raises(granwave.GranwaveValueError, match=r"^chain: radii: 4 items, at most 3 \(n = 3\)$"):
        granwave.chain(n=3, radii=Long([1e-3] * 4))
    # at the bound: taken
    r = granwave.drop(n=3, gap=[1e-4, 2e-4], t_max=2e-3)
    assert r.gaps.tolist() == [1e-4, 2e-4]


def _set(study, name, text):
    st = _lib.lib.gw_study_find(study.encode()).contents
    buf = ctypes.create_string_buffer(st.params_size)
    st.init(buf)
    err = _lib.GwErr()
    try:
        rc = _lib.lib.gw_param_set(st.params(), buf, name.encode(), text.encode(), ctypes.byref(err))
    finally:
        st.clear(buf)
    return rc, err.msg.decode()


def test_the_library_refuses_a_list_above_its_rows_bound():
    """The bound is the library's: a C caller's text is refused with the same
    words, counted before anything is parsed; at the bound it is taken."""
    assert _set("layer-impact", "snapshots", ",".join(["0.01"] * 10001)) == (-1, "snapshots: 10001 items, at most 10000")
    assert _set("layer-impact", "snapshots", ",".join(["0.01"] * 10000)) == (0, "")
    assert _set("falcon", "vimp", ",".join(["0.3"] * 2000001)) == (-1, "vimp: 2000001 items, at most 2000000")
    # radii and gap are counted against n: at most n's maximum here, the study checks n itself
    assert _set("chain", "radii", "1e-3,2e-3,3e-3") == (0, "")
    rows = {p.name: p for p in _core.Study("chain").params}
    assert rows["radii"].rows == "n" and rows["n"].max == 5e7


def test_a_sweep_config_as_text_is_bounded_as_a_file():
    """gw_sweep_run_text took a config of any size; a file is read up to 1 MiB
    (GW_SWEEP_CONFIG_MAX). Python names the key whose values make it longer."""
    text = "[sweep]\nmodel = chain\n[grid]\nvimp = 0.3\n[params]\n#" + "x" * (1 << 20) + "\n"
    values, ncases = _lib.c_double_p(), ctypes.c_long()
    model, err = ctypes.POINTER(_lib.GwSweepModel)(), _lib.GwErr()
    rc = _lib.lib.gw_sweep_run_text(text.encode(), b"t", 1, _lib.PROGRESS(), None, ctypes.byref(values),
                                    ctypes.byref(ncases), ctypes.byref(model), ctypes.byref(err))
    assert rc == -1 and err.msg.decode() == f"t: the config takes {len(text)} bytes, above the 1048576 of a sweep config"
    with pytest.raises(granwave.GranwaveValueError, match=r"^sweep\(\) grid: 'vimp': the sweep's config takes \d+ "
                                                          r"bytes, above the 1048576"):
        granwave.sweep("chain", grid={"n": [1, 2], "vimp": np.linspace(0.01, 1, 60000)})
    # consecutive integers are written A:B: a long list of them fits
    s = granwave.sweep("chain", grid={"n": list(range(1, 6))}, jobs=1)
    assert s.ncases == 5


def _json(program, *args):
    return json.loads(subprocess.run([program, "layer-stats", *map(str, args), "--json"], check=True,
                                     capture_output=True, text=True).stdout)


@pytest.mark.parametrize("kw,python,cli", [({}, "measured: mean penetration_rm / 2 of the cells bracketing the "
                                                 "boundary", None),
                                           ({"delta_rm": 1.0}, "delta_rm", "--delta-rm"),
                                           ({"fit": "beta,a_over_b,offset"}, "fitted", None)],
                         ids=["measured", "delta_rm", "fitted"])
def test_layer_stats_offset_source_names_the_keyword(program, tmp_path, kw, python, cli):
    t = write_synthetic_sweep(tmp_path / "syn.csv")
    r = granwave.layer_stats(t, **kw)
    args = [a for k, v in kw.items() for a in ("--" + k.replace("_", "-"), v)]
    j = _json(program, t, *args)
    assert r.ndiagrams == len(j["diagrams"]) == 1
    assert list(r.diagrams["offset_source"]) == [python] and list(r.diagrams["fit_reason"]) == [None]
    assert j["diagrams"][0]["fit"]["offset_source"] == (cli or python)  # the program's, as before


def test_layer_stats_fit_reason_names_the_keyword(program, tmp_path):
    t = write_synthetic_sweep(tmp_path / "nopen.csv", penetration=False)
    r = granwave.layer_stats(t)
    j = _json(program, t)
    assert j["diagrams"][0]["fit"] is None
    assert j["diagrams"][0]["fit_reason"] == "no offset: no boundary crossing with a penetration (give --delta-rm)"
    assert list(r.diagrams["fit_reason"]) == ["no offset: no boundary crossing with a penetration (give delta_rm)"]
    assert list(r.diagrams["offset_source"]) == [None]
    # the offset given: fitted
    e = granwave.layer_stats(t, delta_rm=0.5)
    assert list(e.diagrams["fit_reason"]) == [None] and list(e.diagrams["offset_source"]) == ["delta_rm"]


@pytest.mark.parametrize("call,match", [
    (lambda: granwave.chain(n=1, radii=bytearray([1])), r"^chain: radii: expected a number or a sequence"),
    (lambda: granwave.falcon(n=(1, 2), vimp=bytearray(b"\x01"), heights=[]), r"^falcon: vimp: expected a number"),
    (lambda: granwave.falcon(n=bytearray([1, 3]), vimp=[0.3], heights=[]), r"^falcon: n: expected \(A, B\)"),
    (lambda: granwave.falcon(n=b"\x01\x03", vimp=[0.3], heights=[]), r"^falcon: n: expected \(A, B\)"),
    (lambda: granwave.sweep("chain", grid={"n": b"12"}), r"^sweep\(\) grid: 'n': expected a list"),
    (lambda: granwave.sweep("chain", grid={"n": bytearray(b"12")}), r"^sweep\(\) grid: 'n': expected a list"),
    (lambda: granwave.sweep(["chain"], grid={"n": [1]}), r"^sweep\(\): model must be a str"),
], ids=["radii bytearray", "vimp bytearray", "n bytearray", "n bytes", "grid bytes", "grid bytearray", "model list"])
def test_bytes_where_numbers_go_are_refused(call, match):
    with pytest.raises(TypeError, match=match):
        call()


class Lying(str):
    """A str whose own methods do not tell its characters."""

    def __contains__(self, x):
        return False

    def split(self, *a, **k):
        return ["0.1"]

    def __str__(self):
        return "0.1"


def test_a_str_subclass_is_taken_by_its_characters(tmp_path):
    (tmp_path / "a.txt").write_text("a sample\n")
    with pytest.raises(granwave.GranwaveValueError, match=r"^layer_impact: sample: .* holds a NUL character"):
        granwave.layer_impact(sample=Lying(str(tmp_path / "a.txt") + "\0x"), t_max=1e-3)
    s = granwave.sweep("chain", grid={"vimp": Lying("0.2,0.3")}, jobs=1)
    assert s.vimp.tolist() == [0.2, 0.3]
    assert granwave.chain(vimp=Lying("0.3")) == granwave.chain(vimp=0.3)


class BadPath:
    def __fspath__(self):
        return 3


def test_a_path_object_that_gives_no_path_is_named():
    with pytest.raises(TypeError, match=r"^layer_stats: input: expected BadPath.__fspath__\(\) to return str"):
        granwave.layer_stats(BadPath())
    with pytest.raises(TypeError, match=r"^sweep\(\) grid: 'sample': expected BadPath.__fspath__\(\)"):
        granwave.sweep("layer", grid={"sample": [BadPath()]})
