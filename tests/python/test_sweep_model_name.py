"""granwave.sweep's unknown model is named in one line (the thirtieth hostile
pass, issue 18): the name was put in the message as it was, so a model with a
newline or a control character ('chain\\n', read from a file with its line end)
gave a message over two lines with the character unseen. It is quoted as
repr now ('chain\\n'), as the module quotes every other value it names back;
an ordinary misspelling reads as before ('chian'). On the module before, 2 of
the 3 tests fail (the plain misspelling passes).
"""
import pytest

import granwave


@pytest.mark.parametrize("model,shown", [("chain\n", r"'chain\n'"), ("la\tyer", r"'la\tyer'")])
def test_control_characters_quoted(model, shown):
    with pytest.raises(ValueError) as e:
        granwave.sweep(model, {"n": [1]}, jobs=1)
    msg = str(e.value)
    assert "\n" not in msg and "\t" not in msg
    assert msg == f"sweep: unknown model {shown} (chain, layer)"


def test_misspelling_reads_as_before():
    with pytest.raises(ValueError, match=r"^sweep: unknown model 'chian' \(chain, layer\)$"):
        granwave.sweep("chian", {"n": [1]}, jobs=1)
