"""The Python module refuses a libgranwave of another ABI before calling it
(issue 18): session 29's stale ctypes mirror of gw_layer_sample (96 bytes for
168) was written past its end by the library. The module now checks, first,
gw_abi_version() against the ABI its mirrors are written for (ABI_VERSION in
granwave/_lib.py), then gw_struct_size() of each struct it mirrors and hands
to the library (gw_err, gw_param, gw_study).

A library of another ABI is a stand-in compiled here (a few functions with the
library's names), loaded through GRANWAVE_LIB in a fresh interpreter.
"""
import ctypes
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import granwave
from granwave import _lib

REPO = Path(__file__).resolve().parents[2]


def _stand_in(tmp_path, source):
    cc = shutil.which("cc") or shutil.which("gcc")
    if not cc:
        pytest.skip("no C compiler to build a stand-in library")
    src = tmp_path / "stub.c"
    src.write_text("#include <stddef.h>\n#include <string.h>\n" + source
                   + ('const char *gw_version(void) { return "0.1.0"; }\n' if "gw_version(" not in source else ""))
    out = tmp_path / "libgranwave.so"
    subprocess.run([cc, "-shared", "-fPIC", "-o", str(out), str(src)], check=True)
    return out


def _import_with(lib):
    env = dict(os.environ, GRANWAVE_LIB=str(lib), PYTHONPATH=str(REPO / "python"), PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run([sys.executable, "-c", "import granwave"], env=env, capture_output=True, text=True,
                          timeout=60)


def _import_error(p):
    """The ImportError's text: the import failed with one, not a crash."""
    assert p.returncode == 1, (p.returncode, p.stderr)
    last = p.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: granwave: "), p.stderr
    return last


def test_another_abi_refused_naming_both_numbers_and_the_path(tmp_path):
    other = _lib.ABI_VERSION + 1
    lib = _stand_in(tmp_path, f"int gw_abi_version(void) {{ return {other}; }}\n"
                              "size_t gw_struct_size(const char *n) { (void)n; return 512; }\n")
    msg = _import_error(_import_with(lib))
    assert f"{lib} has ABI {other}, this module is written for ABI {_lib.ABI_VERSION}" in msg


def test_a_library_older_than_abi_numbers_refused(tmp_path):
    # every libgranwave before the ABI number (soname libgranwave.so.0.1) has
    # gw_version but no gw_abi_version
    lib = _stand_in(tmp_path, 'const char *gw_version(void) { return "0.1.0"; }\n')
    msg = _import_error(_import_with(lib))
    assert f"{lib} is a libgranwave older than ABI numbers (0.1.0, no gw_abi_version)" in msg
    assert f"written for ABI {_lib.ABI_VERSION}" in msg


def test_a_mirror_of_another_size_refused(tmp_path):
    # the right ABI number and a gw_err of 256 bytes: the module's GwErr (512)
    # would be read short, and a longer one written past; refused naming it
    lib = _stand_in(tmp_path, f"int gw_abi_version(void) {{ return {_lib.ABI_VERSION}; }}\n"
                              "size_t gw_struct_size(const char *n) {\n"
                              f"  if (!strcmp(n, \"gw_err\")) return 256;\n"
                              f"  if (!strcmp(n, \"gw_param\")) return {ctypes.sizeof(_lib.GwParam)};\n"
                              f"  if (!strcmp(n, \"gw_study\")) return {ctypes.sizeof(_lib.GwStudy)};\n"
                              "  return 0; }\n")
    msg = _import_error(_import_with(lib))
    assert f"{lib} (ABI {_lib.ABI_VERSION}) does not match this module: gw_err is 256 bytes there, 512 here" in msg


def test_the_build_library_is_of_the_module_abi():
    lib = _lib.lib
    lib.gw_abi_version.restype = ctypes.c_int
    assert lib.gw_abi_version() == _lib.ABI_VERSION
    lib.gw_layer_sample_size.restype = ctypes.c_size_t
    # gw_struct_size knows the struct of session 29's overrun, by the size its own call gives
    assert lib.gw_struct_size(b"gw_layer_sample") == lib.gw_layer_sample_size() > 96
    assert lib.gw_struct_size(b"gw_err") == ctypes.sizeof(_lib.GwErr) == 512
    assert lib.gw_struct_size(b"gw_no_such_struct") == 0
    assert lib.gw_struct_size(None) == 0
    assert granwave.chain(n=1, vimp=0.3).f_max > 0  # and the module runs on it
