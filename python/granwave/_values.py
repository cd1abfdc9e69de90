"""Parameter tables and the values set through them: a table's rows read
from the library (Param: name, keyword, type, unit, range, default, help),
and a caller's Python value (a number, a bool, a path, a sequence, a range)
taken as the text gw_param_set parses, each kind refused by keyword when it
is no such value. Separate from the studies that call it (_core.py) and the
sweeps (_sweep.py), which convert their values the same way.
"""
import itertools
import decimal
import math
import numbers
import os
import reprlib

import numpy as np

from ._errors import GW_EINVAL, GranwaveValueError


# gw_param_type (common/gw_param.h); COUNT: a whole number the library holds as a
# double (dispersion's min_bins): 30 and 30.0 are taken, 1.5 is refused by the library
DOUBLE, INT, LONG, FLAG, CHOICE, TEXT, LIST, RANGE, DARRAY, IARRAY, FARRAY, COUNT = range(12)
_TYPE_NAMES = ["float", "int", "int", "bool", "choice", "str", "list of float", "range A:B",
               "array", "int array", "bool array", "count"]


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
        # a text row names a file (sample, out, input: metavar FILE,
        # RESULTS.csv) unless it holds a list of names (layer_stats' fit:
        # metavar LIST), which no path object or bytes spells
        self.is_file = self.type == TEXT and (row.metavar or b"").decode() != "LIST"

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


class _Beyond(float):
    """A real number no double holds (nonzero below the smallest subnormal, or
    above the largest double: an np.longdouble, a Fraction): its float (0 or
    an infinity) with repr() its own value in decimal, so that the library
    refuses the digits as the program refuses them ("'1e-4000' is too small in
    magnitude"). float() made it 0 (refused as "0 is outside [1e-09, 1000]",
    a value not given) or raised OverflowError (a Fraction: "cannot use")."""

    def __new__(cls, f, text):
        o = float.__new__(cls, f)
        o.text = text
        return o

    def __repr__(self):
        return self.text

    __str__ = __repr__


def _beyond(v):
    """v (numbers.Real, not Integral) as a float, or a _Beyond when no double
    holds it; None when it has no ratio (an odd subclass)."""
    try:
        f = float(v)
    except OverflowError:
        f = None
    if f is not None and (f != 0 or v == 0) and (math.isfinite(f) or not _finite_real(v)):
        return f
    try:
        num, den = v.as_integer_ratio()
    except (AttributeError, TypeError, ValueError, OverflowError):
        try:
            num, den = v.numerator, v.denominator
        except AttributeError:
            return None
    with decimal.localcontext() as ctx:
        ctx.prec, ctx.Emax, ctx.Emin = 17, decimal.MAX_EMAX, decimal.MIN_EMIN
        text = format((decimal.Decimal(num) / decimal.Decimal(den)).normalize(), "e")
    return _Beyond(-math.inf if num < 0 else math.inf if f is None or not math.isfinite(f) else f, text)


def _finite_real(v):
    try:
        return bool(np.isfinite(v))
    except (TypeError, ValueError, OverflowError):
        return True  # a Fraction: always finite


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
            return _beyond(v)
    except (TypeError, ValueError, OverflowError):  # a Fraction beyond a double, an odd subclass
        return None
    return None


def _integer(v):
    """v as a plain Python int when it is one integer, the one rule of every
    integer keyword (a table's row, a range's end, sweep's jobs): an int, a
    numpy integer or a 0-d array of one (np.array(5)); None for anything else,
    a bool, a float (5.0) or a str among them. sweep(jobs=np.array(2)) was
    refused where n=np.array(5) ran."""
    x = _scalar(v)
    return x if isinstance(x, int) and not isinstance(x, bool) else None


def _digits(what, v):
    """An int's decimal digits, for the library to parse and hold to its row's
    range. str() of an int of more than Python's 4300 digits raises Python's
    own ValueError ("Exceeds the limit (4300 digits) for integer string
    conversion"), which named no keyword (chain(vimp=10**5000), an item of a
    list, a range's end, a sweep's grid value); no input's range comes near
    such a number, so it is refused here naming what."""
    try:
        return str(v)
    except ValueError:
        n = int(v.bit_length() * math.log10(2)) + 1
        raise GranwaveValueError(f"{what}: an integer of about {n} digits is beyond every input's range",
                                 GW_EINVAL) from None


# A caller's value quoted in a message: at most about a line, and never an
# exception of its own. repr() of a list of 10**6 numbers given for vimp made a
# TypeError of 7.9 MB, and a value whose __repr__ raised replaced the refusal
# naming the keyword by that error (chain(vimp=obj) raised obj's RuntimeError).
_REPR = reprlib.Repr()
_REPR.maxstring = _REPR.maxother = 80
_REPR.maxlong = 40
_REPR.maxlist = _REPR.maxtuple = _REPR.maxarray = _REPR.maxset = _REPR.maxfrozenset = _REPR.maxdeque = 8
_REPR.maxdict = 4


def _show(value):
    """repr(value) for a message: cut to about 80 characters, and a plain
    '<TYPE instance ...>' when its __repr__ fails (reprlib's rule)."""
    try:
        return _REPR.repr(value)
    except Exception:  # noqa: BLE001 - a container whose items' repr fails in reprlib's own code
        return f"<{type(value).__name__} object>"


def _line(text):
    """A caller's text (a keyword name) quoted in a message as the library
    quotes one (gw_one_line): one line, a newline, CR and tab written \\n, \\r,
    \\t and another control character, or a byte of no UTF-8 character (a
    lone surrogate), \\xHH. sweep(grid={"vimp\\nn": ...}) raised a TypeError
    of two lines, the key quoted raw."""
    out = []
    for c in str(text):
        o = ord(c)
        if c in "\n\r\t":
            out.append({"\n": "\\n", "\r": "\\r", "\t": "\\t"}[c])
        elif o < 0x20 or o == 0x7f:
            out.append(f"\\x{o:02x}")
        elif 0xd800 <= o <= 0xdfff:  # a byte read with surrogateescape, else the surrogate's bytes
            out.extend(f"\\x{b:02x}" for b in c.encode("utf-8", "surrogateescape" if o >= 0xdc80 and o <= 0xdcff
                                                       else "surrogatepass"))
        else:
            out.append(c)
    return "".join(out)


def _kind(value):
    return f"{type(value).__name__} ({_show(value)})"


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
    if r.type in (INT, LONG, COUNT):
        given = kwargs.get(r.keyword)
        v = _integer(given) if given is not None else int(r.default) if (r.default or "").isdigit() else None
        if v is not None and r.min <= v <= r.max:
            return min(v, _INT_MAX), f" ({r.keyword} = {v}{'' if given is not None else ', its default'})"
    return int(min(max(r.max, 0), _INT_MAX)), f" (the most {r.keyword} takes)"


def _text(p, value, most=(_INT_MAX, "")):
    """A Python value as the text gw_param_set parses; most: the most items a
    list row takes in this call and why (list_most)."""
    if p.type == FLAG:  # every bool keyword, of every study and sweep, here
        return _flag(p, value)
    if p.type == TEXT and not p.is_file and not isinstance(value, str):
        # fit=pathlib.Path("beta,a_over_b") and fit=b"beta" ran as the text;
        # fit=["beta", "a_over_b"] was told "expected a str or a path"
        raise TypeError(f"{p.keyword}: expected a str (comma-separated names, \"beta,a_over_b\"), got {_kind(value)}")
    value = _fspath(p.keyword, value)
    if isinstance(value, bytes) and p.type == TEXT:  # a file name as the OS gives it
        value = os.fsdecode(value)
    if p.type == TEXT and not isinstance(value, str):
        # a number went to C as its digits: sample=3 looked for a file named '3'
        raise TypeError(f"{p.keyword}: expected a str or a path, got {_kind(value)}")
    if isinstance(value, str):
        value = _plain(value)
        if "\0" in value:  # C would read up to the NUL: another file, silently
            raise GranwaveValueError(f"{p.keyword}: {_show(value)} holds a NUL character", GW_EINVAL)
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
                raise TypeError(f"{p.keyword}: item {k + 1} is not a number ({_show(x)})")
            # an integer by its digits, as a scalar's: float() of one beyond the
            # largest double raised OverflowError naming nothing (radii=[1e-3,
            # 2**2000]); the library refuses it as not finite, naming the keyword
            items.append(_digits(f"{p.keyword}: item {k + 1}", v) if isinstance(v, int) else repr(v))
        if any("," in x for x in items):
            raise GranwaveValueError(f"{p.keyword}: an item holds ',' ({_show(items)})", GW_EINVAL)
        return ",".join(items) if items else "none"
    if p.type == RANGE:
        if isinstance(value, range):
            # len() of range(1, 2**80) raised OverflowError naming nothing
            if value.step != 1 or value.stop <= value.start:
                raise GranwaveValueError(f"{p.keyword}: a range of step 1 with at least one value, got {_show(value)}",
                                         GW_EINVAL)
            return f"{_digits(p.keyword, value.start)}:{_digits(p.keyword, value.stop - 1)}"
        x = _integer(value)
        if x is not None:  # 7, np.int64(7), np.array(7)
            return _digits(p.keyword, x)
        # (A, B): exactly two ends; a fractional end goes to C as written, which
        # refuses it ("'1.5' is not an integer"), instead of being cut by int()
        if isinstance(value, (str,) + _BYTES) or not hasattr(value, "__len__") or \
                (isinstance(value, np.ndarray) and value.ndim != 1) or len(value) != 2:
            raise TypeError(f"{p.keyword}: expected (A, B), an integer or a range, got {_show(value)}")
        ends = []
        for x in _items(p.keyword, value, 2):
            v = _scalar(x)
            if v is None or isinstance(v, bool):
                raise TypeError(f"{p.keyword}: a range end must be a number, got {_show(x)}")
            ends.append(_digits(p.keyword, v) if isinstance(v, int) else repr(v))
        return ":".join(ends)
    x = _scalar(value)
    if isinstance(x, bool):
        raise TypeError(f"{p.keyword}: expected a number, got {_show(value)}")
    if isinstance(x, int):
        return _digits(p.keyword, x)
    if isinstance(x, float):
        return repr(x)
    raise TypeError(f"{p.keyword}: cannot use a {_kind(value)}")
