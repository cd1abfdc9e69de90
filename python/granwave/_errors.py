"""The library's statuses as Python exceptions: the codes, the exception
classes (GranwaveError and its ValueError, OSError, RuntimeError and
NotImplementedError kinds, GranwaveWarning) and the library's texts with
their inputs named by Python's keywords (keyword_text). Separate from the
values and the studies: every other part raises through it, and it needs
none of them.
"""
import re

from ._lib import lib


# status codes (common/gw_common.h)
GW_EINVAL, GW_ENOMEM, GW_EIO, GW_ESOLVER, GW_EFORMAT, GW_EUNSUPPORTED, GW_EENERGY, GW_ELIMIT, \
    GW_ECANCELED = -1, -2, -3, -4, -5, -6, -7, -8, -9


class GranwaveError(Exception):
    """A libgranwave call failed; .status is the library's code, the text its message."""

    def __init__(self, message, status):
        super().__init__(message)
        self.status = status

    def __reduce__(self):
        # pickle and copy rebuild an exception from its args, here (message,)
        # alone, which __init__ refuses without the status: an error raised in
        # a worker process could not come back (ProcessPoolExecutor reported
        # its pool broken, multiprocessing.Pool's get() waited for ever)
        return (type(self), (str(self), self.status), self.__dict__)


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
