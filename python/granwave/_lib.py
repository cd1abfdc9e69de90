"""Loading libgranwave with ctypes and declaring the calls the module uses.

Where the library is looked for, first found wins:
  1. the environment variable GRANWAVE_LIB (a file, or a directory holding
     libgranwave.so);
  2. an installed prefix: the library directory that cmake --install recorded
     in _install.py beside this file (P/lib for the module in
     P/lib/python3/dist-packages/granwave);
  3. otherwise the build tree of a source checkout: <repo>/build/lib/libgranwave.so
     (what ./setup.sh build makes), when this package is <repo>/python/granwave;
  4. the system's search path (ctypes.util.find_library("granwave")).
No compilation happens at import: the C structs the module reads are mirrored
here. Before any other call the library's ABI (gw_abi_version) must be the one
these mirrors were written for (ABI_VERSION), and their sizes the library's
(gw_struct_size): a library of another ABI is refused with ImportError, not
called with structs it would write past.
"""
import ctypes
import ctypes.util
import os
from pathlib import Path

c_double_p = ctypes.POINTER(ctypes.c_double)

# The ABI of libgranwave (GW_ABI_VERSION, its soname number) these mirrors are
# written for; test_abi fails while it differs from the headers'.
ABI_VERSION = 8


class GwErr(ctypes.Structure):
    _fields_ = [("msg", ctypes.c_char * 512)]


class GwParam(ctypes.Structure):
    """Mirror of gw_param (common/gw_param.h)."""
    _fields_ = [("name", ctypes.c_char_p), ("type", ctypes.c_int), ("offset", ctypes.c_size_t),
                ("unit", ctypes.c_char_p), ("min", ctypes.c_double), ("max", ctypes.c_double),
                ("open_min", ctypes.c_int), ("open_max", ctypes.c_int), ("default", ctypes.c_char_p),
                ("help", ctypes.c_char_p), ("choices", ctypes.c_char_p), ("metavar", ctypes.c_char_p),
                ("rows", ctypes.c_char_p), ("cols", ctypes.c_char_p), ("optional", ctypes.c_int),
                ("or_zero", ctypes.c_int)]


PROGRESS = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_long, ctypes.c_long)
TABLE_FN = ctypes.CFUNCTYPE(ctypes.POINTER(GwParam))
INIT_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p)
CLEAR_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p)
RUN_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, PROGRESS, ctypes.c_void_p,
                          ctypes.POINTER(GwErr))


class GwStudy(ctypes.Structure):
    """Mirror of gw_study (app/lib/gw_study.h)."""
    _fields_ = [("name", ctypes.c_char_p), ("summary", ctypes.c_char_p), ("params", TABLE_FN),
                ("params_size", ctypes.c_size_t), ("init", INIT_FN), ("clear", CLEAR_FN),
                ("fields", TABLE_FN), ("fields_size", ctypes.c_size_t), ("run", RUN_FN),
                ("free_out", CLEAR_FN)]


class GwSweepModel(ctypes.Structure):
    """Mirror of gw_sweep_model (common/sweep/gw_sweep.h); only name, columns and has_key are used."""
    _fields_ = [("name", ctypes.c_char_p), ("ncolumns", ctypes.c_int),
                ("columns", ctypes.POINTER(ctypes.c_char_p)),
                ("has_key", ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_char_p)),
                ("run", ctypes.c_void_p), ("check", ctypes.c_void_p)]


def _candidates():
    env = os.environ.get("GRANWAVE_LIB")
    if env:
        p = Path(env)
        return [p / "libgranwave.so" if p.is_dir() else p], True
    here = Path(__file__).resolve().parent
    try:  # written by cmake --install: the library directory relative to this package
        from ._install import LIBDIR_FROM_PACKAGE
        return [(here / LIBDIR_FROM_PACKAGE / "libgranwave.so").resolve()], False
    except ImportError:
        pass
    return [here.parent.parent / "build" / "lib" / "libgranwave.so"], False  # source checkout


def _open(p, from_env):
    # a file that is no shared library raised the loader's OSError ("file too
    # short"), naming neither the module nor GRANWAVE_LIB
    try:
        return ctypes.CDLL(p)
    except OSError as e:
        who = f"GRANWAVE_LIB={os.environ['GRANWAVE_LIB']}" if from_env else p
        raise ImportError(f"granwave: {who} cannot be loaded ({e})") from None


def _load():
    paths, from_env = _candidates()
    for p in paths:
        if p.exists():
            return _open(str(p), from_env), str(p)
    if from_env:
        raise ImportError(f"granwave: GRANWAVE_LIB={os.environ['GRANWAVE_LIB']} names no library "
                          f"(looked for {paths[0]})")
    name = ctypes.util.find_library("granwave")
    if name:
        return _open(name, False), name
    raise ImportError("granwave: libgranwave.so not found; build it (./setup.sh build), install it "
                      "(cmake --install build --prefix P), or set GRANWAVE_LIB to its path. Looked in: "
                      + ", ".join(str(p) for p in paths))


lib, path = _load()


def _declare(name, restype, *argtypes):
    try:  # another library (or another version's) lacks it: AttributeError "undefined symbol" before
        f = getattr(lib, name)
    except AttributeError:
        raise ImportError(f"granwave: {path} is not a libgranwave this module can use (it has no {name}): "
                          "use the module installed with that library, or set GRANWAVE_LIB to the build's "
                          "lib/libgranwave.so") from None
    f.restype = restype
    f.argtypes = list(argtypes)


def _check_abi():
    # first, before any call whose arguments or structs could differ: a library
    # of another ABI (or older than the ABI number) is named with both numbers;
    # one without gw_version is no libgranwave at all (_declare says so)
    _declare("gw_version", ctypes.c_char_p)
    try:
        f = lib.gw_abi_version
    except AttributeError:
        raise ImportError(f"granwave: {path} is a libgranwave older than ABI numbers ({lib.gw_version().decode()}, "
                          "no gw_abi_version); "
                          f"this module is written for ABI {ABI_VERSION}: use the module installed with that "
                          "library, or set GRANWAVE_LIB to the build's lib/libgranwave.so") from None
    f.restype, f.argtypes = ctypes.c_int, []
    if f() != ABI_VERSION:
        raise ImportError(f"granwave: {path} has ABI {f()}, this module is written for ABI {ABI_VERSION}: use the "
                          "module installed with that library, or set GRANWAVE_LIB to a libgranwave.so of "
                          f"ABI {ABI_VERSION}")
    _declare("gw_struct_size", ctypes.c_size_t, ctypes.c_char_p)
    for name, mirror in (("gw_err", GwErr), ("gw_param", GwParam), ("gw_study", GwStudy)):
        if lib.gw_struct_size(name.encode()) != ctypes.sizeof(mirror):
            raise ImportError(f"granwave: {path} (ABI {ABI_VERSION}) does not match this module: {name} is "
                              f"{lib.gw_struct_size(name.encode())} bytes there, {ctypes.sizeof(mirror)} here")


_check_abi()
_declare("gw_version_major", ctypes.c_int)
_declare("gw_version_minor", ctypes.c_int)
_declare("gw_version_patch", ctypes.c_int)
_declare("gw_strerror", ctypes.c_char_p, ctypes.c_int)
_declare("gw_param_row_size", ctypes.c_size_t)
_declare("gw_study_size", ctypes.c_size_t)
_declare("gw_study_find", ctypes.POINTER(GwStudy), ctypes.c_char_p)
_declare("gw_study_count", ctypes.c_int)
_declare("gw_study_get", ctypes.POINTER(GwStudy), ctypes.c_int)
_declare("gw_param_set", ctypes.c_int, ctypes.POINTER(GwParam), ctypes.c_void_p, ctypes.c_char_p,
         ctypes.c_char_p, ctypes.POINTER(GwErr))
_declare("gw_sweep_models", ctypes.POINTER(ctypes.POINTER(GwSweepModel)), ctypes.POINTER(ctypes.c_int))
_declare("gw_sweep_run_text", ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int, PROGRESS,
         ctypes.c_void_p, ctypes.POINTER(c_double_p), ctypes.POINTER(ctypes.c_long),
         ctypes.POINTER(ctypes.POINTER(GwSweepModel)), ctypes.POINTER(GwErr))
_declare("gw_sweep_run_text_warned", ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int, PROGRESS,
         ctypes.c_void_p, ctypes.POINTER(c_double_p), ctypes.POINTER(ctypes.c_long),
         ctypes.POINTER(ctypes.POINTER(GwSweepModel)), ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(GwErr))
_declare("gw_free", None, ctypes.c_void_p)
_declare("gw_interrupt_begin", ctypes.c_int)
_declare("gw_interrupt_end", ctypes.c_int)

if lib.gw_param_row_size() != ctypes.sizeof(GwParam) or lib.gw_study_size() != ctypes.sizeof(GwStudy):
    raise ImportError(f"granwave: {path} does not match this module (gw_param {lib.gw_param_row_size()} "
                      f"bytes, expected {ctypes.sizeof(GwParam)}; gw_study {lib.gw_study_size()}, expected "
                      f"{ctypes.sizeof(GwStudy)}): use the module installed with that library")
