#!/usr/bin/python3
"""test_docs_numbers.py PROGRAM SRCDIR: the files and numbers the documentation promises.

A new user reads docs/cli.md, docs/formats.md and the `--help` of a command, runs it
with --out, and looks for the files, columns and numbers named there. For the fast
commands (chain, falcon, wavespeed and softwall on small ranges, dispersion and its
--column-n mode, drop, layer-make and layer-impact on a 60-disc sample), in a scratch
directory:
  1. every file the run writes into --out is named in the command's row of cli.md's
     "Where the outputs go" table (`trace_nN...` stands for any N);
  2. every file the `--out` line of `granwave CMD --help` names is written, and that
     line names at least one file;
  3. with --json, the object has `version` and `settings` and the command's JSON file
     under --out holds it (formats.md: "--out DIR writes the same object into the
     directory"), timings aside;
  4. every CSV has at least two columns, and one that formats.md's CSV table lists
     (or drop.md's, for the drop's) has exactly the columns listed there, in order
     (`x1_m` .. `xN_m` expanded to the run's N);
  5. the HDF5 traces' datasets carry the units formats.md gives (with h5py, when
     Debian's python3-h5py is there);
  6. a layer sweep's results.csv has the columns formats.md's "Each row holds" lists.
Then the numbers: each claim below is a piece of text a page quotes and the command
that gives it; the test fails when the page no longer holds the text or the command's
value, printed to the digits the page shows, differs (both directions of drift: a
changed page or a changed code). The 300-disc default sample and impact of README.md
(porosity 0.192, T_f = 0.06 s, e_n = 0.020), with the other runs of it that layer.md,
formats.md and outcomes.md quote (a claim may take several runs), take about 14 s; the rest 10 s.
Since the fifteenth pass also the results a user tries first that nothing recomputed:
column.md's closed forms, final velocities, E_rel/E_K, energy errors, the N = 5..20 wave
speeds and the memory bound's messages; drop.md's comparison with chain, its 300 ms runs,
gaps and first collision; sheets.md's tau_max(1) under every law for the bare sensor and the
four target sheets, brass's yield stresses, the loss, guide friction and PVC's F_max(N); the
exact 3 m/s impact of outcomes.md (about 20 s of CPU more). Since the forty-sixth session also the
crown speeds README.md and crowns.md quote over 16 impact points and layer.md's one-impact crown
fits (34 impacts, about 2 s of CPU). And the defaults the `--help` of
chain, drop, falcon, dispersion, layer-make and layer-impact states, against the settings
the runs record (HELP_DEFAULTS: a numeric [default] read from the help line, or a formula
such as dt-max's quarter of the shortest binary contact computed from the run's closed forms).
First it checks itself on made-up pages (unnamed files, columns other than the
listed ones, a wrong quoted number, a --help default the run does not use) and fails if any
goes unnoticed. Exit 0 when all hold, 1
otherwise (each fault printed), 2 on bad usage.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from docs_frame import finish, noticed, not_caught, program_srcdir

TIMING_KEYS = {"wall_time_ms", "wall_time_s", "integrate_ms", "fft_ms"}


def cli_rows(srcdir):
    """{command: set of file-name patterns} from cli.md's outputs table."""
    text = open(os.path.join(srcdir, "docs", "cli.md"), encoding="utf-8").read()
    sec = text.split("## Where the outputs go", 1)[1].split("\n## ", 1)[0]
    rows = {}
    for line in sec.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or not cells[0].startswith("`"):
            continue
        cmd = cells[0].strip("`").split()[0]
        names = set()
        for tok in re.findall(r"`([^`]+)`", cells[2]):
            tok = tok.replace("DIR/", "")
            if re.fullmatch(r"[\w.]+\.(csv|json|h5|md|vtk|pvd)", tok):
                names.add(tok)
        rows[cmd] = names
    return rows


def name_matches(name, patterns):
    for p in patterns:
        rx = "^" + re.escape(p).replace("nN", r"n\d+").replace("FILE", ".*") + "$"
        if re.match(rx, name):
            return True
    return False


def csv_columns_doc(srcdir):
    """{file pattern: [columns]} from formats.md's CSV table (and drop.md's outputs table,
    whose rows give the columns as one `a,b,c` string). In a formats.md cell the column
    names are the backticked words in order, `..` kept; parenthesised remarks and links
    are prose; a row that points to another page is checked from that page."""
    out = {}
    text = open(os.path.join(srcdir, "docs", "formats.md"), encoding="utf-8").read()
    sec = text.split("## CSV tables", 1)[1].split("\n## ", 1)[0]
    for line in sec.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or not cells[0].startswith("`") or cells[1].startswith("as in ["):
            continue
        cell = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", cells[1])
        while True:
            c2 = re.sub(r"\([^()]*\)", "", cell)
            if c2 == cell:
                break
            cell = c2
        cols = [a or ".." for a, _ in re.findall(r"`(\w+)`|(\.\.)", cell)]
        for f in re.findall(r"`([\w.]+\.csv)`", cells[0]):
            out.setdefault(f, cols)
    text = open(os.path.join(srcdir, "docs", "drop.md"), encoding="utf-8").read()
    sec = text.split("## Outputs", 1)[1].split("\n## ", 1)[0]
    for line in sec.splitlines():
        m = re.fullmatch(r"\|\s*`([\w.]+\.csv)`\s*\|\s*`([\w,]+)`\s*\|", line.strip())
        if m:
            out.setdefault(m.group(1), m.group(2).split(","))
    return out


def expand(cols, header):
    """`x1_m` .. `xN_m` against the header: the run's N."""
    if ".." not in cols:
        return cols
    res = []
    i = 0
    while i < len(cols):
        if i + 2 < len(cols) and cols[i + 1] == "..":
            a, b = cols[i], cols[i + 2]
            pre, suf = re.match(r"([a-z]+)1(_.*)", a).groups()
            n = sum(1 for h in header if re.fullmatch(re.escape(pre) + r"\d+" + re.escape(suf), h))
            res.extend(f"{pre}{k}{suf}" for k in range(1, n + 1))
            i += 3
        else:
            res.append(cols[i])
            i += 1
    return res


def strip_timing(o):
    if isinstance(o, dict):
        return {k: strip_timing(v) for k, v in o.items() if k not in TIMING_KEYS}
    if isinstance(o, list):
        return [strip_timing(v) for v in o]
    return o


class Checker:
    def __init__(self, program, srcdir, work):
        self.program, self.src, self.work = program, srcdir, work
        self.faults = []
        self.rows = cli_rows(srcdir)
        self.cols = csv_columns_doc(srcdir)
        self.cache = {}

    def fault(self, msg):
        self.faults.append(msg)

    def run(self, args, timeout=300):
        return subprocess.run([self.program, *args], capture_output=True, text=True, timeout=timeout,
                              cwd=self.work)

    def help_out_names(self, cmd, args):
        """The files the --out line of `CMD --help` names for a run with args: the names
        outside parentheses, or those of a "(--flag: ...)" group when the run gives --flag."""
        p = self.run([cmd, "--help"])
        line = next((ln for ln in p.stdout.splitlines() if ln.strip().startswith("--out ")), "")
        names = re.compile(r"\b([\w]+\.(?:csv|json|h5|md|vtk|pvd))\b")
        text = line
        for flag, group in re.findall(r"\((--[\w-]+): ([^)]*)\)", line):
            text = text.replace(f"({flag}: {group})", "")
            if flag in args:
                return line, names.findall(group)
        return line, names.findall(text)

    def outputs(self, cmd, args, out, json_file=None):
        p = self.run([cmd, *args, "--out", out] + (["--json"] if json_file else []))
        where = f"granwave {cmd} {' '.join(args)} --out {out}"
        if p.returncode != 0:
            self.fault(f"{where}: exit {p.returncode}: {p.stderr.strip()[-300:]}")
            return
        d = os.path.join(self.work, out)
        written = sorted(os.listdir(d))
        # 1. named in cli.md
        pats = self.rows.get(cmd)
        if pats is None:
            self.fault(f"docs/cli.md: no row for '{cmd}' in 'Where the outputs go'")
        else:
            for f in written:
                if not name_matches(f, pats):
                    self.fault(f"{where}: wrote {f}, which docs/cli.md's row for {cmd} does not name")
        # 2. --help's --out line
        line, names = self.help_out_names(cmd, args)
        if not names:
            self.fault(f"granwave {cmd} --help: the --out line names no file: {line.strip()!r}")
        for f in names:
            no_h5 = f.endswith(".h5") and "with HDF5" in line and not any(w.endswith(".h5") for w in written)
            if f not in written and not no_h5:  # (a build without HDF5 writes no .h5)
                self.fault(f"{where}: --help says it writes {f}; not written")
        # 3. the JSON file holds the --json object
        if json_file:
            path = os.path.join(d, json_file)
            if not os.path.exists(path):
                self.fault(f"{where} --json: no {json_file} under --out (formats.md: the same object is written)")
            else:
                printed = json.loads(p.stdout)
                missing = [k for k in ("version", "settings") if k not in printed]
                if missing:  # formats.md: "Every object has version and settings"
                    self.fault(f"{where} --json: no {' and no '.join(missing)} in the object")
                a = strip_timing(printed)
                b = strip_timing(json.load(open(path)))
                if a != b:
                    keys = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
                    self.fault(f"{where} --json: {json_file} differs from stdout in {keys[:5]}")
        # 4. CSV columns
        for f in written:
            if not f.endswith(".csv"):
                continue
            header = None
            with open(os.path.join(d, f)) as fp:
                for ln in fp:
                    if not ln.startswith("#"):
                        header = ln.strip().split(",")
                        break
            if not header or len(header) < 2:
                self.fault(f"{where}: {f} has the columns {header}: no data beside them")
                continue
            doc = next((c for pat, c in self.cols.items() if name_matches(f, [pat])), None)
            if doc is not None and expand(doc, header) != header:
                self.fault(f"{where}: {f} has the columns {header}; the docs list {expand(doc, header)}")
        # 5. HDF5 units
        try:
            import h5py
        except ImportError:
            return
        units = {"t": "s", "f_wall": "N", "x": "m", "v": "m/s"}
        for f in written:
            if f.endswith(".h5") and (f.startswith("trace_n") or f in ("chain.h5", "drop.h5")):
                with h5py.File(os.path.join(d, f), "r") as h:
                    for k in h:
                        u = h[k].attrs.get("units")
                        u = u.decode() if isinstance(u, bytes) else u
                        if k in units and u != units[k]:
                            self.fault(f"{where}: {f}:{k} has units {u!r}; formats.md says {units[k]!r}")
                        if 0 in h[k].shape:
                            self.fault(f"{where}: {f}:{k} is empty {h[k].shape}")

    def sweep_columns(self):
        """A two-case layer sweep: its results.csv columns between the grid keys and the
        hashes are the ones formats.md's "Each row holds" lists, in order."""
        with open(os.path.join(self.work, "sw.ini"), "w") as f:
            f.write("[sweep]\nmodel = layer\nout = o_sweep\n[grid]\nrb-rm = 1\npoint = 0:1\n[params]\n"
                    "sample = s60.txt\npoints = 2\nt-max = 0.005\n")
        p = self.run(["sweep", "sw.ini", "--jobs", "1", "--quiet"])
        if p.returncode != 0:
            self.fault(f"granwave sweep sw.ini: exit {p.returncode}: {p.stderr.strip()[-300:]}")
            return
        with open(os.path.join(self.work, "o_sweep", "results.csv")) as fp:
            header = next(ln for ln in fp if not ln.startswith("#")).strip().split(",")
        model = header[header.index("point") + 1:header.index("case_config_fnv1a64")]
        text = re.sub(r"\s+", " ", open(os.path.join(self.src, "docs", "formats.md"), encoding="utf-8").read())
        m = re.search(r"Each row holds (.*?)\(\[outcomes\.md\]", text)
        doc = re.findall(r"`(\w+)`", m.group(1)) if m else None
        if doc != model:
            self.fault(f"granwave sweep (model layer): results.csv's columns {model}; docs/formats.md lists {doc}")

    def value(self, key, args):
        """The run's JSON object; for a run with --out and no --json, its directory (the
        claim reads the files); for a run whose first word is REFUSED, its stderr line
        (the run must exit 2)."""
        if key not in self.cache:
            refused = args[0] == "REFUSED"
            p = self.run(args[1:] if refused else args)
            if refused:
                self.cache[key] = p.stderr.strip() if p.returncode == 2 else None
                if p.returncode != 2:
                    self.fault(f"granwave {' '.join(args[1:])}: exit {p.returncode}, not 2")
            elif p.returncode != 0:
                self.cache[key] = None
                self.fault(f"granwave {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()[-300:]}")
            elif "--out" in args and "--json" not in args:
                self.cache[key] = os.path.join(self.work, args[args.index("--out") + 1])
            else:
                self.cache[key] = json.loads(p.stdout)
        return self.cache[key]

    def help_default(self, cmd, flag, text, args, check):
        """`granwave CMD --help`'s line of FLAG holds text, and check(the run's JSON) is
        None (the run uses that default) or the fault's words."""
        p = self.run([cmd, "--help"])
        line = next((ln.strip() for ln in p.stdout.splitlines() if ln.strip().startswith(flag + " ")), "")
        if text != "NUMBER" and text not in line:
            self.fault(f"granwave {cmd} --help: {flag} says {line!r}, not {text!r}")
            return
        if text == "NUMBER":  # the line's last [default], its first number, against the settings
            m = re.search(r"\[([-+0-9.e]+)[],;]", line[line.rfind("["):] if "[" in line else "")
            if not m:
                self.fault(f"granwave {cmd} --help: {flag} states no numeric default: {line!r}")
                return
            want, get = float(m.group(1)), check
            check = lambda j: None if _rel(float(get(j)), want, 1e-12) else f"records {get(j)!r}, not {m.group(1)}"
        js = self.value(tuple(args), args)
        if js is None:
            return
        try:
            why = check(js)
        except (KeyError, IndexError, TypeError) as e:
            why = f"has no such value ({e!r})"
        if why:
            self.fault(f"granwave {cmd} --help: {flag} says {text!r}; granwave {' '.join(args)}: {why}")

    def claim(self, page, text, args, get, fmt):
        body = open(os.path.join(self.src, page), encoding="utf-8").read()
        body = re.sub(r"\s+", " ", body)
        if text not in body:
            self.fault(f"{page}: no longer says {text!r} (update this test with the page)")
            return
        if args and isinstance(args[0], list):  # a claim on several runs: get takes their objects
            args = [[a.replace("{SRC}", self.src) for a in one] for one in args]
            js = [self.value(tuple(one), one) for one in args]
            if any(j is None for j in js):
                return
            args = [" ;".join(" ".join(one) for one in args)]
        else:
            args = [a.replace("{SRC}", self.src) for a in args]
            js = self.value(tuple(args), args)
            if js is None:
                return
        try:
            v = get(js)
        except (KeyError, IndexError, TypeError) as e:
            self.fault(f"{page}: {text!r}: granwave {' '.join(args)} has no such value ({e!r})")
            return
        got = fmt(v)
        if got not in text:
            self.fault(f"{page}: says {text!r}; granwave {' '.join(args)} gives {got} ({v!r})")


def vel(js, h):
    return next(v for v in js["velocities"] if (v["h_mm"] or 0) == h)


FALCON = ["falcon", "--json", "--quiet"]
SAMPLE300 = ["layer-make", "--n", "300", "--seed", "1", "--out", "sample300.txt", "--json"]
IMPACT300 = ["layer-impact", "--sample", "sample300.txt", "--rb-rm", "1", "--vi", "20", "--json"]
VERDICT300 = ["layer-impact", "--sample", "sample300.txt", "--until", "verdict", "--json"]
DISP = ["dispersion", "--json"]
DROP51 = ["drop", "--n", "40", "--height", "5.1e-3", "--t-max", "10e-3", "--dt-out", "5e-6", "--damping", "kk",
          "--restitution", "0.9", "--json"]
DROP19 = ["drop", "--n", "40", "--height", "1.9e-3", "--t-max", "10e-3", "--dt-out", "5e-6", "--damping", "kk",
          "--restitution", "0.9", "--json"]


def sci(x, digits=1):
    """1.2e-5 as the pages write it (no zero-padded exponent)."""
    m, e = f"{x:.{digits}e}".split("e")
    return f"{m}e{int(e)}"


def f1(x):
    return f"{x:.1f}"


def f2(x):
    return f"{x:.2f}"


def impacts(js):
    return ", ".join(f"{i['f_max']:.2f} at {i['t_fmax'] * 1e3:.2f}" for i in js["impacts"])


CLAIMS = [
    # README.md's Falcon table (h = 5.1 mm unless said) and docs/column.md's
    ("README.md", "| F_max, mean over N = 1..40 (N) | 72.4 |", FALCON, lambda j: vel(j, 5.1)["f_max_mean"], f1),
    ("README.md", "| tau_max (us) | 18.04 |", FALCON, lambda j: vel(j, 5.1)["tau_max_mean"] * 1e6, f2),
    ("README.md", "| T_q, slope of tau_N over N = 1..20 (us) | 25.41 |", FALCON,
     lambda j: vel(j, 5.1)["t_q_n20"] * 1e6, f2),
    ("README.md", "| T_q at h = 2.9 mm (us) | 26.89 |", FALCON, lambda j: vel(j, 2.9)["t_q_n20"] * 1e6, f2),
    ("README.md", "| wave speed 4R/T_q, N <= 20 (m/s) | 629.6 |", FALCON,
     lambda j: vel(j, 5.1)["wave_speed_n20"], f1),
    ("README.md", "| wave speed 4R/T_q, N <= 40 (m/s) | 606.6 |", FALCON, lambda j: vel(j, 5.1)["wave_speed"], f1),
    ("README.md", "| collision time N = 40 (ms) | 1.062 |", FALCON,
     lambda j: vel(j, 5.1)["tau_n_last"] * 1e3, lambda x: f"{x:.3f}"),
    ("docs/column.md", "| F_max (N) | 3.1 | 53.7 |", FALCON, lambda j: vel(j, 3.1)["f_max_mean"], f1),
    ("docs/column.md", "| period P (us) | 5.1 | 31.46 |", FALCON, lambda j: vel(j, 5.1)["period_mean"] * 1e6, f2),
    ("docs/column.md", "| period P (us) | 3.1 | 33.06 |", FALCON, lambda j: vel(j, 3.1)["period_mean"] * 1e6, f2),
    ("docs/column.md", "| T_q, slope over N = 1..40 (us) | 5.1 | 26.38 |", FALCON,
     lambda j: vel(j, 5.1)["t_q"] * 1e6, f2),
    ("docs/column.md", "| wave speed 4R/T_q, N <= 20 (m/s) | 1.9 | 570.4 |", FALCON,
     lambda j: vel(j, 1.9)["wave_speed_n20"], f1),
    ("docs/column.md", "(66.39 N at N = 1, 67.94 N mean", FALCON,
     lambda j: (vel(j, 0)["f_max_min"], vel(j, 0)["f_max_mean"]), lambda x: f"({x[0]:.2f} N at N = 1, {x[1]:.2f} N mean"),
    # the dispersion study of docs/column.md
    ("docs/column.md", "within 7.1e-4 of omega(q)", DISP, lambda j: j["ridge_max_rel_err"], sci),
    ("docs/column.md", "over 509 of 512 wavenumbers", DISP, lambda j: j["n_resolved"], lambda x: f"{x} of 512"),
    ("docs/column.md", "the long-wave sound speed is 598.76 m/s against 598.77 m/s", DISP,
     lambda j: (j["c0_measured"], j["c0"]), lambda x: f"{x[0]:.2f} m/s against {x[1]:.2f} m/s"),
    # README.md and docs/cli.md: the default sample and impact
    ("README.md", "Pluviated samples have porosity 0.192", SAMPLE300, lambda j: j["porosity"], lambda x: f"{x:.3f}"),
    ("README.md", "the default impact stops at T_f = 0.06 s with e_n = 0.020", IMPACT300,
     lambda j: (j["t_f"], j["e_n"]), lambda x: f"T_f = {x[0]:.2f} s with e_n = {x[1]:.3f}"),
    ("docs/cli.md", "the default impact stops at T_f = 0.06 s", IMPACT300, lambda j: j["t_f"], f2),
    # docs/layer.md: the fast mode's row of the default impact
    ("docs/layer.md", "| default: R_b = R_m, 20 m/s, 300 discs (`--until verdict`) | yes | 0.019666 /", VERDICT300,
     lambda j: j["e_n_first"], lambda x: f"| {x:.6f} /"),
    ("docs/layer.md", "| 0.1383082 / 0.1383071 | 3.3e-5 /", VERDICT300,
     lambda j: (j["penetration"], j["energy_error"]), lambda x: f"| {x[0]:.7f} / 0.1383071 | {sci(x[1])} /"),
    ("docs/layer.md", "| 2286 / 25221", VERDICT300, lambda j: j["steps"], lambda x: f"| {x} /"),
    # docs/drop.md's table of the 10 ms windows
    ("docs/drop.md", "| N = 40, h = 5.1 mm | 10 ms | 2 | 0 | 68.97 at 0.02, 3.96 at 6.99 |", DROP51,
     lambda j: (len(j["impacts"]), j["impact_rises"], impacts(j)), lambda x: f"| {x[0]} | {x[1]} | {x[2]} |"),
    ("docs/drop.md", "| N = 40, h = 1.9 mm | 10 ms | 4 | 1 | 38.16 at 0.02, 2.19 at 4.76, 2.03 at 8.23, **5.42** at 9.31 |",
     DROP19, lambda j: (len(j["impacts"]), j["impact_rises"], impacts(j).replace("5.42", "**5.42**")),
     lambda x: f"| {x[0]} | {x[1]} | {x[2]} |"),
]
# the default impact's numbers the pages quote after the skin-independent pluviation (measured on
# the 300-disc sample of `layer-make --n 300 --seed 1`)
VERDICT300_DT = [VERDICT300 + ["--dt", d] for d in ("5e-6", "1e-5", "2e-5")]
F85 = [VERDICT300 + ["--friction", "85", "--dt", d] for d in ("5e-6", "1e-5", "2e-5")]
DIAGRAM8000 = "{SRC}/data/measured/layer_diagram_8000/sample.txt"
CLAIMS += [
    ("docs/layer.md", "e_n 0.019666 at `--dt-out 1.7e-5` and 0.019666 at the default",
     [IMPACT300 + ["--dt-out", "1.7e-5"], IMPACT300], lambda j: (j[0]["e_n"], j[1]["e_n"]),
     lambda x: f"e_n {x[0]:.6f} at `--dt-out 1.7e-5` and {x[1]:.6f} at the default"),
    ("docs/layer.md", "It is second order in dt (8.3e-6, 3.3e-5, 1.4e-4 at 5, 10, 20 us on the default impact)",
     VERDICT300_DT, lambda j: [x["energy_error"] for x in j], lambda x: f"({', '.join(sci(v) for v in x)} at"),
    ("docs/layer.md", "at 85 deg e_n_first is 0.1065, 0.1109 and 0.1053 at 5, 10 and 20 us", F85,
     lambda j: [x["e_n_first"] for x in j], lambda x: f"{x[0]:.4f}, {x[1]:.4f} and {x[2]:.4f} at"),
    ("docs/layer.md", "while at 30 deg it moves by 7.9e-5 over the same range", VERDICT300_DT,
     lambda j: max(x["e_n_first"] for x in j) - min(x["e_n_first"] for x in j), lambda x: f"by {sci(x)} over"),
    ("docs/formats.md", "the default impact to its verdict gives 3.3e-5 at `--dt-out 2e-5` and 3.3e-5 at 1e-3",
     [VERDICT300, VERDICT300 + ["--dt-out", "1e-3"]], lambda j: (j[0]["energy_error"], j[1]["energy_error"]),
     lambda x: f"gives {sci(x[0])} at `--dt-out 2e-5` and {sci(x[1])} at 1e-3"),
    ("docs/formats.md", "it gives 657 +- 15 m/s at 2e-5 and 657 +- 15 m/s at 1e-2",
     [IMPACT300, IMPACT300 + ["--dt-out", "1e-2"]],
     lambda j: (j[0]["wave_speed"], j[0]["wave_speed_err"], j[1]["wave_speed"], j[1]["wave_speed_err"]),
     lambda x: f"{x[0]:.0f} +- {x[1]:.0f} m/s at 2e-5 and {x[2]:.0f} +- {x[3]:.0f} m/s at 1e-2"),
    ("docs/outcomes.md", "T_f = 0.303, 0.063 and 0.961 s at 10, 20 and 40 m/s (e_n 0.179, 0.020, 0.248;",
     [[("10" if a == "20" else a) for a in IMPACT300], IMPACT300, [("40" if a == "20" else a) for a in IMPACT300]],
     lambda j: ([x["t_f"] for x in j], [x["e_n"] for x in j]),
     lambda x: "T_f = {:.3f}, {:.3f} and {:.3f} s at 10, 20 and 40 m/s (e_n {:.3f}, {:.3f}, {:.3f};".format(*x[0], *x[1])),
    ("docs/outcomes.md", "`layer_diagram_8000`: 230 steps of 10 us and 0.01 s of CPU, against 45 044 steps and 0.8 s to T_f = 0.450 s;",
     [["layer-impact", "--sample", DIAGRAM8000, "--until", "verdict", "--json"],
      ["layer-impact", "--sample", DIAGRAM8000, "--json"]],
     lambda j: (j[0]["steps"], j[0]["settings"]["solver"]["dt"], j[1]["steps"], j[1]["t_f"]),
     lambda x: f"{x[0]} steps of {x[1] * 1e6:.0f} us and 0.01 s of CPU, against {x[2] // 1000} {x[2] % 1000:03d} steps "
               f"and 0.8 s to T_f = {x[3]:.3f} s;"),
]
# docs/cli.md: the default pile under a lower friction than it settled at, and the pile settled
# again at that friction (a packing of its own), hit at 2 m/s
_F20 = ["--vi", "2", "--friction", "20", "--json"]
CLAIMS.append(("docs/cli.md", "At 2 m/s the 300-disc pile's e_n at 20 degrees is 0.1065 from zero springs (0.0849 with "
               "its springs) against 0.2236 on the pile settled again at 20",
               [SAMPLE300, ["layer-make", "--n", "300", "--seed", "1", "--friction", "20", "--out", "s300_f20.txt", "--json"],
                ["layer-impact", "--sample", "sample300.txt", "--other-settling", "--zero-springs", *_F20],
                ["layer-impact", "--sample", "sample300.txt", "--other-settling", *_F20],
                ["layer-impact", "--sample", "s300_f20.txt", *_F20],
                ["layer-impact", "--sample", "s300_f20.txt", "--zero-springs", *_F20]],
               lambda j: (j[2]["e_n"], j[3]["e_n"], j[4]["e_n"], j[5]["e_n"]),
               lambda x: (f"is {x[0]:.4f} from zero springs ({x[1]:.4f} with its springs) against {x[2]:.4f} on the pile"
                          if f"{x[2]:.4f}" == f"{x[3]:.4f}" else f"the pile settled at 20 gives {x[2]:.4f} and {x[3]:.4f}")))
# docs/layer.md: the default block set down on the 300-disc pile for 100 ms, with its springs and
# from zero, run with the flags the page gives (read from it): the soil's potential energy lost
# (the block's fall taken out) and its E_k at 10 ms
def _rest_flags():
    page = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "layer.md"),
                encoding="utf-8").read()
    m = re.search(r"set down on the piles of `layer-make --seed 1` \(30\s+degrees; `([^`]*)`", page)
    return m.group(1).split() if m else ["--page-gives-no-flags"]


_REST = ["layer-impact", "--sample", "sample300.txt", *_rest_flags()]


def _soil(d):
    """(soil PE lost by 100 ms, soil E_k at 10 ms) from a run's ledger.csv and impact.json."""
    import csv
    m = json.load(open(os.path.join(d, "impact.json")))["block_mass"]
    with open(os.path.join(d, "ledger.csv")) as f:
        rows = list(csv.DictReader(ln for ln in f if not ln.startswith("#")))
    at = lambda t: min(rows, key=lambda r: abs(float(r["t"]) - t))
    pe = float(at(0.1)["potential"]) - m * 9.81 * (float(at(0.1)["block_y"]) - float(rows[0]["block_y"]))
    return -pe, float(at(0.01)["kinetic_soil"])


CLAIMS.append(("docs/layer.md", "| 300 discs | -6 J against 36 J | 4.4 J against 26 J | 8.6 J |",
               [SAMPLE300, _REST + ["--out", "o_rest"], _REST + ["--zero-springs", "--out", "o_rest0"]],
               lambda j: (_soil(j[1]), _soil(j[2])),
               lambda x: f"| {x[0][0]:.0f} J against {x[1][0]:.0f} J | {x[0][1]:.1f} J against {x[1][1]:.0f} J |"))
# docs/column.md: the sampling plan's refusal of a wall far stiffer than the bead contacts
CLAIMS.append(("docs/column.md", "today's plan expects 27.3 ms, 6.24e6 samples, and its refusal says so",
               ["REFUSED", "chain", "--n", "2", "--k", "1e3", "--kwall", "1e14"],
               lambda t: re.search(r"about (\S+) samples over the collision \(about (\S+) s\)", t).groups(),
               lambda x: f"plan expects {float(x[1]) * 1e3:.1f} ms, {x[0].replace('e+0', 'e')} samples"))
# docs/column.md: the calibration's one-bead run has its own end time and sampling
_KK20 = ["chain", "--n", "20", "--damping", "kk", "--restitution", "0.9", "--json"]
CLAIMS.append(("docs/column.md", "gamma 7035.97 for N = 20 at every `--dt-out`",
               [_KK20, _KK20[:-1] + ["--dt-out", "1e-5", "--json"]],
               lambda j: [x["settings"]["model"]["gamma"] for x in j],
               lambda x: f"gamma {x[0]:.2f} for" if len(set(x)) == 1 else f"gamma {x} differ"))
# docs/outcomes.md: the dt-out independence of the fast mode today (two of the four sampling steps)
for _d in ("1e-5", "1e-3"):
    CLAIMS.append(("docs/outcomes.md", "e_n_first 0.2198175, T_i 2.28 ms and 0.0182499 m at each of the four",
                   ["layer-impact", "--sample", "{SRC}/data/measured/layer_diagram_8000/sample.txt", "--until", "verdict",
                    "--dt-out", _d, "--json"],
                   lambda j: (j["e_n_first"], j["t_rebound_first"] * 1e3, j["penetration"]),
                   lambda x: f"e_n_first {x[0]:.7f}, T_i {x[1]:.2f} ms and {x[2]:.7f} m"))
# the damped columns of docs/column.md: eps_eff for N = 1, 2, 5, 10, 20, 40 (Kuwabara-Kono, e = 0.9)
KK = "eps_eff falls with N as in the experiment: 0.900, 0.874, 0.864, 0.863, 0.860, 0.860 for N = 1, 2, 5, 10, 20, 40"
for _i, _n in enumerate((1, 2, 5, 10, 20, 40)):
    CLAIMS.append(("docs/column.md", KK, ["chain", "--n", str(_n), "--damping", "kk", "--restitution", "0.9", "--json"],
                   lambda j: j["eps_eff"], lambda x, i=_i: (f"{x:.3f}" if i == 0 else f", {x:.3f}")))
# docs/column.md: N_d on two soft walls (tolerance 1 %, N = 1..40) and (F.8) there
for _k, _nd in (("2e9", "4"), ("1e9", "7")):
    CLAIMS.append(("docs/column.md", "| N_d measured in the model | 4 | 7 | 11 | 20 |",
                   ["softwall", "--kwall", _k, "--n", "1:40", "--json", "--quiet"], lambda j: j["n_d"],
                   lambda x: f"| {x} |"))
    CLAIMS.append(("docs/column.md", "| (F.8) at that N_d | 4 | 7 | 11 | 21 |",
                   ["softwall", "--kwall", _k, "--n", "1:40", "--json", "--quiet"], lambda j: j["n_d_predicted"],
                   lambda x: f"| {x} |"))

# ---- the fifteenth pass: the quoted results a user tries first that nothing recomputed ----
def csv_rows(d, name):
    import csv
    with open(os.path.join(d, name)) as f:
        return list(csv.DictReader(ln for ln in f if not ln.startswith("#")))


def falcon_runs(d, v="0.3"):
    return [r for r in csv_rows(d, "falcon_runs.csv") if r["v_imp_m_s"] == v]


def final_v(d, n):
    return [float(r["final_v_m_s"]) for r in csv_rows(d, "falcon_final_velocities.csv")
            if r["v_imp_m_s"] == "0.3" and r["n"] == str(n)]


FALCON_OUT = ["falcon", "--quiet", "--out", "o_falcon_all"]
WS20 = ["wavespeed", "--n", "5:20", "--json", "--quiet"]
V51 = "0.3163257814"  # sqrt(2 g h) at h = 5.1 mm, g = 9.81
V29 = "0.23853301658261064"
KK9 = ["--damping", "kk", "--restitution", "0.9"]
BEAD300 = ["drop", "--n", "1", "--height", "5.1e-3", *KK9, "--t-max", "0.3", "--json"]
BLOCK300 = ["drop", "--n", "40", "--block", "--height", "5.1e-3", *KK9, "--t-max", "0.3", "--json"]


def e_first(j):
    i = j["impacts"][0]
    return -i["v_out"] / i["v_in"]


CLAIMS += [
    # docs/column.md's table and paragraph on the main job
    ("docs/column.md", "| tau_1 = tau_N(N = 1) (us) | 5.1 | 34.62 | 34.62 (F.2) |", FALCON,
     lambda j: (vel(j, 5.1)["tau_n_first"] * 1e6, vel(j, 5.1)["tau_1_theory"] * 1e6),
     lambda x: f"| {x[0]:.2f} | {x[1]:.2f} (F.2) |"),
    ("docs/column.md", "| F_max, mean over N = 1..40 (N) | 5.1 | 72.4 | 70.75 (F.13, N = 1) |", FALCON,
     lambda j: vel(j, 5.1)["f_max_1_theory"], lambda x: f"| {x:.2f} (F.13"),
    ("docs/column.md", "| wave speed 4R/T_q, N <= 20 (m/s) | 3.1 | 599.0 | 616.0 |", FALCON,
     lambda j: (vel(j, 3.1)["wave_speed_n20"], vel(j, 3.1)["wave_speed_theory"]),
     lambda x: f"| {x[0]:.1f} | {x[1]:.1f} |"),
    ("docs/column.md", "| T_q, slope over N = 1..20 (us) | 2.9 | 26.89 | 26.15 |", FALCON,
     lambda j: (vel(j, 2.9)["t_q_n20"] * 1e6, vel(j, 2.9)["t_q_theory"] * 1e6),
     lambda x: f"| {x[0]:.2f} | {x[1]:.2f} |"),
    ("docs/column.md", "tau_N is linear in N (r^2 = 0.99966)", FALCON, lambda j: vel(j, 0)["r2"],
     lambda x: f"(r^2 = {x:.5f})"),
    ("docs/column.md", "(1.82 v_imp for the top bead at N = 40) and bead 1 slower (0.036 v_imp)", FALCON_OUT,
     lambda d: (-final_v(d, 40)[-1] / 0.3, -final_v(d, 40)[0] / 0.3),
     lambda x: f"({x[0]:.2f} v_imp for the top bead at N = 40) and bead 1 slower ({x[1]:.3f} v_imp)"),
    ("docs/column.md", "E_rel/E_K grows from 0.058 (N = 2) to 0.187 (N = 40), rising in 38 of 39 steps", FALCON_OUT,
     lambda d: [float(r["e_rel_over_e_k"]) for r in falcon_runs(d)],
     lambda e: f"from {e[1]:.3f} (N = 2) to {e[39]:.3f} (N = 40), rising in "
               f"{sum(b > a for a, b in zip(e, e[1:]))} of {len(e) - 1} steps"),
    ("docs/column.md", "Measured relative energy error: 7.7e-8 to 8.4e-7 over the 200 Falcon runs", FALCON_OUT,
     lambda d: [float(r["energy_error"]) for r in csv_rows(d, "falcon_runs.csv")],
     lambda e: f"{sci(min(e))} to {sci(max(e))} over the {len(e)} Falcon"),
    # the wave speed's table (N = 5..20) and its two ratios
    ("docs/column.md", "| N = 5..20 | 1.946 | 2.012 | 2.409 | 1.967 | 3.4 % |", WS20,
     lambda j: ([j["fits"][k]["c3"] for k in ("tq", "front", "group", "group_front")], j["max_disagreement"]),
     lambda x: "| {:.3f} | {:.3f} | {:.3f} | {:.3f} | ".format(*x[0]) + f"{x[1] * 100:.1f} % |"),
    ("docs/column.md", "The measured c0/v_front is 1.197 at every velocity over N = 5..20", WS20,
     lambda j: sorted({f"{g / f:.3f}" for g, f in zip(j["v_group"], j["v_front"])}),
     lambda x: f"is {' or '.join(x)} at every velocity"),
    ("docs/column.md", "with C2 = 2.54 (N = 5..20;", WS20, lambda j: j["c2"], f2),
    # the memory bound's messages
    ("docs/column.md", "needs about 47.2 GB ...: at most 2274873 beads here", ["REFUSED", "chain", "--n", "50000000"],
     lambda t: re.search(r"needs about (\S+ GB) .*at most (\d+) beads here", t).groups(),
     lambda x: f"needs about {x[0]} ...: at most {x[1]} beads here"),
    ("docs/column.md", "at most 2164797 beads on a 100 kg body on 1e3 N/m",
     ["REFUSED", "chain", "--n", "20000000", "--sensor-mass", "100", "--sensor-stiffness", "1e3"],
     lambda t: re.search(r"at most (\d+) beads here", t).group(1), lambda x: f"at most {x} beads on a 100 kg body"),
    ("docs/column.md", "on 1 kg, 1.33e8 steps over the",
     ["REFUSED", "chain", "--n", "20000000", "--sensor-mass", "1", "--sensor-stiffness", "1e3"],
     lambda t: re.search(r"needs about (\S+) steps over the collision", t).group(1), lambda x: f"on 1 kg, {x.replace('e+0', 'e')} steps over the"),
    # docs/drop.md: the first collision against chain, the runs of its tables
    ("docs/drop.md", "| 1 | F_max (N) | 70.77858 | 70.74761 | 4.4e-4 | 70.77858 |",
     [["drop", "--n", "1", "--json"], ["chain", "--n", "1", "--vimp", V51, "--json"],
      ["chain", "--n", "1", "--vimp", V51, "--gravity", "9.81", "--json"]],
     lambda j: (j[0]["impacts"][0]["f_max"], j[1]["f_max"], j[2]["f_max"]),
     lambda x: f"| {x[0]:.5f} | {x[1]:.5f} | {sci(x[0] / x[1] - 1)} | {x[2]:.5f} |"),
    ("docs/drop.md", "| 10 | contact time (us) | 266.0576 | 265.9323 | 4.7e-4 | 266.0576 |",
     [["drop", "--n", "10", "--json"], ["chain", "--n", "10", "--vimp", V51, "--json"],
      ["chain", "--n", "10", "--vimp", V51, "--gravity", "9.81", "--json"]],
     lambda j: (j[0]["first_collision"]["tau_n"] * 1e6, j[1]["tau_n"] * 1e6, j[2]["tau_n"] * 1e6),
     lambda x: f"| {x[0]:.4f} | {x[1]:.4f} | {sci(x[0] / x[1] - 1)} | {x[2]:.4f} |"),
    ("docs/drop.md", "the rounded `--vimp 0.31633` gives F_max 1.6e-5 higher, 70.74874 N at N = 1",
     [["chain", "--n", "1", "--vimp", "0.31633", "--json"], ["chain", "--n", "1", "--vimp", V51, "--json"]],
     lambda j: (j[0]["f_max"] / j[1]["f_max"] - 1, j[0]["f_max"]), lambda x: f"F_max {sci(x[0])} higher, {x[1]:.5f} N"),
    ("docs/drop.md", "(70.78, 71.68, 72.57, 73.45, 74.33 N for N = 5 undamped)",
     ["drop", "--n", "5", "--gap", "1e-4", "--t-max", "2e-3", "--json"],
     lambda j: [i["f_max"] for i in j["impacts"]], lambda x: "(" + ", ".join(f"{v:.2f}" for v in x) + " N for"),
    ("docs/drop.md", "| one bead, h = 5.1 mm (first bounce: e = 0.900) | 300 ms | 7 | 0 | 66.70, 58.85, 52.05, 46.15, 41.02, 36.54, 32.62 |",
     BEAD300, lambda j: (e_first(j), len(j["impacts"]), j["impact_rises"], [i["f_max"] for i in j["impacts"]]),
     lambda x: f"e = {x[0]:.3f}) | 300 ms | {x[1]} | {x[2]} | " + ", ".join(f"{v:.2f}" for v in x[3]) + " |"),
    ("docs/drop.md", "| rigid block of 40 bead masses, h = 5.1 mm (first bounce: e = 0.976) | 300 ms | 5 | 0 | 639.0, 620.6, 602.8, 585.6, 569.0 |",
     BLOCK300, lambda j: (e_first(j), len(j["impacts"]), j["impact_rises"], [i["f_max"] for i in j["impacts"]]),
     lambda x: f"e = {x[0]:.3f}) | 300 ms | {x[1]} | {x[2]} | " + ", ".join(f"{v:.1f}" for v in x[3]) + " |"),
    ("docs/drop.md", "(gamma = 6957 N s/m^1.5 at 5.1 mm)", DROP51, lambda j: j["settings"]["model"]["gamma"],
     lambda x: f"(gamma = {x:.0f} N"),
    ("docs/drop.md", "the damped collision of 40 beads lasts 0.987 ms (tau_N; 1.066 ms undamped)",
     [DROP51, ["drop", "--n", "40", "--json"]], lambda j: [x["first_collision"]["tau_n"] * 1e3 for x in j],
     lambda x: f"lasts {x[0]:.3f} ms (tau_N; {x[1]:.3f} ms undamped)"),
    ("docs/drop.md", "(at tau_N: bead 1 at 0.029 m/s, bead 2 at 0.066 m/s, the top bead at 0.368 m/s = 1.16 v_imp; N_s = 4 beads leave from the top before a cluster of 36)",
     DROP51, lambda j: (j["first_collision"]["velocities_at_tau_n"], j["v_imp"], j["first_collision"]["n_s"],
                        j["first_collision"]["cluster"]),
     lambda x: f"bead 1 at {-x[0][0]:.3f} m/s, bead 2 at {-x[0][1]:.3f} m/s, the top bead at {-x[0][-1]:.3f} m/s = "
               f"{-x[0][-1] / x[1]:.2f} v_imp; N_s = {x[2]} beads leave from the top before a cluster of {x[3]})"),
    ("docs/drop.md", "is 4.2e-10 to 9.1e-10 over the 10 ms and 300 ms runs above (today's build)",
     [DROP51, DROP19, BEAD300, BLOCK300], lambda j: [x["energy_error"] for x in j],
     lambda e: f"is {sci(min(e))} to {sci(max(e))} over"),
    # docs/sheets.md: one bead on each target sheet under each law, brass's yield stresses,
    # the loss, guide friction, PVC's F_max(N) on the bonded layer
    ("docs/sheets.md", "energy ledger closes to 2e-10, and eps_eff falls as the friction grows (N = 10 at h = 2.9 mm: 0.9206, 0.9133 and 0.9061",
     [["chain", "--n", "10", "--vimp", V29, "--json"],
      ["chain", "--n", "10", "--vimp", V29, "--guide-friction", "0.01", "--guide-viscous", "0.05", "--json"],
      ["chain", "--n", "10", "--vimp", V29, "--guide-friction", "0.02", "--guide-viscous", "0.1", "--json"]],
     lambda j: ([x["eps_eff"] for x in j], max(x["energy_error"] for x in j[1:])),
     lambda x: f"closes to {sci(x[1], 0)}, and eps_eff falls as the friction grows (N = 10 at h = 2.9 mm: "
               f"{x[0][0]:.4f}, {x[0][1]:.4f} and {x[0][2]:.4f}"),
    ("docs/sheets.md", "0.9172 and 0.9138 with the Coulomb part alone",
     [["chain", "--n", "10", "--vimp", V29, "--guide-friction", f, "--json"] for f in ("0.01", "0.02")],
     lambda j: [x["eps_eff"] for x in j], lambda x: f"{x[0]:.4f} and {x[1]:.4f} with"),
    ("docs/sheets.md", "Tests: restitution 0.888, 0.9873, 0.99871 and 1 for losses 0.1, 0.01, 0.001 and 0",
     [["chain", "--vimp", V29, "--sheet", "pmma", "--sheet-law", "material", "--sheet-loss", l, "--json"]
      for l in ("0.1", "0.01", "0.001", "0")],
     lambda j: [x["eps_eff"] for x in j], lambda x: f"restitution {x[0]:.3f}, {x[1]:.4f}, {x[2]:.5f} and {x[3]:.0f} for"),
    ("docs/sheets.md", "The rebound of one bead drops to e = 0.975 (PVC) and 0.93 (PMMA).",
     [["chain", "--vimp", V29, "--sheet", s_, "--sheet-law", "material", "--json"] for s_ in ("pvc", "pmma")],
     lambda j: [x["eps_eff"] for x in j], lambda x: f"e = {x[0]:.3f} (PVC) and {x[1]:.2f} (PMMA)"),
    ("docs/sheets.md", "it goes 13.8, 20.9, 26.4, 30.3, 33.1, 35.1, 36.3, 37.2 N for N = 1..8, against 38.9 N at N = 30",
     [["chain", "--n", str(n), "--vimp", V29, "--sheet", "pvc", "--sheet-law", "layer", "--json"]
      for n in (1, 2, 3, 4, 5, 6, 7, 8, 30)],
     lambda j: [x["f_max"] for x in j],
     lambda x: "goes " + ", ".join(f"{v:.1f}" for v in x[:8]) + f" N for N = 1..8, against {x[8]:.1f} N at N = 30"),
]
_TAU1 = {"none": "| none | 17.0 | 17.0 | 18.3 | 18.3 | 18.3 | 20.8 |",
         "brass": "| brass | 47.5 | 47.5 | 21.7 | 21.2 | 27.9 | 29.4 |",
         "tape": "| tape | 47.5 | 47.5 | 74.9 | 56.1 | 55.5 | 54.1 |",
         "pvc": "| pvc | 67.5 | 67.5 | 74.9 | 68.9 | 68.1 | 68.3 |",
         "pmma": "| pmma | 69.0 | 69.0 | 72.4 | 66.8 | 64.4 | 61.5 |"}
for _s, _row in _TAU1.items():
    _sh = [] if _s == "none" else ["--sheet", _s]
    _laws = [["--sheet-law", l] if _sh else [] for l in ("hertz", "layer", "material")]
    CLAIMS.append(("docs/sheets.md", _row,
                   [["chain", "--vimp", V29, *_sh, *lw, "--json"] for lw in _laws] +
                   [["chain", "--vimp", V29, *_sh, *(_laws[2]), "--sensor-mass", "3e-3", "--sensor-stiffness", "2e9",
                     "--json"]],
                   lambda j: [x["tau_max"] * 1e6 for x in j], lambda x: "| " + " | ".join(f"{v:.1f}" for v in x) + " |"))
for _y, _row in (("1e8", "| 100 MPa | 38.6 | 0.425 | 7 / 5 | 62.4 |"), ("2e8", "| 200 MPa | 27.9 | 0.649 | 4 / 3 | 51.0 |"),
                 ("3.5e8", "| 350 MPa | 22.8 | 0.886 | 2 / 1 | 25.5 |")):
    _a = ["--vimp", V29, "--sheet", "brass", "--sheet-law", "material", "--sheet-yield", _y, "--json"]
    CLAIMS.append(("docs/sheets.md", _row, [["chain", *_a], ["chain", "--n", "2", *_a]],
                   lambda j: (j[0]["tau_max"] * 1e6, j[0]["eps_eff"], j[1]["tau_max"] * 1e6),
                   lambda x, row=_row: (f"| {x[0]:.1f} | {x[1]:.3f} |" if f"| {x[2]:.1f} |" in row
                                        else f"tau_max(2) {x[2]:.1f}")))
# docs/outcomes.md: the exact 3 m/s impact on the 100-disc test sample as pluviated today
CLAIMS.append(("docs/outcomes.md", "the same impact gives e_n 0.149848, T_f 48.005 ms and a penetration of 0.00279124 m",
               [["layer-make", "--n", "100", "--width-rm", "20", "--seed", "5", "--out", "s100.txt", "--json"],
                ["layer-impact", "--sample", "s100.txt", "--exact", "--vi", "3", "--t-max", "0.05", "--json"]],
               lambda j: (j[1]["e_n"], j[1]["t_f"] * 1e3, j[1]["penetration"]),
               lambda x: f"e_n {x[0]:.6f}, T_f {x[1]:.3f} ms and a penetration of {x[2]:.8f} m"))


# README.md's and crowns.md's crown speeds, as data/measured/layer_wave_speed/README.md runs them: 16
# impact points 0.15 m apart around the box centre, `--full --t-max 0.02`, the mean +- standard error
# over the points of the cross-correlation and strain-peak speeds (series disc_r7 at 20 m/s on the
# README's stored sample, sphere at 40 m/s on its sphere-mass sample); 32 impacts, about 2 s of CPU
def _crown_runs(sample, vi, extra=()):
    return [["layer-impact", "--sample", sample, "--vi", vi, "--x", repr(round((k - 7.5) * 0.15, 10)), "--full",
             "--t-max", "0.02", *extra, "--json"] for k in range(16)]


def _mean_se(js, key):
    v = [j[key] for j in js]
    m = sum(v) / len(v)
    return m, (sum((x - m) ** 2 for x in v) / (len(v) - 1) / len(v)) ** 0.5


def _near(quoted, *values):
    """quoted ("716 +- 12") when each value is within 0.6 of its quoted whole number, else the values
    as the page would write them: the stored series were rounded from a mean of 715.50 where today's
    runs give 715.48, so a whole m/s either side of a .5 is not a drift."""
    q = [float(t) for t in re.findall(r"\d+", quoted)]
    if len(q) == len(values) and all(abs(a - b) <= 0.6 for a, b in zip(q, values)):
        return quoted
    return " +- ".join(f"{v:.0f}" for v in values)


_R7_20 = _crown_runs("{SRC}/data/measured/restitution_full/sample.txt", "20", ("--rings", "7"))
_SPHERE_40 = _crown_runs("{SRC}/data/measured/layer_wave_speed/sample_sphere.txt", "40")
CLAIMS += [
    ("README.md", "at 20 m/s on the 7 inner rings 716 +- 12 m/s against 702 +- 16 by peak picking", _R7_20,
     lambda j: (_mean_se(j, "wave_speed_xcorr"), _mean_se(j, "wave_speed")),
     lambda x: f"{_near('716 +- 12', *x[0])} m/s against {_near('702 +- 16', *x[1])} by"),
    ("docs/crowns.md", "| 671 +- 11 | 716 +- 12 | 760 +- 13 |", _R7_20, lambda j: _mean_se(j, "wave_speed_xcorr"),
     lambda x: f"| 671 +- 11 | {_near('716 +- 12', *x)} | 760"),
    ("docs/crowns.md", "| 662 +- 14 | 702 +- 16 | 744 +- 19 |", _R7_20, lambda j: _mean_se(j, "wave_speed"),
     lambda x: f"| 662 +- 14 | {_near('702 +- 16', *x)} | 744"),
    ("README.md", "~1000 m/s is reached at 40 m/s with sphere masses (1032 +- 27)", _SPHERE_40,
     lambda j: _mean_se(j, "wave_speed_xcorr"), lambda x: f"({_near('1032 +- 27', *x)})"),
    ("docs/crowns.md", "| 890 +- 22 | 1032 +- 27 | 1207 +- 32 |", _SPHERE_40,
     lambda j: _mean_se(j, "wave_speed_xcorr"), lambda x: f"| 890 +- 22 | {_near('1032 +- 27', *x)} | 1207"),
    ("docs/crowns.md", "| 797 +- 26 | 934 +- 34 | 1108 +- 37 |", _SPHERE_40,
     lambda j: _mean_se(j, "wave_speed"), lambda x: f"| 797 +- 26 | {_near('934 +- 34', *x)} | 1108"),
]
# layer.md's one impact at the box centre of each sample (`--full --t-max 0.012`), the strain peaks' fit
# and the kinetic peaks' speed
_CENTRE = [["layer-impact", "--sample", "{SRC}/data/measured/" + f, "--vi", "20", "--full", "--t-max", "0.012",
            "--json"] for f in ("restitution_full/sample.txt", "layer_wave_speed/sample_sphere.txt")]
CLAIMS.append(("docs/layer.md", "gives c = 575 +- 21 m/s from the strain peaks (611 from the kinetic peaks) with disc",
               _CENTRE[0], lambda j: (j["wave_speed"], j["wave_speed_err"], j["wave_speed_kinetic"]),
               lambda x: "c = {:.0f} +- {:.0f} m/s from the strain peaks ({:.0f} from".format(*x)))
CLAIMS.append(("docs/layer.md", "and 892 +- 24 m/s (948) with sphere masses on its sphere-mass sample",
               _CENTRE[1], lambda j: (j["wave_speed"], j["wave_speed_err"], j["wave_speed_kinetic"]),
               lambda x: "and {:.0f} +- {:.0f} m/s ({:.0f}) with".format(*x)))


def _pair_tau(j, v):
    """The shortest binary contact at 2 v of a uniform steel column (chain_contact_tau_min):
    two beads (m/2, k) or bead on wall (m, kwall), from the closed-form tau_1 (m, kwall, v)."""
    m = j["settings"]["model"]
    t1 = j["closed_forms"]["tau_1"] if "closed_forms" in j else j["first_collision"]["closed_forms"]["tau_1"]
    return min(t1 * (0.5 * m["kwall"] / m["k"]) ** 0.4, t1) * 2 ** -0.2


def _rel(a, b, tol=1e-9):
    return a is not None and b is not None and abs(a - b) <= tol * abs(b)


CHAIN3 = ["chain", "--n", "3", "--json"]
# (command, flag, text in its --help line, run, check: None or what is wrong)
HELP_DEFAULTS = [
    ("chain", "--dt-max", "[0 = a quarter of the shortest binary contact time at 2 v_imp]", CHAIN3,
     lambda j: None if _rel(j["settings"]["solver"]["dt_max"], 0.25 * _pair_tau(j, 0.3))
     else f"dt_max {j['settings']['solver']['dt_max']!r}, a quarter of the shortest contact is {0.25 * _pair_tau(j, 0.3)!r}"),
    ("drop", "--dt-max", "[0 = a quarter of the shortest binary contact time at 2 v_imp]", ["drop", "--n", "3", "--json"],
     lambda j: None if _rel(j["settings"]["solver"]["dt_max"], 0.25 * _pair_tau(j, j["v_imp"]))
     else f"dt_max {j['settings']['solver']['dt_max']!r}"),
    ("chain", "--dt", "[0 = T_c/400]", ["chain", "--n", "3", "--solver", "rk4", "--json"],
     lambda j: None if _rel(j["settings"]["solver"]["dt"], j["closed_forms"]["t_q"] / 2 / 400)
     else f"dt {j['settings']['solver']['dt']!r}, T_c/400 = {j['closed_forms']['t_q'] / 800!r}"),
    ("chain", "--dt-out", "[0 = tau_1/200]", CHAIN3,
     lambda j: None if _rel(j["settings"]["solver"]["dt_out"], j["closed_forms"]["tau_1"] / 200)
     else f"dt_out {j['settings']['solver']['dt_out']!r}"),
    ("chain", "--t-max", "[0 = 20 (n T_q + tau_1), of the heaviest bead, + 20 pi sqrt((n m + M)/k_s) on a sensor body, going on while contacts still act, up to 50 times that]", CHAIN3,
     lambda j: None if _rel(j["settings"]["solver"]["t_max"], 20 * (3 * j["closed_forms"]["t_q"] + j["closed_forms"]["tau_1"]))
     else f"t_max {j['settings']['solver']['t_max']!r}"),
    ("falcon", "--solver", "[rk4 by --accuracy;", FALCON, lambda j: None if j["settings"]["solver"]["name"] == "rk4"
     else f"solver {j['settings']['solver']['name']}"),
    ("falcon", "--dt", "[0 = T_c/M by --accuracy, M = 37 at 1e-6;", FALCON,
     lambda j: None if j["settings"]["solver"]["steps_per_tc"] == 37 and j["accuracy_target"] == 1e-6
     else f"steps_per_tc {j['settings']['solver']['steps_per_tc']}"),
    ("falcon", "--dt-out", "[0 = tau_1/10 of the fastest impact by --accuracy,", FALCON,
     lambda j: None if _rel(j["settings"]["solver"]["dt_out"], min(v["tau_1_theory"] for v in j["velocities"]) / 10)
     else f"dt_out {j['settings']['solver']['dt_out']!r}"),
    # the layer's method: its help said "[default]", which names none; cvode runs adams there
    ("layer-impact", "--method", "[adams / erk]", VERDICT300 + ["--solver", "cvode"],
     lambda j: None if j["settings"]["solver"]["method"] == "adams" else f"method {j['settings']['solver']['method']}"),
    ("layer-impact", "--method", "[adams / erk]", VERDICT300 + ["--solver", "arkode"],
     lambda j: None if j["settings"]["solver"]["method"] == "erk" else f"method {j['settings']['solver']['method']}"),
    ("drop", "--peak-threshold", "[1 % of F_max(1) (F.13) at v_imp;", ["drop", "--n", "3", "--json"],
     lambda j: None if _rel(j["peak_threshold"], 0.01 * j["first_collision"]["closed_forms"]["f_max_1"])
     else f"peak_threshold {j['peak_threshold']!r}"),
]
# the defaults each --help states as a number, against the settings the run records
for _cmd, _flag, _args, _path in (
        ("chain", "--rtol", CHAIN3, ("solver", "rtol")), ("chain", "--atol", CHAIN3, ("solver", "atol")),
        ("chain", "--max-steps", CHAIN3, ("solver", "max_steps")), ("chain", "--radius", CHAIN3, ("model", "radius")),
        ("drop", "--t-max", ["drop", "--json"], ("drop", "t_max")), ("drop", "--height", ["drop", "--json"], ("drop", "height")),
        ("drop", "--gravity", ["drop", "--json"], ("drop", "gravity")),
        ("dispersion", "--n", ["dispersion", "--n", "1024", "--json"], ("model", "n")),
        ("dispersion", "--f0", DISP, ("model", "f0")), ("dispersion", "--amp", DISP, ("model", "amp")),
        ("dispersion", "--t-samples", DISP, ("spectrum", "t_samples")),
        ("dispersion", "--steps-per-sample", DISP, ("solver", "steps_per_sample")),
        ("dispersion", "--min-bins", DISP, ("spectrum", "min_bins")),
        ("layer-make", "--rm", SAMPLE300, ("rm",)), ("layer-make", "--volume-ratio", SAMPLE300, ("volume_ratio",)),
        ("layer-make", "--width-rm", SAMPLE300, ("width_rm",)), ("layer-make", "--ke-threshold", SAMPLE300, ("ke_threshold",)),
        ("layer-make", "--t-max", SAMPLE300, ("t_max",)), ("layer-make", "--damping", SAMPLE300, ("damping",)),
        ("layer-make", "--dt", SAMPLE300, ("dt",)), ("layer-make", "--friction", SAMPLE300, ("material", "friction_deg")),
        ("layer-make", "--shear-modulus", SAMPLE300, ("material", "shear_modulus")),
        ("layer-make", "--poisson", SAMPLE300, ("material", "poisson")), ("layer-make", "--density", SAMPLE300, ("material", "density")),
        ("layer-make", "--gravity", SAMPLE300, ("material", "gravity")), ("layer-make", "--skin", SAMPLE300, ("material", "skin")),
        ("layer-impact", "--vi", VERDICT300, ("vi",)), ("layer-impact", "--rb-rm", VERDICT300, ("rb_rm",)),
        ("layer-impact", "--gap", VERDICT300, ("gap",)), ("layer-impact", "--t-max", VERDICT300, ("t_max",)),
        ("layer-impact", "--dt-out", VERDICT300, ("dt_out",)), ("layer-impact", "--rings", VERDICT300, ("rings",)),
        ("layer-impact", "--rtol", VERDICT300, ("solver", "rtol")), ("layer-impact", "--atol", VERDICT300, ("solver", "atol"))):
    def _num(j, path=_path):
        v = j["settings"]
        for k in path:
            v = v[k]
        return v
    HELP_DEFAULTS.append((_cmd, _flag, "NUMBER", _args, _num))

OUTPUT_RUNS = [
    ("chain", ["--n", "7", "--solver", "rk4"], "o_chain", "chain.json"),
    ("falcon", ["--n", "1:30", "--quiet"], "o_falcon", "falcon_summary.json"),
    ("wavespeed", ["--vimp", "0.3", "--n", "5:8", "--quiet"], "o_wavespeed", "wavespeed.json"),
    ("softwall", ["--kwall", "1e9", "--n", "1:8", "--quiet"], "o_softwall", "softwall.json"),
    ("dispersion", ["--n", "256"], "o_disp", "dispersion.json"),
    ("dispersion", ["--column-n", "10"], "o_disp_col", "dispersion.json"),
    ("drop", ["--n", "5", "--height", "1e-3", "--t-max", "2e-3"], "o_drop", "drop.json"),
    ("layer-impact", ["--sample", "s60.txt", "--t-max", "0.01", "--full"], "o_impact", "impact.json"),
]


def self_test(program, srcdir):
    """Made-up pages: unnamed output files, columns that differ, a wrong number."""
    with tempfile.TemporaryDirectory() as src, tempfile.TemporaryDirectory() as work:
        os.makedirs(os.path.join(src, "docs"))
        with open(os.path.join(src, "docs", "cli.md"), "w") as f:
            f.write("## Where the outputs go\n\n| command | json | files |\n|---|---|---|\n"
                    "| `chain` | x | `DIR/chain_wall_force.csv`, `chain.json` |\n")
        with open(os.path.join(src, "docs", "formats.md"), "w") as f:
            f.write("## CSV tables\n\n| file | columns |\n|---|---|\n| `chain_beads.csv` | `t_s`, `q1_m` .. `qN_m` |\n")
        with open(os.path.join(src, "docs", "drop.md"), "w") as f:
            f.write("## Outputs\n\n| file | contents |\n|---|---|\n| `chain_wall_force.csv` | `t_s,f_N` |\n")
        with open(os.path.join(src, "README.md"), "w") as f:
            f.write("F_max is 99.9 N here.\n")
        c = Checker(program, src, work)
        c.outputs("chain", ["--n", "2"], "o", "chain.json")
        c.claim("README.md", "F_max is 99.9 N", ["chain", "--n", "2", "--json"], lambda j: j["f_max"], f1)
        # a --help default the run does not use, and a help line that does not say it
        c.help_default("chain", "--rtol", "NUMBER", ["chain", "--n", "2", "--json"], lambda j: 1e-6)
        c.help_default("chain", "--dt-max", "[unlimited]", ["chain", "--n", "2", "--json"], lambda j: None)
        c.help_default("chain", "--dt-out", "[0 = tau_1/200]", ["chain", "--n", "2", "--json"], lambda j: "made-up fault")
        want = ("chain_beads.csv, which docs/cli.md", "chain.h5, which docs/cli.md", "chain_beads.csv has the columns",
            "the docs list ['t_s', 'f_N']", "says 'F_max is 99.9 N'", "--rtol says", "records 1e-06, not 1e-12",
            "--dt-max says", "made-up fault")
        return noticed(not_caught(want, c.faults), c.faults)


def main():
    args = program_srcdir(__doc__)
    if args is None:
        return 2
    program, srcdir = args
    if not self_test(program, srcdir):
        return 1
    with tempfile.TemporaryDirectory() as work:
        c = Checker(program, srcdir, work)
        p = c.run(["layer-make", "--n", "60", "--width-rm", "16", "--seed", "3", "--out", "s60.txt"])
        if p.returncode != 0:
            print("FAIL: could not make the 60-disc sample: " + p.stderr)
            return 1
        for cmd, args, out, js in OUTPUT_RUNS:
            c.outputs(cmd, args, out, js)
        c.sweep_columns()
        for page, text, args, get, fmt in CLAIMS:
            c.claim(page, text, args, get, fmt)
        for cmd, flag, text, args, check in HELP_DEFAULTS:
            c.help_default(cmd, flag, text, args, check)
    return finish(c.faults, f"{len(OUTPUT_RUNS)} --out runs, {len(CLAIMS)} quoted numbers and {len(HELP_DEFAULTS)} "
                  f"--help defaults, {len(c.faults)} fault(s)", prefix="FAIL: ")


if __name__ == "__main__":
    sys.exit(main())
