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
- gw_sweep_run, gw_chain_drop_run, gw_chain_disp_run and
  gw_layer_sample_write (given a path) dereferenced a NULL argument (SIGSEGV) where gw_sweep_run_text and gw_chain_collide refuse it
  with GW_EINVAL and a line naming the call and the argument. Each is called
  in a child process here, so that a crash fails the check, not the session.
- gw_layer_sample_write, which says it refuses what the reader refuses, wrote
  a sample of two discs at one place (overlap 2 R_p) that gw_layer_sample_read
  and every command then refused: it runs the reader's overlap check too.
"""
import ctypes
import json
import os
import subprocess
import sys
import warnings

import pytest

import granwave
from sample_mirror import _Sample  # the struct's mirror, shared

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
    _null_call(name, f"[ctypes.c_void_p(0)] * ({nargs} - 1)", arg)


def test_sample_write_null_sample_refused(tmp_path):
    """gw_layer_sample_write(NULL, path): the path was checked, then the
    sample read (SIGSEGV)."""
    _null_call("gw_layer_sample_write", f"[None, {str(tmp_path / 's.txt').encode()!r}, None]", "s")
    assert not (tmp_path / "s.txt").exists()


# void calls given NULL: nothing to return, nothing done (they dereferenced it: SIGSEGV)
_NULL_VOID_CALLS = [
    ("gw_chain_trace_init", "[None, ctypes.c_int(3)]"),
    ("gw_thornton_init", "[None, ctypes.c_double(1e11), ctypes.c_double(1e-3), ctypes.c_double(1e8)]"),
]


@pytest.mark.parametrize("name, args", _NULL_VOID_CALLS)
def test_null_void_calls_no_crash(name, args):
    lib = granwave.library_path
    code = f"""
import ctypes
lib = ctypes.CDLL({lib!r})
f = getattr(lib, {name!r})
f.restype = None
f(*{args})
print("done")
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0 and p.stdout.strip() == "done", (name, p.returncode, p.stderr[-300:])


def _null_call(name, args, arg):
    """name(*args, err) in a child interpreter: -1 and 'NAME: ARG is NULL'."""
    lib = granwave.library_path
    code = f"""
import ctypes
lib = ctypes.CDLL({lib!r})
err = ctypes.create_string_buffer(4096)
f = getattr(lib, {name!r})
f.restype = ctypes.c_int
args = {args} + [ctypes.cast(err, ctypes.c_void_p)]
print(f(*args), err.value.decode())
"""
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, (name, p.returncode, p.stderr[-300:])
    assert p.stdout.strip() == f"-1 {name}: {arg} is NULL", p.stdout


def test_sample_mirror_is_the_library_size():
    lib = ctypes.CDLL(granwave.library_path)
    lib.gw_layer_sample_size.restype = ctypes.c_size_t
    assert ctypes.sizeof(_Sample) == lib.gw_layer_sample_size()


@pytest.mark.parametrize("x0, written", [(0.1, False), (0.3, True)])
def test_sample_write_refuses_what_the_reader_refuses(tmp_path, x0, written):
    """gw_layer_sample_write says it refuses a sample that fails the reader's
    checks; two discs at one place (overlap 2 R_p) were written all the same
    and then refused by gw_layer_sample_read. Touching discs are written."""
    lib = ctypes.CDLL(granwave.library_path)
    lib.gw_layer_sample_size.restype = ctypes.c_size_t
    assert ctypes.sizeof(_Sample) == lib.gw_layer_sample_size()  # before the library writes one
    d = lambda v: (ctypes.c_double * 3)(*v)  # noqa: E731
    s = _Sample(n=3, width=1.0, rm=0.1, volume_ratio=0, porosity=float("nan"), seed=0, mass_law=0, clump_mass=0,
                x=d([0.1, x0, 0.5]), y=d([0.1, 0.1, 0.1]), r=d([0.1, 0.1, 0.1]), body=None)
    err = ctypes.create_string_buffer(512)
    for name in ("s.txt", "s.h5"):
        path = tmp_path / name
        rc = lib.gw_layer_sample_write(ctypes.byref(s), str(path).encode(), None, err)
        if written:
            assert rc == 0 and path.exists(), err.value
            back = _Sample()
            assert lib.gw_layer_sample_read(str(path).encode(), ctypes.byref(back), err) == 0, err.value
            lib.gw_layer_sample_free(ctypes.byref(back))
        else:
            assert rc == -1 and not path.exists(), (rc, err.value)
            assert b"particles 0 and 1 overlap by 2 R_p" in err.value, err.value
