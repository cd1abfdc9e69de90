"""A study's results in Python: the Result dict (attribute access, == by
value with the run's own timings left out) and the reading of a result
struct through its field table into Python numbers and numpy arrays.
Separate from the studies (_core.py) and the sweeps (_sweep.py), which both
return Results.
"""
import ctypes

import numpy as np

from ._values import DARRAY, DOUBLE, FARRAY, FLAG, IARRAY, INT, LONG, TEXT


# the results that time the run on the machine, not results of the model, left
# out of ==: the field tables' rows in ms and their "wall-clock time" rows
# (wall_time_ms, wall_time_s; dispersion's integrate_ms and fft_ms), gathered
# as each Study reads its table
CLOCK_KEYS = set()


def same_value(a, b):
    """a and b hold the same results: dicts by key (wall-clock times left out),
    arrays by shape and value (NaN equal to NaN in the same place), floats by
    value or both NaN, lists and tuples item by item, anything else by ==."""
    if isinstance(a, dict) and isinstance(b, dict):
        ka, kb = set(a) - CLOCK_KEYS, set(b) - CLOCK_KEYS
        return ka == kb and all(same_value(a[k], b[k]) for k in ka)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        if not (isinstance(a, np.ndarray) and isinstance(b, np.ndarray)) or a.shape != b.shape:
            return False
        if np.ma.isMaskedArray(a) or np.ma.isMaskedArray(b):  # undecided flags: masked in the same places
            ma, mb = np.ma.getmaskarray(a), np.ma.getmaskarray(b)
            return bool((ma == mb).all() and np.array_equal(np.ma.getdata(a)[~ma], np.ma.getdata(b)[~mb]))
        try:
            return bool(np.array_equal(a, b, equal_nan=True))
        except TypeError:  # text columns (a sweep's grid of names): no NaN to match
            return bool(np.array_equal(a, b))
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return type(a) is type(b) and len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float) and a != a and b != b:
        return True
    r = a == b
    return r if isinstance(r, bool) else bool(r)


class Result(dict):
    """A study's results: a dict (keys as in the CLI's JSON) with attribute access.
    Numbers are Python floats and ints, yes/no results bools (None where the
    program's JSON has null: undecided), series numpy arrays, yes/no arrays
    bool arrays (a numpy masked array, masked where undecided, when any entry
    is: tolist() gives None there, as the JSON's null); tables with named
    columns (the energy ledger) are dicts of arrays. Two results are == when
    they hold the same results: the same keys, arrays of the same shape and
    values (NaN equal to NaN in the same place), the same numbers; the run's
    own timings (wall_time_ms, wall_time_s, dispersion's integrate_ms and
    fft_ms) are left out. A Result pickles and copies as a dict does."""

    __hash__ = None

    def __eq__(self, other):
        # dict's == compared arrays element-wise and asked their truth: two runs
        # of the same inputs raised "The truth value of an array ... is
        # ambiguous", or were unequal by their wall-clock time
        if not isinstance(other, dict):
            return NotImplemented
        return same_value(self, other)

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):  # the keys an attribute reaches, for completion (r.<TAB> in a notebook)
        return sorted(set(super().__dir__()) | {k for k in self if isinstance(k, str) and k.isidentifier()})

    def __repr__(self):
        parts = []
        for k, v in self.items():
            if isinstance(v, np.ndarray):
                parts.append(f"{k}=array{list(v.shape)}")
            elif isinstance(v, dict):
                parts.append(f"{k}={{{', '.join(v)}}}")
            elif isinstance(v, float):
                parts.append(f"{k}={v:.6g}")
            else:
                parts.append(f"{k}={v!r}")
        return "Result(" + ", ".join(parts) + ")"


def _dim(spec, scalars):
    if spec is None:
        return 1
    return int(spec) if spec.isdigit() else int(scalars[spec])


def read_result(fields, base):
    res = Result()
    scalars = {}
    for f in fields:
        addr = base + f.offset
        if f.type == DOUBLE:
            v = ctypes.c_double.from_address(addr).value
        elif f.type == INT:
            v = ctypes.c_int.from_address(addr).value
        elif f.type == FLAG:  # as the JSON's true, false (and null: -1, undecided)
            i = ctypes.c_int.from_address(addr).value
            v = None if i < 0 else bool(i)
        elif f.type == LONG:
            v = ctypes.c_long.from_address(addr).value
        elif f.type == TEXT:  # a text result (names, comma-separated): str or None
            t = ctypes.c_char_p.from_address(addr).value
            res[f.name] = t.decode() if t is not None else None
            continue
        else:
            continue
        scalars[f.name] = v
        res[f.name] = v
    for f in fields:
        if f.type not in (DARRAY, IARRAY, FARRAY):
            continue
        ptr = ctypes.c_void_p.from_address(base + f.offset).value
        rows, cols = _dim(f.rows, scalars), _dim(f.cols, scalars)
        if not ptr or rows <= 0 or cols <= 0:
            continue
        ctype = ctypes.c_double if f.type == DARRAY else ctypes.c_int
        a = np.ctypeslib.as_array((ctype * (rows * cols)).from_address(ptr)).copy()
        if f.type == FARRAY:  # as the JSON's true, false and null: -1 (undecided) masked
            a = np.ma.MaskedArray(a > 0, mask=a < 0) if (a < 0).any() else a != 0
        if f.cols is not None:
            a = a.reshape(rows, cols)
        if f.choices and a.ndim == 2 and len(f.choices) == cols:
            res[f.name] = {c: a[:, j].copy() for j, c in enumerate(f.choices)}
        else:
            res[f.name] = a
    return res
