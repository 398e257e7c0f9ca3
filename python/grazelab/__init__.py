# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""GrazeLab from Python: the exact simulator of a 2-dof chain against a rigid stop in 1:2
internal resonance, its maps and its nonlinear normal modes (docs/python.md).

Each function is a command of ``grazelab-cli`` run in this process by the command line's own
code: each flag is a keyword argument in snake_case with the same meaning and default
(``t_end`` is ``--t-end``), each result field has the JSON's name. Tables are NumPy structured
arrays with the CSV's column names, maps a dict of 2-D arrays (row = y, column = x).

Invalid input raises ``ValueError`` with the command line's one-line message; Ctrl+C stops a
running computation within a second and raises ``KeyboardInterrupt``; the GIL is released while
the core computes, so threads run computations at once. Long calls take ``progress``, a callable
``progress(fraction, text)`` (fraction None when not known), called on the calling thread.

    >>> import grazelab as gl
    >>> run = gl.simulate(m2=0.5, glo=0.5, perturb=(0, 0, 0, -0.05), contacts=200)
    >>> run.events["t"][:3], run.trust.verdict
"""

import os
import shutil
import tempfile
import warnings

import numpy as np

from . import _convert
from ._convert import Result
from ._native import run as _run
from ._native import version as __version__

# map and help are left out of a star import: they would hide Python's own
__all__ = ["info", "simulate", "merge", "family", "orbit", "modes", "report", "stability",
           "Result", "GrazeLabWarning", "MAX_EVENTS"]


# a run's events are held in memory (80 bytes each): beyond this many, stream them to a file
# with grazelab-cli simulate --format csv or jsonl, whose memory stays bounded
MAX_EVENTS = 2**25


class GrazeLabWarning(UserWarning):
    """A result came back that its own error estimate does not trust (verdict unreliable)."""


def _command(command, options, progress=None, events=False, positional=()):
    """Runs one command; returns (output text, messages, events, decimals) or raises. A
    progress callback hears (1.0, "done") when the command has ended well."""
    for name in ("help", "version", "help_all"):
        if name in options:
            raise ValueError(f"{name}: see grazelab.help() and help(grazelab.{command})")
    line = _convert.arguments(command, options) + [str(p) for p in positional]
    code, output, messages, table, decimals = _run(line, progress, events, MAX_EVENTS)
    lines = [text for text in messages.splitlines() if text.strip()]
    if code == 2:
        raise ValueError(_message(lines[-1] if lines else "invalid input"))
    if code != 0:
        raise OSError(_message(lines[-1] if lines else f"{command} failed (exit {code})"))
    if progress is not None:
        progress(1.0, "done")
    return output.decode("utf-8"), lines, table, decimals


def _message(line):
    for prefix in ("grazelab-cli: ", "grazelab-cli report: ", "grazelab-cli stability: "):
        if line.startswith(prefix):
            return line[len(prefix):]
    return line


def _notes(lines):
    prefix = "grazelab-cli: note: "
    return [line[len(prefix):] for line in lines if line.startswith(prefix)]


def help():  # noqa: A001 (Python's help() still works on the functions)
    """The command line's options with their meanings and defaults (``grazelab-cli --help``):
    each is a keyword argument here, in snake_case."""
    output, _, _, _ = _command("--help", {})
    print(output.replace("<executable_name>", "grazelab-cli"), end="")


def info(**options):
    """``grazelab-cli info``: the chain's derived quantities (k2, omega1, omega2, T1, T2, P,
    lambda_star) as the JSON's ``model`` object. Options: m1, m2, k1, k2, gap, branch,
    precision. With precision long or quad the numbers are also under ``decimal`` as the
    exact text written."""
    output, _, _, _ = _command("info", options)
    precision = options.get("precision", "double")
    return _convert.parse_json(output, exact_decimals=precision in ("long", "quad"))


def simulate(*, progress=None, **options):
    """``grazelab-cli simulate``: one exact run. Options as the command line's (m1, m2, k1,
    k2, gap, branch, precision, glo, onepp, state, perturb, contacts, t_end, search_steps,
    trust). Returns the JSON's fields (model, initial, final, stop_reason, contacts, energy,
    accuracy, trust, precision, timing) with ``events`` a structured array of the columns
    t, type, u1, u2, v1, v2_pre, v2_post (the arrays the core filled, no copy), ``notes`` the
    command line's notes. A run in long double or binary128 also has ``events_decimal``: each
    numeric column as the exact decimal text the command line writes, and ``decimal``: the
    JSON's numbers as text. Warns (GrazeLabWarning) when the run's own error estimate says
    unreliable."""
    if options.get("format") not in (None, "json"):
        raise ValueError("format: the Python module returns the run as arrays; write jsonl, csv "
                         "or summary with grazelab-cli")
    options.pop("format", None)
    try:
        contacts = int(_convert._text("contacts", options["contacts"]))
    except (KeyError, ValueError):
        contacts = None  # absent, or the command line says what is wrong with it
    if contacts is not None and contacts > MAX_EVENTS:
        raise ValueError(f"contacts: {contacts} events would take {contacts * 80 / 1e9:.1f} GB "
                         f"in memory (at most grazelab.MAX_EVENTS = {MAX_EVENTS}); stream them "
                         f"to a file with grazelab-cli simulate --format csv")
    output, lines, table, decimals = _command("simulate", options, progress, events=True)
    used_precision_exact = decimals is not None
    result = _convert.parse_json(output, exact_decimals=used_precision_exact)
    result["events"] = table
    result["notes"] = _notes(lines)
    if used_precision_exact:
        columns = ("t", "u1", "u2", "v1", "v2_pre", "v2_post")
        text = np.array(decimals, dtype=str).reshape(-1, len(columns))
        result["events_decimal"] = {name: text[:, i] for i, name in enumerate(columns)}
        result["decimal"].pop("events", None)
    if result.get("trust", {}).get("verdict") == "unreliable":
        warnings.warn(f"simulate: the run's error estimate says unreliable: "
                      f"{result['trust'].get('reason', '')}", GrazeLabWarning, stacklevel=2)
    return result


def orbit(**options):
    """``grazelab-cli orbit``: one periodic impacting orbit with its exact multipliers. Either
    ``onepp=True, period=T`` or ``impacts=K, energy=E, guess=(u1, v1)``; model options and
    precision. Raises ValueError when Newton does not converge or the orbit is not admissible
    (the command line's message). In long or quad precision the numbers are also under
    ``decimal`` as exact text."""
    output, _, _, _ = _command("orbit", options)
    result = _convert.parse_json(output, exact_decimals=True)
    if result.get("precision") not in ("long", "quad"):
        result.pop("decimal")
    return result


class _Output:
    """Where a command that writes files writes: `out` (kept) or a temporary folder."""

    def __init__(self, out, name):
        self.kept = out is not None
        if self.kept:
            self.prefix = os.fspath(out)
        else:
            self.folder = tempfile.mkdtemp(prefix="grazelab-")
            self.prefix = os.path.join(self.folder, name)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if not self.kept:
            shutil.rmtree(self.folder, ignore_errors=True)


def _map_result(target):
    with open(target.prefix + ".json") as handle:
        result = _convert.parse_json(handle.read())
    result["arrays"] = _convert.map_arrays(target.prefix, result["run"])
    # the columns' and rows' coordinates, as the spec says: numpy.linspace(from, to, count)
    for axis in ("x", "y"):
        spec = result["spec"][axis]
        result[axis] = np.linspace(spec["from"], spec["to"], spec["count"])
    if not target.kept:
        result["run"].pop("files")  # they were in a temporary folder, now gone
    return result


def map(*, out=None, progress=None, **options):  # noqa: A001 (the command's name)
    """``grazelab-cli map``: a 2-D grid of exact runs reduced to summaries, on ``threads``
    threads (default all cores). ``x``, ``y``: "NAME:from:to:count" or (NAME, from, to, count).
    Returns the JSON's ``spec`` and ``run`` with ``arrays``: one 2-D array per quantity
    (row = y, column = x; counts int64, the rest float64), equal to the command line's .npy.
    ``x`` and ``y`` in the result are the columns' and rows' coordinates. With ``out=PREFIX``
    the command line's files are kept there (without pictures); a stripe (``shard=(k, n)``)
    needs one, for :func:`merge` to read."""
    if options.get("shard") is not None and out is None:
        raise ValueError("shard: a stripe is kept for merge: give out=PREFIX for its files")
    with _Output(out, "map") as target:
        _command("map", dict(options, out=target.prefix), progress)
        return _map_result(target)


def merge(parts, *, out=None):
    """``grazelab-cli merge``: the stripes of one map (their prefixes, computed with
    ``shard=(k, n)`` and ``out``) joined; returns the whole map as :func:`map` does."""
    if isinstance(parts, (str, os.PathLike)):
        parts = [parts]
    with _Output(out, "map") as target:
        _command("merge", {"out": target.prefix}, positional=[os.fspath(p) for p in parts])
        return _map_result(target)


def family(*, out=None, progress=None, onepp=True, **options):
    """``grazelab-cli family --onepp``: the 1IPP family. Returns the JSON's fields with
    ``table``: a structured array with the CSV's columns (T, omega, V, u1, energy, admissible,
    trace, stability; admissible 1.0/0.0, stability 0..3, NaN where not admissible), the
    command line's .npy viewed without a copy. Options: model, precision, count."""
    with _Output(out, "family") as target:
        _command("family", dict(options, onepp=onepp, out=target.prefix), progress)
        with open(target.prefix + ".json") as handle:
            result = _convert.parse_json(handle.read())
        result["table"] = _convert.table(target.prefix + ".npy", target.prefix + ".csv")
        if not target.kept:
            result.pop("files")
        return result


def modes(*, out=None, progress=None, **options):
    """``grazelab-cli modes``: the atlas of the chain's periodic impacting families up to
    ``max_impacts`` (default 4), energies in ``energy_range`` ("A:B" or (A, B)). Returns the
    JSON's fields; each family of ``families`` has ``table``, its rows as a structured array
    with the CSV's columns."""
    with _Output(out, "modes") as target:
        _command("modes", dict(options, out=target.prefix), progress)
        with open(target.prefix + ".json") as handle:
            result = _convert.parse_json(handle.read())
        folder = os.path.dirname(target.prefix)
        for entry in result["families"]:
            csv_path = os.path.join(folder, entry["file"])
            entry["table"] = _convert.table(csv_path[:-len(".csv")] + ".npy", csv_path)
            if not target.kept:
                entry.pop("file")
        return result


def _directory_command(command, table_file, out, progress, options):
    with _Output(out, command) as target:
        folder = target.prefix
        _, lines, _, _ = _command(command, dict(options, out=folder), progress)
        if not target.kept:  # the files' folder is deleted: the log does not name it
            lines = [line for line in lines if " wrote " not in line]
        result = Result(out=folder if target.kept else None,
                        table=_convert.csv_table(os.path.join(folder, table_file)),
                        log=[_message(line) for line in lines])
        markdown = os.path.join(folder, table_file.rsplit(".", 1)[0] + ".md")
        if not os.path.exists(markdown):
            markdown = os.path.join(folder, "report.md")
        with open(markdown) as handle:
            result["markdown"] = handle.read()
        return result


def report(*, out=None, progress=None, **options):
    """``grazelab-cli report``: every comparison method against the exact solver, error
    against run time. Returns ``table`` (results.csv as a structured array), ``markdown``
    (report.md) and ``log``; with ``out=DIR`` the files stay there (the Python module draws no
    pictures: use grazelab-cli for them). Options: model, start, methods, quick, t_end."""
    return _directory_command("report", "results.csv", out, progress, options)


def stability(*, out=None, progress=None, **options):
    """``grazelab-cli stability``: every method on stiff and extreme cases. Returns ``table``
    (matrix.csv as a structured array), ``markdown`` (matrix.md) and ``log``."""
    return _directory_command("stability", "matrix.csv", out, progress, options)
