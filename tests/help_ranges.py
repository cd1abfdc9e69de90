"""help_ranges.py: what test_help_json_ranges.py and test_help_text_ranges.py share
(imported from the tests directory, beside them): the numbers of a range, the text
of a value given to an option, a runner of the program in a scratch directory, the
self-test's frame and the list of commands."""
import json
import os
import shutil
import subprocess
import sys
import tempfile


def num(text):
    try:
        return float(text)
    except ValueError:
        return None


def close(a, b):
    """a and b the same number to 1e-5 (None only as None)."""
    if a is None or b is None:
        return a is b
    return a == b or abs(a - b) <= 1e-5 * max(abs(a), abs(b))


def value_text(o, x):
    return str(int(x)) if o["kind"] == "integer" else repr(x)


def runner(program, work):
    """run(args) -> (exit code, stderr, the files it wrote in work, then removed)."""
    def run(args):
        p = subprocess.run([program, *args], capture_output=True, text=True, timeout=60, cwd=work)
        wrote = ", ".join(sorted(os.listdir(work)))
        for f in os.listdir(work):
            p2 = os.path.join(work, f)
            if os.path.isdir(p2) and not os.path.islink(p2):
                shutil.rmtree(p2)
            else:
                os.remove(p2)
        return p.returncode, p.stderr, wrote
    return run


def self_test(program, cases, check, want, faults=None, wrong=lambda f: False):
    """The checker checked on made-up cases before it is trusted: check(run, case,
    faults) for each case, with the program run in a scratch directory; every text of
    want must be in a fault found (the faults made up were noticed) and no fault may
    be wrong(f) (a case that holds was taken for one). faults: those found before."""
    faults = [] if faults is None else faults
    with tempfile.TemporaryDirectory() as d:
        run = runner(program, d)
        for c in cases:
            check(run, c, faults)
    missed = [w for w in want if not any(w in f for f in faults)]
    if missed or any(wrong(f) for f in faults):
        print("self-test: faults not noticed: " + ", ".join(missed) + "\n" + "\n".join(faults))
        return False
    return True


def program_arg(doc):
    """The program given as the one argument (absolute), else None with the usage said."""
    if len(sys.argv) != 2:
        print(doc.split("\n")[0], file=sys.stderr)
        return None
    return os.path.abspath(sys.argv[1])


def commands(program):
    p = subprocess.run([program, "--help", "--json"], capture_output=True, text=True, timeout=60)
    return [c["name"] for c in json.loads(p.stdout)["commands"]]
