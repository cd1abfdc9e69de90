#!/usr/bin/python3
"""test_docs_examples.py PROGRAM SRCDIR: the commands README.md and docs/ show still work.

A new user copies the documentation's commands. Over README.md and docs/*.md:
  1. every `build/granwave CMD ...` line of a ```sh block names a command whose
     `--help` lists each of its flags (a renamed or removed flag fails here);
  2. the fast ones (below about a second each; FAST) run as written, in a scratch
     directory, and exit 0; a `--json` line prints one JSON object; the files its
     comment names (name.csv, name.json, name.md) exist under its --out directory.
     Lines that need a sample (`--sample sample.txt`) run on a small one made first
     (60 discs, as the Python tests); lines longer than that budget are only
     checked by 1 (wavespeed, softwall, the 300-disc pluviation, --full impacts,
     sweeps and their statistics: minutes);
  3. every `$ granwave ...` example of a ```text block (docs/reliability.md) prints
     on stderr exactly the line the page shows under it, and exits 2;
  3b. the Python a page shows (with GRANWAVE_LIB, the library to load, in the
     environment: not in a sanitizer build): every `PYTHONPATH=python /usr/bin/python3
     -c "..."` line of a ```sh block (README.md, library.md) runs from the scratch
     directory with the checkout's module, exits 0 and prints, and every `>>> granwave.CALL`
     of a ```text block raises the exception the line under it shows, with its message
     exactly (`granwave.GranwaveValueError: layer_impact: vi: ...`);
  1b. every `granwave CMD ...` the prose of README.md and docs/ quotes in backticks (outside
     code blocks) names only flags that `granwave CMD --help` lists (those before a `--`
     that ends the options);
  4. every default or range the prose of README.md and the user's pages (cli.md,
     layer.md, column.md, drop.md, sheets.md, crowns.md, outcomes.md, formats.md,
     library.md) quotes for a flag is the one `granwave CMD --help --json` gives
     (`default`, `range`) for a command that has the flag (those the paragraph names
     in backticks, when it names any). The forms read: "`--flag` (UNIT, VALUE)",
     "`--flag` (VALUE)", "`--flag` (default VALUE ...", "`--flag` defaults to VALUE",
     "`--flag` ... (default VALUE", "the default `--flag` is VALUE", "`--flag VALUE`
     (the default" / "(default", "`--flag` ... must be in RANGE"; a VALUE of numbers
     with a unit (us, ms, s, ...) is compared as a number, a formula (T_c/400) as
     text inside the help's default.
First it checks itself on a made-up page with a removed flag, a failing command,
a wrong message, a wrong default and a wrong range, and fails if any goes unnoticed. Exit 0 when all hold, 1
otherwise (each fault printed as file:line: message), 2 on bad usage.
"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

from docs_frame import finish, noticed, not_caught, program_srcdir
from docs_runner import Runner, command_args, fenced, split_comment

# run as written (each well below a second, the drops about one)
FAST = ("chain", "falcon", "dispersion", "drop", "layer-impact")
SLOW_MARKS = ("--full", "--sheets")
FILE_IN_COMMENT = re.compile(r"\b([\w./-]+\.(?:csv|json|md))\b")


def doc_lines(srcdir):
    """(file, line number, text) of every line of the ```sh and ```text blocks."""
    files = ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(srcdir, "docs"))
                                   if f.endswith(".md"))
    out = []
    for rel in files:
        text = open(os.path.join(srcdir, rel), encoding="utf-8").read()
        for kind in ("sh", "text"):  # the sh blocks first, as before
            for _, first, lines in fenced(text, (kind,)):
                out.extend((rel, first + i, kind, line) for i, line in enumerate(lines))
    return out


PY_LINE = re.compile(r"^PYTHONPATH=python /usr/bin/python3 -c ")


class Checker(Runner):
    """The shared runner (docs_runner.Runner: run, help, fault, refused_as) with the
    checks of this page's lines."""

    def __init__(self, program, workdir, srcdir=None):
        super().__init__(program, workdir)
        self.srcdir = os.path.abspath(srcdir or os.path.join(os.path.dirname(__file__), ".."))
        self.lib = os.environ.get("GRANWAVE_LIB")
        self.python_run = 0
        self.sample = None

    def run(self, args, timeout=120, cwd=None, env=None):
        return super().run(args, timeout, cwd, env)

    def make_sample(self):
        if self.sample is None:
            p = self.run(["layer-make", "--n", "60", "--width-rm", "16", "--seed", "3", "--out", "sample.txt"])
            self.sample = p.returncode == 0
            if self.sample:
                with open(os.path.join(self.work, "sample.txt"), "rb") as a, \
                        open(os.path.join(self.work, "s.txt"), "wb") as b:
                    b.write(a.read())
        return self.sample

    def command(self, where, line):
        comment = split_comment(line)[1]
        args = command_args(line, "build/granwave ")
        if not args:
            return
        cmd = args[0]
        h = self.help(cmd)
        if h is None:
            self.fault(where, f"'granwave {cmd} --help' fails: no such command")
            return
        for a in args[1:]:
            if a.startswith("--"):
                flag = a.split("=", 1)[0]
                if not re.search(re.escape(flag) + r"(?![\w-])", h):
                    self.fault(where, f"'{flag}' is not in 'granwave {cmd} --help'")
        if cmd not in FAST or any(m in args for m in SLOW_MARKS):
            return
        if "--sample" in args and not self.make_sample():
            self.fault(where, "could not make the small sample")
            return
        p = self.run(args)
        if p.returncode != 0:
            self.fault(where, f"exit {p.returncode}: {p.stderr.strip()[-300:]}")
            return
        if "--json" in args:
            try:
                json.loads(p.stdout)
            except ValueError as e:
                self.fault(where, f"--json did not print one JSON object ({e})")
        if "--out" in args:
            out = args[args.index("--out") + 1]
            for name in FILE_IN_COMMENT.findall(comment):
                path = os.path.join(self.work, name if "/" in name else os.path.join(out, name))
                if not os.path.exists(path):
                    self.fault(where, f"the comment names {name}, not written under {out}")

    def refusal(self, where, line, expected):
        args = command_args(line, "$ granwave ")
        if args[:2] == ["sweep", "bad.ini"]:  # the page's config: a key of no model on line 5
            with open(os.path.join(self.work, "bad.ini"), "w") as f:
                f.write("[sweep]\nmodel = chain\n[grid]\nn = 1:2\nfoo = 1\n")
        if "s.txt" in args:
            self.make_sample()
        self.refused_as(where, args, expected)

    def python_env(self):
        env = dict(os.environ, PYTHONPATH=os.path.join(self.srcdir, "python"), PYTHONDONTWRITEBYTECODE="1")
        env["GRANWAVE_LIB"] = self.lib
        return env

    def python_line(self, where, line):
        """3b: a `PYTHONPATH=python /usr/bin/python3 -c "..."` line, run as written from the
        scratch directory with the checkout's module."""
        if not self.lib:
            return
        code, _ = split_comment(line)
        args = shlex.split(code)[1:]
        p = subprocess.run(args, capture_output=True, text=True, timeout=120, cwd=self.work, env=self.python_env())
        self.python_run += 1
        if p.returncode != 0 or not p.stdout.strip():
            self.fault(where, f"exit {p.returncode}, stdout {p.stdout.strip()[:80]!r}: {p.stderr.strip()[-300:]}")

    def python_refusal(self, where, line, expected):
        """3b: `>>> granwave.CALL(...)` raises the exception shown under it."""
        if not self.lib:
            return
        if "s.txt" in line:
            self.make_sample()
        prog = ("import granwave\n"
                "try:\n"
                f"    {line[4:].strip()}\n"
                "except Exception as e:\n"
                "    print(f'{type(e).__module__.split(\".\")[0]}.{type(e).__name__}: {e}')\n"
                "else:\n"
                "    print('no exception')\n")
        p = subprocess.run(["/usr/bin/python3", "-c", prog], capture_output=True, text=True, timeout=120,
                           cwd=self.work, env=self.python_env())
        self.python_run += 1
        if p.returncode != 0 or p.stdout.strip() != expected:
            self.fault(where, f"Python printed {p.stdout.strip()!r} (exit {p.returncode}{': ' + p.stderr.strip()[-200:] if p.stderr.strip() else ''}); "
                              f"the page says {expected!r}")

    def check(self, lines):
        for i, (rel, n, kind, line) in enumerate(lines):
            where = f"{rel}:{n}"
            s = line.strip()
            if kind == "sh" and s.startswith("build/granwave "):
                self.command(where, s)
            elif kind == "sh" and PY_LINE.match(s):
                self.python_line(where, s)
            elif kind == "text" and s.startswith(("$ granwave ", ">>> granwave.")):
                nxt = lines[i + 1] if i + 1 < len(lines) else None
                if nxt and nxt[0] == rel and nxt[1] == n + 1:
                    if s.startswith("$"):
                        self.refusal(where, split_comment(s)[0].strip(), nxt[3].strip())
                    else:
                        self.python_refusal(where, s, nxt[3].strip())
        return self.faults


# 1b. the commands the prose quotes inline
INLINE = re.compile(r"`(?:build/)?granwave ([a-z][a-z-]*)((?: [^`]*)?)`")


def inline_faults(checker, rel, text):
    """Flags of an inline `granwave CMD ...` that CMD's --help does not list."""
    text = re.sub(r"^```.*?^```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S | re.M)
    out = []
    for m in INLINE.finditer(text):
        cmd = m.group(1)
        if cmd in ("help", "version"):
            continue
        h = checker.help(cmd)
        where = f"{rel}:{text.count(chr(10), 0, m.start()) + 1}"
        if h is None:
            out.append(f"{where}: 'granwave {cmd} --help' fails: no such command")
            continue
        rest = m.group(2).replace("\n", " ").split(" -- ")[0]
        for flag in re.findall(r"(?<![\w-])(--[a-z][\w-]*)", rest):
            if not re.search(re.escape(flag) + r"(?![\w-])", h):
                out.append(f"{where}: '{flag}' is not in 'granwave {cmd} --help' (inline `granwave {cmd}{m.group(2)[:60]}`)")
    return out


# 4. the defaults and ranges the prose quotes, against `--help --json`
CLAIM_PAGES = ["README.md"] + ["docs/" + f for f in (
    "cli.md", "layer.md", "column.md", "drop.md", "sheets.md", "crowns.md", "outcomes.md",
    "formats.md", "library.md")]
UNITS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3}
NUM = r"-?\d[\d.]*(?:e[-+]?\d+)?"
VALUE = NUM + r"(?: ?(?:ns|us|ms|m/s\^2|m/s|kg/m\^3|s|m|deg|Pa|N)\b)?"
FLAG = r"`--([a-z][\w-]*)`"
CLAIM_FORMS = [  # (regex, group of the flag, group of the value, kind)
    (re.compile(FLAG + r"\s\((?:[\w/^.]+, )?(" + VALUE + r")[);]"), "default"),
    (re.compile(FLAG + r"(?:[^`.;]|\.\d){0,60}?\((?:[^()`;]{0,30}?,\s)?default\s(" + VALUE + r"|[\w/]+)[\s,;)]"), "default"),
    (re.compile(FLAG + r"\sdefaults to (" + VALUE + r")"), "default"),
    (re.compile(r"[Dd]efault\s" + FLAG + r"\sis\s(" + VALUE + r"|[\w/]+)"), "default"),
    (re.compile(r"`--([a-z][\w-]*) ([\w.-]+)`\s+\((?:the )?default\b"), "default"),
    (re.compile(FLAG + r"(?:[^`.;]|\.\d){0,60}?must be in ([\[(][^\])]*[\])])"), "range"),
]
# the commands a page is about, besides those a paragraph names
PAGE_COMMANDS = {"docs/drop.md": {"drop"}, "docs/outcomes.md": {"layer-impact"},
                 "docs/crowns.md": {"layer-impact"},
                 "docs/layer.md": {"layer-make", "layer-impact", "layer-stats"},
                 "docs/column.md": {"chain", "falcon", "wavespeed", "softwall", "dispersion"},
                 "docs/sheets.md": {"chain", "drop", "softwall"}}
COMMAND_NAME = re.compile(r"`(?:granwave )?([a-z][a-z-]+)(?: [^`]*)?`")


def as_number(text):
    """A value with its unit as a number in SI (20 us -> 2e-5), else None."""
    m = re.fullmatch(r"(" + NUM + r") ?([a-zA-Z/^\d]*)", text.strip())
    if not m:
        return None
    try:
        v = float(m.group(1))
    except ValueError:
        return None
    return v * UNITS.get(m.group(2), 1.0)


def default_holds(claim, default):
    if default is None:
        return False
    d = default[4:] if default.startswith("0 = ") else default
    c = as_number(claim)
    if c is not None:
        head = re.match(NUM, d.replace(" ", ""))
        return head is not None and as_number(head.group(0)) is not None and \
            abs(as_number(head.group(0)) - c) <= 1e-9 * abs(c)
    return claim in d.split(" / ") or claim in re.split(r"[ ;,]+", d)


def range_holds(claim, rng):
    return rng is not None and claim.replace(" ", "") == rng.replace(" ", "")


def help_tables(program):
    """{command: {flag: option object}} from `granwave CMD --help --json`."""
    p = subprocess.run([program, "--help", "--json"], capture_output=True, text=True, timeout=60)
    out = {}
    for c in json.loads(p.stdout)["commands"]:
        q = subprocess.run([program, c["name"], "--help", "--json"], capture_output=True, text=True, timeout=60)
        if q.returncode == 0:
            out[c["name"]] = {o["name"]: o for o in json.loads(q.stdout)["options"]}
    return out


def prose_claims(rel, text):
    """(where, flag, kind, value, paragraph) of each default or range a page quotes,
    outside code blocks."""
    text = re.sub(r"^```.*?^```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S | re.M)
    out = []
    for rx, kind in CLAIM_FORMS:
        for m in rx.finditer(text):
            a = text.rfind("\n\n", 0, m.start())
            b = text.find("\n\n", m.end())
            para = text[a + 1:b if b >= 0 else len(text)]
            out.append((f"{rel}:{text.count(chr(10), 0, m.start()) + 1}", m.group(1), kind,
                        m.group(2), para))
    return out


def check_claims(claims, tables):
    faults = []
    for where, flag, kind, value, para in claims:
        having = {c: t[flag] for c, t in tables.items() if flag in t}
        if not having:
            continue  # a flag of no command (or of sweep's keys): check 1's business
        page = PAGE_COMMANDS.get(where.split(":")[0], set())
        named = {c for c in set(COMMAND_NAME.findall(para)) | page if c in having}
        cands = {c: having[c] for c in named} or having
        if kind == "default":
            ok = any(default_holds(value, o["default"]) for o in cands.values())
            got = "; ".join(f"{c}: {o['default']!r}" for c, o in sorted(cands.items()))
        else:
            ok = any(range_holds(value, o["range"]) for o in cands.values())
            got = "; ".join(f"{c}: {o['range']!r}" for c, o in sorted(cands.items()))
        if not ok:
            faults.append(f"{where}: the page quotes --{flag}'s {kind} as {value!r}; --help --json says {got}")
    return faults


def self_test(program):
    page = ("```sh\n"
            "build/granwave chain --n 3 --no-such-flag 1\n"
            "build/granwave chain --n 0\n"
            "build/granwave chain --n 2 --out o    # o/not_written.csv\n"
            "```\n\n```text\n$ granwave chain --n 0\ngranwave chain --n: not what it says\n```\n")
    with tempfile.TemporaryDirectory() as d:
        lines = [("self", i + 1, k, l) for i, (k, l) in enumerate(
            [("sh", x) for x in page.split("```text")[0].splitlines()[1:4]])]
        lines += [("self", 10, "text", "$ granwave chain --n 0"),
                  ("self", 11, "text", "granwave chain --n: not what it says")]
        faults = Checker(program, d).check(lines)
    want = ["'--no-such-flag' is not in", "exit 2", "not_written.csv", "the page says"]
    with tempfile.TemporaryDirectory() as d:  # 1b: an inline command with a removed flag, one after `--`
        faults += inline_faults(Checker(program, d), "self.md",
                                "Run `granwave chain --n 3 --no-such-inline 1` or `granwave sweep --out D -- --odd.ini`.\n")
    want += ["self.md:1: '--no-such-inline' is not in"]
    if any("--odd.ini" in f for f in faults):
        print("self-test: a name after `--` taken for a flag")
        return False
    if os.environ.get("GRANWAVE_LIB"):  # 3b: a Python line that fails, a refusal of another text
        with tempfile.TemporaryDirectory() as d:
            faults += Checker(program, d).check([
                ("self", 20, "sh", 'PYTHONPATH=python /usr/bin/python3 -c "import granwave; print(granwave.chain(n=0))"'),
                ("self", 30, "text", ">>> granwave.chain(n=2, vimp=2000)"),
                ("self", 31, "text", "granwave.GranwaveValueError: chain: vimp: 2000 is outside (0, 1]")])
        want += ["self:20: exit 1", "self:30: Python printed 'granwave.GranwaveValueError: chain: vimp"]
    # 4: a default and a range that drifted, a choice's default, and claims that hold
    page = ("For `drop`: `--gravity` defaults to 9.8 m/s^2 and must be in [1e-3, 1e5].\n"
            "`--solver rk4` (the default) and `--t-max` (default 10 ms).\n\n"
            "`--friction` (deg, 30), `--dt-out` (20 us).\n")
    tables = help_tables(program)
    claims = prose_claims("self.md", page)
    faults += check_claims(claims, tables)
    want += ["--gravity's default as '9.8 m/s^2'", "--gravity's range as '[1e-3, 1e5]'",
             "--solver's default as 'rk4'"]
    if len(claims) != 6 or sum("the page quotes" in f for f in faults) != 3:
        print(f"self-test: {len(claims)} claims read of 6, "
              f"{sum('the page quotes' in f for f in faults)} faults of 3:\n" + "\n".join(faults))
        return False
    return noticed(not_caught(want, faults), faults)


def main():
    args = program_srcdir(__doc__)
    if args is None:
        return 2
    program, srcdir = args
    if not self_test(program):
        return 1
    lines = doc_lines(srcdir)
    with tempfile.TemporaryDirectory() as d:
        c = Checker(program, d, srcdir)
        faults = c.check(lines)
    with tempfile.TemporaryDirectory() as d:
        c1 = Checker(program, d, srcdir)
        ninline = 0
        for rel in ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(srcdir, "docs"))
                                          if f.endswith(".md")):
            text = open(os.path.join(srcdir, rel), encoding="utf-8").read()
            ninline += len(INLINE.findall(text))
            faults += inline_faults(c1, rel, text)
    claims = []
    for rel in CLAIM_PAGES:
        claims += prose_claims(rel, open(os.path.join(srcdir, rel), encoding="utf-8").read())
    faults += check_claims(claims, help_tables(program))
    ncmd = sum(1 for _, _, k, l in lines if l.strip().startswith(("build/granwave ", "$ granwave ")))
    npy = sum(1 for _, _, k, l in lines if PY_LINE.match(l.strip()) or l.strip().startswith(">>> granwave."))
    pyrun = (f"{c.python_run} of {npy} Python lines run" if c.lib
             else f"{npy} Python lines not run (no GRANWAVE_LIB)")
    return finish(faults, f"{ncmd} documented commands, {ninline} inline ones, {pyrun}, {len(claims)} quoted defaults "
                  f"and ranges, {len(faults)} fault(s)")


if __name__ == "__main__":
    sys.exit(main())
