# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Keyword arguments to the command line's flags, and its output to Python and NumPy."""

import csv
import io
import decimal
import fractions
import json
import math
import numbers
import os as _os
import re

import numpy as _np

# the flags that take no value (given as True)
_BARE = {"quick", "onepp", "each_impact"}  # (--onepp is bare for family and orbit only)
# options that are flags only
_FLAGS = {"quick", "each_impact"}
# flags whose parts are joined by ':' (an axis NAME:from:to:count, an energy range A:B) or '/'
_JOINED_BY = {"x": ":", "y": ":", "energy_range": ":", "shard": "/"}


_OPTION = re.compile(r"(?<![\w-])--([a-z][a-z0-9]*(?:-[a-z0-9]+)*)")


def keywords_of_options(text):
    """A command line's message in the module's words: each ``--flag-name`` as ``flag_name``."""
    return _OPTION.sub(lambda found: found.group(1).replace("-", "_"), text)


class Result(dict):
    """A command's result: a dict whose keys are the JSON's field names, also readable as
    attributes (``run.events``, ``run.trust.verdict``)."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __setattr__(self, name, value):
        self[name] = value

    def __dir__(self):
        return list(self.keys()) + list(super().__dir__())

    def __repr__(self):
        # one line that says what is inside (the whole is result["key"] or dict(result))
        return "Result(" + ", ".join(f"{key}={_brief(value)}" for key, value in self.items()) + ")"


def _brief(value):
    """A value as a few characters: arrays by shape and type, containers by size."""
    if isinstance(value, _np.ndarray):
        return f"<array {value.shape} {value.dtype}>"
    if isinstance(value, dict):
        return "{" + f"{len(value)} keys" + "}"
    if isinstance(value, (list, tuple)):
        return repr(value) if len(value) <= 2 and len(repr(value)) <= 60 else f"[{len(value)} items]"
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


# options that take several values: a sequence (or their text as the command line writes it)
_VECTORS = {"state", "perturb", "guess", "x", "y", "energy_range", "shard", "methods", "sample_times",
            "masses", "springs", "glo_weights", "bar", "masses_count"}
# options that take words, not numbers


def _text(name, value):
    """One value as the command line's text: the number exactly (a Fraction to 40 digits), or
    a TypeError for what is not a number or text."""
    kind = type(value)  # the common types first, as the general rules below would write them
    if kind is float:
        return str(int(value)) if value.is_integer() and abs(value) < 2.0**53 else repr(value)
    if kind is int:
        return str(value)
    if kind is str:
        return value
    if isinstance(value, _np.ndarray) and value.ndim == 0:
        value = value[()]  # a 0-d array is its number
    if isinstance(value, (bool, _np.bool_)):
        raise TypeError(f"{name}: expected a number or text, got {value!r}")
    if isinstance(value, str):
        return str.__str__(value)  # (NumPy's str_, a str enum: the text itself, as a plain str)
    if isinstance(value, fractions.Fraction):
        # the exact ratio to 40 significant digits: beyond binary128's 34, read in any precision
        with decimal.localcontext() as context:
            context.prec = 40
            return str(decimal.Decimal(value.numerator) / decimal.Decimal(value.denominator))
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, _np.floating) and _np.finfo(value.dtype).nmant > 52:
        # long double: NumPy's shortest decimal that reads back as the same long double
        return _np.format_float_positional(value, unique=True, trim="-")
    if isinstance(value, numbers.Real):
        value = float(value)
        if value.is_integer() and abs(value) < 2.0**53:
            return str(int(value))  # the same number, and a count where one is expected
        # repr: the shortest decimal that reads back as the same double
        return repr(value)
    raise TypeError(f"{name}: expected a number or text, got {type(value).__name__}")


def option_texts(options, bare=_BARE):
    """`options` as (flag name without dashes, text) pairs, the text None for a bare flag: the
    command line's words without the line, as the module hands them to a command. For the
    options in `bare` (--quick, --onepp of family and orbit) True is the bare flag and False
    leaves it out (--quick takes nothing else: any other value is a TypeError); a vector option's
    sequence is joined by ',' (':' for the axes and --energy-range, '/' for --shard); a sequence
    where one value is expected, or a bool anywhere else, is a TypeError."""
    texts = []
    for name, value in options.items():
        flag = name.replace("_", "-")
        kind = type(value)
        if name in _FLAGS and not isinstance(value, (bool, _np.bool_)):
            raise TypeError(f"{name}: expected True or False, got {value!r}")
        if kind is float or kind is str or (kind is int and name not in bare):
            texts.append((flag, _text(name, value)))
            continue
        if name in bare and isinstance(value, (bool, _np.bool_)):
            if value:
                texts.append((flag, None))
            continue
        if isinstance(value, _os.PathLike):
            value = _os.fspath(value)
        sequence = isinstance(value, (list, tuple)) or (isinstance(value, _np.ndarray) and value.ndim > 0)
        if sequence:
            if name not in _VECTORS:
                raise TypeError(f"{name}: expected one value, got {type(value).__name__} {list(value)!r}")
            separator = _JOINED_BY.get(name, ",")
            texts.append((flag, separator.join(_text(name, v) for v in value)))
        else:
            texts.append((flag, _text(name, value)))
    return texts


def _results(value):
    if isinstance(value, dict):
        return Result({k: _results(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_results(v) for v in value]
    return value


def _null_as_nan(value):
    return math.nan if value is None else value


def parse_json(text, exact_decimals=False):
    """A command's JSON as Results. Numbers are Python floats (correctly rounded: the same
    doubles the command line printed). With `exact_decimals` the document is also read with
    its numbers as the decimal text written (binary128 and long double results), under
    ``decimal``."""
    result = _results(json.loads(text))
    if exact_decimals:
        result["decimal"] = _results(json.loads(text, parse_float=str, parse_int=str))
    return result


def csv_text_table(text):
    """A CSV's text (report, stability) as a structured array: a column of numbers as float64
    (empty cells NaN), any other as text."""
    rows = list(csv.reader(io.StringIO(text, newline="")))
    names, body = rows[0], rows[1:]
    columns = []
    for index, name in enumerate(names):
        cells = [row[index] if index < len(row) else "" for row in body]
        try:
            columns.append(_np.array([float(c) if c != "" else math.nan for c in cells], dtype="<f8"))
        except ValueError:
            columns.append(_np.array(cells, dtype=str))
    dtype = _np.dtype([(name, column.dtype) for name, column in zip(names, columns)])
    out = _np.empty(len(body), dtype=dtype)
    for name, column in zip(names, columns):
        out[name] = column
    return out


def multipliers(pairs):
    """The JSON's multipliers, [re, im] pairs, as a NumPy complex array."""
    return _np.array([complex(re, im) for re, im in pairs], dtype=complex)

