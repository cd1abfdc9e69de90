"""The Python examples of docs/library.md run, and the numbers their comments
quote are what the code gives now.

Each ```python block runs line by line in a scratch directory, as a user pastes
it (the one line of minutes, the sheets of Table 2 under the material law, and
the lines reading its result are left out). A line `EXPR  # 67.98 N, 18.25 us`
whose comment starts with a number is checked: the comment's leading numbers
(with their units N, s, ms, us, Hz, m) against the values EXPR gives, in
order, to the digits shown. Before this test the page quoted e_n 0.0406 and
energy_error 1.8e-3 for an impact that gives 0.131 and 2.7e-5, and indexed the
soft-wall table with the wave-speed result (IndexError).
"""
import math
import re
from pathlib import Path

import numpy as np
import pytest

import granwave

DOC = Path(__file__).resolve().parents[2] / "docs" / "library.md"
SLOW = ("softwall(sheets=True",)   # about 18 s of CPU
NUMBER = re.compile(r"^\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)\s*(us|ms|s|N|Hz|m)?\b")
UNIT = {"us": 1e-6, "ms": 1e-3, None: 1.0, "s": 1.0, "N": 1.0, "Hz": 1.0, "m": 1.0}


def blocks():
    text = DOC.read_text()
    return [m.group(1) for m in re.finditer(r"^```python\n(.*?)^```", text, re.S | re.M)]


def quoted(comment):
    """The numbers a comment starts with: [(value in SI, half a unit of the last digit shown)]."""
    out = []
    rest = comment
    while True:
        m = NUMBER.match(rest)
        if not m:
            return out
        txt, unit = m.group(1), m.group(2)
        mant = txt.lower().split("e")[0]
        exp = int(txt.lower().split("e")[1]) if "e" in txt.lower() else 0
        decimals = len(mant.split(".")[1]) if "." in mant else 0
        out.append((float(txt) * UNIT[unit], 0.5 * 10.0 ** (exp - decimals) * UNIT[unit] * 1.0001))
        rest = rest[m.end():]
        if not re.match(r"\s*[,;:]", rest) and not re.match(r"\s*impacts?:", rest):
            return out
        rest = re.sub(r"^\s*(impacts?:|[,;:])", "", rest)


def scalars(v):
    vals = v if isinstance(v, tuple) else (v,)
    out = []
    for x in vals:
        if isinstance(x, np.ndarray):
            if x.size <= 3:
                out.extend(float(y) for y in x.ravel())
        elif isinstance(x, (int, float)) and not isinstance(x, bool):
            out.append(float(x))
    return out


def test_quoted_reads_what_the_page_writes():
    assert quoted(" 67.98 N, 18.25 us, 193.0 us") == [
        (67.98, pytest.approx(0.005 * 1.0001)), (pytest.approx(18.25e-6), pytest.approx(0.005e-6 * 1.0001)),
        (pytest.approx(193.0e-6), pytest.approx(0.05e-6 * 1.0001))]
    assert [v for v, _ in quoted(" 2 impacts: 68.97 N, 3.96 N")] == [2, 68.97, 3.96]
    assert quoted(" closed forms (F.13)") == []


@pytest.mark.parametrize("k", range(len(blocks())))
def test_library_md_python_block(k, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # the statistics example reads a sweep table: the stored 8000-impact one
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "results.csv").write_bytes(
        (DOC.parents[1] / "data" / "measured" / "layer_diagram_8000" / "results.csv").read_bytes())
    env = {"granwave": granwave}  # the statistics example comes before the page's import
    checked = 0
    skip_names = set()
    for n, line in enumerate(blocks()[k].splitlines(), 1):
        code, _, comment = line.partition("  #")
        if not code.strip():
            continue
        if any(s in code for s in SLOW):
            skip_names.add(code.split("=")[0].strip())
            continue
        if any(re.search(r"\b%s\b" % re.escape(s), code) for s in skip_names):
            continue
        try:
            value = eval(compile(code.strip(), "library.md", "eval"), env)
        except SyntaxError:
            exec(compile(code.strip(), "library.md", "exec"), env)
            continue
        want = quoted(comment)
        got = scalars(value)
        for (w, tol), g in zip(want, got):
            assert abs(g - w) <= tol, f"docs/library.md block {k + 1} line {n}: {code.strip()} gives {g:.6g}, the page says {w:.6g}"
            checked += 1
        assert math.isfinite(sum(got)) or not got or not want
    if k == 1:  # the block of calls quotes values on several lines
        assert checked >= 8
