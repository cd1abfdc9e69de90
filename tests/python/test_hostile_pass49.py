"""The forty-ninth hostile pass through Python: a study's name quoted in its
refusal, and the parameter tables' set calls given NULL through ctypes.

granwave.params("chain\\0") and params("ch\\x1bain") put the NUL and the ESC
raw into the GranwaveValueError's message ("no study 'chain\\x00' ..." now,
as the keywords' names are quoted: one line, control characters escaped).

Through ctypes: gw_param_set and gw_param_set_double given a NULL table
said "unknown parameter 'n'", given a NULL name "unknown parameter
'(null)'", and gw_param_set_value given a NULL row "(null): a result, not a
parameter"; each now names the call and the argument, as every other entry
point of the library does (docs/library.md, "The contract of every call").
"""
import ctypes

import pytest

import granwave


@pytest.mark.parametrize("name, shown", [("chain\x00", "chain\\x00"), ("ch\x1bain", "ch\\x1bain"),
                                         ("chain\n", "chain\\n"), ("chain\x7f", "chain\\x7f")])
def test_study_name_quoted(name, shown):
    with pytest.raises(granwave.GranwaveValueError) as e:
        granwave.params(name)
    msg = str(e.value)
    assert f"no study '{shown}'" in msg
    assert all(ord(c) >= 0x20 and ord(c) != 0x7f for c in msg)


def test_study_name_control():
    """a known name, and one written with '_', still found (control)"""
    assert any(p["keyword"] == "vimp" for p in granwave.params("chain"))
    assert any(p["keyword"] == "rb_rm" for p in granwave.params("layer_impact"))


def _lib():
    lib = ctypes.CDLL(granwave.library_path)
    lib.gw_param_set.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_char_p]
    lib.gw_param_set_double.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_double,
                                        ctypes.c_char_p]
    lib.gw_param_set_value.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_char_p]
    lib.gw_chain_setup_params.restype = ctypes.c_void_p
    return lib


def _call(f, *args):
    err = ctypes.create_string_buffer(512)
    rc = f(*args, err)
    return rc, err.value.decode()


@pytest.mark.parametrize("call, args, said", [
    ("gw_param_set", (None, "obj", b"n", b"3"), "gw_param_set: table is NULL"),
    ("gw_param_set", ("table", "obj", None, b"3"), "gw_param_set: name is NULL"),
    ("gw_param_set_double", (None, "obj", b"vimp", 0.3), "gw_param_set_double: table is NULL"),
    ("gw_param_set_double", ("table", "obj", None, 0.3), "gw_param_set_double: name is NULL"),
    ("gw_param_set_value", (None, "obj", b"3"), "gw_param_set_value: p is NULL"),
])
def test_set_calls_name_null(call, args, said):
    lib = _lib()
    obj = ctypes.create_string_buffer(4096)  # larger than the chain's setup; never written here
    table = lib.gw_chain_setup_params()
    real = [table if a == "table" else obj if a == "obj" else a for a in args]
    rc, msg = _call(getattr(lib, call), *real)
    assert rc == -1 and said in msg, msg
    assert obj.raw == b"\0" * 4096


def test_set_unknown_control():
    """an unknown name is still said so (control)"""
    lib = _lib()
    obj = ctypes.create_string_buffer(4096)
    rc, msg = _call(lib.gw_param_set, lib.gw_chain_setup_params(), obj, b"bogus", b"3")
    assert rc == -1 and "unknown parameter 'bogus'" in msg
