#!/usr/bin/env python3
"""bench/sensor_end_grid.py GRANWAVE [JOBS]: how often a column on a sensor body's
spring ends its default run before its last contact. Run by hand, never by ctest.

Over n x sensor mass x sensor stiffness, each case runs twice with GRANWAVE:
  default    `chain --n N --sensor-mass M --sensor-stiffness K --json --quiet`
  reference  the same with --t-max 400 times the collision's expected length
             (20 times the default t-max of the code before the forty-first
             session), the same sampling: the same run, longer (a column
             whose bead 1 chatters on a light body is chaotic: --n 5
             --sensor-mass 1e-4 --sensor-stiffness 1e3 ends with eps_eff
             0.9923, 0.9947 and 0.9894 at three dt-out)
The last contact is the reference's latest opening (its detach times and
tau_N). A default run fails when it did not converge (cut at its t-max) or
ended before that last contact. Prints one line a case and the tally.
The grid: GRID_N, GRID_M, GRID_K (comma lists) in the environment override it.

Measured (n 1, 2, 3, 5, 10, 20, 40 x M 1e-4, 1e-3, 1e-2, 3e-2, 0.1 kg x k_s 1e3,
1e4, 1e6 N/m): the code before, 25 of 105 default runs cut before their last
contact (one case refused at the reference's t-max; the latest last contact
355 expected lengths, 17 default t-max). Now 23 of those 25 end at the
reference's last contact (three past what the reference reached); 2 stop at
their t-max with a warning naming the pair and its meeting, beyond the bound
(--n 20 --sensor-mass 0.1 --sensor-stiffness 1e3: beads 17 and 18 at 758 s;
--n 40 --sensor-mass 0.1 --sensor-stiffness 1e4: beads 13 and 14 at 32 s).
"""
import concurrent.futures
import json
import math
import os
import subprocess
import sys

PROG = sys.argv[1]
JOBS = int(sys.argv[2]) if len(sys.argv) > 2 else 2


def grid(name, default):
    v = os.environ.get(name)
    return [float(x) for x in v.split(",")] if v else default


NS = [int(x) for x in grid("GRID_N", [1, 2, 3, 5, 10, 20, 40])]
MS = grid("GRID_M", [1e-4, 1e-3, 1e-2, 3e-2, 1e-1])
KS = grid("GRID_K", [1e3, 1e4, 1e6])


def run(args, cpu=300):
    p = subprocess.run(["bash", "-c", 'ulimit -t %d; exec "$@"' % cpu, "run", PROG, "chain", *args,
                        "--json", "--quiet"], capture_output=True, text=True)
    if p.returncode != 0:
        return {"error": (p.stderr.strip() or "exit %d" % p.returncode)[:200]}
    return json.loads(p.stdout)


def last_contact(d):
    ts = [t for t in (d.get("detach_times") or []) if t is not None]
    if d.get("tau_n") is not None:
        ts.append(d["tau_n"])
    return max(ts) if ts else float("nan")


def case(n, m, k):
    a = ["--n", str(n), "--sensor-mass", repr(m), "--sensor-stiffness", repr(k)]
    d = run(a)
    if "error" in d:
        return (n, m, k, "error", d["error"], None)
    # the collision's expected length (chain_collision_length); the code
    # before used 20 of it as its default t-max
    cf = d["closed_forms"]
    ride = math.pi * math.sqrt((n * d["settings"]["model"]["mass"] + m) / k)
    t_col = n * cf["t_q"] + cf["tau_1"] + ride
    ref = run(a + ["--t-max", repr(400 * t_col)], cpu=900)
    if "error" in ref:
        return (n, m, k, "referror", ref["error"], d)
    last = last_contact(ref)
    fail = not d["converged"] or d["t_end"] < last * (1 - 1e-9)
    info = {"t_col": t_col, "def_t_end": d["t_end"], "def_t_max": d["settings"]["solver"]["t_max"],
            "def_conv": d["converged"], "def_warn": d["warnings"], "ref_conv": ref["converged"],
            "ref_t_end": ref["t_end"], "last": last, "last_over_tcol": last / t_col,
            "ref_energy": ref["energy_error"], "def_eps": d["eps_eff"], "ref_eps": ref["eps_eff"]}
    return (n, m, k, "FAIL" if fail else "ok", info, None)


def main():
    cases = [(n, m, k) for n in NS for m in MS for k in KS]
    fails = total = undecided = 0
    worst = 0.0
    with concurrent.futures.ThreadPoolExecutor(JOBS) as ex:
        for n, m, k, status, info, _ in ex.map(lambda c: case(*c), cases):
            total += 1
            if status in ("error", "referror"):
                print("%3d %-7g %-7g %s %s" % (n, m, k, status, info), flush=True)
                fails += status == "error"
                continue
            fails += status == "FAIL"
            undecided += not info["ref_conv"]
            worst = max(worst, info["last_over_tcol"])
            print("%3d %-7g %-7g %-4s default end %.6g s (conv %s, t-max %.4g) ref end %.6g s (conv %s) last "
                  "contact %.6g s = %.3g t_col; eps %s / %s%s" %
                  (n, m, k, status, info["def_t_end"], info["def_conv"], info["def_t_max"], info["ref_t_end"],
                   info["ref_conv"], info["last"], info["last_over_tcol"], info["def_eps"], info["ref_eps"],
                   "; " + info["def_warn"][0][:120] if info["def_warn"] else ""), flush=True)
    print("%d of %d default runs end before the last contact (or are cut); %d references undecided; latest last "
          "contact %.3g expected lengths" % (fails, total, undecided, worst))


main()
