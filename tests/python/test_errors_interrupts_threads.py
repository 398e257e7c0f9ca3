# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Refusals are the command line's (in the module's words), Ctrl+C stops a computation, threads compute at once."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import grazelab as gl


@pytest.mark.parametrize("call,flags", [
    (lambda: gl.simulate(m2=-1), ["simulate", "--m2", "-1"]),
    (lambda: gl.simulate(glo=0.5, state=(0, 0, 0, 0)), ["simulate", "--glo", "0.5", "--state=0,0,0,0"]),
    (lambda: gl.simulate(contacts="many"), ["simulate", "--contacts", "many"]),
    (lambda: gl.map(x="u1:-1:1:4", y="v1:-1:1:4", precision="quad"),
     ["map", "--x", "u1:-1:1:4", "--y", "v1:-1:1:4", "--precision", "quad", "--out", "/tmp/never"]),
    (lambda: gl.map(x="nonsense:0:1:4", y="v1:-1:1:4"),
     ["map", "--x", "nonsense:0:1:4", "--y", "v1:-1:1:4", "--out", "/tmp/never"]),
    (lambda: gl.orbit(onepp=1e9), ["orbit", "--onepp", "--period", "1000000000"]),
    (lambda: gl.orbit(impacts=2, energy=-1, guess=(0, 0)),
     ["orbit", "--impacts", "2", "--energy", "-1", "--guess=0,0"]),
    (lambda: gl.modes(max_impacts=0), ["modes", "--max-impacts", "0", "--out", "/tmp/never"]),
    (lambda: gl.info(m1=0), ["info", "--m1", "0"]),
])
def test_invalid_input_raises_value_error_with_the_cli_message(cli, call, flags):
    done = cli(*flags)
    assert done.returncode == 2 and done.stdout == ""
    cli_line = done.stderr.strip().splitlines()[-1]
    with pytest.raises(ValueError) as raised:
        call()
    # the same line, its options named by their keywords (--max-impacts: max_impacts)
    assert gl._convert.keywords_of_options(cli_line) == "grazelab-cli: " + str(raised.value)
    assert "--" not in str(raised.value)
    assert not os.path.exists("/tmp/never.json")


def test_python_only_refusals_are_value_errors():
    with pytest.raises(ValueError, match="GB in memory"):
        gl.simulate(contacts=10**9)


def test_functions_have_python_signatures_and_refuse_what_is_not_theirs():
    import inspect
    simulate = inspect.signature(gl.simulate).parameters
    assert simulate["m2"].default == 0.5 and simulate["trust"].default == "auto"
    assert simulate["t_end"].kind is inspect.Parameter.KEYWORD_ONLY
    assert inspect.signature(gl.map).parameters["trust"].default == "off"
    assert "mass 2" in gl.simulate.__doc__ and "{chain}" not in gl.simulate.__doc__
    # a keyword that is not the function's: TypeError naming it, as Python's own functions do
    with pytest.raises(TypeError, match="t_ned"):
        gl.simulate(t_ned=1)
    with pytest.raises(TypeError, match="format"):
        gl.simulate(format="csv")
    with pytest.raises(TypeError, match="max_impacts"):  # another command's option
        gl.family(max_impacts=1)
    # a list where a number is expected, a bool as a number
    with pytest.raises(TypeError, match="glo"):
        gl.simulate(glo=[0.5])
    with pytest.raises(TypeError, match="expected a number"):
        gl.simulate(contacts=True, m2=True)
    # simulate's onepp is a period, on every path; quick is a flag only
    for call in (lambda: gl.simulate(onepp=True), lambda: gl.simulate(onepp=True, t_end=3),
                 lambda: gl.Chain(masses=[1, 0.5], frequencies=[2, 1]).simulate(onepp=True)):
        with pytest.raises(TypeError, match="onepp: expected a number"):
            call()
    with pytest.raises(TypeError, match="quick: expected True or False"):
        gl.report(quick=0)
    # --onepp is a bare flag of family and orbit only: elsewhere a period
    with pytest.raises(TypeError, match="onepp: expected a number"):
        gl.map(x="u1:0:1:2", y="v1:0:1:2", onepp=True)
    # a bad value: ValueError in the module's words (keywords, not the command line's flags),
    # on the direct path and on the text path alike
    for call in (lambda: gl.simulate(glo=0.5, onepp=6), lambda: gl.simulate(glo=0.5, onepp=6, t_end=3)):
        with pytest.raises(ValueError, match=r"^give one of glo, onepp, state") as raised:
            call()
        assert "--" not in str(raised.value)
    with pytest.raises(ValueError, match="^search_steps"):
        gl.simulate(search_steps=0)
    with pytest.raises(ValueError, match="describe a chain given by masses$"):
        gl.map(x="u1:0:1:2", y="v1:0:1:2", glo_weights=[1, 0])
    # the module's names only
    assert [name for name in dir(gl) if not name.startswith("_")] == sorted(
        set(gl.__all__) | {"map", "help"})


def test_text_of_other_string_types_is_its_text():
    # NumPy's str_ and a str enum read as the text they hold, on both simulate paths
    import enum

    class Precision(str, enum.Enum):
        QUAD = "quad"

    for precision in (np.str_("quad"), Precision.QUAD):
        assert gl.simulate(precision=precision, contacts=2).precision.used == "quad"
        chain = gl.Chain(masses=[1, 0.5], frequencies=[2, 1])
        assert chain.simulate(precision=precision, glo_weights=[0.5, 0.5], contacts=2).precision.used == "quad"


def test_numpy_scalars_zero_d_arrays_and_fractions_are_numbers(cli_json):
    import fractions
    import numpy as np
    assert gl.simulate(glo=np.array(0.3), contacts=3).initial == gl.simulate(glo=0.3, contacts=3).initial
    assert gl.simulate(glo=np.float64(0.3), contacts=3).initial == gl.simulate(glo=0.3, contacts=3).initial
    # a Fraction is its exact ratio: in binary128 1/3 is the nearest binary128, not 1/3 of a double
    third = gl.simulate(glo=fractions.Fraction(1, 3), contacts=2, precision="quad")
    expected = cli_json("simulate", "--glo", "0." + "3" * 40, "--contacts", "2", "--precision", "quad",
                        exact=True)
    assert third.decimal.initial == expected["initial"]


def test_a_result_reads_in_one_line_and_a_stripe_has_its_own_rows(tmp_path):
    run = gl.simulate(contacts=150)
    text = repr(run)
    assert "\n" not in text and len(text) < 1000 and "events=<array (150,)" in text
    whole = gl.map(x="u1:-1:1:4", y="v1:-1:1:6", contacts=2)
    stripe = gl.map(x="u1:-1:1:4", y="v1:-1:1:6", contacts=2, shard=(2, 3), out=tmp_path / "s")
    assert stripe.arrays["impacts"].shape == (2, 4) and len(stripe.y) == 2
    assert list(stripe.y) == list(whole.y[2:4]) and list(stripe.x) == list(whole.x)


def test_help_lists_every_function_with_its_keywords(capsys):
    gl.help()
    text = capsys.readouterr().out
    for call in ("simulate(*, m1: float = 1.0", "t_end", "map(*, x", "modes(*", "energy_range"):
        assert call in text, call


def _interrupt_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


LONG_MAP = dict(x="u1:-1.5:1.5:400", y="v1:-1:1:400", contacts=4000, threads=2)


def test_ctrl_c_stops_a_long_map_within_a_second():
    timer = _interrupt_after(0.5)
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        gl.map(**LONG_MAP)
    stopped = time.monotonic() - started - 0.5
    timer.join()
    # the map alone takes minutes; the stop is asked at most 0.1 s after the signal and the
    # points finish their current contact
    assert stopped < 1.0, f"stopped {stopped:.2f} s after Ctrl+C"


def test_ctrl_c_stops_a_long_simulation():
    timer = _interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        gl.simulate(t_end=1e9)
    timer.join()


def test_ctrl_c_stops_a_report_and_a_stability_matrix_within_a_second(tmp_path):
    # each takes a minute or more in full; stopped, nothing is written where out names
    for call in (lambda: gl.report(out=tmp_path / "r"), lambda: gl.stability(out=tmp_path / "s")):
        timer = _interrupt_after(0.5)
        started = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            call()
        stopped = time.monotonic() - started - 0.5
        timer.join()
        assert stopped < 1.0, f"stopped {stopped:.2f} s after Ctrl+C"
    assert not any(path.is_file() for path in tmp_path.rglob("*"))


def test_progress_of_report_and_stability_reaches_the_caller_in_order():
    # the calling thread hears the latest line at each wake-up (every 100 ms) and the last one at
    # the end: a short call may hear only that one, then (1.0, "done")
    for call in (gl.report, gl.stability):
        seen = []
        call(quick=True, methods="exact", progress=lambda fraction, text: seen.append((fraction, text)))
        fractions = [fraction for fraction, _ in seen if fraction is not None and fraction >= 0]
        assert len(seen) >= 2 and seen[-1] == (1.0, "done") and seen[-2][1] != "done"
        assert fractions == sorted(fractions) and all(0 <= f <= 1 for f in fractions)


def test_progress_reaches_the_caller_and_can_stop_the_computation():
    seen = []

    def progress(fraction, text):
        seen.append((fraction, text))
        if len(seen) == 3:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        gl.map(**LONG_MAP, progress=progress)
    assert len(seen) == 3
    fractions = [fraction for fraction, _ in seen]
    assert all(0 <= f <= 1 for f in fractions) and fractions == sorted(fractions)
    assert "points" in seen[0][1]


@pytest.mark.parametrize("raised", [RuntimeError("enough"), ValueError("mine")])
@pytest.mark.parametrize("call", [
    lambda progress: gl.family(count=400, progress=progress),
    lambda progress: gl.modes(max_impacts=2, progress=progress),
])
def test_a_progress_callbacks_own_exception_goes_through_family_and_modes(call, raised):
    # the typed commands' refusals are their own types: what the caller's callback raised is
    # neither renamed (a RuntimeError as OSError) nor reworded
    def progress(fraction, text):
        raise raised

    with pytest.raises(type(raised)) as caught:
        call(progress)
    assert type(caught.value) is type(raised) and str(caught.value) == str(raised)


@pytest.mark.parametrize("call", [
    lambda progress: gl.family(count=400, progress=progress),
    lambda progress: gl.modes(max_impacts=2, progress=progress),
    lambda progress: gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), t_end=4e6, trust="off",
                                 progress=progress),
])
def test_family_modes_and_simulate_report_progress(call):
    seen = []
    call(lambda fraction, text: seen.append((fraction, text)))
    assert seen and all(isinstance(text, str) and text for _, text in seen)
    assert all(f is None or 0 <= f <= 1 for f, _ in seen)


def test_progress_of_a_short_map_ends_complete():
    seen = []
    gl.map(x="u1:-1:1:40", y="v1:-1:1:40", contacts=400, progress=lambda f, t: seen.append(f))
    assert seen, "no progress reported"


def test_two_threads_compute_at_once():
    # the GIL is released while the core computes: the two runs' wall intervals overlap
    intervals = {}

    def run(name):
        started = time.monotonic()
        gl.simulate(m2=0.3, glo=0.4, perturb=(0, 0, 0, -0.02), contacts=300000, trust="off")
        intervals[name] = (started, time.monotonic())

    threads = [threading.Thread(target=run, args=(name,)) for name in "ab"]
    for thread in threads:
        thread.start()
    ticks = 0
    while any(thread.is_alive() for thread in threads):
        ticks += 1  # the calling thread runs Python meanwhile
        time.sleep(0.01)
    for thread in threads:
        thread.join()
    (a0, a1), (b0, b1) = intervals["a"], intervals["b"]
    overlap = min(a1, b1) - max(a0, b0)
    assert overlap > 0.5 * min(a1 - a0, b1 - b0), intervals
    assert ticks > 5


def test_the_events_held_in_memory_are_bounded_however_the_run_is_bounded(monkeypatch):
    monkeypatch.setattr(gl, "MAX_EVENTS", 100)
    with pytest.raises(ValueError, match="more than 100 events"):
        gl.simulate(t_end=2000)  # ~225 impacts: only the run itself can tell
    with pytest.raises(ValueError, match="GB in memory|MAX_EVENTS"):
        gl.simulate(contacts="150")
    assert len(gl.simulate(contacts=100).events) == 100


def test_statistics_only_keep_no_event_and_have_no_event_bound(monkeypatch):
    whole = gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=150)
    monkeypatch.setattr(gl, "MAX_EVENTS", 100)
    brief = gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=150, events=False)
    assert brief.events is None and brief.contacts == whole.contacts
    assert brief.final == whole.final and brief.energy == whole.energy
    with pytest.raises(ValueError, match="GB in memory|MAX_EVENTS"):
        gl.simulate(glo=0.5, contacts=150)  # the same run, its events kept


def test_a_stripe_without_files_is_refused_and_one_part_may_be_given_alone(tmp_path):
    with pytest.raises(ValueError, match="out=PREFIX"):
        gl.map(x="u1:-1:1:4", y="v1:-1:1:4", shard=(1, 2))
    gl.map(x="u1:-1:1:4", y="v1:-1:1:4", contacts=2, out=tmp_path / "whole")
    with pytest.raises(ValueError, match="merge"):
        gl.merge(str(tmp_path / "missing"))  # one prefix, not its characters
    with pytest.raises(ValueError, match="cannot read sh/p1.json"):
        gl.merge("sh/p1")


def test_progress_hears_done_at_the_end_of_every_long_call():
    for call in (lambda p: gl.simulate(contacts=10, progress=p),
                 lambda p: gl.family(count=50, progress=p),
                 lambda p: gl.map(x="u1:-1:1:4", y="v1:-1:1:4", contacts=2, progress=p)):
        seen = []
        call(lambda fraction, text: seen.append((fraction, text)))
        assert seen[-1] == (1.0, "done")
