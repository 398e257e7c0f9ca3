# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Every command's result from Python equals the command line's, bit for bit."""

import csv
import json
import math
import os
import tempfile

import numpy as np
import pytest

import grazelab as gl

EVENT_COLUMNS = ("t", "u1", "u2", "v1_pre", "v2_pre", "v2_post")


def bits(values):
    return np.asarray(values, dtype="<f8").view("<u8")


def assert_events_equal(python_run, cli_run, columns=EVENT_COLUMNS):
    events = python_run.events
    assert len(events) == len(cli_run["events"]) > 0
    assert list(events["type"]) == [e["type"] for e in cli_run["events"]]
    for column in columns:
        expected = [e[column] for e in cli_run["events"]]
        np.testing.assert_array_equal(bits(events[column]), bits(expected), err_msg=column)


@pytest.mark.filterwarnings("ignore::grazelab.GrazeLabWarning")  # a chaotic run among them
@pytest.mark.parametrize("options,flags", [
    (dict(m2=0.5, glo=0.5, perturb=(0, 0, 0, -0.05), contacts=200),
     ["--m2", "0.5", "--glo", "0.5", "--perturb=0,0,0,-0.05", "--contacts", "200"]),
    (dict(m2=0.3, gap=0.01, state=(0.2, 0, 0.1, -0.3), t_end=400),
     ["--m2", "0.3", "--gap", "0.01", "--state=0.2,0,0.1,-0.3", "--t-end", "400"]),
    (dict(k2=0.52, state=(0, 0.9, 0, 0.5), t_end=300, branch=None),
     ["--k2", "0.52", "--state=0,0.9,0,0.5", "--t-end", "300"]),
    (dict(onepp=8.0, contacts=50), ["--onepp", "8.0", "--contacts", "50"]),
])
def test_simulate_events_are_the_cli_json_bit_for_bit(cli_json, options, flags):
    run = gl.simulate(**options)
    expected = cli_json("simulate", *flags)
    assert_events_equal(run, expected)
    assert run.final == expected["final"]
    assert run.stop_reason == expected["stop_reason"]
    assert run.contacts == expected["contacts"]
    assert run.model == expected["model"]
    assert run.trust.verdict == expected["trust"]["verdict"]
    assert run.trust.estimated_state_error == expected["trust"]["estimated_state_error"]


def without_timing(document):
    return {key: value for key, value in document.items()
            if key not in ("timing", "events", "notes", "decimal", "events_decimal")}


@pytest.mark.filterwarnings("ignore::grazelab.GrazeLabWarning")
@pytest.mark.parametrize("options,flags", [
    (dict(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=10, trust="off"),
     ["--glo", "0.5", "--perturb=0,0,0,-0.05", "--contacts", "10", "--trust", "off"]),
    (dict(m2=0.3, branch="lower", glo=1.2, contacts=7), ["--m2", "0.3", "--branch", "lower", "--glo", "1.2", "--contacts", "7"]),
    (dict(glo=0, contacts=4), ["--glo", "0", "--contacts", "4"]),  # raised: long double, then more
    (dict(onepp=8.5, contacts=3, trust="full"), ["--onepp", "8.5", "--contacts", "3", "--trust", "full"]),
    (dict(state=(0, 1, 0, 0), contacts=3, precision="quad"), ["--state=0,1,0,0", "--contacts", "3", "--precision", "quad"]),
    (dict(k2=0.7, glo=0.5, perturb=(0, 0, 0, -0.05), contacts=4), ["--k2", "0.7", "--glo", "0.5", "--perturb=0,0,0,-0.05", "--contacts", "4"]),
    (dict(glo=1.5, contacts=0), ["--glo", "1.5", "--contacts", "0"]),
])
def test_simulate_document_is_the_cli_json_on_both_paths(cli_json, options, flags):
    # a short run is computed on the calling thread, a run with progress on a thread of its own,
    # both with their options handed over by name: the same document, and the
    # command line's, field for field (floats where the JSON writes 1 for 1.0: equal numbers)
    document = cli_json("simulate", *flags)
    expected = without_timing(document)
    direct = gl.simulate(**options)
    threaded = gl.simulate(**options, progress=lambda fraction, text: None)
    assert without_timing(direct) == expected
    # one layout for both faces, in any precision: the JSON's fields in its order, then the
    # module's own (notes, decimal, ...)
    assert list(direct)[:len(document)] == list(document)
    assert list(threaded)[:len(document)] == list(document)
    assert without_timing(threaded) == expected
    np.testing.assert_array_equal(direct.events, threaded.events)
    assert direct.notes == threaded.notes
    if "decimal" in direct:
        exact = cli_json("simulate", *flags, exact=True)
        exact.pop("events")
        assert without_timing(direct.decimal) == without_timing(exact)
        assert without_timing(threaded.decimal) == without_timing(exact)


@pytest.mark.parametrize("precision", ["long", "quad"])
def test_simulate_in_long_and_quad_keeps_the_exact_decimals(cli_json, precision):
    flags = ["--glo", "0.3", "--perturb=0,0,0,-0.01", "--contacts", "40", "--precision", precision]
    run = gl.simulate(glo=0.3, perturb=(0, 0, 0, -0.01), contacts=40, precision=precision)
    exact = cli_json("simulate", *flags, exact=True)
    for column in EVENT_COLUMNS:
        assert list(run.events_decimal[column]) == [e[column] for e in exact["events"]], column
        # the float columns are the decimals rounded once
        np.testing.assert_array_equal(run.events[column],
                                      [float(e[column]) for e in exact["events"]])
    assert run.decimal.final == exact["final"]
    assert run.precision.used == precision


def test_arguments_keep_every_digit_of_their_type(cli_json):
    third = np.longdouble(1) / 3
    run = gl.simulate(glo=third, contacts=3, precision="long")
    text = gl.simulate(glo=str(third), contacts=3, precision="long")
    assert run.decimal.initial == text.decimal.initial
    expected = cli_json("simulate", "--glo", str(third), "--contacts", "3", "--precision", "long",
                        exact=True)
    assert list(run.events_decimal["t"]) == [e["t"] for e in expected["events"]]
    # integral floats are the same numbers, and counts where counts are expected
    assert len(gl.simulate(contacts=5.0, m2=np.float32(0.5)).events) == 5
    m = gl.map(x=("u1", -1, 1, 4.0), y="v1:-1:1:3", contacts=2.0)
    assert m.arrays["impacts"].shape == (3, 4)
    with pytest.raises(TypeError, match="expected a number"):
        gl.simulate(trust=False)  # not a way to say "off"


@pytest.mark.parametrize("precision", ["double", "long", "quad", "auto"])
def test_numbers_handed_over_as_numbers_read_as_their_shortest_text(precision):
    # a short run hands its floats to the core as doubles: in double they are read as such, in
    # long and quad as the decimal text Python writes for them (0.1 is the quad nearest 1/10, not
    # the double nearest it); text, NumPy scalars (written as text) and numbers agree throughout
    common = dict(contacts=3, precision=precision, trust="off")
    for numbers, texts in [
        (dict(glo=0.1, m2=0.3, perturb=(0, 0, -0.0, -1e-3)), dict(glo="0.1", m2="0.3", perturb="0,0,0,-0.001")),
        (dict(state=[0.25, 1, 0, 0.5], gap=2.0, k1=3), dict(state="0.25,1,0,0.5", gap="2", k1="3")),
        (dict(onepp=8.5, m1=1.1, gap=1e3), dict(onepp="8.5", m1="1.1", gap="1000")),
    ]:
        run = gl.simulate(**numbers, **common)
        text = gl.simulate(**texts, **common)
        numpy = gl.simulate(**{k: np.float64(v) if isinstance(v, float) else v for k, v in numbers.items()},
                            **common)
        for other in (text, numpy):
            assert without_timing(run) == without_timing(other)
            np.testing.assert_array_equal(run.events, other.events)
            if "decimal" in run:
                assert without_timing(run.decimal) == without_timing(other.decimal)
    # one number where one is expected, a number where a number is expected
    with pytest.raises(TypeError, match="glo"):
        gl.simulate(glo=[0.5], contacts=2)
    with pytest.raises(TypeError, match="expected a number"):
        gl.simulate(glo=True, contacts=2)
    with pytest.raises(ValueError, match="perturb"):
        gl.simulate(perturb=(0, 0, 0), contacts=2)


def test_info_is_the_cli_json(cli_json):
    assert gl.info(m2=0.3, gap=2.5) == cli_json("info", "--m2", "0.3", "--gap", "2.5")
    quad = gl.info(m2=0.3, precision="quad")
    assert quad.decimal == cli_json("info", "--m2", "0.3", "--precision", "quad", exact=True)


def test_map_arrays_equal_the_cli_npy(cli, tmp_path):
    options = dict(x="u1:-1.5:1.5:16", y=("v1", -1, 1, 12), contacts=5, threads=2)
    result = gl.map(**options)
    done = cli("map", "--x", "u1:-1.5:1.5:16", "--y", "v1:-1:1:12", "--contacts", "5",
               "--threads", "2", "--out", str(tmp_path / "m"))
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "m.json") as handle:
        description = json.load(handle)
    assert result.spec == description["spec"]
    assert set(result.arrays) == set(description["spec"]["quantities"])
    coordinates = np.genfromtxt(tmp_path / "m.csv", delimiter=",", names=True)
    np.testing.assert_array_equal(result.x, coordinates["u1"][:16])
    np.testing.assert_array_equal(result.y, coordinates["v1"][::16])
    for quantity, array in result.arrays.items():
        expected = np.load(tmp_path / f"m-{quantity}.npy")
        assert array.shape == (12, 16) and array.dtype == expected.dtype
        np.testing.assert_array_equal(array, expected, err_msg=quantity)
    assert result.arrays["impacts"].dtype == np.int64


def test_a_map_of_n_masses_equals_the_cli_npy(cli, tmp_path):
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1], state=[0, 0, 0.5, 0, 0, 0])
    result = gl.map(**chain, x="u3:-1:0.9:12", y=("v3", -2, 2, 9), contacts=5)
    done = cli("map", "--masses", "1,0.2,0.05", "--frequencies", "3:2:1", "--state", "0,0,0.5,0,0,0",
               "--x", "u3:-1:0.9:12", "--y", "v3:-2:2:9", "--contacts", "5", "--out", str(tmp_path / "n"))
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "n.json") as handle:
        description = json.load(handle)
    assert result.spec == description["spec"] and result.spec["x"]["variable"] == "u3"
    for quantity, array in result.arrays.items():
        np.testing.assert_array_equal(array, np.load(tmp_path / f"n-{quantity}.npy"), err_msg=quantity)
    assert np.nanmax(result.arrays["fft_max"]) <= 1 + 1e-12  # no flight from the stop outlasts T
    with pytest.raises(ValueError, match="u<i>"):
        gl.map(**chain, x="u4:0:1:2", y="v3:0:1:2")
    # over GLO weights, pushed, with each point's horizon
    weights = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1], perturb=[0, 0, 0, 0, 0, -0.05])
    over = gl.map(**weights, x="w1:-1:1.4:9", y="w2:-1:1.4:7", contacts=8, trust="auto")
    done = cli("map", "--masses", "1,0.2,0.05", "--frequencies", "3:2:1", "--perturb", "0,0,0,0,0,-0.05",
               "--x", "w1:-1:1.4:9", "--y", "w2:-1:1.4:7", "--contacts", "8", "--trust", "auto",
               "--out", str(tmp_path / "w"))
    assert done.returncode == 0, done.stderr
    for quantity, array in over.arrays.items():
        np.testing.assert_array_equal(array, np.load(tmp_path / f"w-{quantity}.npy"), err_msg=quantity)
    assert over.spec["start"]["balancing_weight"] == "w3" and np.all(over.arrays["horizon"] >= 0)
    with pytest.raises(ValueError, match="two weight axes"):
        gl.map(**weights, x="w1:0:1:2", y="v3:0:1:2")
    with pytest.raises(ValueError, match="given by masses"):
        gl.map(x="u1:0:1:2", y="v1:0:1:2", glo_weights=[1, 0])


def test_map_shards_merge_to_the_whole_map(tmp_path):
    options = dict(x="u1:-1:1:6", y="v1:-1:1:5", contacts=4)
    whole = gl.map(**options)
    parts = [tmp_path / "a", tmp_path / "b"]
    for k, part in enumerate(parts, start=1):
        gl.map(**options, shard=(k, 2), out=part)
        assert os.path.exists(f"{part}.json")
    merged = gl.merge(parts)
    for quantity, array in whole.arrays.items():
        np.testing.assert_array_equal(merged.arrays[quantity], array, err_msg=quantity)


def _writing_nowhere(tmp_path, monkeypatch, call):
    """call()'s result, run with the working directory and TMPDIR in the empty `tmp_path`,
    asserting it wrote no file anywhere: not there, not in a temporary folder."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    tempfile.tempdir = None
    try:
        result = call()
    finally:
        tempfile.tempdir = None
    assert list(tmp_path.iterdir()) == []
    return result


def test_map_writes_no_file_unless_asked(tmp_path, monkeypatch):
    # no file anywhere; the arrays are views of the points the command computed (one buffer, no
    # copy per quantity)
    result = _writing_nowhere(tmp_path, monkeypatch, lambda: gl.map(x="u1:-1:1:5", y="v1:-1:1:4", contacts=3))
    assert "files" not in result.run
    first = result.arrays["fft_first"]
    assert first.shape == (4, 5) and not first.flags.owndata
    assert first.base is not None and result.arrays["impacts"].base is not None
    # with out, the same arrays, and the files named as the command line names them
    kept = gl.map(x="u1:-1:1:5", y="v1:-1:1:4", contacts=3, out=tmp_path / "m")
    assert sorted(kept.run["files"]) == sorted(list(result.spec["quantities"]) + ["csv"])
    for quantity, array in result.arrays.items():
        np.testing.assert_array_equal(kept.arrays[quantity], array, err_msg=quantity)
        np.testing.assert_array_equal(np.load(tmp_path / f"m-{quantity}.npy"), array, err_msg=quantity)


def test_family_and_modes_write_no_file_unless_asked(tmp_path, monkeypatch):
    # their outcomes are handed over: the tables are the commands' own rows, and nothing is
    # written, not even to a temporary folder; with out, the same tables and the files
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    tempfile.tempdir = None
    try:
        family = gl.family(count=40)
        modes = gl.modes(max_impacts=1)
    finally:
        tempfile.tempdir = None
    assert list(tmp_path.iterdir()) == []
    assert "files" not in family and all("file" not in entry for entry in modes.families)
    assert family.table.base is not None and not family.table.flags.owndata
    kept_family = gl.family(count=40, out=tmp_path / "f")
    kept_modes = gl.modes(max_impacts=1, out=tmp_path / "m")
    assert (tmp_path / "f.npy").exists() and (tmp_path / "m.json").exists()
    for name in family.table.dtype.names:
        np.testing.assert_array_equal(kept_family.table[name], family.table[name], err_msg=name)
    assert len(kept_modes.families) == len(modes.families) > 0
    for kept, held in zip(kept_modes.families, modes.families):
        for name in held.table.dtype.names:  # (NaN where a column has no value: equal)
            np.testing.assert_array_equal(kept.table[name], held.table[name], err_msg=name)


def test_family_table_is_the_cli_npy(cli, tmp_path):
    result = gl.family(m2=0.3, count=60)
    done = cli("family", "--onepp", "--m2", "0.3", "--count", "60", "--out", str(tmp_path / "f"))
    assert done.returncode == 0, done.stderr
    expected = np.load(tmp_path / "f.npy")
    assert result.table.dtype.names == ("T", "omega", "V", "u1", "energy", "admissible", "trace",
                                        "stability")
    np.testing.assert_array_equal(
        np.stack([result.table[name] for name in result.table.dtype.names], axis=1), expected)
    with open(tmp_path / "f.json") as handle:
        description = json.load(handle)
    assert result.bifurcations == description["bifurcations"]
    assert result.lambda_star == description["lambda_star"]


def test_modes_families_are_the_cli_files(cli, tmp_path):
    result = gl.modes(max_impacts=2, energy_range=(0.2, 1))
    done = cli("modes", "--max-impacts", "2", "--energy-range", "0.2:1", "--out",
               str(tmp_path / "a"))
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "a.json") as handle:
        description = json.load(handle)
    assert len(result.families) == len(description["families"]) > 0
    for family, expected in zip(result.families, description["families"]):
        table = family.pop("table")
        assert "file" not in family  # it was in a temporary folder
        assert family == {k: v for k, v in expected.items() if k != "file"}
        data = np.load(tmp_path / expected["file"].replace(".csv", ".npy"))
        assert len(table) == expected["rows"] == data.shape[0]
        np.testing.assert_array_equal(
            np.stack([table[name] for name in table.dtype.names], axis=1), data)


def test_orbit_is_the_cli_json(cli_json):
    period = 0.9 * gl.info().model.T2
    result = gl.orbit(onepp=period)
    expected = cli_json("orbit", "--onepp", "--period", repr(period))
    # the multipliers as complex numbers, the same doubles; the rest as the JSON has it
    assert result.multipliers.dtype == complex
    assert [[m.real, m.imag] for m in result.pop("multipliers")] == expected.pop("multipliers")
    assert result == expected
    assert result.admissible is True and result.impacts == 1
    two = gl.orbit(impacts=2, energy=0.9, guess=(0.2, 0.1))
    two_expected = cli_json("orbit", "--impacts", "2", "--energy", "0.9", "--guess=0.2,0.1")
    assert [[m.real, m.imag] for m in two.pop("multipliers")] == two_expected.pop("multipliers")
    assert two == two_expected
    quad = gl.orbit(onepp=period, precision="quad")
    assert quad.decimal == cli_json("orbit", "--onepp", "--period", repr(period),
                                    "--precision", "quad", exact=True)


@pytest.mark.parametrize("two_mass,chain", [
    (dict(), dict(masses=[1, 0.5], frequencies=(2, 1))),
    (dict(m1=2, m2=0.3, k1=1.5, gap=0.7, branch="lower"),
     dict(masses=[2, 0.3], springs=[1.5], frequencies=(2, 1), design_branch=2, gap=0.7)),
    (dict(m2=0.4, k2=0.37), dict(masses=[1, 0.4], springs=[1, 0.37])),
])
def test_orbit_and_modes_take_the_chain_as_masses(two_mass, chain):
    # one chain however written: the same bits (NaN included, so the tables as bytes)
    period = 0.93 * gl.info(**two_mass).model.T2
    a, b = gl.orbit(onepp=period, **two_mass), gl.orbit(onepp=period, **chain)
    assert bits(a.pop("multipliers").view(float)).tolist() == bits(b.pop("multipliers").view(float)).tolist()
    assert a == b
    # (off the 1:2 design both take the atlas of any chain)
    a, b = gl.modes(max_impacts=1, **two_mass), gl.modes(max_impacts=1, **chain)
    assert len(a.families) == len(b.families) > 0
    for x, y in zip(a.families, b.families):
        assert x.pop("table").tobytes() == y.pop("table").tobytes()
    assert a == b


def test_the_orbit_of_three_masses_is_the_cli_json(cli_json):
    # the 1IPP orbit of any chain with its 2N - 2 multipliers, error bars, circle flags and
    # Krein signatures as NumPy arrays, the same numbers as the command line's
    result = gl.orbit(onepp=7.0, masses=[1, 0.2, 0.05], frequencies=(3, 2, 1))
    expected = cli_json("orbit", "--onepp", "--period", "7", "--masses", "1,0.2,0.05", "--frequencies", "3:2:1")
    assert result.multipliers.dtype == complex and result.multipliers.shape == (4,)
    assert [[m.real, m.imag] for m in result.pop("multipliers")] == expected.pop("multipliers")
    for name, dtype in (("multiplier_errors", float), ("on_circle", bool), ("krein", np.int64)):
        assert result[name].dtype == dtype
        assert result.pop(name).tolist() == expected.pop(name)
    assert result == expected
    assert result.stability == "elliptic"


def test_a_newton_orbit_of_three_masses_is_the_cli_json(cli_json):
    chain = dict(masses=[0.6865, 1.963, 0.8236], springs=[0.8423, 1.0745, 0.7486], stop_mass=2)
    result = gl.orbit(impacts=2, energy=23.412611915561559, guess=(1.28, -6.54, 0.01, -0.01), **chain)
    expected = cli_json("orbit", "--impacts", "2", "--energy", "23.412611915561559", "--guess=1.28,-6.54,0.01,-0.01",
                        "--masses", "0.6865,1.963,0.8236", "--springs", "0.8423,1.0745,0.7486", "--stop-mass", "2")
    assert [[m.real, m.imag] for m in result.pop("multipliers")] == expected.pop("multipliers")
    for name in ("multiplier_errors", "on_circle", "krein"):
        assert result.pop(name).tolist() == expected.pop(name)
    assert result == expected
    assert result.impacts == 2 and result.stability == "hyperbolic"
    at_period = gl.orbit(impacts=1, period=7, guess=(0.13, 0.3, 0.01, 0.01, -0.4), masses=[1, 0.2, 0.05],
                         frequencies=(3, 2, 1))
    assert abs(at_period.period - 7) < 1e-12
    with pytest.raises(ValueError, match="give 4 numbers"):
        gl.orbit(impacts=2, energy=1.0, guess=(0, 0), masses=[1, 0.2, 0.05], frequencies=(3, 2, 1))
    with pytest.raises(ValueError, match="not both"):
        gl.orbit(onepp=7, period=7, masses=[1, 0.2, 0.05], frequencies=(3, 2, 1))


def test_the_modes_of_three_masses_are_the_cli_files(cli, tmp_path):
    # the atlas of any chain: each family's table the CLI's CSV, its multipliers as columns
    chain = dict(masses=[1, 0.7, 0.4], frequencies=(3, 2, 1))
    result = gl.modes(max_impacts=2, **chain)
    done = cli("modes", "--max-impacts", "2", "--masses", "1,0.7,0.4", "--frequencies", "3:2:1", "--out",
               str(tmp_path / "m"))
    assert done.returncode == 0, done.stderr
    assert "model" not in result and result.chain.masses == [1, 0.7, 0.4]
    assert len(result.families) == len(list(tmp_path.glob("m-family-*.csv"))) > 2
    for family in result.families:
        table = family.table
        assert table.dtype.names[-1] == "mu4_krein" and len(table) == family.rows
        written = np.load(tmp_path / f"m-family-{family.id}.npy")
        assert written.tobytes() == table.view((float, len(table.dtype.names))).tobytes()
        assert set(np.unique(table["mu1_krein"])) <= {-1.0, 0.0, 1.0}
    born = [f for f in result.families if f.born_at.kind == "period-doubling"]
    assert born and all(f.impacts == 2 for f in born)


def test_a_family_of_impacts_is_the_cli_files(cli, tmp_path):
    # family(impacts=K): the orbit's family followed both ways, the same rows as the CLI's
    chain = dict(masses=[0.6865, 1.963, 0.8236], springs=[0.8423, 1.0745, 0.7486], stop_mass=2)
    result = gl.family(impacts=2, energy=23.412611915561559, guess=(1.28, -6.54, 0.01, -0.01), count=200, **chain)
    done = cli("family", "--impacts", "2", "--energy", "23.412611915561559", "--guess=1.28,-6.54,0.01,-0.01",
               "--masses", "0.6865,1.963,0.8236", "--springs", "0.8423,1.0745,0.7486", "--stop-mass", "2",
               "--count", "200", "--out", str(tmp_path / "f"))
    assert done.returncode == 0, done.stderr
    [family] = result.families
    assert family.born_at.kind == "given-orbit" and family.impacts == 2
    written = np.load(tmp_path / "f-family-0.npy")
    assert written.tobytes() == family.table.view((float, len(family.table.dtype.names))).tobytes()
    with pytest.raises(ValueError, match="describe the family of impacts"):
        gl.family(guess=(1, 2), **chain)


def test_two_mass_commands_refuse_other_chains_in_words():
    with pytest.raises(ValueError, match="given by masses"):
        gl.report(springs=[1, 0.5], quick=True)
    with pytest.raises(ValueError, match="glo_weights describes a chain given by masses"):
        gl.report(glo_weights=[0.5, 0.5], quick=True)


def test_report_quick_table_matches_its_csv(tmp_path):
    result = gl.report(quick=True, methods="exact,moreau-jean", out=tmp_path / "r")
    assert (tmp_path / "r" / "results.csv").exists()
    assert len(result.table) > 0 and "method" in result.table.dtype.names
    assert set(result.table["method"]) <= {"exact", "moreau-jean"}
    assert "work" in result.markdown.lower() or "method" in result.markdown.lower()


def test_report_of_a_chain_is_the_cli_table_without_a_file(cli, tmp_path, monkeypatch):
    # three masses stopped on the last: the typed report in memory, and the command line's
    # results.csv row for row (but for the timings)
    chain = dict(masses=[1, 0.3, 0.6], springs=[1, 0.7, 1.3], stop_mass=3, gap=0.4,
                 state=[0.1, 0, 0.4, 0, 0.2, -0.3], contacts=12)
    result = _writing_nowhere(tmp_path, monkeypatch,
                              lambda: gl.report(quick=True, methods="exact,moreau-jean", **chain))
    assert result.out is None
    done = cli("report", "--quick", "--methods", "exact,moreau-jean", "--masses", "1,0.3,0.6",
               "--springs", "1,0.7,1.3", "--stop-mass", "3", "--gap", "0.4", "--state", "0.1,0,0.4,0,0.2,-0.3",
               "--contacts", "12", "--out", str(tmp_path / "r"))
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "r" / "results.csv", newline="") as handle:
        expected = list(csv.DictReader(handle))
    assert len(result.table) == len(expected) > 2
    for row, line in zip(result.table, expected):
        for column in ("method", "parameter", "status", "reason"):
            assert row[column] == line[column], (column, line)
        for column in ("value", "state_error", "contact_time_error", "missed_contacts", "extra_contacts"):
            assert repr(float(row[column])) == repr(float(line[column] or "nan")), (column, line)
    exact = [row for row in result.table if row["method"] == "exact"]
    assert exact and all(row["state_error"] < 1e-9 and row["missed_contacts"] == 0 for row in exact)
    assert result.markdown.startswith("# ") and "moreau-jean" in result.markdown


def test_events_are_a_view_of_the_core_table_not_a_copy():
    run = gl.simulate(contacts=20)
    events = run.events
    assert events.dtype.itemsize == 80 and events.flags["C_CONTIGUOUS"]
    assert events.base is not None and not events.flags["OWNDATA"]
    assert np.all(np.diff(events["t"]) > 0)
    assert math.isfinite(run.final.t)


def test_samples_are_the_states_of_runs_that_end_there_and_the_cli_samples(cli_json):
    # the state on a time grid: at each time the state a run stopped there ends with (the same
    # exact flight, to the last bit), the command line's samples, and on the stop's side
    start = dict(glo=0.5, perturb=(0, 0, 0, -0.05))
    times = [0, 1.25, 3.3, 7.7, 20.0, 44.4]
    run = gl.simulate(**start, contacts=10, samples=times)
    assert list(run.samples["t"]) == times and run.samples_truncated is False
    for sample in run.samples[1:]:
        final = gl.simulate(**start, t_end=float(sample["t"])).final
        assert [final.u1, final.u2, final.v1, final.v2] == [sample[c] for c in ("u1", "u2", "v1", "v2")]
    expected = cli_json("simulate", "--glo", "0.5", "--perturb=0,0,0,-0.05", "--contacts", "10",
                        "--sample-times", ",".join(str(t) for t in times))
    for column in ("t", "u1", "u2", "v1", "v2"):
        np.testing.assert_array_equal(bits(run.samples[column]), bits(expected["samples"][column]))
    grid = gl.simulate(**start, contacts=30, samples=0.25)
    assert len(grid.samples) == math.floor(grid.final.t / 0.25) + 1
    assert np.all(grid.samples["u2"] <= 1.0)
    # elastic impacts: every sample has the start's energy (masses 1 and 0.5, springs 1 and 0.5)
    s = grid.samples
    energy = 0.5 * (s["v1"] ** 2 + 0.5 * s["v2"] ** 2) + 0.5 * (s["u1"] ** 2 + 0.5 * (s["u2"] - s["u1"]) ** 2)
    np.testing.assert_allclose(energy, grid.energy.initial, rtol=1e-12)
    with pytest.raises(ValueError, match="ascending"):
        gl.simulate(**start, contacts=3, samples=[2.0, 1.0])


def test_info_of_a_chain_of_n_masses(cli_json):
    # the command line's document; the note's 1:2 chain given as masses reads 2:1 with T = T2
    chain = dict(masses=[1, 1, 1], springs=[1, 1, 1], right_spring=1, stop_mass=2)
    three = gl.info(**chain)
    assert three == cli_json("info", "--masses=1,1,1", "--springs=1,1,1", "--right-spring", "1",
                             "--stop-mass", "2")
    assert [mode.node_at_stop for mode in three.modes] == [False, True, False]
    assert [mode.mode for mode in three.modes] == [1, 2, 3]
    assert three.modes[0].omega > three.modes[1].omega > three.modes[2].omega
    note = gl.info()
    two = gl.info(masses=[1, 0.5], springs=[1, note.model.k2])
    assert two.ratios.commensurate and two.ratios.harmonics == [2, 1]
    assert math.isclose(two.ratios.T, note.model.T2, rel_tol=1e-14)
    assert math.isclose(two.modes[0].omega, note.model.omega1, rel_tol=1e-14)
    with pytest.raises(ValueError, match="whole chain"):
        gl.info(masses=[1, 2], springs=[1, 1], m1=2)
    with pytest.raises(ValueError, match="m2 must be positive"):
        gl.info(masses=[1, -2], springs=[1, 1])
    with pytest.raises(ValueError, match="one spring per mass"):
        gl.info(masses=[1, 2], springs=[1])


def test_info_designs_springs_for_frequency_ratios(cli_json):
    # every design of 4:3:1 for these masses, the chain taking the second; the same document
    # as the command line's
    designed = gl.info(masses=[1, 1, 0.2], springs=[3], frequencies=[4, 3, 1], design_branch=2)
    assert designed == cli_json("info", "--masses=1,1,0.2", "--springs=3", "--frequencies=4:3:1",
                                "--design-branch=2")
    assert designed.ratios.commensurate and designed.ratios.harmonics == [4, 3, 1]
    assert len(designed.design.designs) == 4
    assert designed.chain.springs == designed.design.designs[1].springs
    assert all(d.springs[0] == 3 and d.ratio_error <= 1e-13 for d in designed.design.designs)
    # the note's 1:2 design, both branches
    for branch, index in (("upper", 1), ("lower", 2)):
        two = gl.info(masses=[1, 0.5], frequencies=np.array([2, 1]), design_branch=index)
        assert math.isclose(two.chain.springs[1], gl.info(branch=branch).model.k2, rel_tol=1e-14)
    with pytest.raises(ValueError, match="no chain with these masses"):
        gl.info(masses=[1, 0.6], frequencies=[2, 1])
    with pytest.raises(TypeError, match="whole numbers"):
        gl.info(masses=[1, 0.5], frequencies=[2.5, 1])
    with pytest.raises(ValueError, match="given by masses"):
        gl.info(frequencies=[2, 1])


def test_simulate_a_chain_of_n_masses(cli_json):
    # a designed 3:2:1 chain: the command line's document; every flight after an impact < T
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1])
    run = gl.simulate(**chain, state=[0, 0, 0, 0, 0, 6.7], contacts=15)
    expected = cli_json("simulate", "--masses=1,0.2,0.05", "--frequencies=3:2:1", "--state=0,0,0,0,0,6.7",
                        "--contacts=15")
    assert without_timing(run) == without_timing(expected)
    # the events as for two masses: a structured array of the csv's columns, the same bits
    assert run.events.dtype.names == ("t", "type", "u1", "u2", "u3", "v1_pre", "v2_pre", "v3_pre", "v3_post")
    assert_events_equal(run, expected, columns=[name for name in run.events.dtype.names if name != "type"])
    assert run.contacts.total == run.contacts.impacts == 15 and run.stop_reason == "contact-limit"
    times = run.events["t"]
    assert all(0 < b - a < run.chain.period for a, b in zip(times, times[1:]))
    assert run.energy.relative_drift < 1e-12
    # the note's chain given as masses: the two-mass solver's contacts
    note = gl.simulate(state=(0.5, 0.9, 0.8, 0.6), contacts=20, trust="off")
    two = gl.simulate(masses=[1, 0.5], springs=[1, gl.info().model.k2], state=[0.5, 0.9, 0.8, 0.6], contacts=20)
    np.testing.assert_allclose(two.events["t"], note.events["t"], rtol=1e-12)
    assert two.events.dtype.names == note.events.dtype.names  # one layout for every N
    # one result type: the two writings of the note's chain give the same document, model included
    assert without_timing(two) == without_timing(gl.simulate(k2=gl.info().model.k2, state=(0.5, 0.9, 0.8, 0.6),
                                                             contacts=20))
    # the note's kernel's step budget, however the detuned chain is written (Chain.simulate too)
    detuned = dict(state=[0.5, 0.8, 0, 0], contacts=1, search_steps=10)
    for budgeted in (gl.simulate(masses=[1, 0.5], springs=[1, 0.37], **detuned), gl.simulate(k2=0.37, **detuned),
                     gl.Chain(masses=[1, 0.5], springs=[1, 0.37]).simulate(**detuned)):
        assert budgeted.stop_reason == "search-budget" and budgeted.contacts.total == 0, budgeted.stop_reason
    with pytest.raises(ValueError, match="state u1"):
        gl.simulate(masses=[1, 1], springs=[1, 1])
    with pytest.raises(ValueError, match="not available for a chain"):
        gl.simulate(masses=[1, 1], springs=[1, 1], glo=0.5)
    with pytest.raises(ValueError, match="given by masses"):
        gl.simulate(springs=[1, 1], state=[0, 0, 0, 1])
    # samples: a structured array of (t, u1..uN, v1..vN), the command line's numbers; a sample
    # at an event's time is the state just after it
    sampled = gl.simulate(**chain, state=[0, 0, 0, 0, 0, 6.7], contacts=15, samples=0.25)
    document = cli_json("simulate", "--masses=1,0.2,0.05", "--frequencies=3:2:1", "--state=0,0,0,0,0,6.7",
                        "--contacts=15", "--sample-step=0.25")
    assert sampled.samples.dtype.names == ("t", "u1", "u2", "u3", "v1", "v2", "v3")
    assert len(sampled.samples) == len(document["samples"]["t"]) == int(run.final.t / 0.25) + 1
    for name in sampled.samples.dtype.names:
        assert list(sampled.samples[name]) == document["samples"][name], name
    first = run.events[0]
    at = gl.simulate(**chain, state=[0, 0, 0, 0, 0, 6.7], contacts=15, samples=[first["t"]])
    assert at.samples["u3"][0] == first["u3"] and abs(at.samples["v3"][0] - first["v3_post"]) < 1e-12


def test_statistics_of_a_chain_of_n_masses_without_its_events():
    # events=False: the same run's statistics, its error estimate made as the events came (the
    # same comparison with the shadow run), no event held, so no bound on the contacts
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1], state=[0, 0, 0, 0, 0, 6.7])
    for trust in ("off", "auto", "full"):
        whole = gl.simulate(**chain, contacts=400, trust=trust)
        brief = gl.simulate(**chain, contacts=400, trust=trust, events=False)
        assert brief.events is None and len(whole.events) == 400
        for key in ("initial", "final", "stop_reason", "contacts", "energy", "trust", "precision"):
            assert brief[key] == whole[key], (trust, key)
    # the events held in memory stop at MAX_EVENTS, as for two masses (refused before the run)
    with pytest.raises(ValueError, match="MAX_EVENTS"):
        gl.simulate(**chain, contacts=gl.MAX_EVENTS + 1, trust="off")
    long = gl.simulate(**chain, contacts=1_000_001, trust="off", events=False)
    assert long.contacts.total == 1_000_001 and long.stop_reason == "contact-limit"


def test_family_and_modes_in_long_and_quad_give_floats_and_their_exact_text():
    # one convention for every command: numbers are floats, and in long or quad the exact
    # decimal text written is under `decimal` (family and modes once returned the text alone)
    family = gl.family(count=50, precision="quad")
    point = family.bifurcations[1]
    assert isinstance(point["T"], float) and isinstance(family.model["T2"], float)
    assert point["T"] / family.model["T2"] == pytest.approx(point["T_over_T2"], rel=1e-15)
    exact = family.decimal.bifurcations[1]["T"]
    assert isinstance(exact, str) and len(exact.replace(".", "")) > 30 and float(exact) == point["T"]
    atlas = gl.modes(precision="long", max_impacts=2)
    assert isinstance(atlas.model["T2"], float) and float(atlas.decimal.model["T2"]) == atlas.model["T2"]
    assert "decimal" not in gl.family(count=50)


def test_glo_starts_and_grazing_sets_of_n_masses(cli_json):
    # a GLO start of the designed 3:2:1 chain: the command line's document, grazing touches one
    # period apart; the grazing sets as the command line writes them (the note's [0, 4/3])
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1])
    run = gl.simulate(**chain, glo_weights=[0.5, 0.3, 0.2], contacts=3)
    expected = cli_json("simulate", "--masses=1,0.2,0.05", "--frequencies=3:2:1", "--glo-weights=0.5,0.3,0.2",
                        "--contacts=3")
    assert without_timing(run) == without_timing(expected)
    assert_events_equal(run, expected, columns=[name for name in run.events.dtype.names if name != "type"])
    assert list(run.events["type"]) == ["grazing"] * 3
    pushed = gl.simulate(**chain, glo_weights=np.array([0.5, 0.3, 0.2]), perturb=[0, 0, 0, 0, 0, 0.01], contacts=3)
    assert pushed.events[0]["type"] == "impact"
    note = gl.glo_set()
    assert note == cli_json("glo-set")
    assert note.harmonics == [2, 1] and note.grazing_set.low == 0 and note.grazing_set.high == 4 / 3
    region = gl.glo_set(**chain, directions=6)
    assert region == cli_json("glo-set", "--masses=1,0.2,0.05", "--frequencies=3:2:1", "--directions=6")
    assert len(region.grazing_set.boundary) == 6
    with pytest.raises(ValueError, match="commensurate"):
        gl.glo_set(masses=[1, 1], springs=[1, 1])
    with pytest.raises(ValueError, match="sum to 1"):
        gl.simulate(masses=[1, 1], springs=[1, 1], glo_weights=[0.5, 0.6])
    with pytest.raises(ValueError, match="given by masses"):
        gl.simulate(glo_weights=[0.5, 0.5])


def test_a_fast_mode_glom_grazes_at_its_own_period(cli_json):
    # GLOM_1 of 3:2:1 (u3 = d cos 3 w0 t) returns after T/3 and GLOM_2 after T/2, decided in double
    # by simulate and by a prepared chain alike, as by the command line (they were undecided at
    # t = 0 in every precision)
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1])
    prepared = gl.Chain(**chain)
    for weights, repeats in (([1, 0, 0], 3), ([0, 1, 0], 2)):
        run = gl.simulate(**chain, glo_weights=weights, contacts=4)
        assert run.precision.used == "double"
        assert list(run.events["type"]) == ["grazing"] * 4
        period = run.chain.period / repeats
        assert np.allclose(run.events["t"], period * np.arange(1, 5), rtol=1e-12, atol=0)
        again = prepared.simulate(glo_weights=weights, contacts=4)
        assert np.array_equal(again.events["t"], run.events["t"])
        expected = cli_json("simulate", "--masses=1,0.2,0.05", "--frequencies=3:2:1",
                            "--glo-weights=" + ",".join(map(str, weights)), "--contacts=4")
        assert_events_equal(run, expected, columns=[name for name in run.events.dtype.names if name != "type"])


def test_the_1ipp_family_of_n_masses(cli, tmp_path):
    # the designed 3:2:1 chain: the same table as the command line's files; the data tend to
    # the grazing limit's GLO; a run from an admissible orbit impacts at T, 2T, 3T
    chain = dict(masses=[1, 0.2, 0.05], frequencies=[3, 2, 1])
    family = gl.family(**chain, count=100)
    done = cli("family", "--onepp", "--masses=1,0.2,0.05", "--frequencies=3:2:1", "--count=100",
               "--out", str(tmp_path / "f"))
    assert done.returncode == 0, done.stderr
    on_disk = np.genfromtxt(tmp_path / "f.csv", delimiter=",", names=True)
    for name in ("T", "V", "energy", "admissible", "u1", "u3"):
        np.testing.assert_array_equal(family.table[name], on_disk[name])
    last = family.table[np.nonzero(family.table["admissible"] == 1)[0][-1]]
    limit = family.grazing_limit
    assert abs(sum(limit.weights) - 1) < 1e-14 and all(w > 0 for w in limit.weights)
    assert max(abs(last[f"u{i + 1}"] - limit.u[i]) for i in range(3)) < 1e-6
    run = gl.simulate(**chain, onepp=float(last["T"]), contacts=3)
    assert list(run.events["type"]) == ["impact"] * 3
    np.testing.assert_allclose(run.events["t"], [k * last["T"] for k in (1, 2, 3)], rtol=1e-9)
    with pytest.raises(ValueError, match="no admissible 1IPP orbit"):
        gl.simulate(**chain, onepp=1.0)


@pytest.mark.parametrize("precision", ["double", "quad"])
def test_a_sampled_result_keeps_the_json_order(cli_json, precision):
    # the samples an array where the JSON has its columns, in the JSON's place, in any precision
    document = cli_json("simulate", "--glo", "0.5", "--perturb=0,0,0,-0.05", "--contacts", "3",
                        "--sample-step", "1", "--precision", precision)
    run = gl.simulate(glo=0.5, perturb=(0, 0, 0, -0.05), contacts=3, samples=1.0, precision=precision)
    assert list(run)[:len(document)] == list(document)
    assert list(run.samples["t"]) == document["samples"]["t"]
    assert run.samples_truncated is document["samples_truncated"]
    if precision == "quad":
        assert "samples" not in run.decimal and "samples_truncated" in run.decimal


def test_stability_of_a_chain_is_the_cli_matrix(cli, tmp_path, monkeypatch):
    # three masses stopped on the last: the typed matrix in memory, no file, and the command
    # line's matrix.csv cell for cell (but for the timings)
    chain = dict(masses=[1, 0.3, 0.6], springs=[1, 0.7, 1.3], stop_mass=3, gap=0.4,
                 state=[0.1, 0, 0.4, 0, 0.2, -0.3])
    result = _writing_nowhere(tmp_path, monkeypatch,
                              lambda: gl.stability(quick=True, methods="exact,moreau-jean", **chain))
    assert result.out is None
    assert result.markdown.startswith("# GrazeLab stability matrix")
    done = cli("stability", "--quick", "--methods", "exact,moreau-jean", "--masses", "1,0.3,0.6",
               "--springs", "1,0.7,1.3", "--stop-mass", "3", "--gap", "0.4", "--state", "0.1,0,0.4,0,0.2,-0.3",
               "--out", str(tmp_path / "m"))
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "m" / "matrix.csv", newline="") as handle:
        expected = list(csv.DictReader(handle))
    assert len(result.table) == len(expected) == 12  # six cases, two methods
    for row, line in zip(result.table, expected):
        assert (row["case"], row["method"]) == (line["case"], line["method"])
        if "budget" in (row["verdict"], line["verdict"]):  # a cell's budget is wall time
            continue
        assert row["verdict"] == line["verdict"], line
        assert repr(float(row["state_error"])) == repr(float(line["state_error"] or "nan")), line
        assert row["reason"] == line["reason"]
    given = {row["method"]: row for row in result.table if row["case"] == "given"}
    assert given["exact"]["verdict"] == "ok" and given["exact"]["state_error"] < 1e-6
    assert given["exact"]["missed_contacts"] == 0 < given["moreau-jean"]["missed_contacts"]
    # with out, the files, named in the log
    kept = gl.stability(quick=True, methods="exact", out=tmp_path / "kept", **chain)
    assert (tmp_path / "kept" / "matrix.csv").exists() and (tmp_path / "kept" / "matrix.md").exists()
    assert any("matrix.csv" in line for line in kept.log)
    for chain_only in (dict(springs=[1, 2]), dict(frequencies=[2, 1]), dict(state=[0, 1, 0, 0])):
        with pytest.raises(ValueError, match="given by masses"):
            gl.stability(quick=True, **chain_only)


def test_bar_is_the_command_lines(cli_json):
    """grazelab.bar is grazelab-cli bar: the same rows (but their wall times), continuum and
    convergence; bad keywords raise ValueError in the module's words."""
    def untimed(document):
        rows = [{key: value for key, value in row.items() if key != "seconds"} for row in document["rows"]]
        return {**{key: value for key, value in document.items() if key != "rows"}, "rows": rows}

    bar = gl.bar(bar=(70e9, 2700, 1e-4, 0.5), speed=2, masses_count=[3, 20, 60], stop_end="first", each_impact=True)
    expected = cli_json("bar", "--bar=70e9,2700,1e-4,0.5", "--speed=2", "--masses-count=3,20,60", "--stop-end=first",
                        "--each-impact")
    assert untimed(bar) == untimed(expected)
    assert [row.impacts for row in bar.rows] == [len(row.impact_times) for row in bar.rows]
    assert bar.continuum.rebound == -2 and bar.rows[2].rebound < 0
    with pytest.raises(ValueError, match="masses_count"):
        gl.bar(masses_count=[10, 5])
    with pytest.raises(TypeError):
        gl.bar(each_impact=1)
