"""layer-make's ke_top_share (session 45): the share of the final kinetic
energy the one grain that moves most holds, which the did-not-settle warning
names from 0.5 on ("0.92 of it in the one grain that moves most ... one clump
or disc still rolling or rocking on a pile at rest"), was in that warning only:
`--json` and Python's result now give it, settled or not.

The 5-clump pile in a 6 R_m box cut at t-max 1 s (about 2 s) did not settle,
one clump rolling on it: Python's value and the program's are the same number,
in [0, 1], and the warning's share is that value to 2 digits; the settled
3-disc pile gives its value too (in [0, 1]).
"""
import json
import re
import subprocess

import granwave
import pytest

ROLLING = dict(clumps=True, n=5, width_rm=6, t_max=1)


def test_ke_top_share_in_python_and_json(program, tmp_path):
    with pytest.warns(granwave.GranwaveWarning) as got:
        m = granwave.layer_make(**ROLLING, out=tmp_path / "p.txt")
    assert not m.converged
    share = m["ke_top_share"]
    assert 0.5 <= share <= 1
    said = [str(w.message) for w in got if "in the one grain that moves most" in str(w.message)]
    assert len(said) == 1, [str(w.message) for w in got]
    assert re.search(r"[0-9.]+(?= of it in the one grain)", said[0]).group(0) == f"{share:.2g}"
    out = subprocess.run([program, "layer-make", "--clumps", "--n", "5", "--width-rm", "6", "--t-max", "1",
                          "--out", str(tmp_path / "c.txt"), "--json", "--quiet"],
                         capture_output=True, text=True, check=True)
    j = json.loads(out.stdout)
    assert j["converged"] is False and j["ke_top_share"] == share


def test_ke_top_share_settled(program, tmp_path):
    out = subprocess.run([program, "layer-make", "--n", "3", "--width-rm", "10", "--out", str(tmp_path / "s.txt"),
                          "--json", "--quiet"], capture_output=True, text=True, check=True)
    j = json.loads(out.stdout)
    assert j["converged"] is True and 0 <= j["ke_top_share"] <= 1
