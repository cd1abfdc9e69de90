"""The generic machinery under granwave's functions: studies of the library's
index run through it (Study: the keywords set with the library's checks, the
run, its warnings), with Ctrl-C (Interruptible) and a progress callback
(Progress). Its parts are files of their own: errors turned into exceptions
(_errors.py), parameter tables and values (_values.py), results
(_result.py), sweeps (_sweep.py). No physics here: every number comes from
libgranwave.
"""
import ctypes
import os
import signal
import threading

import numpy

from . import _lib
from ._lib import lib
# the parts' names are _core's too: the package and the tests reach them as _core.X
from ._errors import (GW_ECANCELED, GW_EENERGY, GW_EFORMAT, GW_EINVAL, GW_EIO, GW_ELIMIT,  # noqa: F401
                      GW_ENOMEM, GW_ESOLVER, GW_EUNSUPPORTED, GranwaveError, GranwaveIOError,
                      GranwaveRunError, GranwaveUnsupported, GranwaveValueError, GranwaveWarning, _raise,
                      keyword_text)
from ._result import CLOCK_KEYS, Result, read_result  # noqa: F401
from ._values import (_TYPE_NAMES, CHOICE, COUNT, DARRAY, DOUBLE, FARRAY, FLAG, IARRAY, INT, LIST,  # noqa: F401
                      LONG, RANGE, TEXT, _flag, _items, _line, _show, _text, _texts, list_most, read_table)


def warn(what, text, stacklevel=3):
    """One GranwaveWarning "what: text", shown at the caller's line (stacklevel
    3: the caller of the public function that calls this)."""
    import warnings
    warnings.warn(f"{what}: {text}", GranwaveWarning, stacklevel=stacklevel)


def issue(what, texts):
    """The library's warning texts (their inputs named by keyword) as one
    GranwaveWarning each, shown at the line that called the public function
    (issue <- Study.run or run_sweep <- the public function <- its caller): the
    one place warnings are issued, for a study's result and for a sweep's."""
    for w in texts:
        warn(what, w, stacklevel=5)


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
                    raise TypeError(f"{self.func}() got an unexpected keyword argument '{_line(k)}'{self.hint(k)}")
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
                    raise GranwaveValueError(f"{self.func}: {p.keyword}: {_show(text)} cannot be encoded", GW_EINVAL) from None
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
        issue(self.func, r["warnings"])
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
        kind = {FLAG: " (bool; 1 is True, 0 False, -1 None)", FARRAY: " (bool array; masked where -1, undecided)"}
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
    again once the library has returned. f returns None or False to go on,
    True (a numpy bool too) to stop; anything else stops the call with a
    TypeError naming f and what it returned (any truthy value stopped it:
    "no", 1, a list)."""

    def __init__(self, fn, what="sweep"):
        if fn is not None and not callable(fn):
            # it failed only at the first report, after that much of the run
            raise TypeError(f"{what}: progress must be a callable f(done, total) or None, got "
                            f"{type(fn).__name__} ({_show(fn)})")
        self.fn = fn
        self.what = what
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
            return self._verdict(self.fn(done, total))
        except BaseException as e:  # noqa: B902 - handed back to the caller
            self.exc = e
            return 1
        finally:
            if swap:
                lib.gw_interrupt_begin()

    def _verdict(self, r):
        # None and False go on, True stops (numpy's bool_ alike: d >= 50 on a
        # numpy number); a string, a number or a container was taken by its
        # truth ("no" stopped the run, 0.0 did not)
        if r is None or r is False:
            return 0
        if r is True:
            return 1
        if isinstance(r, numpy.bool_):
            return 1 if bool(r) else 0
        name = getattr(self.fn, "__qualname__", None) or type(self.fn).__name__
        raise TypeError(f"{self.what}: progress callback {name} returned {type(r).__name__} ({_show(r)}): "
                        f"return None or False to go on, True to stop")

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
