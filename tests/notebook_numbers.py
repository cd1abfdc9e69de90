#!/usr/bin/python3
"""notebook_numbers.py SRCDIR [NBOUT [CMPLOG]]: what docs/notebooks.md says about the
notebooks, against the notebooks.

Each claim is a piece of the page (or of a notebook's own text) with the number it
states, and where the notebooks give that number. A claim fails when the page no longer
holds the text or the notebooks give another value (both directions of drift: a changed
page or a changed code).
  SRCDIR alone: the claims on the notebooks' sources (which notebooks read GW_FULL, the
    sheets runs' settings), about a second; ctest test_notebook_numbers.
  NBOUT: also the numbers the executed notebooks print (NBOUT holds the notebooks
    `jupyter nbconvert --execute --output-dir NBOUT` wrote: test_notebooks passes its
    own, so nothing runs twice): the drop's contact time against granwave.chain with
    gravity, the fresh sheets runs against the stored ones, the size of
    bouncing_diagram's sweep table, the plateau's cases, the paper's numbers drawn, the
    figures' pixel counts, and the diagram a notebook's text describes.
  CMPLOG: the last line of test_notebooks' comparison of `plot_falcon.py --module`
    with the program's files ("runs within X, ..."), against the page's "measured X".
First each claim is checked on a copy of the page with its number changed, and must fail
there (a claim that cannot fail checks nothing). Exit 0 when all hold, 1 otherwise (each
fault printed), 2 on bad usage.
"""
import base64
import glob
import json
import os
import re
import struct
import sys

WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
         "nine": 9, "ten": 10}


class Fault(Exception):
    pass


def norm(text):
    return re.sub(r"\s+", " ", text)


def load_nb(path):
    """(cells, printed): per code cell its source and printed text; all printed text."""
    nb = json.load(open(path, encoding="utf-8"))
    cells = []
    for c in nb["cells"]:
        src = "".join(c["source"])
        out, images = [], []
        for o in c.get("outputs", []):
            if o.get("output_type") == "stream":
                out.append("".join(o["text"]))
            data = o.get("data", {})
            if "image/png" in data:
                png = base64.b64decode(data["image/png"])
                images.append(struct.unpack(">II", png[16:24]))
            for kind in ("text/markdown", "text/plain"):
                if kind in data and "image/png" not in data:
                    out.append("".join(data[kind]))
                    break
        cells.append({"type": c["cell_type"], "source": src, "out": "\n".join(out), "images": images})
    return cells


def doc_values(doc, rx, what):
    m = re.search(rx, doc)
    if not m:
        raise Fault(f"the page no longer says {what!r} (pattern {rx})")
    return m


def num(s):
    s = s.replace(",", "")
    if s.lower() in WORDS:
        return WORDS[s.lower()]
    try:
        return float(s)
    except ValueError:
        raise Fault(f"{s!r} is not a number")


def printed(ctx, nb, rx, what, all_matches=False):
    if nb not in ctx:
        raise Fault(f"no executed {nb}.ipynb")
    text = "\n".join(c["out"] for c in ctx[nb])
    if all_matches:
        found = re.findall(rx, text, re.M)
        if not found:
            raise Fault(f"{nb}.ipynb no longer prints {what!r} (pattern {rx})")
        return found
    m = re.search(rx, text, re.M)
    if not m:
        raise Fault(f"{nb}.ipynb no longer prints {what!r} (pattern {rx})")
    return m


def same(what, stated, got, rel=0.0):
    a, b = num(stated), num(got)
    if abs(a - b) > rel * abs(b):
        raise Fault(f"{what}: the page says {stated}, the notebooks give {got}")


def pattern(rx):
    """The claim's first pattern on its page (the one a self-check changes)."""
    def deco(fn):
        fn.pattern = rx
        return fn
    return deco


# --- the claims: name, the page they read ('doc' or a notebook's own text), the
#     pattern whose groups are the numbers stated, and the check -----------------------

@pattern(r"against `granwave\.chain` with gravity, \S+ then \S+ at the time; now (\S+),")
def c_contact_time(doc, ctx):
    m = doc_values(doc, c_contact_time.pattern, c_contact_time.__name__)
    row = printed(ctx, "experiment", r"^\| contact time \(us\) \|.*\| ([+-]?[\d.]+e[+-]\d+) \|\s*$",
                  "the contact time row")
    same("the drop's contact time against granwave.chain with gravity", m.group(1), row.group(1))


@pattern(r"bonded-layer run against the stored one, \S+ then ([^\s)]+)\)")
def c_fresh_sheets(doc, ctx):
    m = doc_values(doc, c_fresh_sheets.pattern, c_fresh_sheets.__name__)
    doc_values(doc, r"the notebook checks that their N_d equal the stored ones'", "their N_d equal the stored ones'")
    printed(ctx, "experiment", r"^fitted: N_d at every band equal to the stored run", "fitted: N_d ... equal")
    lay = printed(ctx, "experiment", r"^layer: N_d at every band equal to the stored run; tau_max\(1\) within (\S+) of it",
                  "layer: N_d ... equal ... within")
    same("tau_max(1) of the fresh bonded-layer run against the stored one", m.group(1), lay.group(1))


@pattern(r"the (\d+) x (\d+) values of bouncing_diagram's default sweep")
def c_sweep_table(doc, ctx):
    m = doc_values(doc, c_sweep_table.pattern, c_sweep_table.__name__)
    t = printed(ctx, "bouncing_diagram", r"^table: (\d+) rows x (\d+) columns", "table: R rows x C columns")
    same("bouncing_diagram's sweep table, rows", m.group(1), t.group(1))
    same("bouncing_diagram's sweep table, columns", m.group(2), t.group(2))


CASE_ROW = r"^\| ([\w.]+) \| ([^|]+) \| `[^`]*` \|\s*$"


@pattern(r"The (\w+) cases of `plot_sheets\.CASES`")
def c_plateau_cases(doc, ctx):
    m = doc_values(doc, c_plateau_cases.pattern, c_plateau_cases.__name__)
    m2 = doc_values(doc, r"\(3\) the plateau: (\w+) mechanisms", "(3) the plateau: N mechanisms")
    rows = printed(ctx, "experiment", CASE_ROW, "the plateau's cases table", all_matches=True)
    same("the plateau's cases", m.group(1), str(len(rows)))
    same("the plateau's mechanisms", m2.group(1), str(len(rows)))
    g = doc_values(doc, r"guide friction ([\d.]+) and ([\d.]+) N", "guide friction A and B N")
    got = [re.fullmatch(r"guide friction ([\d.]+) N", r[1].strip()) for r in rows]
    got = [x.group(1) for x in got if x]
    if sorted(num(v) for v in g.groups()) != sorted(num(v) for v in got):
        raise Fault(f"guide friction: the page says {' and '.join(g.groups())} N, the cases are {got}")


@pattern(r"the N = 40 collision time ([\d.]+) ms")
def c_paper_numbers(doc, ctx):
    m = doc_values(doc, c_paper_numbers.pattern, c_paper_numbers.__name__)
    t = printed(ctx, "experiment", r"tau_N\(40\) \(ms; paper ([\d.]+)\)", "tau_N(40) (ms; paper X)")
    same("the paper's N = 40 collision time", m.group(1), t.group(1))
    f = doc_values(doc, r"\(F_max = (\d+) N within 5 %", "(F_max = X N within 5 %")
    p = printed(ctx, "falcon_column", r"^\| f_max \| 5\.1 \| ([\d.]+) \|", "| f_max | 5.1 | X |")
    same("the paper's F_max at h = 5.1 mm", f.group(1), p.group(1))


def image_pixels(ctx, nb, marker):
    if nb not in ctx:
        raise Fault(f"no executed {nb}.ipynb")
    for c in ctx[nb]:
        if marker in c["source"] and c["images"]:
            w, h = c["images"][-1]
            return str(w * h)
    raise Fault(f"{nb}.ipynb: no figure from a cell with {marker!r}")


@pattern(r"layer_impact's snapshot \(\d+ of ([\d,]+) pixels")
def c_pixels(doc, ctx):
    m = doc_values(doc, c_pixels.pattern, c_pixels.__name__)
    same("layer_impact's snapshot figure, pixels", m.group(1), image_pixels(ctx, "layer_impact", "snapshots"), 0.01)
    m = doc_values(doc, r"experiment's drop signal \((\d+) of ([\d,]+) pixels", "experiment's drop signal (n of N pixels")
    same("experiment's drop signal figure, pixels", m.group(2), image_pixels(ctx, "experiment", "drop_signal"), 0.01)


@pattern(r"the fit to 1e-9, measured (\S+?)\)")
def c_module_files(doc, ctx):
    m = doc_values(doc, c_module_files.pattern, c_module_files.__name__)
    if "cmplog" not in ctx:
        raise Fault("no comparison log")
    r = re.search(r"runs within (\S+),", ctx["cmplog"])
    if not r:
        raise Fault("the comparison log has no 'runs within X,'")
    same("plot_falcon.py --module against the program's files", m.group(1), r.group(1))


@pattern(r"every column is drawn \\?\"(\w+)\\?\"")
def c_diagram_text(doc, ctx):
    """bouncing_diagram's own text says what its default run draws."""
    m = doc_values(doc, c_diagram_text.pattern, c_diagram_text.__name__)
    kinds = printed(ctx, "bouncing_diagram", r"^\s+[\d.]+\s+(cross|above|below|inverted)\s", "the diagram's kinds",
                    all_matches=True)
    if any(k != m.group(1) for k in kinds):
        raise Fault(f"bouncing_diagram's text says every column is drawn \"{m.group(1)}\"; it prints {kinds}")


@pattern(r"`(\w+)\.ipynb`, `(\w+)\.ipynb`, `(\w+)\.ipynb` and `(\w+)\.ipynb` run small sizes by "
         r"default and the full sizes with `GW_FULL=1`; the other (\w+) have one size")
def c_full_switch(doc, ctx):
    m = doc_values(doc, c_full_switch.pattern, c_full_switch.__name__)
    src = ctx["sources"]
    full = sorted(n for n, s in src.items() if 'os.environ.get("GW_FULL") == "1"' in s)
    other = sorted(set(re.findall(r"""environ(?:\.get\(|\[)["'](\w*FULL\w*)["']""", "\n".join(src.values()))) - {"GW_FULL"})
    if other:
        raise Fault(f"notebooks read {other} for their size, the page names GW_FULL only")
    if sorted(m.groups()[:4]) != full:
        raise Fault(f"the page says {sorted(m.groups()[:4])} have GW_FULL=1; the notebooks reading it: {full}")
    same("the notebooks with one size", m.group(5), str(len(src) - len(full)))


@pattern(r"`granwave\.softwall\(sheets=True, (n=\(\d+, \d+\), tol=[\d.]+)\)`")
def c_sheets_settings(doc, ctx):
    m = doc_values(doc, c_sheets_settings.pattern, c_sheets_settings.__name__)
    if "sheets=True, " + m.group(1) not in ctx["sources"].get("experiment", ""):
        raise Fault(f"experiment.ipynb's sheets runs do not use {m.group(1)} (the page's)")


STATIC = [("GW_FULL and sizes", "doc", c_full_switch), ("the sheets runs' settings", "doc", c_sheets_settings)]
PRINTED = [("drop contact time", "doc", c_contact_time), ("fresh sheets runs", "doc", c_fresh_sheets),
           ("bouncing_diagram table", "doc", c_sweep_table), ("plateau cases", "doc", c_plateau_cases),
           ("paper's numbers", "doc", c_paper_numbers), ("figure pixels", "doc", c_pixels),
           ("bouncing_diagram's text", "bouncing_diagram", c_diagram_text)]
MODULE = [("plot_falcon --module", "doc", c_module_files)]


def mutate(doc, fn):
    """The page with the first number (or word) of fn's pattern changed."""
    hit = re.search(fn.pattern, doc)
    if not hit or not hit.groups():
        return None
    a, b = hit.span(1)
    v = doc[a:b]
    d = re.search(r"\d", v)
    nv = v[:d.start()] + str((int(v[d.start()]) + 1) % 10 or 1) + v[d.start() + 1:] if d else v + "x"
    return doc[:a] + nv + doc[b:]


def main(argv):
    if len(argv) not in (2, 3, 4):
        print(__doc__.split("\n")[0], file=sys.stderr)
        return 2
    src = argv[1]
    docpath = os.path.join(src, "docs", "notebooks.md")
    if not os.path.isfile(docpath):
        print(f"notebook_numbers.py: {docpath} not found", file=sys.stderr)
        return 2
    doc = norm(open(docpath, encoding="utf-8").read())
    ctx = {"sources": {}}
    texts = {"doc": doc}
    for p in sorted(glob.glob(os.path.join(src, "notebooks", "*.ipynb"))):
        name = os.path.basename(p)[:-6]
        cells = load_nb(p)
        ctx["sources"][name] = "\n".join(c["source"] for c in cells if c["type"] == "code")
        texts[name] = norm("\n".join(c["source"] for c in cells if c["type"] == "markdown"))
    claims = list(STATIC)
    if len(argv) >= 3:
        for p in sorted(glob.glob(os.path.join(argv[2], "*.ipynb"))):
            ctx[os.path.basename(p)[:-6]] = load_nb(p)
        claims += PRINTED
    if len(argv) == 4:
        ctx["cmplog"] = open(argv[3], encoding="utf-8").read()
        claims += MODULE
    faults = 0
    for name, page, fn in claims:
        try:
            fn(texts[page], ctx)
            status = None
        except Fault as e:
            status = str(e)
        # the same claim on a page whose number is changed must fail
        bad = mutate(texts[page], fn)
        caught = True
        if bad is not None:
            try:
                fn(bad, ctx)
                caught = False
            except Fault:
                pass
        if status:
            faults += 1
            print(f"FAIL {name}: {status}")
        elif not caught:
            faults += 1
            print(f"FAIL {name}: a changed number on the page went unnoticed (the check checks nothing)")
        else:
            print(f"ok   {name}")
    print(f"{len(claims) - faults} of {len(claims)} claims hold")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
