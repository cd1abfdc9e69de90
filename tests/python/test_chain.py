"""granwave.chain against the column's closed forms and laws (physics.md 1.3),
and against the program's JSON for the same inputs.

Tolerances: the collisions run at rtol = atol = 1e-12 (the defaults of
`granwave chain`), ~1e-9 accurate, so 1e-6 on the closed forms fails for any
wrong exponent or constant; the law checks use the bounds of
tests/test_chain_scaling.c (5 % spread on a rigid wall, > 5 % growth on a soft
one, Hertz scaling invariance to 1e-6); the CLI comparison is 1e-12 (same
library, same inputs: only the printing rounds)."""
import math

import numpy as np
import pytest

import granwave
from conftest import run_cli

V = 0.3


def tau_constant():
    """(4/5) B(2/5, 1/2) of (F.2), from the Gamma function."""
    return 0.8 * math.gamma(0.4) * math.gamma(0.5) / math.gamma(0.9)


def test_one_bead_closed_forms():
    r = granwave.chain(n=1, vimp=V, trace=True)
    m, K = r.mass, r.kwall
    d_max = (5 * m * V**2 / (4 * K)) ** 0.4
    tau_1 = tau_constant() * (5 * m / (4 * K)) ** 0.4 * V**-0.2
    f_max = (5 / 6) ** 0.4 * (45 / 16) ** 0.2 * m**0.6 * V**1.2 * K**0.4  # (F.13, F.14)
    assert r.f_max == pytest.approx(f_max, rel=1e-6)
    assert r.f_max == pytest.approx(K * d_max**1.5, rel=1e-6)
    assert r.tau_max == pytest.approx(tau_1 / 2, rel=1e-6)  # (F.21)
    assert r.tau_n == pytest.approx(tau_1, rel=1e-6)  # (F.2)
    assert r.x[:, 0].max() == pytest.approx(d_max, rel=1e-6)  # peak overlap (an event sample)
    assert r.final_velocities[0] == pytest.approx(-V, rel=1e-6)  # elastic rebound
    assert r.f_wall.max() == pytest.approx(r.f_max, rel=1e-9)
    assert r.t.shape == r.f_wall.shape and r.x.shape == (r.t.size, 1)


def test_fmax_independent_of_n_on_a_rigid_wall_and_not_on_a_soft_one():
    rigid = np.array([granwave.chain(n=n, vimp=V).f_max for n in range(1, 9)])
    soft = [granwave.chain(n=n, vimp=V, kwall=1e9).f_max for n in (1, 8)]
    r1 = granwave.chain(n=1, vimp=V)
    assert r1.kwall > r1.k_c and 1e9 < r1.k_c  # steel wall rigid, K = 1e9 soft (F.22)
    assert (rigid.max() - rigid.min()) / rigid.min() < 0.05
    assert soft[1] > 1.05 * soft[0]


def test_hertz_scaling_invariance():
    """x ~ v^(4/5), t ~ v^(-1/5) leave (F.11) invariant: tau_N v^(1/5) and
    F_max v^(-6/5) do not depend on v."""
    a, b = granwave.chain(n=5, vimp=0.05), granwave.chain(n=5, vimp=2.0)
    assert a.tau_n * 0.05**0.2 == pytest.approx(b.tau_n * 2.0**0.2, rel=1e-6)
    assert a.f_max * 0.05**-1.2 == pytest.approx(b.f_max * 2.0**-1.2, rel=1e-6)


def test_energy_conserved_without_damping_and_lost_with_it():
    r = granwave.chain(n=7, vimp=V)
    assert r.energy_error < 1e-8 and r.eps_col == pytest.approx(1, abs=1e-6)
    d = granwave.chain(n=1, vimp=V, damping="hc", restitution=0.8)
    assert -d.final_velocities[0] / V == pytest.approx(0.8, rel=1e-4)


def test_same_numbers_as_the_program(program):
    cli = run_cli(program, "chain", "--n", 7, "--vimp", V, "--material", "glass", "--dt-out", 1e-7)
    r = granwave.chain(n=7, vimp=V, material="glass", dt_out=1e-7)
    for key in ("f_max", "tau_max", "tau_n", "period", "e_rel_over_e_k", "eps_eff", "eps_col", "energy_error"):
        assert r[key] == pytest.approx(cli[key], rel=1e-12), key
    for key in ("n_maxima", "n_s", "cluster", "wall_contacts", "events", "steps"):
        assert r[key] == cli[key], key
    np.testing.assert_allclose(r.final_velocities, cli["final_velocities"], rtol=1e-12)
    assert r.f_max_1 == pytest.approx(cli["closed_forms"]["f_max_1"], rel=1e-12)
    assert cli["settings"]["model"]["mass"] == pytest.approx(r.mass, rel=1e-15)


def test_version(program):
    import os
    import subprocess
    v = granwave.version()
    assert v == ".".join(map(str, granwave.version_info())) == granwave.__version__
    assert subprocess.run([program, "version"], capture_output=True, text=True).stdout.split()[-1] == v
    if os.environ.get("GRANWAVE_VERSION"):
        assert v == os.environ["GRANWAVE_VERSION"]


def test_keywords_are_the_cli_flags(program):
    """Every keyword of chain() is a flag of `granwave chain` ('-' written '_'),
    except trace (the library's series), and the help text is the same: the
    row's, with the range the parser checks (", in [LO, HI]") where the row's
    text prints none."""
    import re
    import subprocess
    helptext = subprocess.run([program, "chain", "--help"], capture_output=True, text=True).stdout
    for p in granwave.params("chain"):
        if p["keyword"] == "trace":
            continue
        line = re.search(r"^  --" + re.escape(p["name"]) + r"(?: \S+)?\s+(.*)$", helptext, re.M)
        assert line, p["name"]
        added = re.sub(r", in [\[(][^\])]*[\])]( \(or 0\))?", "", line.group(1), count=1)
        assert p["help"] in (line.group(1), added), (p["name"], line.group(1))
        assert p["keyword"] == p["name"].replace("-", "_")
