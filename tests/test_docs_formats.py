#!/usr/bin/python3
"""test_docs_formats.py PROGRAM SRCDIR: the example files docs/formats.md shows are what
the program writes, and its example configs run.

A new user compares the files a run writes with the examples formats.md prints. In a
scratch directory:
  1. the sample file example (the ```text block starting `granwave-layer-sample 1`): the
     command its `# command:` line names is run, and the block's lines, to the particle
     annotation (`x y r  <- ...`), are the file's first lines, one for one and in order
     (a `...` in a line stands for any text there: the page's line must begin with what
     comes before it and end with what comes after);
  2. the springs example (the block starting `springs M`): M and the spring lines shown
     are the ones of that sample (they go together on the page);
  3. the sweep table example (the block starting `# granwave VERSION sweep`): its
     `# grid` and `# param` lines are made a config, run with `sweep`, and the table's
     first line (version, model, config hash, cases), its `# param`, `# grid` and column
     lines and the row shown (with its `...`) are the page's; of the `# build` line only
     the part before the commit (the rest is the machine's);
  5. every top-level key of `chain --json`, `layer-impact --json` (the 300-disc sample)
     and `layer-make --json` is named in the page's table of that command (the text for
     layer-make), `version`, `settings` and `warnings` aside (said for all of them);
  4. every ```ini block passes `sweep CONFIG --check` (exit 0): a block without
     `[sweep]` (a `[grid]` fragment) under `[sweep] model = chain`; the diagram config,
     which names `sample.txt`, beside the sample of the command the page gives for it
     (`layer-make --n 300 --seed 1`).
First it checks itself on made-up blocks (a changed number, a missing header line, a
wrong spring count, a wrong config hash) and fails if any goes unnoticed. About 10 s of
CPU (the 300-disc pluviation: 6 s). 5 of its 9 checks fail on the page before. Exit 0 when all hold, 1 otherwise (each fault
printed), 2 on bad usage.
"""
import json
import os
import re
import shlex
import sys
import tempfile

from docs_frame import drifted, finish, noticed, program_srcdir
from docs_runner import Runner, first_difference, fenced, line_holds, run


def blocks(text):
    """[(kind, first line number, [lines])] of the ```text and ```ini blocks."""
    return fenced(text, ("text", "ini"))


def annotation(line):
    return "<-" in line


_RUNNERS = {}


def made(program, args, cwd):
    """A pluviation run once per scratch directory (the self-test reuses the pages' samples)."""
    return _RUNNERS.setdefault((program, cwd), Runner(program, cwd)).made(args)


def check_sample(program, work, where, shown, springs, faults):
    """1 and 2: the sample block (and the springs block) against the file its command writes."""
    cmd = next((l for l in shown if l.startswith("# command: granwave ")), None)
    if cmd is None:
        faults.append(f"{where}: the sample example names no `# command:` line")
        return
    args = shlex.split(cmd[len("# command: granwave "):])  # as written (a `  #` in it is no comment)
    p = made(program, args, work)  # as written: the file records its command line
    out = args[args.index("--out") + 1] if "--out" in args else None
    if p.returncode != 0 or out is None:
        faults.append(f"{where}: `{cmd[11:]}` exit {p.returncode}: {p.stderr.strip()[-200:]}")
        return
    got = open(os.path.join(work, out), encoding="utf-8").read().splitlines()
    d = first_difference([l for l in shown if not annotation(l)], got)
    if d:
        i, sh, g = d
        faults.append(f"{where + i}: the page shows {sh[:90]!r}; line {i + 1} of {out} is {g[:90]!r}")
    if springs is None:
        return
    swhere, slines = springs
    m = re.match(r"springs (\d+)", slines[0])
    at = next((i for i, l in enumerate(got) if l.startswith("springs ")), None)
    if at is None:
        faults.append(f"{swhere}: the page shows a springs section; {out} has none")
        return
    want = [f"springs {m.group(1)}"] + [l for l in slines[1:] if not annotation(l) and not l.startswith(" ")]
    d = first_difference(want, got[at:])
    if d:
        i, sh, g = d
        faults.append(f"{swhere + i}: the page shows {sh!r} (after the sample's particles); "
                      f"{out} has {g!r}")


def check_table(program, work, where, shown, faults):
    """3: the sweep table example against the table of a sweep of its grid and params."""
    m = re.match(r"# granwave \S+ sweep, model (\w+), config ", shown[0])
    if not m:
        faults.append(f"{where}: not a sweep table's first line: {shown[0]!r}")
        return
    cfg = ["[sweep]", f"model = {m.group(1)}", "[grid]"]
    cfg += [l[len("# grid "):] for l in shown if l.startswith("# grid ")]
    cfg += ["[params]"] + [l[len("# param "):] for l in shown if l.startswith("# param ")]
    d = tempfile.mkdtemp(dir=work)
    with open(os.path.join(d, "t.ini"), "w") as f:
        f.write("\n".join(cfg) + "\n")
    p = run(program, ["sweep", "t.ini", "--out", "t", "--jobs", "1", "--quiet"], d)
    if p.returncode != 0:
        faults.append(f"{where}: the example's sweep exit {p.returncode}: {p.stderr.strip()[-200:]}")
        return
    got = open(os.path.join(d, "t", "results.csv"), encoding="utf-8").read().splitlines()
    for i, s in enumerate(shown):
        g = got[i] if i < len(got) else "(end of file)"
        if s.startswith("# build "):
            s, g = s.split(", commit")[0], g.split(", commit")[0]
        if not line_holds(s, g):
            faults.append(f"{where + i}: the page shows {s[:100]!r}; the sweep's table has {g[:100]!r}")


def check_ini(program, work, where, lines, sample300, faults):
    """4: an ini block passes `sweep --check`."""
    text = "\n".join(lines) + "\n"
    if "[sweep]" not in text:
        text = "[sweep]\nmodel = chain\n" + text
    d = tempfile.mkdtemp(dir=work)
    if re.search(r"^sample = sample\.txt", text, re.M):
        if not sample300():
            faults.append(f"{where}: could not make the page's sample (layer-make --n 300 --seed 1)")
            return
        os.link(os.path.join(work, "sample300.txt"), os.path.join(d, "sample.txt"))
    with open(os.path.join(d, "c.ini"), "w") as f:
        f.write(text)
    p = run(program, ["sweep", "c.ini", "--out", "o", "--check"], d)
    if p.returncode != 0:
        faults.append(f"{where}: `sweep --check` exit {p.returncode}: {p.stderr.strip()[-200:]}")


JSON_DOCS = (  # (command run, the page's text that names its keys: from, to)
    (["chain", "--n", "5", "--json"], "`granwave chain --json`:", "`granwave layer-impact --json`:"),
    (["layer-impact", "--sample", "sample300.txt", "--json"], "`granwave layer-impact --json`:",
     "`granwave layer-make --json`"),
    (None, "`granwave layer-make --json` gives", "\n\n"))  # the 300-disc sample's own run
SAMPLE300 = ["layer-make", "--n", "300", "--seed", "1", "--out", "sample300.txt", "--json", "--quiet"]


def check_json_keys(program, work, rel, text, sample300, faults):
    """5: the keys a command's --json prints are named on the page."""
    for args, start, end in JSON_DOCS:
        if start not in text:
            faults.append(f"{rel}: no longer holds {start!r} (update this test with the page)")
            continue
        sec = text.split(start, 1)[1].split(end, 1)[0]
        named = set(re.findall(r"`(\w+)`", sec))
        if args is None:
            args = SAMPLE300
            p = made(program, args, work)
        else:
            if "sample300.txt" in args and not sample300():
                faults.append(f"{rel}: could not make the 300-disc sample")
                continue
            p = run(program, args + ["--quiet"], work)
        if p.returncode != 0:
            faults.append(f"{rel}: granwave {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()[-200:]}")
            continue
        keys = set(json.loads(p.stdout)) - {"version", "settings", "warnings"}
        missing = sorted(keys - named)
        if missing:
            faults.append(f"{rel}: `granwave {args[0]} --json` prints {', '.join(missing)}, which the page's "
                          f"text after {start!r} does not name")


def check_page(program, work, rel, text):
    faults = []

    def sample300():
        return made(program, SAMPLE300, work).returncode == 0

    check_json_keys(program, work, rel, text, sample300, faults)
    bl = blocks(text)
    seen = set()
    for i, (kind, n, lines) in enumerate(bl):
        where = f"{rel}:{n}"
        if kind == "ini":
            check_ini(program, work, where, lines, sample300, faults)
        elif lines and lines[0].startswith("granwave-layer-sample "):
            nxt = bl[i + 1] if i + 1 < len(bl) else None
            springs = (_Where(rel, nxt[1]), nxt[2]) if nxt and nxt[2] and nxt[2][0].startswith("springs ") else None
            check_sample(program, work, _Where(rel, n), lines, springs, faults)
            seen.add("sample")
            if springs:
                seen.add("springs")
        elif lines and re.match(r"# granwave \S+ sweep, ", lines[0]):
            check_table(program, work, _Where(rel, n), lines, faults)
            seen.add("table")
    for what in ("sample", "springs", "table"):
        if what not in seen:
            faults.append(f"{rel}: no {what} example found (the test reads a block it no longer finds)")
    return faults


class _Where:
    """file:line, with + giving the line i lines further."""

    def __init__(self, rel, n):
        self.rel, self.n = rel, n

    def __add__(self, i):
        return f"{self.rel}:{self.n + i}"

    def __str__(self):
        return f"{self.rel}:{self.n}"

    __format__ = lambda self, spec: str(self)


def self_test(program, page, work):
    """The real page with faults put in: each must be noticed."""
    cases = {
        "porosity": (r"porosity 0\.\d+", "porosity 0.19"),
        "header line": (r"# units: metres[^\n]*\n", ""),
        "spring count": (r"springs (\d+)", "springs 9999"),
        "config hash": (r"config [0-9a-f]{16}", "config 0123456789abcdef"),
        "ini": (r"n = 1:40", "n = 0:40"),
        "json key": (r"\| `t_f`, `undecided` \|", "| `t_ff`, `undecided` |"),
    }
    missed = []
    for name, (rx, new) in cases.items():
        bad = drifted(page, rx, new, regex=True)
        if bad is None:
            missed.append(f"{name} (not on the page)")
            continue
        if not check_page(program, work, "self.md", bad):
            missed.append(name)
    return noticed(missed)


def main():
    args = program_srcdir(__doc__)
    if args is None:
        return 2
    program, srcdir = args
    rel = "docs/formats.md"
    page = open(os.path.join(srcdir, rel), encoding="utf-8").read()
    with tempfile.TemporaryDirectory() as work:
        faults = check_page(program, work, rel, page)
        ok = self_test(program, page, work)
    nini = sum(1 for k, _, _ in blocks(page) if k == "ini")
    return finish(faults, f"test_docs_formats: the sample, springs and sweep table examples and {nini} configs of "
                  f"{rel}, {len(faults)} fault(s)", ok)


if __name__ == "__main__":
    sys.exit(main())
