"""docs_frame.py: the frame the docs tests share (test_docs_commands.py, test_docs_examples.py,
test_docs_formats.py, test_docs_numbers.py, and for their SRCDIR argument test_docs_links.py
and test_docs_tests.py; imported from the tests directory, beside them): their arguments, a
real page with one text changed
(a drift put in), the self-test's verdict on the faults it must notice, and the closing
lines (each fault, then the count)."""
import os
import re
import sys


def program_srcdir(doc):
    """(program, srcdir), both absolute, from the two arguments; None with the usage (the
    first line of doc) said on stderr when they are not two."""
    if len(sys.argv) != 3:
        print(doc.split("\n")[0], file=sys.stderr)
        return None
    return os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])


def srcdir_arg(doc):
    """The source directory given as the one argument (absolute), else None with the usage
    (the first line of doc) said on stderr (test_docs_links.py, test_docs_tests.py)."""
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print(doc.split("\n")[0], file=sys.stderr)
        return None
    return os.path.abspath(sys.argv[1])


def drifted(page, old, new, regex=False):
    """page with its first old (a regular expression when regex) made new, None when page
    does not hold old (the self-test's case no longer applies: a fault of its own)."""
    bad = re.sub(old, new, page, count=1) if regex else page.replace(old, new, 1)
    return None if bad == page else bad


def not_caught(want, faults):
    """The texts of want that no fault holds."""
    return [w for w in want if not any(w in f for f in faults)]


def noticed(missed, faults=()):
    """The self-test's verdict: True when nothing was missed, else False with the missed
    ones said (and the faults found, when given)."""
    if not missed:
        return True
    print("self-test: faults not noticed: " + "; ".join(missed) + "".join("\n" + f for f in faults))
    return False


def finish(faults, summary, ok=True, prefix=""):
    """Each fault (after prefix), then summary; the exit code: 1 when a fault was found or
    the self-test failed (not ok), else 0."""
    for f in faults:
        print(prefix + f)
    print(summary)
    return 1 if faults or not ok else 0
