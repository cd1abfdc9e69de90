"""What the forty-ninth library pass left, through Python.

layer_make(out=...) wrote a sample whose name held an ESC or a newline (the
library's output check took any name). A name to make that holds a control
character is refused now, naming the byte, nothing written; a directory the
user made whose name holds one is still written into.
"""
import os

import pytest

import granwave


@pytest.mark.parametrize("name", ["o\x1bk.txt", "o\nk.txt", "o\x7fk.txt"])
def test_layer_make_control_name_refused(tmp_path, name):
    out = tmp_path / name
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.layer_make(n=20, t_max=0.01, out=str(out))
    assert "control character" in str(e.value) and "\n" not in str(e.value)
    assert os.listdir(tmp_path) == []  # nothing written


def test_layer_make_into_users_directory(tmp_path):
    d = tmp_path / "nl\nx"
    d.mkdir()
    out = d / "s.txt"
    with pytest.warns(granwave.GranwaveWarning):  # t_max 0.01 s ends before the pile settles
        granwave.layer_make(n=20, t_max=0.01, out=str(out))
    assert out.read_text().startswith("granwave-layer-sample")  # control: written as before
