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
import os
import re
import shutil
import subprocess
import sys
import tempfile

RANGE = re.compile(r"([\[(])\s*([^,\s]+),\s*([^\])\s]+)([\])])( \(or 0\))?")


def num(text):
    try:
        return float(text)
    except ValueError:
        return None


def close(a, b):
    if a is None or b is None:
        return a is b
    if a == b:
        return True
    return abs(a - b) <= 1e-5 * max(abs(a), abs(b))


REFUSED = re.compile(r"(?:outside|integer in) ([\[(])([^,\s]+), ([^\])\s]+)([\])])")


def same_range(err, m):
    """err names the range m (a RANGE match) in its refusal's notation, or the same
    brackets and ends to six digits ("[1e-06, 1]" for a line's "[1e-6, 1]")."""
    if m.group(0).split(" (or 0)")[0] in err:
        return True
    r = REFUSED.search(err)
    return r is not None and r.group(1) == m.group(1) and r.group(4) == m.group(4) and \
        all(close(num(a), num(b)) for a, b in ((r.group(2), m.group(2)), (r.group(3), m.group(3))))


def value_text(o, x):
    return str(int(x)) if o["kind"] == "integer" else repr(x)


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


def runner(program, work):
    def run(args):
        p = subprocess.run([program, *args], capture_output=True, text=True, timeout=60, cwd=work)
        wrote = ", ".join(sorted(os.listdir(work)))
        for f in os.listdir(work):
            p2 = os.path.join(work, f)
            if os.path.isdir(p2):
                shutil.rmtree(p2)
            else:
                os.remove(p2)
        return p.returncode, p.stderr, wrote
    return run


def self_test(program):
    opts = [  # chain's --n is [1, 5e7]; dispersion's --f0 is (0, 1e9]
        {"name": "n", "kind": "integer", "min": 1, "max": 50000000, "range": None, "help": ""},
        {"name": "n", "kind": "integer", "min": 1, "max": 50000000, "range": "[1, 6e7]", "help": ""},
        {"name": "vimp", "kind": "number", "min": 1e-9, "max": 1000, "range": "(1e-09, 1000]", "help": ""},
    ]
    faults = []
    with tempfile.TemporaryDirectory() as d:
        run = runner(program, d)
        for o in opts:
            check_option("chain", o, run, faults)
    want = ["chain --n: range null", "range '[1, 6e7]'", "the range '(1e-09, 1000]' is open there"]
    missed = [w for w in want if not any(w in f for f in faults)]
    if missed:
        print("self-test: faults not noticed: " + ", ".join(missed) + "\n" + "\n".join(faults))
        return False
    return True


def main():
    if len(sys.argv) != 2:
        print(__doc__.split("\n")[0], file=sys.stderr)
        return 2
    program = os.path.abspath(sys.argv[1])
    if not self_test(program):
        return 1
    p = subprocess.run([program, "--help", "--json"], capture_output=True, text=True, timeout=60)
    cmds = [c["name"] for c in json.loads(p.stdout)["commands"]]
    faults, n = [], 0
    with tempfile.TemporaryDirectory() as d:
        run = runner(program, d)
        for cmd in cmds:
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
