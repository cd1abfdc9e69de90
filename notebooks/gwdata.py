"""gwdata: load granwave's reference tables and run the granwave program.

Small helpers shared by the notebooks and plot scripts. No physics lives here: the
numbers come either from the paper (data/falcon1998/*.csv) or from the program.

    load_table(name)       a table of data/falcon1998 (e.g. "wave_speed_table1")
    load_csv(path)         any granwave CSV ('#' comment lines, one header row)
    load_json(path)        a JSON file of the program (an object)
    open_regular(path)     open a regular file for reading; anything else is refused
    paper_value(q, h_mm)   one row of rigid_wall.csv, selected by quantity and height
    find_granwave()        path of the program: $GRANWAVE, ../build/granwave, build/granwave
    run_granwave(args)     run it; parsed JSON (json=True) or stdout text
    import_granwave()      the Python module granwave (python/granwave over libgranwave)
    run_main(main, argv)   a plot script's entry: a stdout that cannot be written (a
                           closed pipe, a full disk) ends in one line and exit 1
    InputError, OutputError  a plot script's two failures (exit 2 and exit 1)
    save_pngs(figs, outdir, dpi)  write figures as outdir/NAME.png, OutputError naming one

Columns whose non-empty cells all parse as numbers become float numpy arrays (empty cells
and "nan" -> NaN); other columns are lists of str. Dicts keep the file's column order.
Use Debian's /usr/bin/python3 (numpy).
"""

import csv
import json as _json
import os
import stat
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DATA_DIR = os.path.normpath(os.path.join(HERE, "..", "data", "falcon1998"))

def read_error(path, e):
    """The one-line message of an error e raised while reading path (naming path once)."""
    msg = getattr(e, "strerror", None) or str(e) if isinstance(e, OSError) else str(e)
    return msg if path in msg else f"cannot read {path}: {msg}"


__all__ = ["read_error", "DATA_DIR", "GranwaveError", "open_regular", "load_csv", "load_json", "load_table", "paper_value",
           "find_granwave", "run_granwave", "import_granwave", "run_main"]


class InputError(Exception):
    """A missing or malformed input; a plot script's main() prints it and exits with 2."""


class OutputError(Exception):
    """A figure that cannot be written; a plot script's main() prints it and exits with 1."""


def save_pngs(figs, outdir, dpi, metadata=None, quiet=False):
    """Write each figure of figs ({name: Figure}) as outdir/name.png, in order, printing
    each path unless quiet; the paths. A write that fails raises OutputError naming the
    file (outdir must exist)."""
    paths = []
    for name, fig in figs.items():
        p = os.path.join(outdir, name + ".png")
        try:
            fig.savefig(p, dpi=dpi, metadata=metadata)
        except OSError as e:
            raise OutputError(f"cannot write {p}: {e.strerror or e}")
        paths.append(p)
        if not quiet:
            print(p)
    return paths


class GranwaveError(RuntimeError):
    """The granwave program could not be found, failed, or printed invalid JSON."""


def _column(cells):
    """Float array if every non-empty cell is a number, else the list of strings."""
    values = []
    for c in cells:
        c = c.strip()
        if c == "":
            values.append(np.nan)
            continue
        try:
            values.append(float(c))
        except ValueError:
            return [x.strip() for x in cells]
    return np.array(values, dtype=float)


def open_regular(path, **kw):
    """open(path) for reading text, refusing anything but a regular file.

    A FIFO, a device or a socket given where a table or a JSON file is expected would
    block the reader or never end (issue 18, class 3): the file is opened without
    blocking and checked before a byte is read. Raises FileNotFoundError if path does
    not exist, ValueError naming path and its kind if it is not a regular file.
    """
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except IsADirectoryError:
        raise ValueError(f"{path} is a directory, not a file")
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            kind = ("a directory" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode)
                    else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
                    else "a socket" if stat.S_ISSOCK(mode) else "not a regular file")
            raise ValueError(f"{path} is {kind}, not a regular file")
        os.set_blocking(fd, True)
        return os.fdopen(fd, "r", **kw)
    except BaseException:
        os.close(fd)
        raise


def load_json(path):
    """The JSON object in the regular file path (a dict). Raises FileNotFoundError if
    path is missing, ValueError naming path if it is not a regular file, not UTF-8 or
    not JSON, or holds something other than an object."""
    with open_regular(path) as f:
        try:
            obj = _json.load(f)
        except UnicodeDecodeError as e:
            raise ValueError(f"{path}: not UTF-8 text ({e.reason} at byte {e.start})")
        except ValueError as e:
            raise ValueError(f"{path}: not JSON ({e})")
    if not isinstance(obj, dict):
        kind = {list: "an array", str: "a string", type(None): "null", bool: "a boolean"}.get(type(obj), "a number")
        raise ValueError(f"{path}: holds {kind}, not a JSON object")
    return obj


def load_csv(path, comments=False):
    """Read a CSV with leading/interleaved '#' comment lines and one header row.

    Returns {column: numpy array or list of str}; with comments=True returns
    (table, list of comment lines without the leading '#').
    Raises FileNotFoundError if path is missing, ValueError if it is not a regular file or
    not UTF-8, has no header or a row has the wrong number of cells (the message names
    the file and line).
    """
    notes, header, rows = [], None, []
    with open_regular(path, newline="") as f:
        try:
            lines = list(csv.reader(f))
        except UnicodeDecodeError as e:
            raise ValueError(f"{path}: not UTF-8 text ({e.reason} at byte {e.start})")
        except csv.Error as e:
            raise ValueError(f"{path}: {e}")
        for lineno, row in enumerate(lines, start=1):
            if not row or (len(row) == 1 and row[0].strip() == ""):
                continue
            if row[0].lstrip().startswith("#"):
                notes.append(",".join(row).lstrip()[1:].strip())
                continue
            if header is None:
                header = [h.strip() for h in row]
                continue
            if len(row) != len(header):
                raise ValueError(f"{path}:{lineno}: {len(row)} cells, header has {len(header)}")
            rows.append(row)
    if header is None:
        raise ValueError(f"{path}: no header row")
    cols = list(zip(*rows)) if rows else [()] * len(header)
    table = {name: _column(list(c)) for name, c in zip(header, cols)}
    return (table, notes) if comments else table


def load_table(name):
    """A table of data/falcon1998: name with or without '.csv' (or a path to a CSV).

    Example: load_table("soft_walls_table2")["n_d"] -> array([1, 2, 4, ...]).
    """
    path = name
    if not os.path.isfile(path):
        base = name if name.endswith(".csv") else name + ".csv"
        path = os.path.join(DATA_DIR, base)
    if not os.path.isfile(path):
        have = sorted(f[:-4] for f in os.listdir(DATA_DIR) if f.endswith(".csv")) \
            if os.path.isdir(DATA_DIR) else []
        raise FileNotFoundError(f"no table '{name}' in {DATA_DIR} (have: {', '.join(have)})")
    return load_csv(path)


def paper_value(quantity, h_mm, unit=None):
    """(value, uncertainty or NaN, unit) of rigid_wall.csv for quantity at drop height h_mm.

    The row is the one whose condition starts with 'h = <h_mm> mm'; with several rows
    (collision_time), pass unit or get the first. Returns None if there is no such row.
    """
    t = load_table("rigid_wall")
    for q, v, u, un, cond in zip(t["quantity"], t["value"], t["uncertainty"],
                                 t["unit"], t["condition"]):
        if q != quantity or (unit is not None and un != unit):
            continue
        head = cond.split(";")[0].replace(" ", "")
        if head.startswith("h=") and head.endswith("mm"):
            try:
                h = float(head[2:-2])
            except ValueError:
                continue
            if abs(h - float(h_mm)) < 1e-9:
                return float(v), float(u), un
    return None


def find_granwave():
    """Path of the granwave program.

    Order: $GRANWAVE; ../build/granwave relative to this file's directory; build/granwave
    relative to the current directory. Raises GranwaveError naming what was tried.
    """
    tried = []
    env = os.environ.get("GRANWAVE")
    if env:
        if os.path.isfile(env) and os.access(env, os.X_OK):
            return os.path.abspath(env)
        raise GranwaveError(f"GRANWAVE={env} is not an executable file")
    for cand in (os.path.join(HERE, "..", "build", "granwave"),
                 os.path.join(os.getcwd(), "build", "granwave")):
        cand = os.path.normpath(cand)
        tried.append(cand)
        if os.path.isfile(cand) and os.access(cand, os.X_OK):
            return cand
    raise GranwaveError("granwave program not found: set GRANWAVE=/path/to/granwave or build "
                        "it (cmake --build build); tried " + ", ".join(tried))


def run_granwave(args, json=True, timeout=600, program=None):
    """Run granwave with the argument list args (e.g. ["chain", "--n", "7"]).

    json=True appends --json (unless present) and returns the parsed object; json=False
    returns stdout as text. Raises GranwaveError with the command line, exit code and
    stderr if the program exits non-zero, times out (timeout in s), or prints invalid JSON.
    """
    exe = program or find_granwave()
    args = [str(a) for a in args]
    if json and "--json" not in args:
        args.append("--json")
    cmd = [exe] + args
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        raise GranwaveError(f"{' '.join(cmd)}: no answer after {timeout} s") from e
    if p.returncode != 0:
        raise GranwaveError(f"{' '.join(cmd)} exited with code {p.returncode}:\n"
                            f"{p.stderr.strip() or '(no stderr)'}")
    if not json:
        return p.stdout
    try:
        return _json.loads(p.stdout)
    except ValueError as e:
        raise GranwaveError(f"{' '.join(cmd)}: stdout is not JSON ({e}); "
                            f"first 200 chars: {p.stdout[:200]!r}") from e


def import_granwave():
    """The Python module granwave (the repository's python/granwave), imported.

    ../python (relative to this file) goes first on sys.path unless the module is already
    importable from an installed prefix. The library is the module's choice (GRANWAVE_LIB,
    an installed prefix, then <repo>/build/lib), except that when GRANWAVE_LIB is unset and
    GRANWAVE names a program whose build tree holds lib/libgranwave.so, that library is
    used, so that the program and the module of one notebook come from the same build.
    Raises GranwaveError with the module's message if it cannot be loaded.
    """
    import importlib
    import sys
    src = os.path.normpath(os.path.join(HERE, "..", "python"))
    if os.path.isdir(os.path.join(src, "granwave")) and src not in sys.path:
        sys.path.insert(0, src)
    exe = os.environ.get("GRANWAVE")
    if not os.environ.get("GRANWAVE_LIB") and exe:
        lib = os.path.join(os.path.dirname(os.path.abspath(exe)), "lib", "libgranwave.so")
        if os.path.isfile(lib):
            os.environ["GRANWAVE_LIB"] = lib
    try:
        return importlib.import_module("granwave")
    except ImportError as e:
        raise GranwaveError(f"the Python module granwave could not be loaded: {e}") from e


class _StdoutError(Exception):
    """A write to stdout failed (the OSError is the argument)."""


class _GuardedStdout:
    """sys.stdout whose write and flush failures are told apart from other files'."""

    def __init__(self, f):
        self._f = f

    def write(self, text):
        try:
            return self._f.write(text)
        except OSError as e:
            raise _StdoutError(e) from None

    def flush(self):
        try:
            self._f.flush()
        except OSError as e:
            raise _StdoutError(e) from None

    def __getattr__(self, name):
        return getattr(self._f, name)


def run_main(main, argv):
    """main(argv)'s exit status. A stdout that cannot be written (`| head` closing the
    pipe, a full disk) ends in one line on stderr naming the script, exit 1, instead of
    a traceback; what was not written is dropped."""
    name = os.path.basename(argv[0])
    real = sys.stdout
    sys.stdout = _GuardedStdout(real)
    try:
        rc = main(argv)
        sys.stdout.flush()
        return rc
    except _StdoutError as e:
        err = e.args[0]
        # the rest of the buffer goes nowhere, so that the exit flush cannot fail again
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, real.fileno())
        os.close(devnull)
        print(f"{name}: stdout: write failed: {err.strerror or err}", file=sys.stderr)
        return 1
    finally:
        sys.stdout = real
