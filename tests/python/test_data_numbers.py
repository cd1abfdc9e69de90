"""Numbers in data files, through the module (the forty-first session of stage
2): the program's options and the module's keywords refuse a real in
hexadecimal ('0x1p-2'), but the files' readers took it through strtod, a text
sample's x '0x1p-1' as 0.5 and a layer-stats table's param 'vi = 0x14' as 20.
The readers now share one rule (gw_data_number) and refuse it naming the file,
the line and the field; the same files in decimal run (controls)."""
import pytest

import granwave
from conftest import write_synthetic_sweep

SAMPLE = "granwave-layer-sample 1\nwidth 1\nrm 0.1\nn 3\n0.3 0.1 0.1\n{x} 0.1 0.1\n0.7 0.1 0.1\n"


def _refused(call, path, line, field):
    with pytest.raises(granwave.GranwaveValueError) as e:
        call()
    msg = str(e.value)
    assert str(path) in msg and line in msg and field in msg and "not a decimal number" in msg, msg


@pytest.mark.parametrize("x", ["0x1p-1", "0X.8P0"])
def test_sample_hexadecimal_refused(tmp_path, x):
    p = tmp_path / "s.txt"
    p.write_text(SAMPLE.format(x=x))
    _refused(lambda: granwave.layer_impact(sample=str(p), t_max=1e-4), p, "line 6", f"x '{x}' of particle 2")
    _refused(lambda: granwave.sweep("layer", grid={"sample": [str(p)], "vi": [1, 2]}, t_max=1e-4), p, "line 6",
             f"x '{x}' of particle 2")


def test_sample_decimal_runs(tmp_path):
    p = tmp_path / "s.txt"
    p.write_text(SAMPLE.format(x="0.5"))
    with pytest.warns(granwave.GranwaveWarning, match="raise t_max"):  # cut at 0.1 ms on purpose
        r = granwave.layer_impact(sample=str(p), t_max=1e-4)
    assert r["t_end"] == pytest.approx(1e-4, rel=1e-12)


@pytest.mark.parametrize("old,new,line,field", [
    ("# param vi = 20\n", "# param vi = 0x14\n", ":2:", "param vi: '0x14'"),
    ("\n0,0.5,3,0,", "\n0,0x1p-1,3,0,", ":4:", "grid key rb-rm: '0x1p-1'"),
])
def test_table_hexadecimal_refused(tmp_path, old, new, line, field):
    p = write_synthetic_sweep(tmp_path / "t.csv")
    text = p.read_text()
    assert old in text
    p.write_text(text.replace(old, new, 1))
    _refused(lambda: granwave.layer_stats(str(p)), p, line, field)


def test_table_decimal_runs(tmp_path):
    p = write_synthetic_sweep(tmp_path / "t.csv")
    r = granwave.layer_stats(str(p))
    assert r["rows"] == 168
