#!/usr/bin/python3
"""test_help_text_ranges.py PROGRAM: `granwave CMD --help` prints every bounded option's range.

A user reads a flag's accepted values in the text help. `CMD --help --json` gave each
number option with a bound its parser's range, but the text help printed none for 82 of
those 186 options (`chain --n`, `chain --rtol`, `layer-make --width-rm`, `falcon --jobs`):
nothing on the line said what was accepted. For every command that `granwave --help
--json` lists:
  1. the text help lists the options the JSON lists, and for every option the range the
     text line prints (its first "in [..]" or "in (..)", with a following " (or 0)") is
     the JSON's `range` (both null for an option without one); every number option with
     a bound (`min` or `max` not null) prints one;
  2. for each end of a range in numbers (ranges in words, drop's `[t-max/1e7, t-max]`,
     are left out), the end printed agrees with `min` or `max` to the six digits a range
     prints, and the option parser (`CMD --help --FLAG V`: the value is checked, nothing
     runs) takes the end as printed where it is closed and refuses it where it is open;
     a value just outside (an integer's next one, a real's end moved out by 1e-5 of
     itself, past the rounding of six printed digits; 1e-300 past a 0) is refused,
     exit 2, one line on stderr naming `CMD --FLAG` and, where it names a range, that
     range's ends; nothing is written (the scratch directory stays empty).
First it checks itself on made-up lines (a line without its range, a range other than
the JSON's, an end the parser takes outside) and fails if any goes unnoticed. About 700
short runs of the parser, a few seconds. Exit 0 when all hold, 1 otherwise (each fault
printed), 2 on bad usage.
"""
import json
import re
import subprocess
import sys
import tempfile

import help_ranges
from help_ranges import close, num, runner, value_text

# a help line's range as help_range (app/gw_cli.c) reads it: the first " in [" or
# " in (" (or at the start) to the first "]" or ")", and " (or 0)" after it
TEXT_RANGE = re.compile(r"(?:^|(?<= ))in ([\[(][^\])]*[\])](?: \(or 0\))?)")
RANGE = re.compile(r"([\[(])([^,\s]+), ([^\])\s]+)([\])])( \(or 0\))?")
OPTION_LINE = re.compile(r"^  --([a-z0-9-]+)(?: \S+)?\s+(.*)$")
# the range a refusal names: "outside [A, B]", "(give an integer in [A, B])",
# "must be > A" / ">= A"
REFUSED_RANGE = re.compile(r"(?:outside|integer in) ([\[(])([^,\s]+), ([^\])\s]+)([\])])")
REFUSED_BELOW = re.compile(r"must be (>=?) (\S+)")


def text_ranges(text):
    """{flag: the range its line prints, or None} of a text help."""
    lines = text.splitlines()
    out = {}
    for line in lines[lines.index("options:") + 1:] if "options:" in lines else []:
        m = OPTION_LINE.match(line)
        if m:
            r = TEXT_RANGE.search(m.group(2))
            out[m.group(1)] = r.group(1) if r else None
    return out


def outside(o, x, upper):
    """A value just outside the end x (upper 1: above it)."""
    s = 1 if upper else -1
    if o["kind"] == "integer":
        return x + s
    if x == 0:
        return s * 1e-300
    return x * (1 + s * 1e-5) if x > 0 else x * (1 - s * 1e-5)


def refusal_fault(cmd, o, err, rng):
    """None when err is one line naming CMD --FLAG, with the ends of rng where it
    names a range; else the fault's words."""
    lines = err.strip().splitlines()
    if len(lines) != 1 or not lines[0].startswith(f"granwave {cmd} --{o['name']}:"):
        return f"not one line naming {cmd} --{o['name']}: {err.strip()[:200]!r}"
    m, b = REFUSED_RANGE.search(lines[0]), REFUSED_BELOW.search(lines[0])
    r = RANGE.fullmatch(rng)
    if m:
        got = (m.group(1), num(m.group(2)), num(m.group(3)), m.group(4))
        want = (r.group(1), num(r.group(2)), num(r.group(3)), r.group(4))
    elif b:
        got = ("(" if b.group(1) == ">" else "[", num(b.group(2)))
        want = (r.group(1), num(r.group(2)))
    else:
        return None
    same = got[0] == want[0] and all(
        (g is None) == (w is None) and (g is None or close(g, w)) for g, w in zip(got[1:3], want[1:3]))
    if len(got) == 4:
        same = same and got[3] == want[3]
    return None if same else f"names the range {lines[0][lines[0].find(':') + 1:].strip()[:120]!r}, where --help prints {rng!r}"


def check_option(cmd, o, printed, run, faults):
    """The faults of one option: o its JSON object, printed the range its text line
    prints (None: none), run(args) -> (exit, stderr, what was written)."""
    where = f"{cmd} --{o['name']}"
    checks = 1
    if printed != o["range"]:
        faults.append(f"{where}: the text help prints {printed!r}, --help --json says {o['range']!r}")
        return checks
    bounded = o["kind"] in ("number", "integer") and (o["min"] is not None or o["max"] is not None)
    if not bounded:
        return checks
    if printed is None:
        faults.append(f"{where}: no range in the text help, --help --json: min {o['min']!r} max {o['max']!r}")
        return checks
    m = RANGE.fullmatch(printed)
    if not m or any(num(e) is None for e in m.group(2, 3)):
        return checks  # a range in words ("inf" reads as a number)
    for upper, text, bracket, bound in ((0, m.group(2), m.group(1), o["min"]), (1, m.group(3), m.group(4), o["max"])):
        x = num(text)
        if text in ("inf", "-inf") or bound is None:
            continue
        checks += 1
        if not close(x, bound):
            faults.append(f"{where}: the text help prints the end {text} of {printed!r}, the parser's is {bound!r}")
            continue
        is_open = bracket in "()"
        if is_open and m.group(5) and x == 0:
            is_open = False  # "(0, 1] (or 0)": 0 is taken
        checks += 1
        rc, err, wrote = run([cmd, "--help", f"--{o['name']}", text])
        if is_open and (rc != 2 or wrote or refusal_fault(cmd, o, err, printed)):
            faults.append(f"{where} {text}: the open end of {printed!r} is taken or not refused as it should "
                          f"(exit {rc}, {err.strip()[:160]!r}{', wrote ' + wrote if wrote else ''})")
        elif not is_open and (rc != 0 or wrote):
            faults.append(f"{where} {text}: the closed end of {printed!r} is refused: exit {rc}, {err.strip()[:160]!r}")
        checks += 1
        v = value_text(o, outside(o, int(text) if o["kind"] == "integer" else x, upper))
        rc, err, wrote = run([cmd, "--help", f"--{o['name']}", v])
        why = refusal_fault(cmd, o, err, printed) if rc == 2 else None
        if rc != 2 or wrote or why:
            faults.append(f"{where} {v}: just outside {printed!r}: exit {rc}, "
                          f"{why or repr(err.strip()[:160])}{', wrote ' + wrote if wrote else ''}")
    return checks


def self_test(program):
    n = {"name": "n", "kind": "integer", "min": 1, "max": 50000000, "range": "[1, 50000000]"}
    vimp = {"name": "vimp", "kind": "number", "min": 1e-9, "max": 1000, "range": "(1e-09, 1000]"}
    rtol = {"name": "rtol", "kind": "number", "min": 1e-15, "max": 1e-4, "range": "[1e-15, 0.0001]"}
    cases = [(n, None), (n, "[1, 6e7]"), (dict(n, range="[1, 60000000]"), "[1, 60000000]"),
             (vimp, "(1e-09, 1000]"), (rtol, "[1e-15, 0.0001]")]
    parsed = text_ranges("usage: x\n\noptions:\n  --n N                  number of beads [1]\n"
                         "  --rtol R               relative tolerance, in [1e-15, 0.0001] (or 0) [1e-12]\n")
    faults = []
    if parsed != {"n": None, "rtol": "[1e-15, 0.0001] (or 0)"}:
        faults.append(f"text_ranges read {parsed!r}")
    want = ["chain --n: the text help prints None", "prints '[1, 6e7]'", "the end 60000000",
            "chain --vimp 1e-09: the open end"]
    return help_ranges.self_test(program, cases, lambda run, c, faults: check_option("chain", c[0], c[1], run, faults),
                                 want, faults, wrong=lambda f: "--rtol" in f or "text_ranges" in f)  # rtol's line holds


def main():
    program = help_ranges.program_arg(__doc__)
    if program is None:
        return 2
    if not self_test(program):
        return 1
    cmds = help_ranges.commands(program)
    faults, nopt, nbounded, nchecks = [], 0, 0, 0
    with tempfile.TemporaryDirectory() as d:
        run = runner(program, d)
        for cmd in cmds:
            t = subprocess.run([program, cmd, "--help"], capture_output=True, text=True, timeout=60)
            j = subprocess.run([program, cmd, "--help", "--json"], capture_output=True, text=True, timeout=60)
            texts, opts = text_ranges(t.stdout), json.loads(j.stdout)["options"]
            nchecks += 1
            if list(texts) != [o["name"] for o in opts]:
                faults.append(f"{cmd}: the text help lists {list(texts)}, --help --json {[o['name'] for o in opts]}")
                continue
            for o in opts:
                nopt += 1
                nbounded += o["kind"] in ("number", "integer") and (o["min"] is not None or o["max"] is not None)
                nchecks += check_option(cmd, o, texts[o["name"]], run, faults)
    for f in faults:
        print(f)
    print(f"{len(cmds)} commands, {nopt} options ({nbounded} with a bound), {nchecks} checks, {len(faults)} fault(s)")
    return 1 if faults or nbounded < 150 else 0


if __name__ == "__main__":
    sys.exit(main())
