# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""grazelab.Chain: a chain of N masses read and designed once, run many times, with the same
bits as simulate(masses=...) and as the command line."""

import copy
import os
import signal
import threading
import time

import numpy as np
import pytest

import grazelab as gl

# chains the issues do not name: a designed 3:2:1 chain and its second design, springs given
# (not commensurate), an interior stop with a right wall, four masses designed 4:3:2:1
CHAINS = [
    (dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1]), [0, 0, 0, 0, 0, 6.7]),
    (dict(masses=[1, 0.5, 0.3], frequencies=[3, 2, 1], design_branch=2, gap=0.7), [0, 0, 0.1, 0.2, -0.3, 2.5]),
    (dict(masses=[1, 0.7, 0.4], springs=[1, 0.8, 0.6], stop_mass=2), [1.4, 1, 1.3, 0.1, 0, -0.2]),
    (dict(masses=[2, 1, 1], springs=[1, 2, 1.5], right_spring=0.5, stop_mass=2, gap=0.3), [0, 0.1, 0, 0.4, 1.2, -0.1]),
    (dict(masses=[1, 0.6, 0.36, 0.216], frequencies=[4, 3, 2, 1]), [0, 0, 0, 0, 0, 0, 0, 3.0]),
]


def bits(values):
    return np.asarray(values, dtype="<f8").view("<u8")


def assert_same_run(a, b):
    assert a.events.dtype == b.events.dtype
    assert list(a.events["type"]) == list(b.events["type"])
    for name in a.events.dtype.names:
        if name != "type":
            np.testing.assert_array_equal(bits(a.events[name]), bits(b.events[name]), err_msg=name)
    for key in ("chain", "initial", "final", "stop_reason", "contacts", "energy", "trust", "precision"):
        assert a[key] == b[key], key


@pytest.mark.parametrize("chain,state", CHAINS)
def test_a_prepared_chain_runs_as_simulate_and_the_command_line(cli_json, chain, state):
    prepared = gl.Chain(**chain)
    flags = [f"--{name.replace('_', '-')}={':'.join(map(str, value)) if name == 'frequencies' else ','.join(map(str, value)) if isinstance(value, list) else value}"
             for name, value in chain.items()]
    for contacts in (1, 12):
        run = prepared.simulate(state=state, contacts=contacts)
        assert_same_run(run, gl.simulate(**chain, state=state, contacts=contacts))
        document = cli_json("simulate", *flags, f"--state={','.join(map(str, state))}", f"--contacts={contacts}")
        assert len(run.events) == len(document["events"]) > 0
        for name in run.events.dtype.names:
            column = [event[name] for event in document["events"]]
            if name == "type":
                assert list(run.events[name]) == column
            else:
                np.testing.assert_array_equal(bits(run.events[name]), bits(column), err_msg=name)
        assert run.final == document["final"] and run.trust == document["trust"]
    # the chain as the documents write it (its springs as designed)
    assert prepared.description == run.chain
    # reused: the same bits on the second call, from NumPy numbers (read as their text) too
    again = prepared.simulate(state=np.array(state), contacts=np.int64(12))
    assert_same_run(again, run)


def test_a_prepared_chain_in_wider_precisions_and_without_its_events():
    chain, state = CHAINS[0]
    prepared = gl.Chain(**chain)
    for precision in ("long", "quad"):
        run = prepared.simulate(state=state, contacts=5, precision=precision)
        assert_same_run(run, gl.simulate(**chain, state=state, contacts=5, precision=precision))
        assert run.precision.used == precision
        # the exact text of each number, as for two masses
        assert float(run.events_decimal["t"][4]) == run.events["t"][4]
        assert len(run.events_decimal["t"][4].replace(".", "")) > 17
    brief = prepared.simulate(state=state, contacts=50, events=False)
    whole = prepared.simulate(state=state, contacts=50)
    assert brief.events is None and brief.contacts == whole.contacts and brief.trust == whole.trust
    # samples: the state on a grid, a structured array of t, u1..uN, v1..vN
    sampled = prepared.simulate(state=state, contacts=5, samples=0.5)
    assert sampled.samples.dtype.names == ("t", "u1", "u2", "u3", "v1", "v2", "v3")
    assert sampled.samples["t"][-1] <= sampled.final.t < sampled.samples["t"][-1] + 0.5
    assert sampled.samples["u3"].max() <= 1


def test_a_zero_given_as_minus_zero_is_the_zero_of_its_text():
    prepared = gl.Chain(masses=[1, 0.7, 0.4], springs=[1, 0.8, 0.6])
    plain = prepared.simulate(state=[0.1, 0, 0, 0, 0, 1], contacts=4)
    signed = prepared.simulate(state=[0.1, -0.0, 0, 0, -0.0, 1], contacts=4)
    assert_same_run(plain, signed)


def test_a_chain_that_cannot_be_made_or_run_says_why():
    with pytest.raises(ValueError, match="no chain with these masses has these ratios"):
        gl.Chain(masses=[1, 1, 1], frequencies=[3, 2, 1])
    with pytest.raises(ValueError, match="springs"):
        gl.Chain(masses=[1, 1])
    with pytest.raises(ValueError, match="must be positive"):
        gl.Chain(masses=[1, -1], springs=[1, 1])
    prepared = gl.Chain(masses=[1, 1], springs=[1, 1])
    with pytest.raises(ValueError, match="past the stop"):
        prepared.simulate(state=[0, 2, 0, 0])
    with pytest.raises(ValueError, match="glo_weights"):
        prepared.simulate(state=[0, 0, 0, 1], glo_weights=[0.5, 0.5])
    # a refused run changes nothing: the next run is the same as on a fresh chain
    assert_same_run(prepared.simulate(state=[0, 0.5, 0, 1], contacts=3),
                    gl.Chain(masses=[1, 1], springs=[1, 1]).simulate(state=[0, 0.5, 0, 1], contacts=3))


def _interrupted_within_a_second(call):
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        call()
    stopped = time.monotonic() - started - 0.5
    timer.join()
    assert stopped < 1.0, f"stopped {stopped:.2f} s after Ctrl+C"


def test_ctrl_c_stops_a_long_run_and_a_long_design_of_a_chain():
    prepared = gl.Chain(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1])
    _interrupted_within_a_second(lambda: prepared.simulate(state=[0, 0, 0, 0, 0, 6.7], contacts=10**9,
                                                           events=False, trust="off"))
    # a seven-mass design follows 7! paths: seconds
    _interrupted_within_a_second(lambda: gl.Chain(masses=[1, 0.8, 0.6, 0.5, 0.4, 0.3, 0.2],
                                                  frequencies=[7, 6, 5, 4, 3, 2, 1]))


@pytest.mark.parametrize("two_mass,chain", [
    (dict(), dict(masses=[1, 0.5], frequencies=[2, 1])),
    (dict(m1=2, m2=0.3, k1=1.5, gap=0.7, branch="lower"),
     dict(masses=[2, 0.3], springs=[1.5], frequencies=[2, 1], design_branch=2, gap=0.7)),
])
def test_the_notes_chain_written_as_masses_is_run_by_the_notes_engine(two_mass, chain):
    # the same result as the two-mass keywords, to the bit: its events, model, final state and
    # error estimate (GLO_lambda given as the weights 1 - lambda, lambda), in double and binary128
    for precision in ("auto", "quad"):
        note = gl.simulate(**two_mass, glo=0.3, perturb=(0, 0, 0, -0.01), contacts=20, precision=precision)
        for run in (gl.simulate(**chain, glo_weights=[0.7, 0.3], perturb=[0, 0, 0, -0.01], contacts=20,
                                precision=precision),
                    gl.Chain(**chain).simulate(glo_weights=[0.7, 0.3], perturb=[0, 0, 0, -0.01], contacts=20,
                                               precision=precision)):
            assert run.events.dtype == note.events.dtype and len(run.events) == 20
            for name in note.events.dtype.names:
                if name != "type":
                    np.testing.assert_array_equal(bits(run.events[name]), bits(note.events[name]), err_msg=name)
            for key in ("model", "initial", "final", "stop_reason", "contacts", "energy", "trust", "precision"):
                assert run[key] == note[key], key
            if precision == "quad":
                assert (run.events_decimal["t"] == note.events_decimal["t"]).all()


def test_a_chains_sections_are_each_runs_own_and_follow_the_chain():
    """The chain and the note's model are made once per chain and copied into each run's result:
    a result changed by its script leaves the next one whole, and each chain gets its own."""
    note = dict(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=3, trust="off")
    first = gl.simulate(m2=0.3, **note)
    reference = {key: copy.deepcopy(dict(first[key])) for key in ("chain", "model")}
    first.model["m2"] = -1.0
    first.model["P"][0][0] = 99.0
    first.chain["masses"].append(7.0)
    second = gl.simulate(m2=0.3, **note)
    assert second.model["m2"] == 0.3 and second.model["P"][0][0] != 99.0
    assert len(second.chain["masses"]) == 2
    # a copy changed, inside too, leaves the next whole: nothing of one result is another's
    second.model["P"][1].append(5.0)
    second.chain["springs"][0] = 0.0
    second_again = gl.simulate(m2=0.3, **note)
    assert dict(second_again.model) == reference["model"] and dict(second_again.chain) == reference["chain"]
    for key, inner in (("model", "P"), ("chain", "masses"), ("chain", "springs")):
        assert second_again[key][inner] is not second[key][inner]
    assert second_again.model["P"][1] is not second.model["P"][1]
    assert type(second.model) is type(first) and type(second.chain) is type(first)
    # another chain, and the same chain at another precision asked for, have their own
    other = gl.simulate(m2=0.45, **note)
    assert other.model["m2"] == 0.45 and other.chain["masses"] == [1.0, 0.45]
    assert gl.simulate(m2=0.3, precision="double", **note).model["precision"] == "double"
    assert gl.simulate(m2=0.3, **note).model["precision"] == "auto"
    # a prepared chain's chain section likewise, and chains made again after others were freed
    for masses in ([1, 0.2, 0.05], [1, 0.3, 0.05], [1, 0.2, 0.05]):
        chain = gl.Chain(masses=masses, frequencies=[3, 2, 1])
        run = chain.simulate(glo_weights=(0.2, 0.3, 0.5), contacts=2, trust="off")
        assert run.chain["masses"] == [float(m) for m in masses]
        run.chain["masses"][0] = -5.0
        assert chain.simulate(glo_weights=(0.2, 0.3, 0.5), contacts=2, trust="off").chain["masses"][0] == 1.0
        del chain
