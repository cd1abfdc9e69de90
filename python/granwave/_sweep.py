"""Sweeps over the library's sweep models from Python: a grid and the
parameters as the text of a sweep config (each value converted as a study's
keyword is, each line within the library's reader), run by the library,
its table returned as a Result of arrays. Separate from the studies
(_core.py): a sweep runs many cases through one config, not one study's
struct.
"""
import ctypes
import itertools
import math
import numbers
import os
import re

import numpy as np

from . import _lib
from ._core import Interruptible, Progress, issue
from ._errors import GW_EINVAL, GranwaveError, GranwaveValueError, _raise, keyword_text
from ._lib import lib
from ._result import Result
from ._values import (FLAG, TEXT, _BYTES, _digits, _fspath, _integer, _items, _kind, _line, _plain, _scalar, _show,
                      _text, _texts, read_table)


def sweep_models():
    n = ctypes.c_int()
    arr = lib.gw_sweep_models(ctypes.byref(n))
    return {arr[i].contents.name.decode(): arr[i].contents for i in range(n.value)}


_SWEEP_ROWS = {}


def _sweep_rows(model, m, key):
    """The rows of the studies' tables named as the sweep key (the tables a
    model's keys come from: chain's, layer-impact's), [] for a key of the model
    alone (the layer's placement: point, points, spacing)."""
    if model not in _SWEEP_ROWS:
        rows = {}
        for i in range(lib.gw_study_count()):
            _, table = read_table(lib.gw_study_get(i).contents.params)
            for r in table:
                if m.has_key(r.name.encode()):
                    rows.setdefault(r.name, []).append(r)
        _SWEEP_ROWS[model] = rows
    return _SWEEP_ROWS[model].get(key.replace("_", "-"), [])


def _ini_value(key, v, rows=()):
    """v as the text of a sweep config's value of key. A flag's value (a row of
    type bool) is converted by the row as a study's keyword is (True, False,
    an np.bool_: _flag); any other key refuses a bool as the studies do ("expected a
    number, got True"): grid={"n": [True, 2]} ran a column of 1 bead, and
    vimp=True an impact at 1 m/s, where chain(n=True) is refused."""
    if rows and all(r.type == FLAG for r in rows):
        try:
            return _text(rows[0], v)
        except TypeError as e:  # named by the caller, as the other values are
            raise TypeError(str(e).split(": ", 1)[-1]) from None
    if not isinstance(v, (str, os.PathLike)) and isinstance(_scalar(v), bool):
        raise TypeError(f"expected a number, got {_show(v)}")
    s = _text_plain(v, key)
    if any(c in s for c in "\n\r;#\0") or not s.strip():
        raise GranwaveValueError(f"{key}: value {_show(s)} cannot go into a sweep (empty, or holds ';', '#', NUL or a "
                                 "newline)", GW_EINVAL)
    # The config reader drops the blanks around a value: sample=" a.txt" ran
    # the file 'a.txt' (the result's column said ' a.txt'), where
    # layer_impact(sample=" a.txt") opens ' a.txt'. (Around a number or a
    # choice they change nothing.)
    file = bool(rows) and all(r.type == TEXT for r in rows)
    if file and s != s.strip(_INI_BLANKS):
        raise GranwaveValueError(f"{key}: value {_show(s)} begins or ends with a blank, which a sweep's config reader "
                                 f"drops (it would run {_show(s.strip(_INI_BLANKS))})", GW_EINVAL)
    # A file name as the OS gives it (undecodable bytes as surrogates, from
    # os.listdir or os.fsdecode) goes into the config as those bytes, as a
    # study's keyword does; any other value must be text (the whole config
    # failed to encode, a UnicodeEncodeError naming no keyword).
    try:
        s.encode()
    except UnicodeEncodeError:
        if not file:
            raise GranwaveValueError(f"{key}: {_show(s)} cannot be encoded", GW_EINVAL) from None
    return s


_INI_BLANKS = " \t\v\f"  # what libinih's strip takes (isspace; newlines are refused above)


def _text_plain(v, key="value"):
    if isinstance(v, os.PathLike):
        v = _fspath("", v)
        return os.fsdecode(v) if isinstance(v, bytes) else _plain(v)
    if isinstance(v, str):
        return _plain(v)
    x = _scalar(v)
    if isinstance(x, bool):
        return "1" if x else "0"
    if isinstance(x, int):
        return _digits(key, x)
    if isinstance(x, float):
        return repr(x)
    raise TypeError(f"cannot use a {_kind(v)} as a sweep value")


def _looks_like_range(s):
    """The library's test of a grid value "A:B" (common/sweep/gw_sweep_config.c,
    looks_like_range): one ':' and only digits, signs and blanks around it.
    Such a value alone on its grid line is the range A..B, not one value."""
    return s.count(":") == 1 and all(c in " \t+-0123456789" for c in s.replace(":", ""))


_GRID_MAX = 10**9  # cases of a sweep (the library's bound: "the grid has more than 1e9 cases")
_SWEEP_CONFIG_MAX = 1 << 20  # bytes of a sweep's config, as text too (the library's GW_SWEEP_CONFIG_MAX)
# the most values of one grid key but a range (written A:B): each takes a character and its ','
_GRID_VALUES_MOST = _SWEEP_CONFIG_MAX // 2


def _grid_values(key, v):
    given = v
    if isinstance(v, str) and _looks_like_range(_plain(v)):
        # the string 'A:B' is the range A..B: bounded as a range object is
        # ('1:9223372036854775807' raised a bare MemoryError naming nothing)
        a, b = (x.strip() for x in _plain(v).split(":"))
        try:  # '+1:3' ran 3 cases in C and was one value '+1:3' here
            v = range(int(a), int(b) + 1)
        except ValueError:
            return [_plain(v)]  # not integers ('1-:3'): the library names it
    if isinstance(v, range):
        # read whole below: range(2, 10**12) raised an empty MemoryError after
        # taking the memory there was, range(1, 2**80) OverflowError
        try:
            n = len(v)
        except OverflowError:
            n = math.inf
        if n > _GRID_MAX:
            raise GranwaveValueError(f"sweep() grid: '{key}': {_show(given)} holds more than 1e9 values: the grid has more "
                                     f"than 1e9 cases", GW_EINVAL)
    if isinstance(v, str):
        return [x.strip() for x in _plain(v).split(",")]
    if isinstance(v, (numbers.Number, os.PathLike)):
        return [v]
    if isinstance(v, range):
        return list(v)
    return _items(f"sweep() grid: '{key}'", v, _GRID_VALUES_MOST)


_SWEEP_KEYWORDS = {}


def _sweep_names(model, m):
    """The rows' names of the model's keys (keyword_text)."""
    _sweep_rows(model, m, "")
    return set(_SWEEP_ROWS[model]) | {"point", "points", "spacing"}


def _sweep_hint(model, m, k):
    """ " (did you mean 'vimp'?)" for a misspelt sweep key: the nearest keyword
    of the studies' tables that the model takes, else ""."""
    import difflib
    if model not in _SWEEP_KEYWORDS:
        names = set()
        for i in range(lib.gw_study_count()):
            _, rows = read_table(lib.gw_study_get(i).contents.params)
            names.update(r.name for r in rows if m.has_key(r.name.encode()))
        names.add("point")
        _SWEEP_KEYWORDS[model] = sorted(n.replace("-", "_") for n in names if m.has_key(n.encode()))
    close = difflib.get_close_matches(k.replace("-", "_").lower(), _SWEEP_KEYWORDS[model], n=1, cutoff=0.75)
    return f" (did you mean '{close[0]}'?)" if close else ""


def _model_has(m, name):
    """Whether the sweep model m takes the key name. A name holding a NUL is
    none: the library reads a name up to its first NUL, so that 'n\\x00x'
    passed as 'n' and the config text then failed as "sweep:4: syntax error"."""
    return "\0" not in name and bool(m.has_key(name.encode()))


_SWEEP_LINE_MAX = 198  # the longest line the library's config reader takes (libinih's buffer less 2)


def _in_section(e, section):
    """A refusal of a grid or params value, "KEY: ...", as the library words
    its own for a sweep's values: "sweep: [grid] KEY: ..." ("n: empty list of
    grid values" named no call before session 43). One that names its call
    already ("sweep: ...", "sweep() grid: ...") is kept."""
    text = str(e)
    if text.startswith("sweep"):
        return e
    return GranwaveValueError(f"sweep: [{section}] {text}", e.status)


def _grid_lines(model, m, k, v, lines, axes, key_bytes):
    """The config lines of grid key k (values v) appended to lines, its
    values to axes and its lines' bytes to key_bytes; refused naming k."""
    name = k.replace("_", "-")
    if not _model_has(m, name):
        raise TypeError(f"sweep() grid: '{_line(k)}' is not a parameter of model {model}{_sweep_hint(model, m, k)}")
    if v is None or isinstance(v, (set, frozenset, dict) + _BYTES) or \
            (isinstance(v, np.ndarray) and v.ndim != 1):
        raise TypeError(f"sweep() grid: '{_line(k)}': expected a list, a range, a 1-D array or a string, "
                        f"got {type(v).__name__}")
    vals = _grid_values(k, v)
    if not vals:
        # a reversed range "A:B" as the library names one (grid={"n": "5:1"}
        # said "n: empty list of grid values")
        if isinstance(v, str):
            raise GranwaveValueError(f"{_line(k)}: range '{_line(_plain(v).strip())}' is empty (start > end)",
                                     GW_EINVAL)
        raise GranwaveValueError(f"{_line(k)}: empty list of grid values", GW_EINVAL)
    axes[k] = vals
    try:
        texts = [_ini_value(k, x, _sweep_rows(model, m, k)) for x in vals]
    except TypeError as e:
        raise TypeError(f"sweep() grid: '{_line(k)}': {e}") from None
    if any("," in t for t in texts):  # the list's separator: 'a,b' ran two cases
        raise GranwaveValueError(f"{_line(k)}: a grid value holds ',' (the list separator of a sweep)", GW_EINVAL)
    # a list item 'A:B' alone on its line is the library's range: grid={"n": ["1:3"]}
    # ran 3 cases where the result's n had one entry (its columns 3)
    if not isinstance(v, str) and any(_looks_like_range(t) for t in texts):
        raise GranwaveValueError(f"sweep() grid: '{_line(k)}': a list item "
                                 f"{next(t for t in texts if _looks_like_range(t))!r} is a range, not one value: give "
                                 f"the string 'A:B' or range(A, B + 1)", GW_EINVAL)
    n_lines = len(lines)
    # consecutive integers as the range A:B; a longer list goes on over
    # indented lines after a line ending with a comma (each line of the
    # config at most 198 characters, the library's reader's buffer)
    ints = [x for x in vals if isinstance(x, numbers.Integral) and not isinstance(x, bool)]
    if len(vals) > 2 and len(ints) == len(vals) and all(b - a == 1 for a, b in zip(ints, ints[1:])):
        lines.append(f"{name} = {int(ints[0])}:{int(ints[-1])}")
    else:
        line = f"{name} = "
        for j, t in enumerate(texts):
            item = t + ("," if j < len(texts) - 1 else "")
            if len(line) + len(item) + 1 > _SWEEP_LINE_MAX and line.strip() and not line.endswith("= "):
                lines.append(line.rstrip())
                line = "    "
            line += item + " "
        lines.append(line.rstrip())
    key_bytes[k] = sum(len(x) + 1 for x in lines[n_lines:])
    if any(len(x) > _SWEEP_LINE_MAX for x in lines):  # one value longer than a line
        raise GranwaveValueError(f"sweep() grid: '{_line(k)}': a value takes "
                                 f"{max(len(t) for t in texts)} characters, "
                                 f"above the {_SWEEP_LINE_MAX} of a line of the library's config reader", GW_EINVAL)


def _config_text(model, grid, params):
    """The text of the sweep config of model, grid and params, as sweep()
    hands it to the library, with the model and the grid's values by key
    (axes); refused naming the keyword."""
    if not isinstance(grid, dict):
        raise TypeError(f"sweep(): grid must be a dict {{keyword: values}}, not {type(grid).__name__}")
    models = sweep_models()
    if not isinstance(model, str):  # a list raised "unhashable type: 'list'"
        raise TypeError(f"sweep(): model must be a str ({', '.join(map(repr, models))}), not {_kind(model)}")
    if model not in models:
        # quoted as repr: a newline or a control character in the name broke the message's line
        raise GranwaveValueError(f"sweep: unknown model {_show(model)} ({', '.join(models)})", GW_EINVAL)
    m = models[model]
    if not grid:
        raise GranwaveValueError("sweep: grid needs at least one key with its values", GW_EINVAL)
    lines = ["[sweep]", f"model = {model}", "[grid]"]
    axes = {}
    key_bytes = {}  # the config's bytes of each grid key's lines
    seen = {}  # t_max and t-max are one key: "sweep: sweep:5: duplicate key 't-max'" named a line of a text never shown
    for k in itertools.chain(grid, (k for k, v in params.items() if v is not None)):
        if not isinstance(k, str):  # AttributeError: 'int' object has no attribute 'replace'
            raise TypeError(f"sweep() grid: a key is a keyword name (str), got {type(k).__name__} ({_show(k)})")
        name = k.replace("_", "-")
        if name in seen and seen[name] != k:
            raise TypeError(f"sweep(): '{_line(seen[name])}' and '{_line(k)}' name the same parameter")
        seen.setdefault(name, k)
    for k, v in grid.items():
        try:
            _grid_lines(model, m, k, v, lines, axes, key_bytes)
        except GranwaveValueError as e:
            raise _in_section(e, "grid") from None
    lines.append("[params]")
    for k, v in params.items():
        if v is None:
            continue
        name = k.replace("_", "-")
        if not _model_has(m, name):
            raise TypeError(f"sweep() got an unexpected keyword argument '{_line(k)}' "
                            f"(not a parameter of model {model})"
                            f"{_sweep_hint(model, m, k)}")
        if k in grid:
            raise TypeError(f"sweep(): '{_line(k)}' given both in grid and as a keyword")
        try:
            lines.append(f"{name} = {_ini_value(k, v, _sweep_rows(model, m, k))}")
        except TypeError as e:
            raise TypeError(f"sweep(): '{_line(k)}': {e}") from None
        except GranwaveValueError as e:
            raise _in_section(e, "params") from None
        if len(lines[-1]) > _SWEEP_LINE_MAX:  # a long path: "sweep:6: a line of ..." before
            raise GranwaveValueError(f"sweep(): '{_line(k)}': its value takes {len(lines[-1])} "
                                     f"characters on the sweep's "
                                     f"config line, above the {_SWEEP_LINE_MAX} the library's reader takes (a shorter "
                                     f"path, relative to the working directory)", GW_EINVAL)
    text = "\n".join(lines) + "\n"
    if len(text.encode(errors="surrogateescape")) > _SWEEP_CONFIG_MAX:  # the library's bound, by key
        big = max(key_bytes, key=key_bytes.get)
        raise GranwaveValueError(f"sweep() grid: '{big}': the sweep's config takes {len(text)} bytes, above the "
                                 f"{_SWEEP_CONFIG_MAX} the library reads (a range for consecutive integers, or "
                                 f"fewer values)", GW_EINVAL)
    return text, m, axes


def _sweep_raise(rc, err, model, m, params, axes):
    """The library's refusal of a sweep's config or of its check pass, raised
    as sweep() raises it."""
    # "sweep:4: n: '3' and '3' in list '3, 3' are the same value" named
    # a line of the config this module wrote, which the caller never
    # saw: the key the message names after it is the caller's input
    line = re.match(rb"sweep:[0-9]+: ", err.msg)
    if line:
        err.msg = err.msg[line.end():]
    _raise(rc, err, "sweep", _sweep_names(model, m), _texts(list(params.values()) + [
        x for v in axes.values() for x in v]))


_lib._declare("gw_sweep_check_text", ctypes.c_int, ctypes.c_char_p, ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p),
              ctypes.POINTER(_lib.GwErr))


def check_sweep(model, grid, params):
    """The check pass of sweep(model, grid, **params) (gw_sweep_check_text):
    its refusals raised as sweep() raises them, else the pass's warnings as
    sweep() lists them (a list, empty when none). Nothing runs."""
    text, m, axes = _config_text(model, grid, params)
    err = _lib.GwErr()
    wtext = ctypes.c_void_p()
    rc = lib.gw_sweep_check_text(text.encode(errors="surrogateescape"), b"sweep", ctypes.byref(wtext),
                                 ctypes.byref(err))
    said = ctypes.string_at(wtext.value).decode(errors="replace") if wtext.value else ""
    lib.gw_free(wtext)
    if rc != 0:
        _sweep_raise(rc, err, model, m, params, axes)
    return [keyword_text(t, _sweep_names(model, m), _texts(list(params.values())))
            for t in said[:-1].split("\n")] if said else []


def run_sweep(model, grid, params, jobs, progress):
    # jobs reaches C as an int: a float, a bool or a str was cut or read
    # silently (1.5 ran 1 thread, 10**12 wrapped to a negative int: one per
    # CPU); an integer as every integer keyword takes one (_integer: a 0-d
    # array np.array(2) too, as n takes np.array(5))
    given, jobs = jobs, _integer(jobs)
    if jobs is None:
        raise TypeError(f"sweep(): jobs must be an integer, not {type(given).__name__}")
    if not -2**31 <= jobs < 2**31:  # the library's message for what does not fit its int
        raise GranwaveValueError(f"sweep: jobs: {_digits('sweep: jobs', jobs)} is outside [0, 4096] (0: one per CPU)",
                                 GW_EINVAL)
    if not isinstance(grid, dict):
        raise TypeError(f"sweep(): grid must be a dict {{keyword: values}}, not {type(grid).__name__}")
    cb = Progress(progress)
    text, m, axes = _config_text(model, grid, params)
    values = _lib.c_double_p()
    ncases = ctypes.c_long()
    mod = ctypes.POINTER(_lib.GwSweepModel)()
    err = _lib.GwErr()
    wtext = ctypes.c_void_p()  # the sweep's warnings, the program's lines (they were never issued here)
    try:
        with Interruptible() as it:
            cb.interruptible = it.on
            rc = lib.gw_sweep_run_text_warned(text.encode(errors="surrogateescape"), b"sweep", int(jobs), cb.c_fn,
                                              None, ctypes.byref(values), ctypes.byref(ncases), ctypes.byref(mod),
                                              ctypes.byref(wtext), ctypes.byref(err))
        said = ctypes.string_at(wtext.value).decode(errors="replace") if wtext.value else ""
        lib.gw_free(wtext)
        cb.reraise()
        if rc != 0:
            _sweep_raise(rc, err, model, m, params, axes)
        cases = list(itertools.product(*axes.values()))  # the C order: last key fastest
        if ncases.value != len(cases):  # each grid value here must be one case's value there
            raise GranwaveError(f"sweep: the library ran {ncases.value} cases where the grid gives {len(cases)}: "
                                f"the grid values are not one value each ({_show(text)})", GW_EINVAL)
        ncol = m.ncolumns
        cols = [m.columns[j].decode() for j in range(ncol)]
        a = np.ctypeslib.as_array(values, shape=(ncases.value * ncol,)).copy().reshape(ncases.value, ncol)
    finally:
        lib.gw_free(values)
    res = Result()
    for i, k in enumerate(axes):
        col = [c[i] for c in cases]
        try:
            res[k] = np.array(col, dtype=float)
        except (TypeError, ValueError):
            res[k] = np.array([_text_plain(x) for x in col])
    for j, c in enumerate(cols):
        res[c] = a[:, j]
    res["ncases"] = ncases.value
    # issued as GranwaveWarning and listed, as the studies' results do, with
    # the inputs named by their keywords (a dt above the step the cases take,
    # layer cases on a sample settled otherwise, chain cases that did not end)
    res["warnings"] = [keyword_text(t, _sweep_names(model, m), _texts(list(params.values())))
                       for t in said[:-1].split("\n")] if said else []
    issue("sweep", res["warnings"])
    return res
