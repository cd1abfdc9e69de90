"""The library's N x v grid (gw_chain_sweep_n_warned, chain/gw_chain.h) from
Python: one collision of the column for every impact speed and every N of a
range, the column's keywords those of granwave.chain, with the grid's "no
effect" warnings as a chain sweep's check pass says them. The grid's setup is
the chain study's (its table, gw_param_set), resolved by the library
(gw_chain_setup_resolve) as falcon resolves its column: N the range's first,
v_imp the first speed. No physics here.
"""
import copy
import ctypes

import numpy as np

from . import _lib
from ._core import (DARRAY, DOUBLE, FARRAY, FLAG, IARRAY, INT, LONG, TEXT, GranwaveValueError, GW_EINVAL,
                    Interruptible, Progress, Result, _raise, _texts, issue, keyword_text, read_result)
from ._lib import lib
from ._values import _digits, _integer, _items, _kind, _show

_lib._declare("gw_struct_size", ctypes.c_size_t, ctypes.c_char_p)
_lib._declare("gw_chain_setup_resolve", ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_chain_resolved_free", None, ctypes.c_void_p)
_lib._declare("gw_chain_study_work_check", ctypes.c_int, ctypes.c_long, ctypes.c_long, ctypes.c_int,
              ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_chain_sweep_n_warned", ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p,
              ctypes.POINTER(ctypes.c_double), ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int,
              _lib.PROGRESS, ctypes.c_void_p, ctypes.c_void_p, ctypes.POINTER(ctypes.c_void_p),
              ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_chain_result_free", None, ctypes.c_void_p)
_lib._declare("gw_chain_unfinished_warnings", ctypes.c_int, ctypes.c_int, ctypes.c_int,
              ctypes.POINTER(ctypes.c_void_p))

_INT_MAX = 2**31 - 1
_SPEEDS_MAX = 100000  # far above any study's (the work bound holds a grid to 2e6 bead^2)
# the keywords of granwave.chain the grid sets itself (n, vimp) or has no use for
# (trace: the grid keeps no series)
_NOT_TAKEN = {"n": "the grid's range, n=(A, B)", "vimp": "the grid's speeds, vimp=[...]",
              "trace": "the grid keeps no series"}


def _size(name):
    s = lib.gw_struct_size(name.encode())
    if not s:
        raise ImportError(f"granwave: {_lib.path} does not know the struct {name}")
    return s


def _range(n):
    """n=(A, B) (or [A, B], range(A, B + 1), an int N alone) as (A, B)."""
    if isinstance(n, range):
        if n.step != 1 or len(n) == 0:
            raise GranwaveValueError(f"sweep_n: n: {_show(n)} is not a range of consecutive N (step 1, not empty)",
                                     GW_EINVAL)
        return n[0], n[-1]
    one = _integer(n)
    if one is not None:
        return one, one
    if isinstance(n, (tuple, list)) and len(n) == 2:
        a, b = _integer(n[0]), _integer(n[1])
        if a is not None and b is not None:
            return a, b
    raise TypeError(f"sweep_n(): n must be (A, B) (two integers: N = A..B), a range or an integer, not {_kind(n)}")


def _number(v):
    """A 0-d numpy array of a real number as its number (np.array(0.3) is one
    speed, as granwave.chain takes it); anything else as it is."""
    if isinstance(v, np.ndarray) and v.ndim == 0 and v.dtype.kind in "iuf":
        return v[()]
    return v


def _speeds(vimp):
    vimp = _number(vimp)  # iterated, it raised "iteration over a 0-d array", naming no keyword
    if isinstance(vimp, (int, float, np.number)):
        items = [vimp]
    elif isinstance(vimp, (str, bytes, dict)) or not hasattr(vimp, "__iter__") or \
            (isinstance(vimp, np.ndarray) and vimp.ndim == 0):
        raise TypeError(f"sweep_n(): vimp must be a speed or a list of speeds (m/s), not {_kind(vimp)}")
    else:  # a generator that never ends is refused past the speeds a grid can hold
        items = _items("sweep_n: vimp", vimp, _SPEEDS_MAX)
    out = []
    for v in map(_number, items):
        if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating)):
            raise TypeError(f"sweep_n(): vimp: an item is a number (m/s), not {_kind(v)}")
        # an int kept whole, for the library to hold to vimp's range: float()
        # of 10**400 raised OverflowError, naming no keyword
        out.append(int(v) if isinstance(v, (int, np.integer)) else float(v))
    if not out:
        raise GranwaveValueError("sweep_n: vimp: no impact speed (give at least one)", GW_EINVAL)
    return out


_SAME_REL = 1e-12  # the chain sweep config's rule for a value listed twice (as gw_chain_sweep_n's)


def _repeat_check(v):
    """A speed given twice (equal, or within a relative 1e-12) refused naming
    vimp and both items, as gw_chain_sweep_n refuses it: each of its
    collisions would run twice ((1, 2), [0.3, 0.3] ran them into two rows)."""
    order = sorted(range(len(v)), key=lambda k: (v[k], k))
    pair = None
    for a, b in zip(order, order[1:]):
        x, y = v[a], v[b]
        if x == y or abs(y - x) <= _SAME_REL * max(abs(x), abs(y)):
            lo, hi = min(a, b), max(a, b)
            if pair is None or (hi, lo) < (pair[1], pair[0]):
                pair = (lo, hi)
    if pair is None:
        return
    j, i = pair
    if v[i] == v[j]:
        raise GranwaveValueError(f"sweep_n: vimp: item {i + 1} is the impact velocity {v[i]!r} m/s of item {j + 1} "
                                 "(each of its collisions would run twice)", GW_EINVAL)
    raise GranwaveValueError(f"sweep_n: vimp: item {i + 1}, {v[i]!r} m/s, and item {j + 1}, {v[j]!r} m/s, are the "
                             "same impact velocity to 12 digits (each of its collisions would run twice)", GW_EINVAL)


def _set(st, buf, name, value, kwargs):
    """One row of the chain setup, checked by the library against its range."""
    err = _lib.GwErr()
    rc = lib.gw_param_set(st.table, buf, name.encode(), value.encode(), ctypes.byref(err))
    if rc != 0:
        _raise(rc, err, "sweep_n", st.names, _texts(kwargs.values()))


def _warnings_list(ptr):
    text = ctypes.string_at(ptr.value).decode(errors="replace") if ptr.value else ""
    lib.gw_free(ptr)
    return text[:-1].split("\n") if text else []


def run_grid(chain_study, n, vimp, jobs, progress, kwargs):
    st = copy.copy(chain_study)  # the chain's table, its messages named sweep_n
    st.func = "sweep_n"
    for k in kwargs:
        if k in _NOT_TAKEN and kwargs[k] is not None:
            raise TypeError(f"sweep_n() got an unexpected keyword argument '{k}' ({_NOT_TAKEN[k]})")
    given, jobs = jobs, _integer(jobs)
    if jobs is None:
        raise TypeError(f"sweep_n(): jobs must be an integer, not {type(given).__name__}")
    if not 0 <= jobs <= 4096:
        raise GranwaveValueError(f"sweep_n: jobs: {_digits('sweep_n: jobs', jobs)} is outside [0, 4096] "
                                 "(0: one per CPU)", GW_EINVAL)
    lo, hi = _range(n)
    v = _speeds(vimp)
    cb = Progress(progress, "sweep_n")
    # the column's keywords, then N = B (its range) and every speed (theirs),
    # then the first case's N and speed (falcon's column: its calibration's
    # speed when restitution_v is not given)
    buf = st.setup({k: x for k, x in kwargs.items() if k not in _NOT_TAKEN})
    resolved = ctypes.create_string_buffer(_size("gw_chain_resolved"))
    err = _lib.GwErr()
    try:
        for x in (lo, hi):
            if not 1 <= x <= _INT_MAX:
                raise GranwaveValueError(f"sweep_n: n: {_digits('sweep_n: n', x)} is not a bead count >= 1", GW_EINVAL)
            _set(st, buf, "n", str(x), kwargs)
        if lo > hi:
            raise GranwaveValueError(f"sweep_n: n: ({lo}, {hi}): A > B, no column", GW_EINVAL)
        for x in v:
            _set(st, buf, "vimp", _digits("sweep_n: vimp", x) if isinstance(x, int) else repr(x), kwargs)
        v = [float(x) for x in v]
        _repeat_check(v)
        _set(st, buf, "n", str(lo), kwargs)
        _set(st, buf, "vimp", repr(v[0]), kwargs)
        rc = lib.gw_chain_study_work_check(lo, hi, len(v), ctypes.byref(err))
        if rc != 0:
            _raise(rc, err, "sweep_n", st.names, _texts(kwargs.values()))
        rc = lib.gw_chain_setup_resolve(buf, resolved, ctypes.byref(err))
        if rc != 0:
            _raise(rc, err, "sweep_n", st.names, _texts(kwargs.values()))
        # gw_chain_resolved: params, then run (both of 8-byte alignment: run
        # right after params)
        psize, osize = _size("gw_chain_params"), _size("gw_chain_run_opts")
        off = (psize + 7) // 8 * 8
        if off + osize > len(resolved):
            raise ImportError("granwave: gw_chain_resolved is not laid out as this module reads it")
        base = ctypes.addressof(resolved)
        nn, nv = hi - lo + 1, len(v)
        rsize = _size("gw_chain_result")
        res = ctypes.create_string_buffer(rsize * nn * nv)
        speeds = (ctypes.c_double * nv)(*v)
        wl = ctypes.c_void_p()
        try:
            with Interruptible() as it:
                cb.interruptible = it.on
                rc = lib.gw_chain_sweep_n_warned(base, base + off, speeds, nv, lo, hi, jobs, cb.c_fn, None, res,
                                                 ctypes.byref(wl), ctypes.byref(err))
            said = _warnings_list(wl)
            cb.reraise("sweep_n")
            if rc != 0:
                _raise(rc, err, "sweep_n", st.names, _texts(kwargs.values()))
            out = _read(st, res, rsize, nv, nn)
        finally:
            for i in range(nv * nn):
                lib.gw_chain_result_free(ctypes.addressof(res) + i * rsize)
    finally:
        lib.gw_chain_resolved_free(resolved)  # zeroed, or what resolve made (also after a failure)
        st.st.clear(buf)
    unfinished = int(np.count_nonzero(~np.asarray(out["converged"], dtype=bool)))
    if unfinished:  # the collisions not ended at t_max, as falcon says them
        wl = ctypes.c_void_p()
        lib.gw_chain_unfinished_warnings(unfinished, nv * nn, ctypes.byref(wl))
        said += _warnings_list(wl)
    r = Result()
    r["n"] = np.arange(lo, hi + 1)
    r["v_imp"] = np.array(v)
    r.update(out)
    r["warnings"] = [keyword_text(t, st.names, _texts(kwargs.values())) for t in said]
    issue("sweep_n", r["warnings"])
    return r


def _read(st, res, rsize, nv, nn):
    """Every result of the chain study's table held in gw_chain_result (the
    start of gw_chain_collision) as an array [velocity, N]; the per-bead
    series a list [velocity][N] of arrays."""
    fields = [f for f in st.fields if f.offset < rsize]  # n too: the per-bead series' length
    rows = [[read_result(fields, ctypes.addressof(res) + (iv * nn + j) * rsize) for j in range(nn)]
            for iv in range(nv)]
    out = {}
    for f in fields:
        if f.name == "n":  # the grid's N, r.n
            continue
        if f.type in (DARRAY, IARRAY, FARRAY):
            out[f.name] = [[rows[iv][j].get(f.name, np.zeros(0)) for j in range(nn)] for iv in range(nv)]
        elif f.type == TEXT:
            out[f.name] = np.array([[rows[iv][j][f.name] for j in range(nn)] for iv in range(nv)], dtype=object)
        elif f.type == FLAG:
            vals = [[rows[iv][j][f.name] for j in range(nn)] for iv in range(nv)]
            a = np.array([[x is True for x in row] for row in vals])
            undecided = np.array([[x is None for x in row] for row in vals])
            out[f.name] = np.ma.MaskedArray(a, mask=undecided) if undecided.any() else a
        elif f.type in (DOUBLE, INT, LONG):
            out[f.name] = np.array([[rows[iv][j][f.name] for j in range(nn)] for iv in range(nv)],
                                   dtype=float if f.type == DOUBLE else int)
    return out
