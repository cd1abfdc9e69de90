"""The library's checks of the layer's inputs, without a run: what
layer_impact, layer_make and a layer sweep's case refuse before they run,
through the C calls that refuse it (gw_layer_impact_setup_check,
gw_layer_make_plan, a sweep's check pass over one case
gw_sweep_case_check_pass). Each
returns None when the inputs pass and raises what the run raises when they do
not: the same exception and the same text, the library's message byte for
byte with the call's inputs named by their keywords (keyword_text), as the
program prints it after "granwave CMD: " with its flags. Nothing is run,
nothing written.
"""
import ctypes

from . import _lib
from ._errors import GW_EINVAL, GranwaveValueError, _raise
from ._lib import lib
from ._values import _line, _show, _texts

_lib._declare("gw_layer_impact_setup_check", ctypes.c_int, ctypes.c_void_p, ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_layer_impact_setup_settling", ctypes.c_int, ctypes.c_void_p, ctypes.POINTER(ctypes.c_double),
              ctypes.c_char_p, ctypes.c_size_t, ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_layer_make_plan", ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p,
              ctypes.POINTER(_lib.GwErr))
_lib._declare("gw_sweep_case_check_pass", ctypes.c_int, ctypes.POINTER(_lib.GwSweepModel), ctypes.c_int,
              ctypes.POINTER(ctypes.c_char_p), ctypes.POINTER(ctypes.c_char_p), ctypes.c_void_p,
              ctypes.POINTER(_lib.GwErr))


def _setup_check(study, kwargs, call):
    """Set kwargs on the study's setup (the run's keyword checks, its
    refusals) and hand it to call(setup, err); a status other than 0 is raised
    as the run raises it."""
    buf = study.setup(kwargs)
    err = _lib.GwErr()
    try:
        rc = call(buf, err)
    finally:
        study.st.clear(buf)
    if rc != 0:
        _raise(rc, err, study.func, study.names, _texts(kwargs.values()))


def layer_impact_check(study, kwargs):
    # the rows, the sample read and checked (gw_layer_impact_check's form and
    # limits), and the resolution against it under the setup's material
    # (gw_layer_impact_check_with's side walls, the rest and settled checks,
    # the gap and step checks): what gw_layer_impact_run refuses before it runs
    _setup_check(study, kwargs, lambda buf, err: lib.gw_layer_impact_setup_check(buf, ctypes.byref(err)))


def layer_impact_settling(study, kwargs):
    # gw_layer_impact_setup_settling: layer_impact_check's checks, then the
    # settling verdict the run takes (the load ratio, the result's warning)
    from ._errors import keyword_text
    q = ctypes.c_double()
    w = ctypes.create_string_buffer(1024)
    _setup_check(study, kwargs, lambda buf, err: lib.gw_layer_impact_setup_settling(
        buf, ctypes.byref(q), w, len(w), ctypes.byref(err)))
    text = w.value.decode(errors="replace")
    return {"load_ratio": q.value,
            "warning": keyword_text(text, study.names, _texts(kwargs.values())) if text else None}


def layer_make_check(study, kwargs):
    # gw_layer_make_plan: the rows, the rules between them, the out path tried
    # (never written) and the material (gw_layer_params_validate)
    lp = ctypes.create_string_buffer(lib.gw_struct_size(b"gw_layer_params"))
    mp = ctypes.create_string_buffer(lib.gw_struct_size(b"gw_layer_make_params"))
    _setup_check(study, kwargs, lambda buf, err: lib.gw_layer_make_plan(buf, lp, mp, ctypes.byref(err)))


def sweep_case_check(model, params):
    """One case of a sweep model (its keys and values as a sweep's config
    gives them) through the sweep's own check pass over a sweep of that one
    case (gw_sweep_case_check_pass): the model's check of the case and the
    pass's verdict over its cases as a whole (a chain key of no effect in
    every case: n = 1 with k passed the case's check alone, and the sweep of
    it was refused)."""
    from . import _sweep
    models = _sweep.sweep_models()
    if not isinstance(model, str):
        raise TypeError(f"sweep_case_check(): model must be a str ({', '.join(map(repr, models))}), not "
                        f"{type(model).__name__}")
    if model not in models:
        raise GranwaveValueError(f"sweep: unknown model {_show(model)} ({', '.join(models)})", GW_EINVAL)
    m = models[model]
    names, values = [], []
    for k, v in params.items():
        if v is None:
            continue
        if not isinstance(k, str):
            raise TypeError(f"sweep_case_check(): a key is a keyword name (str), got {type(k).__name__}")
        name = k.replace("_", "-")
        if not _sweep._model_has(m, name):
            raise TypeError(f"sweep_case_check() got an unexpected keyword argument '{_line(k)}' "
                            f"(not a parameter of model {model}){_sweep._sweep_hint(model, m, k)}")
        if name in names:
            raise TypeError(f"sweep_case_check(): '{_line(k)}' names a parameter given already")
        try:
            text = _sweep._ini_value(k, v, _sweep._sweep_rows(model, m, k))
        except TypeError as e:
            raise TypeError(f"sweep_case_check(): '{_line(k)}': {e}") from None
        except GranwaveValueError as e:
            raise _sweep._in_section(e, "params") from None
        names.append(name)
        values.append(text)
    n = len(names)
    cn = (ctypes.c_char_p * max(n, 1))(*[x.encode() for x in names])
    cv = (ctypes.c_char_p * max(n, 1))(*[x.encode(errors="surrogateescape") for x in values])
    err = _lib.GwErr()
    rc = lib.gw_sweep_case_check_pass(ctypes.pointer(m), n, cn, cv, None, ctypes.byref(err))
    if rc != 0:
        _raise(rc, err, "sweep", _sweep._sweep_names(model, m), _texts(list(params.values())))
