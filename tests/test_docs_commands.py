#!/usr/bin/python3
"""test_docs_commands.py PROGRAM SRCDIR: what the prose of the docs quotes a command printing.

A new user who runs a command the prose of docs/ names and compares what it prints
with the quote beside it. test_docs_examples holds the ```sh and ```text blocks; this
test holds what they leave (about 12 s of CPU, in a scratch directory):
  1. MESSAGES: each refusal or line the prose quotes (cli.md, formats.md: a flag given
     twice, a value that is an option, a hexadecimal number, a path too long, a sweep
     config's `#` comment, a relative sample that names nothing, a sparse 200 GB sample,
     a file cut inside its last line, `k` on one body, `sweep --check`'s lines before a
     run, on a resume and after the last case; outcomes.md's warning of an undecided
     bounce, on the default 300-disc sample: 8 s of CPU) is still on the page, and the command
     prints it (exit code as the page says; a `...` on the page stands for any text, a
     `/home/me/` for the scratch directory);
  2. DROP_KEYS: every top-level key of `drop --json` is named in docs/drop.md's
     "Outputs" paragraph (`version` and `settings` aside: formats.md says them for all),
     and the keys of its lists and objects ({t_start, ...} of `impacts`, {t, f, ...} of
     `wall_peaks`, `energy` {...}, settings' `drop`: ...) are exactly the ones listed;
  3. NUMBERS: the results docs/library.md's C examples quote in their comments
     (`gw_chain_collision_run` on 7 glass beads, `gw_chain_falcon_run` over N = 1..20),
     and drop.md's step count of the 10 ms CVODE drop, recomputed by the same runs through
     the program, to the digits shown;
  4. the VTK snapshots: formats.md's "VTK snapshots" names every .vtk and .pvd file
     `layer-impact --out` writes (on a 40-disc sample) and every field of its
     snapshot_end.vtk (SCALARS, VECTORS and the field data TIME).
First it checks itself on the real pages with one quote, three keys, one number and three
VTK names changed
and fails if any goes unnoticed. Exit 0 when all hold, 1 otherwise (each fault printed
as page: message), 2 on bad usage.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from docs_frame import drifted, finish, noticed, program_srcdir
from docs_runner import line_holds

HOME = "/home/me/"
_RUNS = {}


def run_once(program, args, cwd):
    """A run that reads and writes no file of its directory (--json alone), once per
    program and arguments (the self-test asks for the same runs again)."""
    key = (program, tuple(args))
    if key not in _RUNS:
        _RUNS[key] = subprocess.run([program, *args], capture_output=True, text=True, timeout=120, cwd=cwd)
    return _RUNS[key]


def flat(text):
    """Blanks and line breaks as one blank (a quote may be broken over lines)."""
    return re.sub(r"\s+", " ", text)


def write(work, name, text):
    path = os.path.join(work, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def sparse(work, name, size):
    with open(os.path.join(work, name), "wb") as f:
        f.truncate(size)


def cut_journal(work, path, rows):
    """Keep the journal's head and its first `rows` rows (a sweep stopped there)."""
    p = os.path.join(work, path)
    lines = open(p, encoding="utf-8").read().splitlines(True)
    head = [l for l in lines if l.startswith("#") or l.startswith("case")]
    body = [l for l in lines if l not in head]
    with open(p, "w") as f:
        f.write("".join(head + body[:rows]))
    os.remove(os.path.join(os.path.dirname(p), "results.csv"))


SAMPLE300 = ["layer-make", "--n", "300", "--seed", "1", "--out", "sample300.txt", "--quiet"]
STUDY = "[sweep]\nmodel = chain\nout = results/study\n[grid]\nn = 1:40\n"
# (page, the quote as the page has it (line breaks as blanks), setup steps, arguments,
#  exit code, which line of the output (stderr for a refusal, else stdout, or "stderr" after it), quoted)
MESSAGES = [
    ("docs/cli.md", "granwave chain --n: given twice", [],
     ["chain", "--n", "3", "--vimp", "0.3", "--n", "30"], 2, 0),
    ("docs/cli.md", "granwave chain --out: needs a value DIR, and '--json' is an option of chain ...", [],
     ["chain", "--out", "--json"], 2, 0),
    ("docs/cli.md", "granwave chain --vimp: '0x1p-2' is not a decimal number (no hexadecimal, as for integers)", [],
     ["chain", "--vimp", "0x1p-2"], 2, 0),
    ("docs/cli.md", "granwave chain --out: the path is 4441 bytes long, more than the 4095 a path may hold: '...'", [],
     ["chain", "--out", "o" * 4441], 2, 0),
    ("docs/cli.md", "granwave sweep: one.ini: k: has no effect on one body (n = 1) in any case (2 of 2 cases; "
                    "the first, case 0): k is the bead-bead contact's coefficient ...",
     [("write", "one.ini", "[sweep]\nmodel = chain\n[grid]\nvimp = 0.1, 0.2\n[params]\nn = 1\nk = 1e9\n")],
     ["sweep", "one.ini", "--check", "--out", "one"], 2, 0),
    ("docs/formats.md", "granwave sweep: c.ini:5: [grid] n: a '#' after a value starts no comment in a config, "
                        "';' does: ...",
     [("write", "c.ini", "[sweep]\nmodel = chain\n[grid]\nvimp = 0.1\nn = 40 #2\n")],
     ["sweep", "c.ini", "--check", "--out", "c"], 2, 0),
    ("docs/formats.md", "granwave sweep: cfg/d.ini: [params] sample = S.txt: no such file /home/me/cfg/S.txt (a "
                        "relative path in a config is taken from the config's directory)",
     [("write", "cfg/d.ini", "[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = S.txt\n")],
     ["sweep", "cfg/d.ini", "--check", "--out", "d"], 2, 0),
    ("docs/formats.md", "granwave sweep: c.ini: [params] sample '/home/me/big.txt': 214748364800 bytes, larger than "
                        "a sample file may be (4294967296 bytes, 4 GiB): not a sample",
     [("sparse", "big.txt", 214748364800),
      ("write", "c.ini", "[sweep]\nmodel = layer\n[grid]\nvi = 10, 20\n[params]\nsample = big.txt\n")],
     ["sweep", "c.ini", "--check", "--out", "big"], 2, 0),
    ("docs/formats.md", "granwave sweep: c.ini:8: the file ends inside this line (no newline after it): cut short? ...",
     [("write", "c.ini", "[sweep]\nmodel = chain\n[grid]\nvimp = 0.1, 0.2\n[params]\nn = 3\nsolver = rk4\nt-max = 1")],
     ["sweep", "c.ini", "--check", "--out", "cut"], 2, 0),
    # cli.md's `--check` before a run, on a resume (its block) and after the last case
    ("docs/cli.md", "sweep: study.ini is valid: model chain, 40 cases", [("write", "study.ini", STUDY)],
     ["sweep", "study.ini", "--check"], 0, 0),
    ("docs/cli.md", "`DIR: no journal yet: a run starts all N cases`", [("write", "study.ini", STUDY)],
     ["sweep", "study.ini", "--check"], 0, 1),
    ("docs/cli.md", "`... N of N cases done: a rerun writes the table only`",
     [("write", "study.ini", STUDY), ("run", ["sweep", "study.ini", "--jobs", "1", "--quiet"])],
     ["sweep", "study.ini", "--check"], 0, 1),
    # outcomes.md's undecided bounce, on the default 300-disc sample (8 s of CPU, made once)
    ("docs/outcomes.md", "granwave layer-impact: warning: bounce undecided: the run ended at t-max = 0.02 s before the "
                         "block left the layer moving up or its rebound ended inside it (block in free flight, "
                         "v_y = -1.655 m/s); raise --t-max",
     [("sample300",)], ["layer-impact", "--sample", "sample.txt", "--t-max", "0.02", "--json"], 0, 0, "stderr"),
    ("docs/cli.md", "sweep: /home/me/results/study/journal.csv: 25 of 40 cases done, 15 to run on a resume",
     [("write", "study.ini", STUDY), ("run", ["sweep", "study.ini", "--jobs", "1", "--quiet"]),
      ("cut", "results/study/journal.csv", 25)],
     ["sweep", "study.ini", "--check"], 0, 1),
]


_SWEPT = {}


def template(quote, work):
    """A quote that stands for a form (`DIR: ... N cases`) as the line it stands for here."""
    q = quote.strip("`")
    if q.startswith("DIR: no journal yet"):
        return "sweep: " + os.path.join(work, "results/study") + q[3:].replace("N cases", "40 cases")
    if q.startswith("... N of N"):
        return "sweep: ..." + q[3:].replace("N of N", "40 of 40")
    return q.replace(HOME, work + "/")


def check_messages(program, work, pages, messages=MESSAGES):
    faults = []
    made = 0
    for page, quote, setup, args, code, line, *stream in messages:
        if flat(quote) not in flat(pages[page]):
            faults.append(f"{page}: no longer quotes {quote[:70]!r} (update this test with the page)")
            continue
        made += 1
        d = os.path.join(work, f"m{made}")
        os.makedirs(d)
        for step in setup:
            if step[0] == "write":
                write(d, step[1], step[2])
            elif step[0] == "sparse":
                sparse(d, step[1], step[2])
            elif step[0] == "cut":
                cut_journal(d, step[1], step[2])
            elif step[0] == "sample300":
                if not os.path.exists(os.path.join(work, "sample300.txt")):
                    subprocess.run([program, *SAMPLE300], capture_output=True, timeout=300, cwd=work)
                if os.path.exists(os.path.join(work, "sample300.txt")):
                    os.symlink(os.path.join(work, "sample300.txt"), os.path.join(d, "sample.txt"))
            else:  # a sweep in the config's directory: once, copied for the next lines
                key = (program, tuple(step[1]), open(os.path.join(d, step[1][1])).read())
                if key not in _SWEPT:
                    subprocess.run([program, *step[1]], capture_output=True, timeout=120, cwd=d)
                    _SWEPT[key] = d
                else:
                    shutil.copytree(os.path.join(_SWEPT[key], "results"), os.path.join(d, "results"))
        p = subprocess.run([program, *args], capture_output=True, text=True, timeout=120, cwd=d)
        out = (p.stderr if code or stream == ["stderr"] else p.stdout).splitlines()
        got = out[line] if line < len(out) else "(no such line)"
        want = template(quote, os.path.realpath(d))
        if p.returncode != code or not line_holds(want, got):
            faults.append(f"{page}: quotes {want[:90]!r}; granwave {' '.join(a[:20] for a in args)}: "
                          f"exit {p.returncode}, line {line + 1}: {got[:140]!r}")
    return faults


DROP_ARGS = ["drop", "--n", "5", "--gap", "1e-4", "--t-max", "2e-3", "--json"]


def drop_outputs(page):
    """The paragraph of drop.md's "Outputs" that lists the --json keys."""
    sec = page.split("## Outputs", 1)[1]
    return flat(sec.split("`--json` prints one object:", 1)[1].split("Without `--json`", 1)[0])


def braced(text, after):
    """The names listed in the {...} after `after` in text ('`impacts` (list of {a, b})')."""
    m = re.search(re.escape(after) + r"[^{]{0,20}\{([^}]*)\}", text)
    return None if m is None else {s.strip() for s in m.group(1).split(",")}


def check_drop_keys(program, work, page):
    faults = []
    try:
        text = drop_outputs(page)
    except IndexError:
        return ["docs/drop.md: no \"`--json` prints one object:\" paragraph under Outputs (update this test)"]
    p = run_once(program, DROP_ARGS, work)
    if p.returncode != 0:
        return [f"docs/drop.md: granwave {' '.join(DROP_ARGS)}: exit {p.returncode}: {p.stderr.strip()[-200:]}"]
    j = json.loads(p.stdout)
    named = set(re.findall(r"`(\w+)`", text))
    missing = sorted(set(j) - {"version", "settings"} - named)
    if missing:
        faults.append(f"docs/drop.md: `drop --json` prints {', '.join(missing)}, which the Outputs paragraph does not name")
    for key, got in (("`impacts`", j["impacts"][0] if j["impacts"] else None),
                     ("`wall_peaks`", j["wall_peaks"][0] if j["wall_peaks"] else None),
                     ("`energy`", j["energy"])):
        listed = braced(text, key)
        if got is None:
            faults.append(f"docs/drop.md: the run gave no {key} entry to compare (update this test)")
        elif listed != set(got):
            faults.append(f"docs/drop.md: {key} lists {sorted(listed or [])}; `drop --json` has {sorted(got)}")
    m = re.search(r"plus `drop`: ([^)]*)\)", text)
    listed = None if m is None else {s.strip() for s in m.group(1).split(",")}
    if listed != set(j["settings"]["drop"]):
        faults.append(f"docs/drop.md: settings' `drop` lists {sorted(listed or [])}; `drop --json` has "
                      f"{sorted(j['settings']['drop'])}")
    return faults


SAMPLE40 = ["layer-make", "--n", "40", "--seed", "1", "--out", "s40.txt", "--quiet"]
_VTK = {}


def check_vtk(program, work, page):
    """4: formats.md's "VTK snapshots" names every file of them an impact writes and every
    field (point and cell data, the field data) of its snapshot_end.vtk."""
    try:
        sec = page.split("## VTK snapshots", 1)[1].split("\n## ", 1)[0]
    except IndexError:
        return ["docs/formats.md: no \"## VTK snapshots\" section (update this test)"]
    named = set(re.findall(r"`([\w.]+)`", sec))
    d = _VTK.get(program)
    if d is None:  # once per program (the self-test reads the same files)
        d = _VTK[program] = os.path.join(work, "vtk")
        os.makedirs(d)
        for args in (SAMPLE40, ["layer-impact", "--sample", "s40.txt", "--out", "imp", "--quiet"]):
            p = subprocess.run([program, *args], capture_output=True, text=True, timeout=120, cwd=d)
            if p.returncode != 0:
                return [f"docs/formats.md: granwave {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()[-200:]}"]
    faults = []
    files = sorted(f for f in os.listdir(os.path.join(d, "imp")) if f.endswith((".vtk", ".pvd")))
    unnamed = [f for f in files if f not in named]
    if unnamed or not files:
        faults.append(f"docs/formats.md: `layer-impact --out` writes {', '.join(unnamed) or 'no snapshot'}, "
                      f"which the VTK section does not name")
    vtk = open(os.path.join(d, "imp", "snapshot_end.vtk"), encoding="utf-8").read()
    fields = re.findall(r"^(?:SCALARS|VECTORS) (\w+)", vtk, re.M) + re.findall(r"^(\w+) 1 1 double$", vtk, re.M)
    unnamed = [f for f in fields if f not in named]
    if unnamed or not fields:
        faults.append(f"docs/formats.md: snapshot_end.vtk holds {', '.join(unnamed) or 'no field'}, "
                      f"which the VTK section does not name")
    return faults


def _chain7(j):
    return (f"c.r.f_max = {j['f_max']:.4f} N at {j['tau_max'] * 1e6:.2f} us, tau_N {j['tau_n'] * 1e6:.1f} us; "
            f"c.f_max_1 = {j['closed_forms']['f_max_1']:.4f} N (F.13)")


def _falcon20(j):
    v = j["velocities"][0]
    return (f"o.t_q[0] = {v['t_q'] * 1e6:.2f} us, o.wave_speed[0] = {v['wave_speed']:.1f} m/s against "
            f"{v['wave_speed_theory']:.1f} m/s (F.27)")


# (page, the text of the comment, the run, its text from the run's JSON)
NUMBERS = [
    ("docs/library.md", "c.r.f_max = 24.4476 N at 15.75 us, tau_N 198.7 us; c.f_max_1 = 24.0906 N (F.13)",
     ["chain", "--n", "7", "--material", "glass", "--vimp", "0.3", "--json"], _chain7),
    ("docs/library.md", "o.t_q[0] = 25.68 us, o.wave_speed[0] = 623.0 m/s against 640.6 m/s (F.27)",
     ["falcon", "--n", "1:20", "--heights", "none", "--json", "--quiet"], _falcon20),
    ("docs/drop.md", "14 858 CVODE steps (",
     ["drop", "--n", "40", "--height", "5.1e-3", "--damping", "kk", "--restitution", "0.9", "--json", "--quiet"],
     lambda j: f"{j['steps'] // 1000} {j['steps'] % 1000:03d} CVODE steps ("),
]


def check_numbers(program, work, pages, numbers=NUMBERS):
    faults = []
    for page, text, args, fmt in numbers:
        if text not in pages[page]:
            faults.append(f"{page}: no longer holds {text!r} (update this test with the page)")
            continue
        p = run_once(program, args, work)
        if p.returncode != 0:
            faults.append(f"{page}: granwave {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()[-200:]}")
            continue
        got = fmt(json.loads(p.stdout))
        if got != text:
            faults.append(f"{page}: quotes {text!r}; granwave {' '.join(args)} gives {got!r}")
    return faults


def check(program, work, pages):
    faults = check_messages(program, os.path.join(work, "msg"), pages)
    faults += check_drop_keys(program, work, pages["docs/drop.md"])
    faults += check_numbers(program, work, pages)
    faults += check_vtk(program, work, pages["docs/formats.md"])
    return faults


def self_test(program, pages):
    """The real pages with one quote, one key and one number changed: each must be noticed,
    and a quote the program does not print (a changed code) too."""
    cases = [
        ("docs/cli.md", "given\ntwice", "given\nagain", "no longer quotes 'granwave chain --n: given twice'"),
        ("docs/drop.md", "`cut_first_collision`", "`cut_first`", "prints cut_first_collision, which"),
        ("docs/drop.md", "v_in, v_out, n_peaks", "v_in, v_exit, n_peaks", "`impacts` lists"),
        ("docs/drop.md", "gaps, t_max, dt_out", "gaps, t_max", "settings' `drop` lists"),
        ("docs/library.md", "24.4476 N at 15.75 us", "24.4477 N at 15.75 us", "no longer holds 'c.r.f_max"),
        ("docs/formats.md", "and `snapshots.pvd`", "and `snapshots.xml`", "writes snapshots.pvd, which"),
        ("docs/formats.md", "point data `radius` (m)", "point data `radii` (m)", "holds radius, which"),
        ("docs/formats.md", "field data\n`TIME` (s)", "field data\n`T` (s)", "holds TIME, which"),
    ]
    missed = []
    for page, old, new, want in cases:
        bad = dict(pages, **{page: drifted(pages[page], old, new)})
        if bad[page] is None:
            missed.append(f"{old!r} (not on {page})")
            continue
        with tempfile.TemporaryDirectory() as d:
            faults = (check_drop_keys(program, d, bad[page]) if page == "docs/drop.md" else
                      check_vtk(program, d, bad[page]) if page == "docs/formats.md" else
                      check_numbers(program, d, bad) if page == "docs/library.md" else
                      check_messages(program, d, bad, MESSAGES[:1]))
        if not any(want in f for f in faults):
            missed.append(f"{old!r} -> {new!r}: {faults}")
    # the code drifting: a quote the program does not print, a number it does not give
    drift_pages = dict(pages, **{"docs/cli.md": pages["docs/cli.md"] + "\n\"granwave chain --n: given two times\"\n",
                                 "docs/library.md": pages["docs/library.md"] + "\nc.r.f_max = 24.4477 N\n"})
    with tempfile.TemporaryDirectory() as d:
        f1 = check_messages(program, d, drift_pages,
                            [("docs/cli.md", "granwave chain --n: given two times", [],
                              ["chain", "--n", "3", "--vimp", "0.3", "--n", "30"], 2, 0)])
        f2 = check_numbers(program, d, drift_pages,
                           [("docs/library.md", "c.r.f_max = 24.4477 N", NUMBERS[0][2],
                             lambda j: f"c.r.f_max = {j['f_max']:.4f} N")])
    if not any("line 1: 'granwave chain --n: given twice'" in f for f in f1):
        missed.append(f"a message the program does not print: {f1}")
    if not any("gives 'c.r.f_max = 24.4476 N'" in f for f in f2):
        missed.append(f"a number the program does not give: {f2}")
    return noticed(missed)


def main():
    args = program_srcdir(__doc__)
    if args is None:
        return 2
    program, srcdir = args
    pages = {rel: open(os.path.join(srcdir, rel), encoding="utf-8").read()
             for rel in ("docs/cli.md", "docs/formats.md", "docs/drop.md", "docs/library.md", "docs/outcomes.md")}
    with tempfile.TemporaryDirectory() as work:
        faults = check(program, work, pages)
        ok = self_test(program, pages)  # reads the VTK run made in work
    return finish(faults, f"test_docs_commands: {len(MESSAGES)} quoted lines, drop's JSON keys, {len(NUMBERS)} quoted "
                  f"results, the VTK fields, {len(faults)} fault(s)", ok)


if __name__ == "__main__":
    sys.exit(main())
