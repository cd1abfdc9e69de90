"""docs_runner.py: what test_docs_formats.py and test_docs_examples.py share to hold a
page's commands and examples against the program: its fenced blocks read with their
line numbers, a documented command line split into the program's arguments, the
program run on them in a scratch directory (a run that makes a file once per directory
remembered), a page's line held against what the program printed or wrote, and the
faults said as "file:line: message". Imported by both (tests/ is on sys.path as the
directory of the running script)."""
import os
import re
import shlex
import subprocess

_FENCE = {}


def fenced(text, kinds):
    """[(kind, first line number, [lines])] of the ```KIND blocks of text, KIND one of
    kinds, in the page's order."""
    rx = _FENCE.get(kinds)
    if rx is None:
        rx = _FENCE[kinds] = re.compile(r"^```(" + "|".join(map(re.escape, kinds)) + r")\n(.*?)^```",
                                        re.S | re.M)
    return [(m.group(1), text.count("\n", 0, m.start(2)) + 1, m.group(2).splitlines()) for m in rx.finditer(text)]


def split_comment(line):
    """(code, comment) of a documented command line: `  #` starts its comment."""
    i = line.find("  #")
    return (line[:i], line[i + 3:]) if i >= 0 else (line, "")


def command_args(line, prefix):
    """The program's arguments of a documented line PREFIX ARGS [ # comment]
    ("build/granwave ", "$ granwave ", "# command: granwave "), None when it is not one."""
    if not line.startswith(prefix):
        return None
    return shlex.split(split_comment(line[len(prefix):])[0])


def line_holds(shown, got):
    """The page's line against the program's: equal, or with `...` standing for any text
    (the page's line must begin with what comes before it and end with what comes after)."""
    if "..." not in shown:
        return shown == got
    parts = shown.split("...")
    if not got.startswith(parts[0]) or not got.endswith(parts[-1]):
        return False
    at = len(parts[0])
    for p in parts[1:-1]:
        i = got.find(p, at)
        if i < 0:
            return False
        at = i + len(p)
    return at <= len(got) - len(parts[-1])


def first_difference(shown, got):
    """(i, shown line, got line) of the first of the page's lines that got does not hold
    at the same place ("(end of file)" past its end), None when every one holds."""
    for i, s in enumerate(shown):
        g = got[i] if i < len(got) else "(end of file)"
        if not line_holds(s, g):
            return i, s, g
    return None


def run(program, args, cwd, timeout=600, env=None):
    """The program on args (stdout and stderr as text), from cwd."""
    return subprocess.run([program, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd, env=env)


class Runner:
    """The program on a page's commands, from a scratch directory, its faults kept."""

    def __init__(self, program, work):
        self.program = program
        self.work = work
        self.faults = []
        self._made = {}
        self._helps = {}

    def fault(self, where, msg):
        self.faults.append(f"{where}: {msg}")

    def run(self, args, timeout=600, cwd=None, env=None):
        """The program on args (stdout and stderr as text), from cwd (the scratch directory)."""
        return run(self.program, args, cwd or self.work, timeout, env)

    def made(self, args, cwd=None):
        """A run that makes a file (a pluviation), once per directory and arguments."""
        key = (cwd or self.work, tuple(args))
        if key not in self._made:
            self._made[key] = self.run(args, cwd=key[0])
        return self._made[key]

    def help(self, cmd):
        """`PROGRAM CMD --help` (stdout and stderr), None when it fails."""
        if cmd not in self._helps:
            p = self.run([cmd, "--help"], timeout=60)
            self._helps[cmd] = p.stdout + p.stderr if p.returncode == 0 else None
        return self._helps[cmd]

    def refused_as(self, where, args, expected):
        """A refusal the page shows: exit 2 and stderr exactly the line under it."""
        p = self.run(args, timeout=120)
        if p.returncode != 2 or p.stderr.strip() != expected:
            self.fault(where, f"exit {p.returncode}, stderr {p.stderr.strip()!r}; the page says {expected!r}")
