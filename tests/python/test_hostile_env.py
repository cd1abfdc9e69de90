"""The module under a hostile process environment (thirteenth pass): a
decimal-comma locale set by the caller, relative paths after chdir, the
umask. Each case runs in a child interpreter, so that its locale, working
directory or umask does not leak into the other tests.
"""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]

# Runs in a child: every call whose numbers cross the library as text (keywords
# parsed by the library, sample files written and read, messages), printed as
# JSON with Python's own (locale-free) repr of the floats.
CHILD = r"""
import json, locale, sys
if sys.argv[1] != "C":
    locale.setlocale(locale.LC_ALL, "")          # as matplotlib / Jupyter users do
    assert locale.localeconv()["decimal_point"] == ",", locale.localeconv()["decimal_point"]
import granwave
out = {}
r = granwave.chain(n=3, vimp=0.3, rtol=1e-7, restitution=0.9, damping="kk")
out["chain"] = [repr(r.f_max), repr(r.tau_n), repr(r.v_imp)]
for kw in ({"vimp": -0.5}, {"rtol": 0.5}, {"vimp": "0,3"}, {"radius": 2.5e-3, "radii": "0.004,0.0035"}):
    try:
        granwave.chain(n=3, **kw)
        out[str(kw)] = "accepted"
    except ValueError as e:
        out[str(kw)] = str(e)
m = granwave.layer_make(n=20, width_rm=10, seed=2, rm=0.325, out=sys.argv[2])
out["make"] = repr(m["porosity"])
i = granwave.layer_impact(sample=sys.argv[2], t_max=0.03, vi=12.5, rb_rm=1.5)
out["impact"] = [repr(i["t_end"]), repr(float(i["e_n"])), repr(float(i["penetration"]))]
s = granwave.sweep("chain", {"n": "2:3", "vimp": [0.1, 0.25]}, rtol=1e-6, jobs=2)
out["sweep"] = [repr(float(x)) for x in s.f_max]
print(json.dumps(out))
"""


def _comma_locale(tmp_path_factory):
    """(environment, name) of a decimal-comma locale: an installed one, or one
    made with localedef into a private directory (LOCPATH); None if neither."""
    try:
        have = subprocess.run(["locale", "-a"], capture_output=True, text=True).stdout.split()
    except OSError:
        have = []
    for name in ("de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8"):
        if name in have:
            return {}, name
    if not shutil.which("localedef"):
        return None
    d = tmp_path_factory.mktemp("locales")
    for src in ("de_DE", "fr_FR"):
        r = subprocess.run(["localedef", "-i", src, "-f", "UTF-8", str(d / (src + ".UTF-8"))],
                           capture_output=True)
        if (d / (src + ".UTF-8")).exists():
            return {"LOCPATH": str(d)}, src + ".UTF-8"
    return None


@pytest.fixture(scope="module")
def comma(tmp_path_factory):
    got = _comma_locale(tmp_path_factory)
    if got is None:
        pytest.skip("no decimal-comma locale installed and localedef cannot make one")
    return got


def _child(code, args, env=None, cwd=None, umask=None):
    e = dict(os.environ)
    e.update(env or {})
    pre = (lambda: os.umask(umask)) if umask is not None else None
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, env=e, cwd=cwd,
                          preexec_fn=pre, timeout=120)


def test_decimal_comma_locale_changes_nothing(comma, tmp_path):
    """Before: the library's strtod read "0.3" as 0 in a de_DE locale set by the
    caller (chain: vimp: '0.3' is not a number) and its printf wrote "0,5"."""
    env, name = comma
    sample = tmp_path / "s.txt"
    c = _child(CHILD, ["C", str(sample)], env=dict(env, LC_ALL="C"))
    assert c.returncode == 0, c.stderr
    c_bytes = sample.read_bytes()
    sample.unlink()
    d = _child(CHILD, ["de", str(sample)], env=dict(env, LC_ALL=name))
    assert d.returncode == 0, d.stderr
    assert json.loads(d.stdout) == json.loads(c.stdout)
    assert sample.read_bytes() == c_bytes  # the sample file, byte for byte
    assert not re.search(rb"\d,\d+e", c_bytes)
    msgs = json.loads(c.stdout)
    assert "accepted" not in msgs[str({"vimp": "0,3"})]  # a comma is no decimal point in any locale


def test_library_sources_format_numbers_locale_free():
    """Every number text in the library goes through gw_locale.h: a bare strtod or
    printf-family call would depend on the caller's locale again."""
    bare = re.compile(r"(?<![\w])(strtod|strtof|atof|sprintf|snprintf|vsnprintf|fprintf|printf|vfprintf)\s*\(")
    found = []
    for d in ("common", "chain", "layer", "app/lib"):
        for f in sorted((REPO / d).rglob("*.[ch]")):
            if f.name.startswith("gw_locale."):
                continue
            for k, line in enumerate(f.read_text().splitlines(), 1):
                code = line.split("//")[0]
                if bare.search(code) and not code.lstrip().startswith(("*", "/*")):
                    found.append(f"{f.relative_to(REPO)}:{k}: {line.strip()}")
    assert not found, "\n".join(found)


def test_umask_and_chdir_are_the_callers(tmp_path):
    """Before: the library's files were 0644 whatever the umask (os.umask(0o077)
    gave world-readable samples). A relative path is the caller's cwd after
    os.chdir, the umask the one in force at the call."""
    code = (
        "import os, stat, sys, granwave\n"
        "os.chdir(sys.argv[1]); os.mkdir('sub'); os.chdir('sub')\n"
        "os.umask(0o077); granwave.layer_make(n=20, width_rm=10, seed=1, out='a b.txt')\n"
        "os.umask(0o002); granwave.layer_make(n=20, width_rm=10, seed=1, out='c.txt')\n"
        "print(oct(stat.S_IMODE(os.stat('a b.txt').st_mode)), oct(stat.S_IMODE(os.stat('c.txt').st_mode)))\n")
    r = _child(code, [str(tmp_path)])
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["0o600", "0o664"]
    assert (tmp_path / "sub" / "a b.txt").is_file() and not (tmp_path / "a b.txt").exists()
