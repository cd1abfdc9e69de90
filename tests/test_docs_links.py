#!/usr/bin/python3
"""test_docs_links.py SRCDIR: the documentation's references resolve inside the repository.

Checks, over the Markdown files of the repository (README.md, docs/, data/, bench/, ...;
fenced code blocks and inline code are skipped):
  1. every relative link or image target [text](path) or [text](path#anchor) names a file
     or directory that exists, inside the repository;
  2. every anchor (#anchor, or path.md#anchor) names a heading of that Markdown file, by
     GitHub's rule (lower case, punctuation dropped, spaces to hyphens, -1, -2 ... for
     repeated headings);
  3. no text file of the repository (Markdown, C, headers, Python, shell, notebooks,
     CMake, INI configs) refers to a file outside it: no "../shared/" path, no bare
     "shared/physics.md", no absolute "/work/" path (recorded provenance in measured
     data tables is not checked: it is the record of a run);
  4. every citation "docs/physics.md N.M" in the sources names a section "### N.M" of
     docs/physics.md, so the source comments and the notes stay in step.
First it runs itself on a small tree with one fault of each kind and fails if any goes
unnoticed (the checks can fail). Exit status 0 when all hold, 1 otherwise (each fault
printed as file:line: message), 2 on bad usage.
"""
import os
import re
import sys
import tempfile

from docs_frame import srcdir_arg

SKIP_DIRS = {".git", "results", "__pycache__", ".ipynb_checkpoints"}
TEXT_EXT = (".md", ".c", ".h", ".py", ".sh", ".ipynb", ".cmake", ".txt", ".ini", ".in")
LINK = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"`[^`]*`")
# built from pieces so that this file does not match its own patterns
OUTSIDE = re.compile(r"\.\./" + "shared/" + r"|(?<![\w/])" + "shared/" + r"physics\.md|(?<![\w.])/" + "work/")
# a section number N or N.M, not a value such as 2.94322 or 4.0e9
CITE = re.compile(r"docs/physics\.md(?:'s)?(?:\s+section)?\s+(\d)(?:\.(\d{1,2}))?(?![\deE]|\.\d)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def walk(root):
    for d, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS and not x.startswith("build"))
        for f in sorted(files):
            yield os.path.join(d, f)


def slug(text):
    """GitHub's anchor of a heading: the rendered text (link targets, code and emphasis
    marks dropped), lower case, punctuation removed, spaces to hyphens."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = text.replace("`", "").replace("*", "")
    s = text.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen, out, fenced = {}, set(), False
        with open(path, encoding="utf-8") as fh:
            for line in fh:
                if FENCE.match(line):
                    fenced = not fenced
                    continue
                m = None if fenced else HEADING.match(line)
                if m:
                    base = slug(m.group(2))
                    n = seen.get(base, 0)
                    out.add(base if n == 0 else f"{base}-{n}")
                    seen[base] = n + 1
        cache[path] = out
    return cache[path]


def markdown_lines(path):
    """(line number, text) of the lines outside fenced blocks, inline code removed."""
    fenced = False
    with open(path, encoding="utf-8") as fh:
        for i, line in enumerate(fh, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if not fenced:
                yield i, CODE_SPAN.sub("", line)


def check(root):
    root = os.path.realpath(root)
    faults, nlinks = [], 0
    files = list(walk(root))
    for path in files:
        rel = os.path.relpath(path, root)
        if path.endswith(".md"):
            for ln, text in markdown_lines(path):
                for m in LINK.finditer(text):
                    target = m.group(1)
                    nlinks += 1
                    if re.match(r"^[a-z][a-z0-9+.-]*:", target):
                        continue  # http:, https:, mailto:
                    where, _, anchor = target.partition("#")
                    dest = os.path.realpath(os.path.join(os.path.dirname(path), where)) if where else path
                    if dest != root and not dest.startswith(root + os.sep):
                        faults.append(f"{rel}:{ln}: link '{target}' leaves the repository")
                        continue
                    if not os.path.exists(dest):
                        faults.append(f"{rel}:{ln}: link '{target}': no such file or directory")
                        continue
                    if anchor and dest.endswith(".md") and anchor not in anchors(dest):
                        faults.append(f"{rel}:{ln}: link '{target}': no heading '#{anchor}' in "
                                      f"{os.path.relpath(dest, root)}")
        if path.endswith(TEXT_EXT) or os.path.basename(path) == "CMakeLists.txt":
            if os.path.abspath(path) == os.path.abspath(__file__):
                continue
            if "/data/measured/" in path and not path.endswith((".md", ".ini")):
                continue  # recorded provenance of past runs
            try:
                with open(path, encoding="utf-8") as fh:
                    lines = fh.readlines()
            except (UnicodeDecodeError, OSError):
                continue
            for ln, line in enumerate(lines, 1):
                if OUTSIDE.search(line):
                    faults.append(f"{rel}:{ln}: refers to a file outside the repository: {line.strip()[:100]}")
    physics = os.path.join(root, "docs", "physics.md")
    if os.path.exists(physics):
        sections = set()
        with open(physics, encoding="utf-8") as fh:
            for line in fh:
                m = re.match(r"^#{2,3}\s+(\d+)\.(\d*)", line)
                if m:
                    sections.add((m.group(1), m.group(2) or None))
        for path in files:
            if path == physics or not path.endswith(TEXT_EXT) or \
                    os.path.abspath(path) == os.path.abspath(__file__):
                continue
            try:
                with open(path, encoding="utf-8") as fh:
                    lines = fh.readlines()
            except (UnicodeDecodeError, OSError):
                continue
            for ln, line in enumerate(lines, 1):
                for m in CITE.finditer(line):
                    if (m.group(1), m.group(2)) not in sections:
                        sec = m.group(1) + ("." + m.group(2) if m.group(2) else "")
                        faults.append(f"{os.path.relpath(path, root)}:{ln}: cites docs/physics.md {sec}, "
                                      "which has no such section")
    return faults, nlinks


def selftest():
    """Each kind of fault in a small tree must be found."""
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "docs"))
        os.makedirs(os.path.join(tmp, "src"))
        with open(os.path.join(tmp, "docs", "physics.md"), "w") as fh:
            fh.write("# Notes\n\n## 1. Column\n\n### 1.1 Model\n\nText.\n")
        with open(os.path.join(tmp, "README.md"), "w") as fh:
            fh.write("[ok](docs/physics.md#11-model) [dead](docs/nothere.md)\n"
                     "[bad anchor](docs/physics.md#12-nothing) [out](../elsewhere.md)\n"
                     "```\n[ignored in a code block](nothere.md)\n```\n"
                     "See " + ".." + "/shared/notes.md.\n")
        with open(os.path.join(tmp, "src", "a.c"), "w") as fh:
            fh.write("/* docs/physics.md 1.1, docs/physics.md 2.94322 (a value) and docs/physics.md 1.9 */\n")
        found, _ = check(tmp)
        want = ["nothere.md': no such", "no heading '#12-nothing'", "leaves the repository",
                "outside the repository", "docs/physics.md 1.9"]
        missed = [w for w in want if not any(w in f for f in found)]
        extra = [f for f in found if not any(w in f for w in want)]
        if missed or extra or len(found) != len(want):
            print("FAIL: self-test: missed", missed, "unexpected", extra)
            return False
    return True


def main():
    srcdir = srcdir_arg(__doc__)
    if srcdir is None:
        return 2
    if not selftest():
        return 1
    faults, nlinks = check(srcdir)
    for f in faults:
        print("FAIL:", f)
    if faults:
        return 1
    print(f"test_docs_links: {nlinks} links checked, every relative link and anchor resolves; "
          "no reference outside the repository")
    return 0


if __name__ == "__main__":
    sys.exit(main())
