"""The twenty-fifth hostile pass over the Python module.

The module's exceptions could not be pickled back: GranwaveError(message,
status) keeps only the message in its args, and pickle and copy rebuild an
exception as type(e)(*e.args), which __init__ refused ("missing 1 required
positional argument: 'status'"). A granwave error raised in a worker process
(the natural way to run studies in parallel from Python) therefore never came
back: concurrent.futures' ProcessPoolExecutor reported "A process in the
process pool was terminated abruptly" (BrokenProcessPool, the pool unusable
after), and multiprocessing.Pool's result thread died, its get() waiting for
ever (or until a timeout). Each exception now pickles and copies as itself:
its class, message, status and any attribute set on it.

A long drop called its progress callback only every hundredth of its samples:
drop(n=1000, t_max=1) was silent for over a minute (the program's display
too: tests/test_hostile_twentyfifth.sh). It now reports after half a second.
"""
import concurrent.futures
import copy
import multiprocessing
import pickle
import time

import pytest

import granwave


def _raised(call):
    """The exception a real call raises (the library's status and text)."""
    with pytest.raises(granwave.GranwaveError) as info:
        call()
    return info.value


# one call per exception class the library raises, each as a user makes it
_CALLS = {
    "GranwaveValueError": lambda: granwave.chain(n=-1),
    "GranwaveIOError": lambda: granwave.layer_impact(sample="/nonexistent/sample.txt"),
    "GranwaveRunError": lambda: granwave.wavespeed(n="6:8", vimp=0.3, kwall=1e13, jobs=1),
}


@pytest.mark.parametrize("name", sorted(_CALLS))
def test_a_raised_error_pickles_and_copies_as_itself(name):
    e = _raised(_CALLS[name])
    assert type(e).__name__ == name
    for back in (pickle.loads(pickle.dumps(e)), copy.copy(e), copy.deepcopy(e)):
        assert type(back) is type(e)
        assert str(back) == str(e) and back.args == e.args
        assert back.status == e.status


@pytest.mark.parametrize("cls", [granwave.GranwaveError, granwave.GranwaveValueError, granwave.GranwaveIOError,
                                 granwave.GranwaveRunError, granwave.GranwaveUnsupported])
def test_every_error_class_keeps_its_attributes(cls):
    e = cls("chain: n: made here", -6)
    e.note = [1, 2]  # an attribute a caller adds (pickled by its __dict__, as any exception's)
    back = pickle.loads(pickle.dumps(e, protocol=pickle.HIGHEST_PROTOCOL))
    assert type(back) is cls and str(back) == "chain: n: made here"
    assert back.status == -6 and back.note == [1, 2]


def _bad_chain(n):
    return granwave.chain(n=n)


def test_an_error_in_a_process_pool_worker_comes_back():
    ctx = multiprocessing.get_context("fork")
    with concurrent.futures.ProcessPoolExecutor(1, mp_context=ctx) as ex:
        with pytest.raises(granwave.GranwaveValueError, match=r"^chain: n: -1 is outside") as info:
            ex.submit(_bad_chain, -1).result(timeout=60)
        assert info.value.status == -1
        # the pool still works after it (it was broken)
        assert ex.submit(_bad_chain, 1).result(timeout=60)["n"] == 1


def test_an_error_in_a_multiprocessing_pool_comes_back():
    with multiprocessing.get_context("fork").Pool(1) as pool:
        with pytest.raises(granwave.GranwaveValueError, match=r"^chain: n: -1 is outside"):
            pool.apply_async(_bad_chain, (-1,)).get(timeout=30)


def test_a_long_drop_reports_its_progress_within_seconds():
    """The library reported a drop's progress every hundredth of its samples
    only: drop(n=1000, t_max=1) (about two hours) called progress after more
    than a minute. It now also reports after half a second of wall time."""
    class Stop(Exception):
        pass

    calls = []
    t0 = time.monotonic()

    def progress(done, total):
        calls.append((time.monotonic() - t0, done, total))
        raise Stop  # ends the call: nothing else is needed of it

    with pytest.raises(Stop):
        granwave.drop(n=1000, t_max=1, progress=progress)
    assert len(calls) == 1
    waited, done, total = calls[0]
    # the report is due 0.5 s of wall time into the run, whatever the load;
    # a hundredth of the samples takes over a minute
    assert waited < 10, f"the first report came after {waited:.1f} s"
    assert total == 2 * 1000000 and 0 < done < total // 100
