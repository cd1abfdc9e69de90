"""The ctypes mirror of gw_layer_sample (layer/gw_layer.h) that the Python
tests calling the library's layer functions directly share
(test_hostile_pass41, test_hostile_twentyninth_py): one copy to keep in step
with the struct. Each test checks its size against gw_layer_sample_size before
the library writes one."""
import ctypes


class _Settled(ctypes.Structure):
    """gw_layer_settled (layer/gw_layer.h)."""
    _fields_ = [("recorded", ctypes.c_int), ("shear_modulus", ctypes.c_double), ("poisson", ctypes.c_double),
                ("friction_deg", ctypes.c_double), ("density", ctypes.c_double), ("gravity", ctypes.c_double),
                ("mass_law", ctypes.c_int), ("line", ctypes.c_long), ("clump_mass", ctypes.c_int)]


class _Sample(ctypes.Structure):
    """gw_layer_sample (layer/gw_layer.h). Its size is checked against the
    library's (gw_layer_sample_size) before gw_layer_sample_read writes one:
    this mirror without the appended settled record was written 72 bytes past
    its end, which corrupted the interpreter's heap and crashed later tests of
    the same session (a segfault in test_hostile_twentyseventh_py's
    layer_impact or in the garbage collector). ABI 2 appended the springs."""
    _fields_ = [("n", ctypes.c_int), ("width", ctypes.c_double), ("rm", ctypes.c_double),
                ("volume_ratio", ctypes.c_double), ("porosity", ctypes.c_double), ("seed", ctypes.c_long),
                ("mass_law", ctypes.c_int), ("clump_mass", ctypes.c_int), ("x", ctypes.POINTER(ctypes.c_double)),
                ("y", ctypes.POINTER(ctypes.c_double)), ("r", ctypes.POINTER(ctypes.c_double)),
                ("body", ctypes.POINTER(ctypes.c_int)), ("content_hash", ctypes.c_ulonglong),
                ("settled", _Settled), ("n_springs", ctypes.c_int), ("springs", ctypes.c_void_p),
                ("settled_converged", ctypes.c_int)]
