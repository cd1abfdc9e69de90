"""The twenty-third hostile pass over the Python module.

A sweep key holding a NUL was taken as the name up to it: the key check asks
the library (gw_sweep_model.has_key) through a C string, which ends at the NUL,
so grid={"n\\x00x": [1]} or a keyword vimp\\x00=0.3 passed the check as n and
vimp, and the config text built from them then failed as
"sweep: sweep:4: syntax error" (a line of a text the caller never sees, naming
no keyword). Such a key is now none of the model's: the TypeError names it as
any other unknown key, for the grid and the keywords, chain and layer models,
quoted on one line as the library quotes text (the NUL as \\x00). The keys
without the NUL still run.
"""
import pytest

import granwave


@pytest.mark.parametrize("model,grid,kw,match", [
    ("chain", {"n\x00x": [1]}, {}, r"^sweep\(\) grid: 'n\\x00x' is not a parameter of model chain"),
    ("chain", {"n\x00": [1, 2]}, {}, r"^sweep\(\) grid: 'n\\x00' is not a parameter of model chain"),
    ("chain", {"n": [1]}, {"vimp\x00": 0.3}, r"^sweep\(\) got an unexpected keyword argument 'vimp\\x00'"),
    ("chain", {"n": [1]}, {"vimp\x00junk": 0.3}, r"^sweep\(\) got an unexpected keyword argument 'vimp\\x00junk'"),
    ("layer", {"vi\x00": [20]}, {"sample": "s.txt"}, r"^sweep\(\) grid: 'vi\\x00' is not a parameter of model layer"),
], ids=["grid-n-nul-x", "grid-n-nul", "keyword-vimp-nul", "keyword-vimp-nul-junk", "layer-grid-vi-nul"])
def test_a_sweep_key_with_a_nul_is_named_as_unknown(model, grid, kw, match):
    with pytest.raises(TypeError, match=match):
        granwave.sweep(model, grid, jobs=1, **kw)


def test_the_keys_without_the_nul_still_run():
    r = granwave.sweep("chain", {"n": [1, 2]}, jobs=1, vimp=0.3)
    assert r.ncases == 2 and list(r["n"]) == [1, 2] and all(f > 0 for f in r["f_max"])
