"""The twenty-ninth hostile pass over the Python module and the library's C
interface (tests/test_hostile_twentyninth.sh holds the program's side).

- A layer sample of fine grains at the default skin (0.1 m: about a thousand
  1 mm grains within it) grew its contact list until the allocation failed
  (20000 grains: 2e8 pairs, some 40 GB with their state): layer_impact and a
  sweep over it raised "out of memory" after the memory was gone, or the
  kernel killed the interpreter. The list stops at 8 pairs a particle (at
  least 1e7) and the call raises GranwaveValueError naming skin at once.
- layer_stats read a table keyed rb_rm, height_rm (the '_' spelling a sweep
  config may give) as grid keys like any other: no diagram, every binary row
  under the default R_b/R_m = 1. It reads them as rb-rm and height-rm now.
- gw_sweep_run, gw_chain_drop_run and gw_chain_disp_run dereferenced a NULL
  argument (SIGSEGV) where gw_sweep_run_text and gw_chain_collide refuse it
  with GW_EINVAL and a line naming the call and the argument. Each is called
  in a child process here, so that a crash fails the check, not the session.
"""
import ctypes
import json
import os
import subprocess
import sys
import warnings

import pytest

import granwave

pytestmark = pytest.mark.filterwarnings("ignore::granwave.GranwaveWarning")


@pytest.fixture(scope="module")
def fine(tmp_path_factory):
    """20000 touching discs of radius 0.5 mm, 200 a row."""
    path = tmp_path_factory.mktemp("fine") / "fine.txt"
    n, nx, r = 20000, 200, 0.0005
    with open(path, "w") as f:
        f.write("granwave-layer-sample 1\nwidth %.17g\nrm %.17g\nvolume_ratio 1\nseed 0\nmass_law disc\nn %d\n"
                % (nx * 2 * r, r, n))
        for i in range(n):
            f.write("%.17g %.17g %.17g\n" % ((i % nx) * 2 * r + r, (i // nx) * 2 * r + r, r))
    return path


def _in_child(code):
    """Run code in a fresh interpreter under a 2 GiB address space (the list
    before the fix went on for tens of GB); its stdout, its exit status."""
    env = dict(os.environ)
    pre = "import resource; resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))\n"
    p = subprocess.run([sys.executable, "-c", pre + code], capture_output=True, text=True, timeout=120, env=env)
    return p.stdout.strip(), p.returncode


def test_fine_grains_at_the_default_skin_name_the_skin(fine):
    out, rc = _in_child(f"""
import granwave, warnings
warnings.simplefilter("ignore")
for call in (lambda: granwave.layer_impact(sample={str(fine)!r}, t_max=1e-4, until="verdict"),
             lambda: granwave.sweep("layer", grid={{"vi": [20, 30]}}, sample={str(fine)!r}, t_max=1e-4,
                                    until="verdict", jobs=1)):
    try:
        call()
        print("ran")
    except granwave.GranwaveValueError as e:
        print("skin" if "skin: 0.1 m lists more than 10000000 pairs of the 20001 particles" in str(e) else str(e))
    except Exception as e:
        print(type(e).__name__, e)
""")
    assert rc == 0 and out.split("\n") == ["skin", "skin"], (rc, out)


def test_fine_grains_with_a_skin_of_their_size_run(fine):
    r = granwave.layer_impact(sample=str(fine), t_max=1e-4, until="verdict", skin=1e-4)
    assert r.v_ni == 20


def test_layer_stats_reads_rb_rm_as_rb_minus_rm(tmp_path):
    sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))
    import synthetic_tables
    dash = tmp_path / "dash.csv"
    synthetic_tables.write_bouncing_diagram(str(dash))
    text = dash.read_text().replace("case,rb-rm,height-rm,", "case,rb_rm,height_rm,")
    under = tmp_path / "under.csv"
    under.write_text(text)
    a, b = granwave.layer_stats(str(dash)), granwave.layer_stats(str(under))
    assert len(b.diagrams["r_crit"]) == len(a.diagrams["r_crit"]) == 1
    assert list(b.binary["rb_rm"]) == list(a.binary["rb_rm"]) == [0.5, 1, 1.5, 2, 3, 4]


# (call, argument types, the NULL argument named)
_NULL_CALLS = [
    ("gw_sweep_run", 7, "cfg"),
    ("gw_chain_drop_run", 4, "p"),
    ("gw_chain_disp_run", 5, "p"),
]


@pytest.mark.parametrize("name, nargs, arg", _NULL_CALLS)
def test_null_arguments_refused(name, nargs, arg):
    lib = granwave.library_path
    code = f"""
import ctypes
lib = ctypes.CDLL({lib!r})
err = ctypes.create_string_buffer(4096)
f = getattr(lib, {name!r})
f.restype = ctypes.c_int
args = [ctypes.c_void_p(0)] * ({nargs} - 1) + [ctypes.cast(err, ctypes.c_void_p)]
print(f(*args), err.value.decode())
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, (name, p.returncode, p.stderr[-300:])
    assert p.stdout.strip() == f"-1 {name}: {arg} is NULL", p.stdout
