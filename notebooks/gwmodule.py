"""gwmodule: what the layer notebooks need around the Python module granwave.

No physics lives here: every number comes from libgranwave through the module
(python/granwave). Lengths in R_m, angles in degrees, as the module returns them.

    granwave_module()            import granwave from ../python (GRANWAVE_LIB is honoured; else
                                 the library beside $GRANWAVE's program, build/lib/)
    write_sweep_table(path, res, grid, params)
                                 a granwave.sweep("layer", ...) result as the table
                                 `granwave sweep` writes (OUT/results.csv), for
                                 granwave.layer_stats, which reads a file
    diagrams(st)                 the bouncing-occurrence diagrams of a granwave.layer_stats
                                 result as dicts shaped like `granwave layer-stats --json`
                                 "diagrams" (cells as a [R_b, H] share matrix, the boundary
                                 as a list of points, the B.31 fit with its curve)

The table is byte-for-byte the program's apart from its first comment line and
the rows' checksums: values are written with repr() (the shortest text that
reads back as the same double; the program writes %.17g, which reads back as
the same double too), so layer_stats sees the same numbers.
"""

import ctypes
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

__all__ = ["granwave_module", "write_sweep_table", "diagrams"]

_BOUNDARY_KINDS = ("cross", "above", "below", "inverted")  # the module's kind 0..3


def granwave_module():
    """The module granwave from the checkout's python/. Its library: $GRANWAVE_LIB; else, when
    $GRANWAVE names a program whose build tree holds lib/libgranwave.so, that one (the test of the
    notebooks sets GRANWAVE to the binary under test); else the module's own search (build/lib)."""
    gw = os.environ.get("GRANWAVE")
    if not os.environ.get("GRANWAVE_LIB") and gw:
        lib = os.path.join(os.path.dirname(os.path.abspath(gw)), "lib", "libgranwave.so")
        if os.path.exists(lib):
            os.environ["GRANWAVE_LIB"] = lib
    py = os.path.normpath(os.path.join(HERE, "..", "python"))
    if py not in sys.path:
        sys.path.insert(0, py)
    import granwave
    return granwave


def _text(v):
    if isinstance(v, float):
        return "nan" if math.isnan(v) else repr(v)
    return str(v)


def _grid_text(v):
    """A grid value as the program's sweep writes it: an integral one without its '.0' (the module's
    arrays hold floats; layer_stats refuses point '0.0' as a sweep config does, an integer key)."""
    return int(v) if isinstance(v, float) and v.is_integer() and abs(v) < 1e15 else v


def write_sweep_table(path, res, grid, params, model="layer"):
    """Write res (granwave.sweep(model, grid, **params)) to path with the columns of
    `granwave sweep`: '# param' lines for params (layer_stats reads rb-rm and alpha
    there when they are not grid keys), then case, the grid keys, the model's columns."""
    gw = granwave_module()
    keys = [k.replace("-", "_") for k in grid]  # the module's keyword names
    # the model's columns: every per-case array (not ncases, not the warnings' list)
    cols = [k for k in res if k not in keys and k not in ("ncases", "warnings")]
    with open(path, "w") as f:
        f.write(f"# granwave {gw.version()} sweep, model {model}, {res['ncases']} cases "
                f"(granwave.sweep in memory)\n")
        for k, v in params.items():
            f.write(f"# param {k.replace('_', '-')} = {_text(v)}\n")
        f.write(",".join(["case"] + [k.replace("_", "-") for k in keys] + cols) + "\n")
        for i in range(res["ncases"]):
            cells = [str(i)] + [_text(_grid_text(res[k][i].item())) for k in keys] + [_text(float(res[c][i])) for c in cols]
            f.write(",".join(cells) + "\n")
    return path


class _B31(ctypes.Structure):
    """Mirror of gw_stats_b31 (common/stats/gw_stats.h)."""
    _fields_ = [("offset", ctypes.c_double), ("beta", ctypes.c_double), ("a_over_b", ctypes.c_double),
                ("tan_gamma", ctypes.c_double)]


def _b31_curve(row, x0, x1, n=201):
    """The library's B.31 (gw_stats_b31_eval) at n points over [x0, x1], as the program's JSON curve."""
    gw = granwave_module()
    f = gw._clib.gw_stats_b31_eval
    f.argtypes, f.restype = [ctypes.POINTER(_B31), ctypes.c_double], ctypes.c_double
    p = _B31(row["offset"], row["beta"], row["a_over_b"], row["tan_gamma"])
    xs = [x0 + (x1 - x0) * i / (n - 1) for i in range(n)]
    return {"rb_rm": xs, "h": [f(ctypes.byref(p), x) for x in xs]}


def _none(v):
    """NaN -> None, an integral value -> int: what json.loads gives for the program's numbers."""
    v = float(v)
    if math.isnan(v):
        return None
    return int(v) if v.is_integer() and abs(v) < 1e15 else v


def diagrams(st):
    """The diagrams of a granwave.layer_stats result, keys as the program's JSON (NaN -> None)."""
    out = []
    D, C, B = st["diagrams"], st["cells"], st["boundary"]
    for i in range(st["ndiagrams"]):
        row = {k: D[k][i] for k in D}
        d = {"keys": {} if st["ndiagrams"] == 1 else {"diagram": i}}
        if row["ok"] != 1:
            d["error"] = "no diagram (layer_stats: ok = 0)"
            out.append(d)
            continue
        m = C["diagram"] == i
        xs = [_none(x) for x in sorted(set(C["rb_rm"][m].tolist()))]
        hs = [_none(h) for h in sorted(set(C["height_rm"][m].tolist()))]
        share = [[math.nan] * len(hs) for _ in xs]
        pen = [[math.nan] * len(hs) for _ in xs]
        for x, h, s, p in zip(C["rb_rm"][m], C["height_rm"][m], C["share"][m], C["penetration_rm"][m]):
            share[xs.index(x)][hs.index(h)] = float(s)
            pen[xs.index(x)][hs.index(h)] = float(p)
        d.update(rb_rm=xs, height_rm=hs, share=share, penetration_rm=pen)
        mb = B["diagram"] == i
        d["boundary"] = [{"rb_rm": _none(B["rb_rm"][j]), "kind": _BOUNDARY_KINDS[int(B["kind"][j])],
                          **{k: _none(B[k][j]) for k in ("h_star", "h_lo", "h_hi", "share_lo", "share_hi",
                                                         "changes", "penetration_rm", "b31")}}
                         for j in range(len(mb)) if mb[j]]
        for k in ("r_crit", "r_crit_upper", "r_min", "h_min", "penetration_rm_boundary", "ncross"):
            d[k] = _none(row[k])
        if row["fit_ok"] == 1:
            fit = {k: _none(row[k]) for k in ("offset", "beta", "beta_err", "a_over_b", "a_over_b_err",
                                             "tan_gamma", "tan_gamma_err", "gamma_deg", "a", "b", "x_min",
                                             "h_min_fit", "rms_residual")}
            fit.update(n_fit=int(row["n_fit"]), dof=int(row["dof"]),
                       fixed=[k for k in ("offset", "beta", "a_over_b", "tan_gamma") if row[k + "_err"] == 0],
                       curve=_b31_curve(row, xs[0], xs[-1]))
            d["fit"] = fit
        else:
            d["fit_reason"] = "not fitted (layer_stats: fit_ok = 0)"
        out.append(d)
    return out
