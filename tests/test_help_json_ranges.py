#!/usr/bin/python3
"""test_help_json_ranges.py PROGRAM: `granwave CMD --help --json` states the range every
number option takes, as the parser checks it.

A user (or a script, or the documentation's own test) reads a flag's accepted values from
the JSON help. For every command and every option of kind `number` or `integer` with a
finite bound (`min` or `max` not null):
  1. `range` is not null: the help line's range, or, where the line prints none, the
     parser's in its refusal's notation (`(0, 1e+06]`, `[1e-09, 0.01] (or 0)`);
     it was null for 82 of the 186 number options, and `min` 0 did not say that 0 is
     refused (`layer-make --width-rm 0`, `dispersion --f0 0`);
  2. its ends are `min` and `max` (to the six digits a message prints), and an open end
     is a bound the parser refuses: `CMD --FLAG MIN` exits 2 naming --FLAG, nothing
     written (the scratch directory stays empty);
  3. a value beyond `max` (ten times it, or one above an integer's) exits 2 naming --FLAG
     and the range `range` states (its ends to six digits: the line's "[1e-6, 1]" is the
     refusal's "[1e-06, 1]").
Ranges written with words (drop's `[t-max/1e7, t-max]`) are left to their own tests.
First it checks itself on a made-up option list (a null range, ends other than min and
max, an open end the parser takes) and fails if any goes unnoticed. Exit 0 when all hold,
1 otherwise (each fault printed), 2 on bad usage.
"""
import json
import re
import subprocess
import sys
import tempfile

import help_ranges
from help_ranges import close, num, runner, value_text

RANGE = re.compile(r"([\[(])\s*([^,\s]+),\s*([^\])\s]+)([\])])( \(or 0\))?")


REFUSED = re.compile(r"(?:outside|integer in) ([\[(])([^,\s]+), ([^\])\s]+)([\])])")


def same_range(err, m):
    """err names the range m (a RANGE match) in its refusal's notation, or the same
    brackets and ends to six digits ("[1e-06, 1]" for a line's "[1e-6, 1]")."""
    if m.group(0).split(" (or 0)")[0] in err:
        return True
    r = REFUSED.search(err)
    return r is not None and r.group(1) == m.group(1) and r.group(4) == m.group(4) and \
        all(close(num(a), num(b)) for a, b in ((r.group(2), m.group(2)), (r.group(3), m.group(3))))


def check_option(cmd, o, run, faults):
    """The faults of one option (run(args) -> (rc, stderr, wrote))."""
    name, lo, hi, rng = o["name"], o["min"], o["max"], o["range"]
    where = f"{cmd} --{name}"
    if lo is None and hi is None:
        return
    if rng is None:
        faults.append(f"{where}: range null, min {lo!r} max {hi!r}")
        return
    m = RANGE.fullmatch(rng.strip())
    if not m or (num(m.group(2)) is None and m.group(2) != "-inf") or \
            (num(m.group(3)) is None and m.group(3) != "inf"):
        return  # a range in words
    rlo, rhi = num(m.group(2)), num(m.group(3))
    if not close(rlo if m.group(2) != "-inf" else None, lo) or not close(rhi if m.group(3) != "inf" else None, hi):
        faults.append(f"{where}: range {rng!r}, min {lo!r} max {hi!r}")
        return
    if m.group(1) == "(" and lo is not None and not (m.group(5) and lo == 0):
        rc, err, wrote = run([cmd, f"--{name}", value_text(o, lo)])
        if rc != 2 or f"--{name}" not in err or wrote:
            faults.append(f"{where} {value_text(o, lo)}: the range {rng!r} is open there; "
                          f"exit {rc}, {err.strip()[:160]!r}{', wrote ' + wrote if wrote else ''}")
    if hi is not None:
        x = int(hi) + 1 if o["kind"] == "integer" else (hi * 10 if hi > 0 else hi + 1)
        rc, err, wrote = run([cmd, f"--{name}", value_text(o, x)])
        if rc != 2 or f"--{name}" not in err or wrote:
            faults.append(f"{where} {value_text(o, x)}: above max {hi!r}; exit {rc}, {err.strip()[:160]!r}")
        elif not same_range(err, m):
            faults.append(f"{where} {value_text(o, x)}: refused with {err.strip()[:160]!r}, "
                          f"where --help --json says {rng!r}")


def self_test(program):
    opts = [  # chain's --n is [1, 5e7]; dispersion's --f0 is (0, 1e9]
        {"name": "n", "kind": "integer", "min": 1, "max": 50000000, "range": None, "help": ""},
        {"name": "n", "kind": "integer", "min": 1, "max": 50000000, "range": "[1, 6e7]", "help": ""},
        {"name": "vimp", "kind": "number", "min": 1e-9, "max": 1000, "range": "(1e-09, 1000]", "help": ""},
    ]
    return help_ranges.self_test(program, opts, lambda run, o, faults: check_option("chain", o, run, faults),
                                 ["chain --n: range null", "range '[1, 6e7]'", "the range '(1e-09, 1000]' is open there"])


def main():
    program = help_ranges.program_arg(__doc__)
    if program is None:
        return 2
    if not self_test(program):
        return 1
    faults, n = [], 0
    with tempfile.TemporaryDirectory() as d:
        run = runner(program, d)
        for cmd in help_ranges.commands(program):
            q = subprocess.run([program, cmd, "--help", "--json"], capture_output=True, text=True, timeout=60)
            for o in json.loads(q.stdout)["options"]:
                if o["kind"] in ("number", "integer"):
                    n += 1
                    check_option(cmd, o, run, faults)
    for f in faults:
        print(f)
    print(f"{n} number options, {len(faults)} fault(s)")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
