#!/usr/bin/python3
"""test_docs_tests.py SRCDIR: every test registered in tests/CMakeLists.txt is listed in
docs/tests.md's table ("every test and what it asserts", README), and every test the table
lists is registered. A row may name several tests ("| test_a, test_b | ..."). Before this
check eight registered tests (test_hostile_chain, test_hostile_layer, ...) had no row.
First it checks itself on a made-up table without one of the registered tests and fails
if that goes unnoticed. Exit 0 when both hold, 1 otherwise (each name printed), 2 on bad
usage.
"""
import os
import re
import sys

from docs_frame import srcdir_arg


def registered(cmake_text):
    """Test names of gw_add_test(NAME, gw_add_script_test(NAME, gw_add_clock_test(NAME, gw_add_py_program_test(NAME and add_test(NAME NAME."""
    names = re.findall(r"^\s*(?:gw_add_test|gw_add_script_test|gw_add_clock_test|gw_add_py_program_test)\((\w+)", cmake_text, re.M)
    names += re.findall(r"^\s*add_test\(NAME (\w+)", cmake_text, re.M)
    return {n for n in names if not n.startswith("$")}


def listed(doc_text):
    """Test names in the first column of the table rows of docs/tests.md."""
    out = set()
    for line in doc_text.splitlines():
        cells = line.strip().split("|")
        if len(cells) > 2 and re.match(r"\s*test_\w+", cells[1]):
            out.update(re.findall(r"test_\w+", cells[1]))
    return out


def faults(cmake_text, doc_text):
    reg, lst = registered(cmake_text), listed(doc_text)
    return ([f"registered in tests/CMakeLists.txt, not in docs/tests.md: {n}" for n in sorted(reg - lst)] +
            [f"in docs/tests.md, not registered in tests/CMakeLists.txt: {n}" for n in sorted(lst - reg)])


def main():
    srcdir = srcdir_arg(__doc__)
    if srcdir is None:
        return 2
    cmake = open(os.path.join(srcdir, "tests", "CMakeLists.txt"), encoding="utf-8").read()
    doc = open(os.path.join(srcdir, "docs", "tests.md"), encoding="utf-8").read()
    some = sorted(registered(cmake))[0]
    made_up = "\n".join(l for l in doc.splitlines() if not re.match(r"\|\s*" + some + r"\s*\|", l))
    if not faults(cmake, made_up):
        print(f"FAIL: a table without {some} went unnoticed")
        return 1
    f = faults(cmake, doc)
    for x in f:
        print("FAIL:", x)
    print(f"test_docs_tests: {len(registered(cmake))} registered tests, {len(f)} fault(s)")
    return 1 if f else 0


if __name__ == "__main__":
    sys.exit(main())
