"""The fifty-second hostile pass through Python (about 50 calls: drop's
sensor body NaN, inf, -0 and 1e308, numpy integers, 0-d and 1-D arrays,
bytes and numbers for choices, progress callbacks raising KeyboardInterrupt
and SystemExit in drop, sweep, softwall, falcon and layer_make, side_walls
7, 1.5, None and a keyword typo, radii strided, float32, big-endian,
complex, of objects, 2-D and of ten million items, sweeps of empty grids
and of 10**6 jobs). The module refused each with one message naming the
keyword, and let KeyboardInterrupt and SystemExit through: no fault there.

Through ctypes, what the library's pass found: gw_fnv1a64_file_max took a
text flag of 7 as yes (it is refused naming text), gw_stats_table_parse
with no name named nothing (":2: no header line"; now "<table>:2: ..."),
and the journal's and the sweep table's writers refused an empty directory
as "path too long" (now named as an empty directory). Controls next to each.
"""
import ctypes

import pytest

import granwave


def _lib():
    return ctypes.CDLL(granwave.library_path)


def _fnv(lib):
    f = lib.gw_fnv1a64_file_max
    f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_ulonglong, ctypes.c_int,
                  ctypes.POINTER(ctypes.c_ulonglong), ctypes.c_char_p]
    f.restype = ctypes.c_int
    return f


@pytest.mark.parametrize("text", [7, -1, 2])
def test_hash_text_flag_refused(tmp_path, text):
    p = tmp_path / "a.txt"
    p.write_bytes(b"ab\n\0cd\n")
    f = _fnv(_lib())
    h, e = ctypes.c_ulonglong(42), ctypes.create_string_buffer(512)
    assert f(str(p).encode(), b"input", 100, text, ctypes.byref(h), e) == -1
    assert e.value.decode() == "gw_fnv1a64_file_max: text is %d, not a flag (0 or 1)" % text
    assert h.value == 42


def test_hash_text_flag_control(tmp_path):
    p = tmp_path / "a.txt"
    p.write_bytes(b"ab\n\0cd\n")
    f = _fnv(_lib())
    h, e = ctypes.c_ulonglong(42), ctypes.create_string_buffer(512)
    assert f(str(p).encode(), b"input", 100, 1, ctypes.byref(h), e) != 0
    assert "line 2: NUL byte" in e.value.decode()
    assert f(str(p).encode(), b"input", 100, 0, ctypes.byref(h), e) == 0 and h.value != 42


def _parse(text, name):
    lib = _lib()
    f = lib.gw_stats_table_parse
    f.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_char_p]
    f.restype = ctypes.c_int
    t = ctypes.create_string_buffer(1 << 16)  # a gw_stats_table (5360 bytes) with room
    e = ctypes.create_string_buffer(512)
    rc = f(text, name, t, e)
    return rc, e.value.decode()


@pytest.mark.parametrize("name", [None, b""])
def test_table_parse_without_name(name):
    rc, msg = _parse(b"# only a comment\n", name)
    assert rc != 0 and msg.startswith("<table>:2: no header line"), msg


def test_table_parse_named_control():
    rc, msg = _parse(b"# only a comment\n", b"hand.csv")
    assert rc != 0 and msg.startswith("hand.csv:2: no header line"), msg


def _sweep_write_table(dirname):
    """gw_sweep_write_table(dir, cfg, m) with a chain config read from text."""
    lib = _lib()
    ms_n = ctypes.c_int()
    models = lib.gw_sweep_models
    models.argtypes = [ctypes.POINTER(ctypes.c_int)]
    models.restype = ctypes.c_void_p
    ms = models(ctypes.byref(ms_n))
    read = lib.gw_sweep_config_read_string
    read.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_int, ctypes.c_void_p,
                     ctypes.POINTER(ctypes.c_void_p), ctypes.c_char_p]
    read.restype = ctypes.c_int
    cfg = ctypes.create_string_buffer(1 << 20)  # a gw_sweep_config, with room
    m = ctypes.c_void_p()
    e = ctypes.create_string_buffer(512)
    text = b"[sweep]\nmodel = chain\n[grid]\nn = 1:2\n[params]\nt-max = 1e-3\n"
    assert read(text, b"t", ms, ms_n.value, cfg, ctypes.byref(m), e) == 0, e.value
    w = lib.gw_sweep_write_table
    w.argtypes = [ctypes.c_char_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p]
    w.restype = ctypes.c_int
    rc = w(dirname, cfg, m, e)
    free = lib.gw_sweep_config_free
    free.argtypes = [ctypes.c_void_p]
    free(cfg)
    return rc, e.value.decode()


def test_sweep_table_empty_dir():
    rc, msg = _sweep_write_table(b"")
    assert rc == -1 and "the directory is empty" in msg and "No such file" not in msg, msg


def test_sweep_table_missing_dir_control(tmp_path):
    rc, msg = _sweep_write_table(str(tmp_path / "none").encode())
    assert rc != 0 and "cannot open the sweep's directory" in msg, msg
