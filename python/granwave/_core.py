"""The generic machinery under granwave's functions: parameter tables read from
the library (names, types, units, ranges, defaults, help), values set by name
with the library's checks, studies run through the library's index, results
read through their tables into Python numbers and numpy arrays, errors turned
into exceptions. No physics here: every number comes from libgranwave.
"""
import ctypes
import itertools
import math
import numbers
import os
import re
import signal
import threading

import numpy as np

from . import _lib
from ._lib import lib

# gw_param_type (common/gw_param.h)
DOUBLE, INT, LONG, FLAG, CHOICE, TEXT, LIST, RANGE, DARRAY, IARRAY, FARRAY = range(11)
_TYPE_NAMES = ["float", "int", "int", "bool", "choice", "str", "list of float", "range A:B",
               "array", "int array", "bool array"]

# status codes (common/gw_common.h)
GW_EINVAL, GW_ENOMEM, GW_EIO, GW_ESOLVER, GW_EFORMAT, GW_EUNSUPPORTED, GW_EENERGY, GW_ELIMIT, \
    GW_ECANCELED = -1, -2, -3, -4, -5, -6, -7, -8, -9


class GranwaveError(Exception):
    """A libgranwave call failed; .status is the library's code, the text its message."""

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status


class GranwaveValueError(GranwaveError, ValueError):
    """A bad input value (GW_EINVAL) or a malformed input file (GW_EFORMAT)."""


class GranwaveIOError(GranwaveError, OSError):
    """A file could not be read or written (GW_EIO)."""


class GranwaveRunError(GranwaveError, RuntimeError):
    """The run failed: solver failure, step or time limit, energy monitor."""


class GranwaveUnsupported(GranwaveError, NotImplementedError):
    """Not available in this build (e.g. HDF5)."""


class GranwaveWarning(RuntimeWarning):
    """A run that ended with results the program warns about on stderr (a
    collision cut at t_max, a sample that did not settle, an undecided
    bounce, ...): the result is returned and records it (converged False,
    undecided, unfinished, ...); the warning says what is not final, in the
    library's text (the program's line after "warning: ", its inputs named by
    their keywords: keyword_text), which the result lists too (warnings)."""


def warn(what, text, stacklevel=3):
    """One GranwaveWarning "what: text", shown at the caller's line (stacklevel
    3: the caller of the public function that calls this)."""
    import warnings
    warnings.warn(f"{what}: {text}", GranwaveWarning, stacklevel=stacklevel)


# an input named as the program's flag ("raise --t-max"): two dashes at a word's
# start, then the flag's name
_FLAG_RE = re.compile(r"(?<![\w./-])--([a-z][a-z0-9]*(?:-[a-z0-9]+)*)(?![\w/-])")
# a command line of the program quoted in a text ("one column's collision:
# granwave chain --n 3"): the program's, left as it is
_COMMAND_RE = re.compile(r"granwave [a-z][a-z-]*(?: --[a-z][a-z0-9-]*(?: [^\s,;()]+)?)+")


def keyword_text(text, names, keep=()):
    """The library's text (an error message, a warning) with its inputs named
    as Python names them. The library writes an input as the program's flag
    ("raise --t-max", "an --f0 so small") or by its row's name ("t-max = 0.05
    s", "dt-out: ..."), the program prints that as it is (its messages stay
    byte for byte), and Python said "--t-max" to a caller who wrote t_max=.
    Here each input of names (the rows' names, '-' in them: the call's
    inputs) becomes its keyword (t_max), as a flag or as a whole word; a
    flag that is no input of the call (the program's --out where the
    function has no out), a quoted command line of the program ("granwave
    chain --n 3") and the call's own text values quoted back (keep: a sample
    file named t-max) stay as they are."""
    if not text or not names:
        return text
    names = set(names)
    hy = sorted((n for n in names if "-" in n), key=len, reverse=True)
    bare = re.compile(r"(?<![\w./-])(" + "|".join(map(re.escape, hy)) + r")(?![\w/-]|\.\w)") if hy else None

    def flag(m):
        return m.group(1).replace("-", "_") if m.group(1) in names else m.group(0)

    def words(part):
        part = _FLAG_RE.sub(flag, part)
        return bare.sub(lambda b: b.group(1).replace("-", "_"), part) if bare else part

    # the spans left as they are: command lines, then the values quoted back
    spans = [m.span() for m in _COMMAND_RE.finditer(text)]
    for k in sorted({k for k in keep if k}, key=len, reverse=True):
        for m in re.finditer(re.escape(k), text):
            if not any(a < m.end() and m.start() < b for a, b in spans):
                spans.append(m.span())
    out, pos = [], 0
    for a, b in sorted(spans):
        out += [words(text[pos:a]), text[a:b]]
        pos = b
    out.append(words(text[pos:]))
    return "".join(out)


def _texts(values):
    """The str values among values (a path as its str): what a message may
    quote back (keyword_text's keep)."""
    out = []
    for v in values:
        try:
            v = _fspath("", v)
        except TypeError:  # refused where it is set
            continue
        if isinstance(v, bytes):
            v = os.fsdecode(v)
        if isinstance(v, str):
            out.append(v)
        elif isinstance(v, (list, tuple)):
            out += [x for x in v if isinstance(x, str)]
    return out


def _raise(rc, err, what, names=(), keep=()):
    """The exception for the library's status rc and message err, in the
    words of the call what; names: the rows' names of its inputs, keep: the
    call's text values (keyword_text)."""
    text = err.msg.decode(errors="replace") or lib.gw_strerror(rc).decode()
    text = keyword_text(text, names, keep)  # the library names a parameter by its flag; Python by its keyword
    # the library's run messages name the study already ("chain: bead 1 still on the wall ...")
    msg = text if text.startswith(what + ": ") else f"{what}: {text}"
    if rc in (GW_EINVAL, GW_EFORMAT):
        raise GranwaveValueError(msg, rc)
    if rc == GW_EIO:
        raise GranwaveIOError(msg, rc)
    if rc == GW_ENOMEM:
        raise MemoryError(msg)
    if rc == GW_EUNSUPPORTED:
        raise GranwaveUnsupported(msg, rc)
    if rc in (GW_ESOLVER, GW_ELIMIT, GW_EENERGY):
        raise GranwaveRunError(msg, rc)
    raise GranwaveError(msg, rc)


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
    program's JSON has null: undecided), series numpy arrays; tables with named
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


class Param:
    """One row of a parameter table."""

    def __init__(self, row):
        self.name = row.name.decode()
        self.keyword = self.name.replace("-", "_")
        self.type = row.type
        self.offset = row.offset
        self.unit = (row.unit or b"").decode()
        self.min, self.max = row.min, row.max
        self.open_min, self.open_max = bool(row.open_min), bool(row.open_max)
        self.or_zero = bool(row.or_zero)  # 0 taken besides [min, max] (gw_param.h)
        self.optional = bool(row.optional)  # not given (None) is told from the default given
        self.default = row.default.decode() if row.default is not None else None
        self.help = (row.help or b"").decode()
        self.choices = row.choices.decode().split(",") if row.choices else None
        self.rows = row.rows.decode() if row.rows else None
        self.cols = row.cols.decode() if row.cols else None

    def doc(self):
        kind = "one of " + ", ".join(self.choices) if self.type == CHOICE else _TYPE_NAMES[self.type]
        unit = f" [{self.unit}]" if self.unit else ""
        return f"{self.keyword} ({kind}){unit}: {self.help}"


def read_table(fn):
    t = fn()
    rows = []
    i = 0
    while t[i].name:
        rows.append(Param(t[i]))
        i += 1
    return t, rows


def _scalar(v):
    """v as a plain Python bool, int or float when it is one number: a Python or
    numpy number (numbers.Real) or a 0-d array of one (a numpy reduction with
    keepdims, np.asarray(x), a[()] of a view); None when it is not. A date or a
    duration (np.datetime64, np.timedelta64, an Integral to numpy) is no number:
    int() of one failed with "int() argument must be ... 'datetime.timedelta'",
    naming no keyword."""
    if isinstance(v, np.ndarray) and v.ndim == 0 and v.dtype.kind in "biuf":
        v = v[()]
    if isinstance(v, (np.datetime64, np.timedelta64)):
        return None
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    try:
        if isinstance(v, numbers.Integral):
            return int(v)
        if isinstance(v, numbers.Real):
            return float(v)
    except (TypeError, ValueError, OverflowError):  # a Fraction beyond a double, an odd subclass
        return None
    return None


def _kind(value):
    return f"{type(value).__name__} ({value!r})"


def _flag(p, value):
    """A bool keyword's value as the text gw_param_set parses ("1", "0"): a
    Python bool, a numpy bool (np.bool_, a 0-d bool array), nothing else. A
    number or a string was taken too: trace=1.0, trace=np.float64(1) and
    trace="true" ran with the trace, trace=0 without, where trace=2 was
    refused; a flag takes True or False as the program's takes no value."""
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind == "b":
        value = value[()]
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    raise TypeError(f"{p.keyword}: expected True or False, got {_kind(value)}")


# text as bytes: a sequence of small integers to Python, never numbers a caller
# means (radii=bytearray([1]) ran a bead of 1 m, grid={"n": b"12"} n = 49 and 50)
_BYTES = (bytes, bytearray)


def _plain(s):
    """A str (a subclass too) as a plain str of its characters: a subclass's
    own __contains__, split or __str__ decided what the module checked and
    wrote (sample=S('a.txt\\0b') hid its NUL and opened 'a.txt')."""
    return str.__str__(s)


def _fspath(what, value):
    """value, an os.PathLike as its path (str or bytes); a path object whose
    __fspath__ fails or gives no path is refused naming what."""
    if not isinstance(value, os.PathLike):
        return value
    try:
        return os.fspath(value)
    except TypeError as e:
        raise TypeError(f"{what}: {e}" if what else str(e)) from None


def _items(what, value, most, why=""):
    """The items of value, a caller's sequence, as a list of at most `most`
    (int) items: the one place the module takes the items of a sequence it
    is given (a list keyword's, a range's ends, a sweep grid's values). A
    sequence that knows its length (a list, a tuple, an array, a range) is
    refused by it before any item is taken; any other iterable (a generator,
    an iterator) is taken item by item up to most + 1. A generator that never
    ends (radii=itertools.count(1)) ran on for good, taking memory as it went.
    Refused: GranwaveValueError "WHAT: N items, at most MOST" (the library's
    words for a list row's bound) or "WHAT: more than MOST items", then why
    (" (n = 3)": where the bound comes from)."""
    try:
        n = len(value)
    except TypeError:  # no length: a generator, an iterator
        n = None
    except OverflowError:  # a range of more items than an index holds
        n = math.inf
    if n is not None and n > most:
        raise GranwaveValueError(f"{what}: {n} items, at most {most}{why}", GW_EINVAL)
    items = list(itertools.islice(value, most + 1))
    if len(items) > most:  # no length, or one its iteration does not keep
        raise GranwaveValueError(f"{what}: more than {most} item{'s' if most != 1 else ''}{why}", GW_EINVAL)
    return items


_INT_MAX = 2**31 - 1  # a list row's count is a C int (gw_param_list.n)


def list_most(p, rows, kwargs):
    """(most, why): the most items list row p takes in a call with kwargs
    (the library's gw_param.rows; rows: the call's table by row name) and
    where that comes from, for a message. Its number; or the call's value of
    the integer row it names (radii: at most n beads; that row's default when
    not given; its maximum when given as no integer in its range, or for a
    range row); INT_MAX when the table gives none."""
    if p.rows is None:
        return _INT_MAX, ""
    if p.rows.isdigit():
        return min(int(p.rows), _INT_MAX), ""
    r = rows.get(p.rows)
    if r is None:
        return _INT_MAX, ""
    if r.type in (INT, LONG):
        given = kwargs.get(r.keyword)
        v = _scalar(given) if given is not None else int(r.default) if (r.default or "").isdigit() else None
        if isinstance(v, int) and not isinstance(v, bool) and r.min <= v <= r.max:
            return min(v, _INT_MAX), f" ({r.keyword} = {v}{'' if given is not None else ', its default'})"
    return int(min(max(r.max, 0), _INT_MAX)), f" (the most {r.keyword} takes)"


def _text(p, value, most=(_INT_MAX, "")):
    """A Python value as the text gw_param_set parses; most: the most items a
    list row takes in this call and why (list_most)."""
    if p.type == FLAG:  # every bool keyword, of every study and sweep, here
        return _flag(p, value)
    value = _fspath(p.keyword, value)
    if isinstance(value, bytes) and p.type == TEXT:  # a file name as the OS gives it
        value = os.fsdecode(value)
    if p.type == TEXT and not isinstance(value, str):
        # a number went to C as its digits: sample=3 looked for a file named '3'
        raise TypeError(f"{p.keyword}: expected a str or a path, got {_kind(value)}")
    if isinstance(value, str):
        value = _plain(value)
        if "\0" in value:  # C would read up to the NUL: another file, silently
            raise GranwaveValueError(f"{p.keyword}: {value!r} holds a NUL character", GW_EINVAL)
        return value
    if p.type == LIST:
        if _scalar(value) is not None and not isinstance(value, (bool, np.bool_, np.ndarray)):
            value = [value]
        # an ordered sequence of numbers: a set or a dict has no order (radii
        # went to the beads in hash order), an array of two or more dimensions
        # was flattened silently, a bad item was named by float() alone
        if isinstance(value, (set, frozenset, dict) + _BYTES) or not hasattr(value, "__iter__"):
            raise TypeError(f"{p.keyword}: expected a number or a sequence of numbers, got {_kind(value)}")
        if isinstance(value, np.ndarray) and value.ndim != 1:  # 0-d: "iteration over a 0-d array", unnamed
            raise TypeError(f"{p.keyword}: expected a 1-D sequence of numbers, got an array of shape {value.shape}")
        items = []
        for k, x in enumerate(_items(p.keyword, value, *most)):
            if isinstance(x, str):
                items.append(_plain(x))  # parsed and checked by the library, as on the command line
                continue
            v = _scalar(x)
            if v is None or isinstance(v, bool):
                raise TypeError(f"{p.keyword}: item {k + 1} is not a number ({x!r})")
            # an integer by its digits, as a scalar's: float() of one beyond the
            # largest double raised OverflowError naming nothing (radii=[1e-3,
            # 2**2000]); the library refuses it as not finite, naming the keyword
            items.append(str(v) if isinstance(v, int) else repr(v))
        if any("," in x for x in items):
            raise GranwaveValueError(f"{p.keyword}: an item holds ',' ({items!r})", GW_EINVAL)
        return ",".join(items) if items else "none"
    if p.type == RANGE:
        if isinstance(value, range):
            # len() of range(1, 2**80) raised OverflowError naming nothing
            if value.step != 1 or value.stop <= value.start:
                raise GranwaveValueError(f"{p.keyword}: a range of step 1 with at least one value, got {value!r}",
                                         GW_EINVAL)
            return f"{value.start}:{value.stop - 1}"
        x = _scalar(value)
        if isinstance(x, int) and not isinstance(x, bool):  # 7, np.int64(7), np.array(7)
            return str(x)
        # (A, B): exactly two ends; a fractional end goes to C as written, which
        # refuses it ("'1.5' is not an integer"), instead of being cut by int()
        if isinstance(value, (str,) + _BYTES) or not hasattr(value, "__len__") or \
                (isinstance(value, np.ndarray) and value.ndim != 1) or len(value) != 2:
            raise TypeError(f"{p.keyword}: expected (A, B), an integer or a range, got {value!r}")
        ends = []
        for x in _items(p.keyword, value, 2):
            v = _scalar(x)
            if v is None or isinstance(v, bool):
                raise TypeError(f"{p.keyword}: a range end must be a number, got {x!r}")
            ends.append(str(v) if isinstance(v, int) else repr(v))
        return ":".join(ends)
    x = _scalar(value)
    if isinstance(x, bool):
        raise TypeError(f"{p.keyword}: expected a number, got {value!r}")
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return repr(x)
    raise TypeError(f"{p.keyword}: cannot use a {_kind(value)}")


class Study:
    """A study of the library's index (app/lib/gw_study.h)."""

    def __init__(self, name):
        ptr = lib.gw_study_find(name.encode()) if "\0" not in name else None  # the library stops at a NUL
        if not ptr:
            raise GranwaveError(f"libgranwave has no study '{name}'", GW_EINVAL)
        self.st = ptr.contents
        self.name = name
        self.func = name.replace("-", "_")
        self.table, self.params = read_table(self.st.params)
        self.by_keyword = {p.keyword: p for p in self.params}
        self.by_name = {p.name: p for p in self.params}
        self.names = {p.name for p in self.params}  # the inputs' rows, for the library's texts (keyword_text)
        self.ftable, self.fields = read_table(self.st.fields)
        CLOCK_KEYS.update(f.name for f in self.fields if f.unit == "ms" or f.help.startswith("wall-clock"))

    def setup(self, kwargs):
        """A C setup struct with kwargs set over the defaults (caller clears it)."""
        buf = ctypes.create_string_buffer(self.st.params_size)
        self.st.init(buf)
        err = _lib.GwErr()
        try:
            for k, v in kwargs.items():
                p = self.by_keyword.get(k)
                if p is None:
                    raise TypeError(f"{self.func}() got an unexpected keyword argument '{k}'{self.hint(k)}")
                if v is None:
                    continue
                try:  # named as the library's messages are: the study, then the keyword
                    text = _text(p, v, list_most(p, self.by_name, kwargs)) if p.type == LIST else _text(p, v)
                except GranwaveValueError as e:
                    raise GranwaveValueError(f"{self.func}: {e}", GW_EINVAL) from None
                except TypeError as e:
                    raise TypeError(f"{self.func}: {e}") from None
                try:  # a file name as the OS gave it (undecodable bytes as surrogates) goes back as those bytes
                    raw = os.fsencode(text) if p.type == TEXT else text.encode()
                except UnicodeEncodeError:
                    raise GranwaveValueError(f"{self.func}: {p.keyword}: {text!r} cannot be encoded", GW_EINVAL) from None
                rc = lib.gw_param_set(self.table, buf, p.name.encode(), raw, ctypes.byref(err))
                if rc != 0:
                    _raise(rc, err, self.func, self.names, _texts(kwargs.values()))
        except BaseException:
            self.st.clear(buf)
            raise
        return buf

    def run(self, kwargs, progress=None):
        cb = Progress(progress, self.func)  # before setup: a refusal leaves nothing to clear
        buf = self.setup(kwargs)
        out = ctypes.create_string_buffer(self.st.fields_size)
        err = _lib.GwErr()
        try:
            with Interruptible() as it:
                cb.interruptible = it.on
                rc = self.st.run(buf, out, cb.c_fn, None, ctypes.byref(err))
            cb.reraise(self.func)
            if rc != 0:
                _raise(rc, err, self.func, self.names, _texts(kwargs.values()))
            r = read_result(self.fields, ctypes.addressof(out))
        finally:
            self.st.free_out(out)
            self.st.clear(buf)
        # The library's warning texts, each ending with a newline (gw_study_warnings;
        # the program prints each after "granwave NAME: warning: "): a list, and a
        # GranwaveWarning each, shown at the line that called the public function
        text = r.get("warnings") or ""
        keep = _texts(kwargs.values())
        r["warnings"] = [keyword_text(t, self.names, keep) for t in text[:-1].split("\n")] if text else []
        for w in r["warnings"]:
            warn(self.func, w, stacklevel=4)
        return r

    def hint(self, k):
        """ " (did you mean 'vimp'?)" for a misspelt keyword (vimpp, tmax, t-max), else ""."""
        if not isinstance(k, str):
            return ""
        import difflib
        close = difflib.get_close_matches(k.replace("-", "_").lower(), self.by_keyword, n=1, cutoff=0.75)
        return f" (did you mean '{close[0]}'?)" if close else ""

    def signature(self, positional=(), progress=False):
        """The public function's signature: every keyword of the table, None by
        default (the library's default, stated in the help); `positional` ones
        may be given by position. help() and a notebook's completion showed
        (**kwargs)."""
        import inspect
        P = inspect.Parameter
        ps = [P(k, P.POSITIONAL_OR_KEYWORD, default=None) for k in positional]
        ps += [P(p.keyword, P.KEYWORD_ONLY, default=None) for p in self.params if p.keyword not in positional]
        if progress:
            ps.append(P("progress", P.KEYWORD_ONLY, default=None))
        return inspect.Signature(ps)

    def doc(self, intro):
        lines = [intro, "", "Keywords (the flags of `granwave %s`, '-' written '_'; units SI):" % self.name]
        lines += ["  " + p.doc() for p in self.params]
        lines += ["", "Results (keys of the returned Result):"]
        kind = {FLAG: " (bool; 1 is True, 0 False, -1 None)", FARRAY: " (bool array)"}
        lines += ["  " + f.name + (f" [{f.unit}]" if f.unit else "") + kind.get(f.type, "") + ": " + f.help
                  for f in self.fields]
        return "\n".join(lines)


class Interruptible:
    """Ctrl-C during a library call. ctypes runs the call with the interpreter
    released, and Python's own SIGINT handling only acts once the call has
    returned: a chain of 20000 beads ran for minutes after Ctrl-C. From the main
    thread, the library's handler is installed for the call
    (gw_interrupt_begin): SIGINT stops the runs under way at their next step,
    and once the call has returned the signal is raised again for Python's own
    handler (KeyboardInterrupt by default; a handler of the program's runs
    instead, and the call then fails with status -9, "interrupted"). Left alone:
    calls from other threads (only the main thread receives signals in Python)
    and a SIGINT the program ignores."""

    def __enter__(self):
        self.on = (threading.current_thread() is threading.main_thread()
                   and signal.getsignal(signal.SIGINT) is not signal.SIG_IGN
                   and lib.gw_interrupt_begin() == 0)
        return self

    def __exit__(self, etype, exc, tb):
        if self.on and lib.gw_interrupt_end() and (etype is None or issubclass(etype, Exception)):
            signal.raise_signal(signal.SIGINT)  # Python's handler, restored by gw_interrupt_end
        return False


class Progress:
    """A Python progress callback f(done, total) as a C gw_progress_fn: an
    exception in f (KeyboardInterrupt included) stops the call and is raised
    again once the library has returned."""

    def __init__(self, fn, what="sweep"):
        if fn is not None and not callable(fn):
            # it failed only at the first report, after that much of the run
            raise TypeError(f"{what}: progress must be a callable f(done, total) or None, got "
                            f"{type(fn).__name__} ({fn!r})")
        self.fn = fn
        self.exc = None
        self.interruptible = False  # set by the call, under Interruptible
        self.interrupted = False
        self.c_fn = _lib.PROGRESS(self._call) if fn else _lib.PROGRESS()

    def _call(self, ctx, done, total):
        # On the main thread of an interruptible call the library's SIGINT
        # handler is in place, and Python's handling never ran while f did: a
        # callback that slept or computed for 10 s ignored Ctrl-C for those
        # 10 s. Python's handler is put back while f runs (KeyboardInterrupt in
        # f stops the call as any exception does) and the library's after it;
        # a SIGINT that came just before, during the run, goes to Python's
        # handler first.
        swap = self.interruptible and threading.current_thread() is threading.main_thread()
        try:
            if swap and lib.gw_interrupt_end():
                self.interrupted = True
                signal.raise_signal(signal.SIGINT)  # KeyboardInterrupt, or the program's own handler
                return 1
            return 1 if self.fn(done, total) else 0
        except BaseException as e:  # noqa: B902 - handed back to the caller
            self.exc = e
            return 1
        finally:
            if swap:
                lib.gw_interrupt_begin()

    def reraise(self, what="sweep"):
        # the C callback holds this object (c_fn -> _call -> self) and the
        # exception's traceback holds _call's frame (-> self -> exc): reference
        # cycles, each call's callback, exception and the frames of f (with
        # what f's locals hold) kept until the cyclic collector ran (6 objects
        # a call, 24 with an exception, with gc off). Both let go here, after
        # the library's call: freed when the caller lets go.
        self.c_fn = self.fn = None
        exc, self.exc = self.exc, None
        if exc is not None:
            try:
                raise exc
            finally:
                del exc
        if self.interrupted:  # the program's own handler ran and did not raise: as a SIGINT in C
            raise GranwaveError(f"{what}: interrupted (SIGINT)", GW_ECANCELED)


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
        if f.type == FARRAY:
            a = a != 0
        if f.cols is not None:
            a = a.reshape(rows, cols)
        if f.choices and a.ndim == 2 and len(f.choices) == cols:
            res[f.name] = {c: a[:, j].copy() for j, c in enumerate(f.choices)}
        else:
            res[f.name] = a
    return res


# ---- sweeps over the library's sweep models ----

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
        raise TypeError(f"expected a number, got {v!r}")
    s = _text_plain(v)
    if any(c in s for c in "\n\r;#\0") or not s.strip():
        raise ValueError(f"{key}: value {s!r} cannot go into a sweep (empty, or holds ';', '#', NUL or a newline)")
    return s


def _text_plain(v):
    if isinstance(v, os.PathLike):
        v = _fspath("", v)
        return os.fsdecode(v) if isinstance(v, bytes) else _plain(v)
    if isinstance(v, str):
        return _plain(v)
    x = _scalar(v)
    if isinstance(x, bool):
        return "1" if x else "0"
    if isinstance(x, int):
        return str(x)
    if isinstance(x, float):
        return repr(x)
    raise TypeError(f"cannot use a {_kind(v)} as a sweep value")


def _looks_like_range(s):
    """The library's test of a grid value "A:B" (common/sweep/gw_sweep.c,
    looks_like_range): one ':' and only digits, signs and blanks around it.
    Such a value alone on its grid line is the range A..B, not one value."""
    return s.count(":") == 1 and all(c in " \t+-0123456789" for c in s.replace(":", ""))


_GRID_MAX = 10**9  # cases of a sweep (the library's bound: "the grid has more than 1e9 cases")
_SWEEP_CONFIG_MAX = 1 << 20  # bytes of a sweep's config, as text too (the library's GW_SWEEP_CONFIG_MAX)
# the most values of one grid key but a range (written A:B): each takes a character and its ','
_GRID_VALUES_MOST = _SWEEP_CONFIG_MAX // 2


def _grid_values(key, v):
    if isinstance(v, range):
        # read whole below: range(2, 10**12) raised an empty MemoryError after
        # taking the memory there was, range(1, 2**80) OverflowError
        try:
            n = len(v)
        except OverflowError:
            n = math.inf
        if n > _GRID_MAX:
            raise GranwaveValueError(f"sweep() grid: '{key}': {v!r} holds more than 1e9 values: the grid has more "
                                     f"than 1e9 cases", GW_EINVAL)
    if isinstance(v, str):
        v = _plain(v)
        if _looks_like_range(v):
            a, b = (x.strip() for x in v.split(":"))
            try:  # '+1:3' ran 3 cases in C and was one value '+1:3' here
                return list(range(int(a), int(b) + 1))
            except ValueError:
                return [v]  # not integers ('1-:3'): the library names it
        return [x.strip() for x in v.split(",")]
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


def run_sweep(model, grid, params, jobs, progress):
    # jobs reaches C as an int: a float, a bool or a str was cut or read
    # silently (1.5 ran 1 thread, 10**12 wrapped to a negative int: one per CPU)
    if isinstance(jobs, bool) or not isinstance(jobs, numbers.Integral):
        raise TypeError(f"sweep(): jobs must be an integer, not {type(jobs).__name__}")
    if not -2**31 <= jobs < 2**31:  # the library's message for what does not fit its int
        raise GranwaveValueError(f"sweep: jobs: {jobs} is outside [0, 4096] (0: one per CPU)", GW_EINVAL)
    if not isinstance(grid, dict):
        raise TypeError(f"sweep(): grid must be a dict {{keyword: values}}, not {type(grid).__name__}")
    cb = Progress(progress)
    models = sweep_models()
    if not isinstance(model, str):  # a list raised "unhashable type: 'list'"
        raise TypeError(f"sweep(): model must be a str ({', '.join(map(repr, models))}), not {_kind(model)}")
    if model not in models:
        raise ValueError(f"sweep: unknown model '{model}' ({', '.join(models)})")
    m = models[model]
    if not grid:
        raise ValueError("sweep: grid needs at least one key with its values")
    lines = ["[sweep]", f"model = {model}", "[grid]"]
    axes = {}
    key_bytes = {}  # the config's bytes of each grid key's lines
    seen = {}  # t_max and t-max are one key: "sweep: sweep:5: duplicate key 't-max'" named a line of a text never shown
    for k in itertools.chain(grid, (k for k, v in params.items() if v is not None)):
        if not isinstance(k, str):  # AttributeError: 'int' object has no attribute 'replace'
            raise TypeError(f"sweep() grid: a key is a keyword name (str), got {type(k).__name__} ({k!r})")
        name = k.replace("_", "-")
        if name in seen and seen[name] != k:
            raise TypeError(f"sweep(): '{seen[name]}' and '{k}' name the same parameter")
        seen.setdefault(name, k)
    for k, v in grid.items():
        name = k.replace("_", "-")
        if not _model_has(m, name):
            raise TypeError(f"sweep() grid: '{k}' is not a parameter of model {model}{_sweep_hint(model, m, k)}")
        if v is None or isinstance(v, (set, frozenset, dict) + _BYTES) or \
                (isinstance(v, np.ndarray) and v.ndim != 1):
            raise TypeError(f"sweep() grid: '{k}': expected a list, a range, a 1-D array or a string, "
                            f"got {type(v).__name__}")
        vals = _grid_values(k, v)
        if not vals:
            raise ValueError(f"{k}: empty list of grid values")
        axes[k] = vals
        try:
            texts = [_ini_value(k, x, _sweep_rows(model, m, k)) for x in vals]
        except TypeError as e:
            raise TypeError(f"sweep() grid: '{k}': {e}") from None
        if any("," in t for t in texts):  # the list's separator: 'a,b' ran two cases
            raise ValueError(f"{k}: a grid value holds ',' (the list separator of a sweep)")
        # a list item 'A:B' alone on its line is the library's range: grid={"n": ["1:3"]}
        # ran 3 cases where the result's n had one entry (its columns 3)
        if not isinstance(v, str) and any(_looks_like_range(t) for t in texts):
            raise ValueError(f"sweep() grid: '{k}': a list item {next(t for t in texts if _looks_like_range(t))!r} "
                             f"is a range, not one value: give the string 'A:B' or range(A, B + 1)")
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
            raise GranwaveValueError(f"sweep() grid: '{k}': a value takes {max(len(t) for t in texts)} characters, "
                                     f"above the {_SWEEP_LINE_MAX} of a line of the library's config reader", GW_EINVAL)
    lines.append("[params]")
    for k, v in params.items():
        if v is None:
            continue
        name = k.replace("_", "-")
        if not _model_has(m, name):
            raise TypeError(f"sweep() got an unexpected keyword argument '{k}' (not a parameter of model {model})"
                            f"{_sweep_hint(model, m, k)}")
        if k in grid:
            raise TypeError(f"sweep(): '{k}' given both in grid and as a keyword")
        try:
            lines.append(f"{name} = {_ini_value(k, v, _sweep_rows(model, m, k))}")
        except TypeError as e:
            raise TypeError(f"sweep(): '{k}': {e}") from None
        if len(lines[-1]) > _SWEEP_LINE_MAX:  # a long path: "sweep:6: a line of ..." before
            raise GranwaveValueError(f"sweep(): '{k}': its value takes {len(lines[-1])} characters on the sweep's "
                                     f"config line, above the {_SWEEP_LINE_MAX} the library's reader takes (a shorter "
                                     f"path, relative to the working directory)", GW_EINVAL)
    text = "\n".join(lines) + "\n"
    if len(text.encode(errors="surrogateescape")) > _SWEEP_CONFIG_MAX:  # the library's bound, by key
        big = max(key_bytes, key=key_bytes.get)
        raise GranwaveValueError(f"sweep() grid: '{big}': the sweep's config takes {len(text)} bytes, above the "
                                 f"{_SWEEP_CONFIG_MAX} the library reads (a range for consecutive integers, or "
                                 f"fewer values)", GW_EINVAL)
    values = _lib.c_double_p()
    ncases = ctypes.c_long()
    mod = ctypes.POINTER(_lib.GwSweepModel)()
    err = _lib.GwErr()
    try:
        with Interruptible() as it:
            cb.interruptible = it.on
            rc = lib.gw_sweep_run_text(text.encode(), b"sweep", int(jobs), cb.c_fn, None, ctypes.byref(values),
                                       ctypes.byref(ncases), ctypes.byref(mod), ctypes.byref(err))
        cb.reraise()
        if rc != 0:
            _raise(rc, err, "sweep", _sweep_names(model, m), _texts(list(params.values()) + [
                x for v in axes.values() for x in v]))
        cases = list(itertools.product(*axes.values()))  # the C order: last key fastest
        if ncases.value != len(cases):  # each grid value here must be one case's value there
            raise GranwaveError(f"sweep: the library ran {ncases.value} cases where the grid gives {len(cases)}: "
                                f"the grid values are not one value each ({text!r})", GW_EINVAL)
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
    return res
