# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""GrazeLab from Python: the exact simulator of chains of masses and springs against a rigid
stop (the note's two masses in 1:2 internal resonance, or N masses in any resonance:
``Chain``), its maps and its nonlinear normal modes (docs/python.md).

Each function is a command of ``grazelab-cli`` run in this process by the command line's own
code. Its keywords are that command's flags in snake_case (``t_end`` is ``--t-end``), with the
same meaning; a keyword left at None takes the command line's default, which the docstring
says. Each result field has the JSON's name. Tables are NumPy structured arrays with the CSV's
column names, maps a dict of 2-D arrays (row = y, column = x).

Numbers are taken as Python or NumPy numbers (0-d arrays too), ``fractions.Fraction`` (the exact
ratio, to 40 digits) or decimal text (read in the run's precision); a keyword that is not the
function's, or a list where a number is expected, raises ``TypeError``. Invalid values raise
``ValueError`` with the command line's one-line message, its options named by their keywords; Ctrl+C stops a
running computation within a second and raises ``KeyboardInterrupt``; the GIL is released while
the core computes, so threads run computations at once. Long calls take ``progress``, a callable
``progress(fraction, text)`` (fraction None when not known), called on the calling thread.

    >>> import grazelab as gl
    >>> run = gl.simulate(m2=0.5, glo=0.5, perturb=(0, 0, 0, -0.05), contacts=200)
    >>> run.events["t"][:3], run.trust.verdict
"""

import os as _os
import warnings as _warnings
from typing import Callable as _Callable
from typing import Optional as _Optional
from typing import Sequence as _Sequence
from typing import Union as _Union

import numpy as _np

from . import _convert
from ._convert import Result
from ._native import bar as _bar
from ._native import family as _family
from ._native import glo_set as _glo_set
from ._native import impacts_family as _impacts_family
from ._native import info as _info
from ._native import map as _map
from ._native import merge as _merge
from ._native import NotWritten as _NotWritten
from ._native import Refused as _Refused
from ._native import modes as _modes
from ._native import orbit as _orbit
from ._native import prepare_chain as _prepare_chain
from ._native import report as _report
from ._native import simulate as _simulate_here
from ._native import simulate_chain as _simulate_chain
from ._native import stability as _stability
from ._native import version as __version__

# map and help are left out of a star import: they would hide Python's own
__all__ = ["Chain", "info", "simulate", "merge", "family", "orbit", "modes", "glo_set", "bar", "report", "stability",
           "Result", "GrazeLabWarning", "MAX_EVENTS"]

# ``progress(fraction, text)``: fraction in [0, 1], or None when not known. (A number keyword,
# annotated float, also takes an int, a NumPy number or 0-d array, a Fraction or decimal text.)
_Progress = _Callable[[_Optional[float], str], None]

# a run's events are held in memory (80 bytes each): beyond this many, stream them to a file
# with grazelab-cli simulate --format csv or jsonl, whose memory stays bounded
MAX_EVENTS = 2**25

# a designed (resonant) chain's run of at most this many contacts (without samples, which may
# be millions) is computed on the calling thread, its options handed over by name (no
# command-line text, no thread): ~0.1 s in binary128, so that Ctrl+C, which nothing polls
# meanwhile, still ends it within a second
_DIRECT_CONTACTS = 1000


class GrazeLabWarning(UserWarning):
    """A result came back that its own error estimate does not trust (verdict unreliable)."""


def _typed(call, options, bare=()):
    """A typed command of the module (info, glo_set, orbit): its options that are not None by
    name (those in ``bare`` as bare flags), its document as Results; its refusal a ValueError in
    the module's words."""
    given = _convert.option_texts({name: value for name, value in options.items() if value is not None}, bare)
    try:
        return call(given, Result)
    except _Refused as error:
        raise ValueError(_message(str(error))) from None


def _message(line):
    """The command line's one-line message in the module's words: its prefix dropped and each
    option named by its keyword (``--glo-weights`` -> ``glo_weights``)."""
    for prefix in ("grazelab-cli: ", "grazelab-cli report: ", "grazelab-cli stability: "):
        if line.startswith(prefix):
            line = line[len(prefix):]
            break
    return _convert.keywords_of_options(line)


def help():  # noqa: A001 (Python's help() still works on the functions)
    """The module's functions with their keywords and defaults; ``help(grazelab.simulate)``
    says what each keyword means."""
    import inspect
    for name in __all__:
        value = globals()[name]
        if callable(value) and not isinstance(value, type):
            summary = (value.__doc__ or "").strip().splitlines()[0]
            print(f"{name}{inspect.signature(value)}\n    {summary}")
    print("map" + str(inspect.signature(map)) + "\n    " + map.__doc__.strip().splitlines()[0])


# The chain's keywords, shared by every command that takes a chain:
_CHAIN_DOC = """    m1: mass 1 [mass] (default 1).
    m2: mass 2, the one that hits the stop [mass] (default 0.5).
    k1: stiffness from the wall to mass 1 [force/length] (default 1).
    k2: stiffness from mass 1 to mass 2, as given: no resonance imposed (a detuned chain);
        default: from the 1:2 design of ``branch``.
    gap: gap d between mass 2 at rest and the stop [length] (default 1).
    branch: "upper" (default) or "lower": the 1:2 design's branch (excludes ``k2``).
"""
_PRECISION_DOC = """    precision: "auto" (default: double, the whole run again in long double, then binary128,
        when a contact touches the stop within rounding), "double", "long" or "quad"
        (binary128). Numbers are read and written in it.
"""
_START_DOC = """    glo: start on GLO_lambda data, this lambda (default 0.5 when no other start is given).
    onepp: start on the one-impact-per-period orbit of period T [time] (T < T2, near T2).
    state: start from (u1, u2, v1, v2) [length, length/time].
    perturb: add (du1, du2, dv1, dv2) to the start.
"""


_TWO_MASS_CHAIN_DOC = """    masses, springs, right_spring, stop_mass, frequencies, design_branch: any chain, as in
        ``info``; ``masses=(1, 0.5), frequencies=(2, 1)`` is the note's chain (``design_branch``
        1 upper, 2 lower), with the same bits as the two-mass keywords.
"""


def _documented(function):
    """Fills a docstring's shared keyword paragraphs: {chain}, {precision}, {start}, {two_mass_chain}."""
    function.__doc__ = (function.__doc__.replace("{chain}", _CHAIN_DOC)
                        .replace("{precision}", _PRECISION_DOC).replace("{start}", _START_DOC)
                        .replace("{two_mass_chain}", _TWO_MASS_CHAIN_DOC))
    return function


@_documented
def info(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
         gap: float = 1.0, branch: _Optional[str] = None, precision: str = "auto",
         masses: _Optional[_Sequence[float]] = None, springs: _Optional[_Sequence[float]] = None,
         right_spring: _Optional[float] = None, stop_mass: _Optional[int] = None,
         frequencies: _Optional[_Sequence[int]] = None, design_branch: _Optional[int] = None) -> Result:
    """The chain's derived quantities (``grazelab-cli info``): k2, omega1, omega2, T1, T2, P,
    lambda_star, as the JSON's ``model`` object. In long or quad precision the numbers are also
    under ``decimal`` as the exact text written.

    With ``masses`` (a chain of N masses, in double for now): ``chain``, ``modes`` (each mode's
    omega, period, shape, node_at_stop and harmonic number, fastest first) and ``ratios``
    (commensurate, harmonics, omega0, T, detuning).

    Keywords:
{chain}{precision}    masses: m1, ..., mN [mass]: a chain of N masses (then the two-mass keywords
        stay at their defaults).
    springs: k1, ..., kN [force/length] of ``masses``: wall to m1, then between neighbours.
    right_spring: k(N+1) from the last mass to a right wall (default none).
    stop_mass: the mass the stop acts on, 1 to N (default the last).
    frequencies: n1, ..., nN, fastest first: design the springs of ``masses`` so that the
        frequencies are in the ratio n1 : ... : nN (``springs`` then gives k1 alone, the scale,
        default 1). ``design`` lists every design found (each positive solution of the design
        equations, checked against the designed chain's spectrum), ordered by k2, largest first;
        a request no chain meets raises ValueError saying why.
    design_branch: which design the chain takes, 1 to the number found (default 1)."""
    options = dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch, precision=precision)
    if masses is not None:
        options = dict(gap=gap, precision=precision,
                       **_mass_chain_options(masses, springs, right_spring, stop_mass, frequencies,
                                             design_branch, dict(m1=m1, m2=m2, k1=k1, k2=k2, branch=branch)))
    elif frequencies is not None or design_branch is not None:
        raise ValueError("frequencies and design_branch design the springs of a chain given by masses")
    return _typed(_info, options)


@_documented
def glo_set(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
            gap: float = 1.0, branch: _Optional[str] = None, masses: _Optional[_Sequence[float]] = None,
            springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
            stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
            design_branch: _Optional[int] = None, directions: _Optional[int] = None) -> Result:
    """Which affine combinations of a resonant chain's GLOMs are grazing linear orbits
    (``grazelab-cli glo-set``): W_lambda = sum_j lambda_j GLOM_j grazes exactly when
    max over theta of sum_j lambda_j cos(n_j theta) is 1. Returns ``chain``, ``modes`` (the modes
    that move the stopped mass, 1-based), their ``harmonics`` and ``grazing_set``: for two modes
    an interval of lambda (weights (1 - lambda, lambda)) with each end bracketed (``low`` and
    ``high`` graze, ``low_out`` and ``high_out`` do not; the note's chain gives [0, 4/3]); for
    three a convex region of the (lambda2, lambda3) plane, its ``boundary`` along ``directions``
    rays from (1/3, 1/3). A chain whose frequencies are not commensurate, or with more than three
    modes moving the stopped mass, raises ValueError saying so.

    Keywords:
{chain}    masses, springs, right_spring, stop_mass, frequencies, design_branch: a chain of N masses,
        as in ``info``.
    directions: three modes: the rays along which the boundary is found (default 72)."""
    options = dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch, directions=directions)
    if masses is not None:
        options = dict(gap=gap, directions=directions,
                       **_mass_chain_options(masses, springs, right_spring, stop_mass, frequencies,
                                             design_branch, dict(m1=m1, m2=m2, k1=k1, k2=k2, branch=branch)))
    elif frequencies is not None or design_branch is not None or springs is not None:
        raise ValueError("springs, frequencies and design_branch describe a chain given by masses")
    return _typed(_glo_set, options)


def bar(*, bar: _Optional[_Sequence[float]] = None, speed: _Optional[float] = None,
        masses_count: _Optional[_Sequence[int]] = None, stop_end: _Optional[str] = None,
        each_impact: bool = False) -> Result:
    """An elastic bar thrown at a rigid wall, lumped into N masses for each N of ``masses_count``
    and each computed exactly (``grazelab-cli bar``; docs/model.md section 13), against the
    continuum's answer (contact 2L/c, force E S v0 / c, rebound -v0, no vibration). Returns
    ``bar``, ``continuum``, ``rows`` (per N: ``impacts``, ``duration``, ``impulse``, ``rebound``,
    ``vibration``, ``mean_force``, each also ``relative`` to the continuum, ``status`` and the
    ``precision`` it took) and ``convergence`` (per quantity: the measured ``orders`` and the limit
    ``extrapolated`` from the last three rows alone).

    Keywords:
    bar: (E, rho, S, L) in Pa, kg/m3, m2, m (default the steel bar 210e9, 7800, 3.14e-4, 1).
    speed: its speed onto the wall, m/s (default 0.1).
    masses_count: the numbers of masses, ascending, 1 to 2000 (default (10, 100, 1000)).
    stop_end: "last" (the wall ahead of mass N, default) or "first" (behind mass 1: the mirror image).
    each_impact: also list every impact's time and impulse (``impact_times``, ``impact_impulses``)."""
    return _typed(_bar, dict(bar=bar, speed=speed, masses_count=masses_count, stop_end=stop_end,
                             each_impact=each_impact), bare=("each_impact",))


def _mass_chain_options(masses, springs, right_spring, stop_mass, frequencies, design_branch, two_mass):
    """The options of a chain of N masses, the two-mass keywords beside it refused."""
    given = {name: value for name, value in two_mass.items()
             if value is not None and value != {"m1": 1.0, "m2": 0.5, "k1": 1.0}.get(name)}
    if given:
        raise ValueError(f"masses describes the whole chain: give it with springs, or "
                         f"{', '.join(given)} and the other two-mass keywords, not both")
    options = dict(masses=masses, springs=springs, right_spring=right_spring, stop_mass=stop_mass,
                   design_branch=design_branch)
    if frequencies is not None:
        if (not isinstance(frequencies, (list, tuple, _np.ndarray))
                or not all(isinstance(n, (int, _np.integer)) and not isinstance(n, bool) for n in frequencies)):
            raise TypeError("frequencies: a sequence of whole numbers n1, ..., nN (fastest first)")
        options["frequencies"] = ":".join(str(int(n)) for n in frequencies)
    return options


def _chain_keywords(options, two_mass, masses, springs, right_spring, stop_mass, frequencies, design_branch):
    """`options` with the chain: the two-mass keywords `two_mass`, or the chain given by masses."""
    if masses is None:
        if any(value is not None for value in (springs, right_spring, stop_mass, frequencies, design_branch)):
            raise ValueError("springs, right_spring, stop_mass, frequencies and design_branch describe a chain "
                             "given by masses")
        return dict(options, **two_mass)
    chain = _mass_chain_options(masses, springs, right_spring, stop_mass, frequencies, design_branch,
                                {name: value for name, value in two_mass.items() if name != "gap"})
    return dict(options, gap=two_mass["gap"], **chain)


@_documented
def simulate(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
             gap: float = 1.0, branch: _Optional[str] = None, precision: str = "auto",
             glo: _Optional[float] = None, onepp: _Optional[float] = None, state: _Optional[_Sequence[float]] = None,
             perturb: _Optional[_Sequence[float]] = None, contacts: _Optional[int] = None,
             t_end: _Optional[float] = None, search_steps: _Optional[int] = None, trust: str = "auto",
             events: bool = True, samples: _Union[float, _Sequence[float], None] = None,
             progress: _Optional[_Progress] = None, masses: _Optional[_Sequence[float]] = None,
             springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
             stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
             design_branch: _Optional[int] = None, glo_weights: _Optional[_Sequence[float]] = None) -> Result:
    """One exact run (``grazelab-cli simulate``). Returns the JSON's fields, one document for every
    chain however it is given (chain, model for the note's chain, initial, final, stop_reason,
    message, contacts, energy, accuracy, trust, precision) with ``events`` a
    structured array of the columns t, type, u1, u2, v1_pre, v2_pre, v2_post (the arrays the core
    filled, no copy; for N masses u1..uN, v1_pre..vN_pre and the stopped mass's v<s>_post, the
    command line's CSV columns) and ``notes`` the command line's notes. A run in long double or binary128
    also has ``events_decimal``: each numeric column as the exact decimal text the command line
    writes, and ``decimal``: the JSON's numbers as text. Warns (GrazeLabWarning) when the run's
    own error estimate says unreliable.

    Keywords:
{chain}{precision}{start}    contacts: stop after this many contacts (default 100 when no ``t_end``; at most
        ``MAX_EVENTS``: the events are held in memory).
    t_end: stop at this time [time] (it also bounds the contact search of a detuned chain).
    search_steps: detuned chains: the most steps one flight's contact search may take (default
        about a second's worth); running out stops the run with stop_reason search-budget.
    trust: the run's error estimate: "auto" (default: a shadow run one precision up while it
        costs about the run itself, then extrapolation), "full" or "off".
    events: False for the run's statistics only (contacts, energy, accuracy, trust, final
        state): no event is kept, so no ``MAX_EVENTS`` bound; ``events`` is then None.
    samples: the state on a time grid as well: a step DT (every DT from t = 0 to the run's end)
        or the times themselves, ascending [time]. ``samples`` is then a structured array
        (t, u1, u2, v1, v2), in double, a time past the run's end left out (at most 4 000 000:
        ``samples_truncated`` says when more were asked for).
    progress: ``progress(fraction, text)``, called on the calling thread.
    masses, springs, right_spring, stop_mass, frequencies, design_branch: a chain of N masses, as
        in ``info`` (then the two-mass keywords stay at their defaults). Its run starts from
        ``state`` = (u1, ..., uN, v1, ..., vN) or from ``glo_weights``, plus ``perturb`` (2N
        numbers), with ``contacts`` and ``t_end``; the result has ``chain`` (with the
        common ``period`` of a commensurate chain), ``initial``, ``events`` (the structured
        array above; None with events=False, which holds none and so takes any number of
        contacts), ``final`` (t, u1..uN, v1..vN), ``stop_reason``, ``message``,
        ``contacts`` (total and by type), ``energy``, ``trust`` (the run again one precision up, compared event
        by event: the whole run with trust="full", its first contacts with "auto") and ``precision``; or from ``onepp`` = T, the 1IPP orbit of that period
        right after its impact; ``samples`` a structured array (t, u1..uN, v1..vN). No
        ``glo``: ``glo_weights`` instead; sticks hold the stopped mass until their release, as for
        two masses.
    glo_weights: lambda_1, ..., lambda_N (fastest mode first, summing to 1): a chain of N masses
        starts on GLO_lambda = sum_j lambda_j GLOM_j at its touch (GLOM_j: mode j alone, its top
        on the stop); ``glo_set`` says which weights graze.
"""
    if masses is not None:
        # (the two-mass keywords beside masses refused)
        _mass_chain_options(masses, springs, right_spring, stop_mass, frequencies, design_branch,
                            dict(m1=m1, m2=m2, k1=k1, k2=k2, branch=branch))
        chain = Chain(masses=masses, springs=springs, right_spring=right_spring, stop_mass=stop_mass,
                      frequencies=frequencies, design_branch=design_branch, gap=gap)
        return chain._simulate(("precision", precision, "state", state, "glo", glo, "onepp", onepp, "perturb", perturb,
                                "contacts", contacts, "t-end", t_end, "trust", trust, "glo-weights", glo_weights,
                                "search-steps", search_steps),
                               events, samples, progress, contacts, t_end)
    if frequencies is not None or design_branch is not None or springs is not None or glo_weights is not None:
        raise ValueError("springs, frequencies, design_branch and glo_weights describe a chain given by masses")
    flat = ("m1", m1, "m2", m2, "k1", k1, "k2", k2, "gap", gap, "branch", branch, "precision", precision, "glo", glo,
            "onepp", onepp, "state", state, "perturb", perturb, "contacts", contacts, "t-end", t_end,
            "search-steps", search_steps, "trust", trust)
    # a short run of a designed chain on the calling thread (its every flight decided within a
    # period); anything longer on a thread of its own that Ctrl+C stops
    direct = ((contacts is None or (type(contacts) is int and 0 <= contacts <= _DIRECT_CONTACTS
                                     and contacts <= MAX_EVENTS))
              and progress is None and k2 is None and t_end is None and samples is None)
    if direct:
        # (the common short call without the text path's frames: it costs about the run itself)
        try:
            answer = _simulate_here(flat, Result, events, MAX_EVENTS, not events, True)
        except ValueError as error:
            raise ValueError(_message(str(error))) from None
        if answer is not None:
            result, decimals = answer
            if decimals is None and result["trust"]["verdict"] != "unreliable":
                return result
            return _simulated(result, decimals)
    else:
        _check_held_events(events, contacts)
        flat = _with_samples(flat, samples)
    answer = _run_simulate(lambda options: _simulate_here(options, Result, events, MAX_EVENTS, not events, direct),
                           flat)
    if progress is not None:
        progress(1.0, "done")
    result, decimals = answer
    if decimals is None and result["trust"]["verdict"] != "unreliable":
        return result  # (the common case, without another call)
    return _simulated(result, decimals)


class Chain:
    """A chain of N masses read, checked and designed once: every run of it reuses its springs
    (designed for ``frequencies`` when asked), its modes and its error estimate's shadow chain,
    so that a script running it many times pays for them once (a 3:2:1 design costs
    milliseconds, a short run microseconds).

    Keywords (as ``simulate``'s chain given by masses):
    masses: m1, ..., mN [mass].
    springs: k1, ..., kN [force/length] (k1 alone, the scale, with ``frequencies``).
    right_spring: a spring from mN to a right wall [force/length] (default none).
    stop_mass: the mass that meets the stop, 1-based (default the last).
    frequencies: n1, ..., nN: springs designed so that w_j = n_j w0 (fastest first).
    design_branch: which design of those ratios, 1-based (default 1).
    gap: the stop's distance from the stopped mass's rest position [length].

    ``chain.description`` is the chain as the documents write it (its springs as designed, the
    common ``period`` of a commensurate chain); ``chain.simulate(...)`` runs it."""

    def __init__(self, *, masses: _Sequence[float], springs: _Optional[_Sequence[float]] = None,
                 right_spring: _Optional[float] = None, stop_mass: _Optional[int] = None,
                 frequencies: _Optional[_Sequence[int]] = None, design_branch: _Optional[int] = None,
                 gap: float = 1.0):
        options = _mass_chain_options(masses, springs, right_spring, stop_mass, frequencies, design_branch, {})
        options["gap"] = gap
        given = _convert.option_texts({name: value for name, value in options.items() if value is not None})
        try:
            self._prepared = _prepare_chain([part for pair in given for part in pair])
        except ValueError as error:
            raise ValueError(_message(str(error))) from None
        self.description = self._prepared.describe(Result)
        self._commensurate = self._prepared.period > 0  # (read once: a native call per run costs)

    def __repr__(self):
        return f"Chain({self.description!r})"

    def simulate(self, *, precision: str = "auto", state: _Optional[_Sequence[float]] = None,
                 glo_weights: _Optional[_Sequence[float]] = None, onepp: _Optional[float] = None,
                 perturb: _Optional[_Sequence[float]] = None, contacts: _Optional[int] = None,
                 t_end: _Optional[float] = None, trust: str = "auto", events: bool = True,
                 samples: _Union[float, _Sequence[float], None] = None,
                 progress: _Optional[_Progress] = None, search_steps: _Optional[int] = None) -> Result:
        """One exact run of this chain: the keywords and the result of ``simulate`` with
        ``masses`` (the same bits), the chain not read nor designed again."""
        return self._simulate(("precision", precision, "state", state, "glo-weights", glo_weights, "onepp", onepp,
                               "perturb", perturb, "contacts", contacts, "t-end", t_end, "trust", trust,
                               "search-steps", search_steps),
                              events, samples, progress, contacts, t_end)

    def _simulate(self, flat, events, samples, progress, contacts, t_end):
        """The run of the options `flat` (name, value, ...; None: not given, `contacts` and
        `t_end` among them) with `samples`."""
        # a short run of a commensurate chain (every flight decided within a period) on the
        # calling thread; anything longer on a thread of its own that Ctrl+C stops
        direct = (progress is None and t_end is None and samples is None and self._commensurate
                  and (contacts is None or (type(contacts) is int and 0 <= contacts <= _DIRECT_CONTACTS)))
        if direct and events and (contacts is None or contacts <= MAX_EVENTS):
            # (the common short call without the other path's frames: it costs about the run itself)
            try:
                answer = _simulate_chain(self._prepared, flat, Result, False, True, MAX_EVENTS)
            except ValueError as error:
                raise ValueError(_message(str(error))) from None
            if answer is not None:
                result, decimals = answer
                if decimals is None and result["trust"]["verdict"] != "unreliable":
                    return result
                return _simulated(result, decimals)
        flat = _with_samples(flat, samples)
        _check_held_events(events, contacts)
        answer = _run_simulate(
            lambda options: _simulate_chain(self._prepared, options, Result, not events, direct, MAX_EVENTS), flat)
        if progress is not None:
            progress(1.0, "done")
        return _simulated(*answer)


def _with_samples(flat, samples):
    """The options (name, value, ...) with the samples asked for: a step, or the times."""
    if samples is None:
        return flat
    grid = isinstance(samples, (list, tuple)) or (isinstance(samples, _np.ndarray) and samples.ndim > 0)
    return flat + ("sample-times" if grid else "sample-step", samples)


def _run_simulate(call, flat):
    """call(options) with the options (name, value, ...) handed over as they are, or, when one
    is of a type the native call does not read (NumPy scalars, Fraction), as the command line's
    text; a refusal as ValueError in the module's words."""
    try:
        answer = call(flat)
        if answer is None:
            given = {name.replace("-", "_"): value for name, value in zip(flat[::2], flat[1::2]) if value is not None}
            answer = call(tuple(part for pair in _convert.option_texts(given, bare=()) for part in pair))
            if answer is None:
                raise TypeError("simulate: a keyword's value is of a type it does not read")
    except ValueError as error:
        raise ValueError(_message(str(error))) from None
    return answer


def _check_held_events(events, contacts):
    """The number of contacts asked for (None when not given or not a number: the command line
    says what is wrong with it); ValueError when the events kept would pass MAX_EVENTS."""
    if contacts is None or type(contacts) is int:
        count = contacts  # (the common case, without the text)
    else:
        try:
            count = int(_convert._text("contacts", contacts))
        except (TypeError, ValueError):
            return None
    if events and count is not None and count > MAX_EVENTS:
        raise ValueError(f"contacts: {count} events would take {count * 80 / 1e9:.1f} GB "
                         f"in memory or more (at most grazelab.MAX_EVENTS = {MAX_EVENTS}); stream them "
                         f"to a file with grazelab-cli simulate --format csv")
    return count


def _simulated(result, decimals):
    """A run's result (its document with its events and notes) and the events' decimal text (None
    in double), as simulate returns it for every chain."""
    if decimals is not None:
        columns = [name for name in result["events"].dtype.names if name != "type"]
        text = _np.array(decimals, dtype=str).reshape(-1, len(columns))
        result["events_decimal"] = {name: text[:, i] for i, name in enumerate(columns)}
    if result.get("trust", {}).get("verdict") == "unreliable":
        _warnings.warn(f"simulate: the run's error estimate says unreliable: "
                       f"{result['trust'].get('reason', '')}", GrazeLabWarning, stacklevel=3)
    return result


@_documented
def orbit(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
          gap: float = 1.0, branch: _Optional[str] = None, precision: str = "auto",
          onepp: _Optional[float] = None, impacts: _Optional[int] = None, energy: _Optional[float] = None,
          period: _Optional[float] = None, guess: _Optional[_Sequence[float]] = None,
          masses: _Optional[_Sequence[float]] = None,
          springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
          stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
          design_branch: _Optional[int] = None) -> Result:
    """One periodic impacting orbit with its exact multipliers (``grazelab-cli orbit``): the
    1IPP orbit of period ``onepp``, or the orbit with ``impacts`` impacts per period at energy
    ``energy`` (or of period ``period``) found by Newton from ``guess``. Raises ValueError when Newton does not converge
    or the orbit is not admissible (the command line's message). In long or quad precision the
    numbers are also under ``decimal`` as exact text. ``multipliers`` is a NumPy complex array
    (the JSON's [re, im] pairs). The orbits of any other chain (N masses, a right wall, a
    stop on any mass), and those at a fixed ``period``, come from its 2N x 2N monodromy: ``multipliers`` then holds its 2N - 2
    nontrivial multipliers by angle, with ``multiplier_errors``, ``on_circle`` and ``krein`` (the
    Krein signature, +1, -1 or 0) as NumPy arrays beside them, and ``stability`` one of
    elliptic, hyperbolic, flip-hyperbolic, complex-quadruplet and undecided.

    Keywords:
{chain}{precision}    onepp: the period T of the one-impact-per-period orbit [time] (as in ``simulate``).
    impacts: impacts per period K of the orbit sought.
    energy: its energy E [energy].
    period: or its period T [time] (with ``impacts``).
    guess: a guess of the orbit's point just after an impact on H: u then v of every mass but
        the stopped one ((u1, v1) for two masses), and with ``period`` the stopped mass's
        speed v_s < 0 last.
{two_mass_chain}"""
    options = _chain_keywords(dict(precision=precision, impacts=impacts, energy=energy, period=period,
                                   guess=guess),
                              dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch),
                              masses, springs, right_spring, stop_mass, frequencies, design_branch)
    if onepp is not None:
        if period is not None:
            raise ValueError("orbit: give onepp (the 1IPP orbit's period) or period (with impacts), not both")
        options.update(onepp=True, period=onepp)
    result = _typed(_orbit, options, ("onepp",))
    result["multipliers"] = _convert.multipliers(result["multipliers"])
    if "krein" in result:  # a chain of N masses: each multiplier's error bar, circle flag, signature
        for name, dtype in (("multiplier_errors", float), ("on_circle", bool), ("krein", _np.int64)):
            result[name] = _np.array(result[name], dtype=dtype)
    return result


def _map_result(result, points):
    """A map handed over in memory: its document (with ``files`` when written, as the file
    PREFIX.json has it) and its points (one structured array, a field per quantity), each
    quantity a 2-D view of them, no copy."""
    shape = tuple(result["run"]["shape"])
    result["arrays"] = {name: points[name].reshape(shape) for name in points.dtype.names}
    # the columns' and rows' coordinates, as the spec says: numpy.linspace(from, to, count)
    for axis in ("x", "y"):
        spec = result["spec"][axis]
        result[axis] = _np.linspace(spec["from"], spec["to"], spec["count"])
    # a stripe's rows are its own: its coordinates too
    rows = result["run"].get("rows")
    if rows is not None:
        result["y"] = result["y"][rows[0]:rows[1]]
    return result


@_documented
def map(*, x: _Union[str, _Sequence], y: _Union[str, _Sequence], m1: float = 1.0, m2: float = 0.5,  # noqa: A001
        k1: float = 1.0, k2: _Optional[float] = None, gap: float = 1.0, branch: _Optional[str] = None,
        precision: str = "auto", glo: _Optional[float] = None, onepp: _Optional[float] = None,
        state: _Optional[_Sequence[float]] = None, perturb: _Optional[_Sequence[float]] = None,
        contacts: _Optional[int] = None, trust: str = "off", threads: _Optional[int] = None,
        shard: _Union[str, _Sequence[int], None] = None, picture: _Optional[str] = None,
        out=None, progress: _Optional[_Progress] = None, masses: _Optional[_Sequence[float]] = None,
        springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
        stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
        design_branch: _Optional[int] = None, glo_weights: _Optional[_Sequence[float]] = None) -> Result:
    """A 2-D grid of exact runs reduced to summaries (``grazelab-cli map``). Returns the JSON's
    ``spec`` and ``run`` with ``arrays``: one 2-D array per quantity (row = y, column = x;
    counts int64, the rest float64), equal to the command line's .npy; ``x`` and ``y`` in the
    result are the columns' and rows' coordinates.

    Keywords:
    x, y: the columns and the rows, "NAME:from:to:count" or (NAME, from, to, count); NAME is
        one of u1, v1, v2, lambda, epsilon, mass-ratio, gap, detuning.
{chain}    precision: "auto" (default; each point raised where a contact needs it) or "double".
{start}    contacts: contacts of each run (default 100).
    trust: "off" (default: horizon NaN) or "auto" (a shadow run per point).
    threads: threads (default: all cores).
    shard: (K, N) or "K/N": compute stripe K of N of the rows only; join the stripes with
        :func:`merge` (needs ``out``).
    picture: with ``out``, the command line would draw this quantity; the module draws none.
    out: a prefix: the command line's files are written there too (without pictures); without
        it the map stays in memory and no file is written.
    progress: ``progress(fraction, text)``, called on the calling thread.
    masses, springs, right_spring, stop_mass, frequencies, design_branch: a chain of N masses, as
        in ``simulate``; its axes are u<i> or v<i> (i from 1 to N) of the start ``state`` (2N
        numbers, default the grazing-start plane: the stopped mass at rest on the stop, all else 0), its flights' ratios in units of the chain's period (the
        common period T, else the slowest mode's), the horizon with ``trust`` "auto" as for two masses.
        Axes w<j> instead (both of them, three modes or more) are GLO weights lambda_j: every run
        starts on GLO_lambda at its touch plus ``perturb`` (2N numbers), lambda ``glo_weights``
        (default 0) with the axes' set and the last weight no axis sets balancing the others.
    glo_weights: a chain of N masses' base GLO weights for axes w<j> (fastest mode first).
"""
    if shard is not None and out is None:
        raise ValueError("shard: a stripe is kept for merge: give out=PREFIX for its files")
    if masses is not None:
        options = dict(x=x, y=y, gap=gap, precision=precision, glo=glo, onepp=onepp, state=state,
                       perturb=perturb, contacts=contacts, trust=trust, threads=threads, shard=shard,
                       picture=picture, glo_weights=glo_weights,
                       **_mass_chain_options(masses, springs, right_spring, stop_mass, frequencies,
                                             design_branch, dict(m1=m1, m2=m2, k1=k1, k2=k2, branch=branch)))
    else:
        options = dict(x=x, y=y, m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch, precision=precision,
                       glo=glo, onepp=onepp, state=state, perturb=perturb, contacts=contacts, trust=trust,
                       threads=threads, shard=shard, picture=picture, springs=springs, right_spring=right_spring,
                       stop_mass=stop_mass, design_branch=design_branch, glo_weights=glo_weights)
    out = None if out is None else _os.fspath(out)
    return _map_result(*_files_command(_map, dict(options, out=out), progress))


def merge(parts, *, out=None):
    """``grazelab-cli merge``: the stripes of one map (their prefixes, computed with
    ``shard=(k, n)`` and ``out``) joined; returns the whole map as :func:`map` does."""
    if isinstance(parts, (str, _os.PathLike)):
        parts = [parts]
    out = None if out is None else _os.fspath(out)
    try:
        document, points = _merge([_os.fspath(p) for p in parts], out, Result)
    except _Refused as error:
        raise ValueError(_message(str(error))) from None
    except _NotWritten as error:
        raise OSError(_message(str(error))) from None
    return _map_result(document, points)


@_documented
def family(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
           gap: float = 1.0, branch: _Optional[str] = None, precision: str = "auto",
           count: int = 2000, out=None, progress: _Optional[_Progress] = None,
           masses: _Optional[_Sequence[float]] = None, springs: _Optional[_Sequence[float]] = None,
           right_spring: _Optional[float] = None, stop_mass: _Optional[int] = None,
           frequencies: _Optional[_Sequence[int]] = None, design_branch: _Optional[int] = None,
           impacts: _Optional[int] = None, energy: _Optional[float] = None, period: _Optional[float] = None,
           guess: _Optional[_Sequence[float]] = None,
           energy_range: _Union[str, _Sequence[float], None] = None) -> Result:
    """The 1IPP family (``grazelab-cli family --onepp``), or with ``impacts`` the family of the
    kIPP orbit found from ``guess`` at ``energy`` (or ``period``), as ``orbit`` finds it, followed
    both ways in energy to its ends (``grazelab-cli family --impacts``): then the result is
    ``modes``'s for an atlas of that one family (``families[0]`` with its ``table``: energy,
    period, omega, class, min_impact_speed, u1..uN, v1..vN, muK_re, muK_im, muK_krein), ``count``
    the most orbits followed each way and ``energy_range`` (A, B) the energies followed (default
    1e-4 to 1e4 times the orbit's). Returns the JSON's fields with
    ``table``: a structured array with the CSV's columns (T, omega, V, u1, energy, admissible,
    trace, stability; admissible 1.0/0.0, stability 0..4 (4: undecided in this precision), NaN where not admissible): the
    command's own rows, without a copy.

    With ``masses`` (a chain of N masses, in double): periods in (0, T_max), T_max the common
    period (or the slowest mode's), the columns T, omega, V, energy, admissible, u1 ... uN, and
    ``grazing_limit``: Theorem 2.1's weights of the GLO the data tend to as T -> T_max.

    Keywords:
{chain}{precision}    count: periods T in (0, T2) (default 2000).
    out: a prefix: the command line's files are kept there (without pictures).
    progress: ``progress(fraction, text)``, called on the calling thread.
    masses, springs, right_spring, stop_mass, frequencies, design_branch: a chain of N masses, as
        in ``info``.
"""
    if impacts is not None:
        options = _chain_keywords(dict(precision=precision, impacts=impacts, energy=energy, period=period,
                                       guess=guess, energy_range=energy_range, count=count),
                                  dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch),
                                  masses, springs, right_spring, stop_mass, frequencies, design_branch)
        result, tables = _files_command(_impacts_family, dict(options, out=out), progress)
        for entry, table in zip(result["families"], tables):
            entry["table"] = table
        return result
    if energy is not None or period is not None or guess is not None or energy_range is not None:
        raise ValueError("energy, period, guess and energy_range describe the family of impacts=K orbits")
    options = dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch, precision=precision,
                   count=count, onepp=True)
    if masses is not None:
        options = dict(gap=gap, precision=precision, count=count, onepp=True,
                       **_mass_chain_options(masses, springs, right_spring, stop_mass, frequencies,
                                             design_branch, dict(m1=m1, m2=m2, k1=k1, k2=k2, branch=branch)))
    elif frequencies is not None or design_branch is not None or springs is not None:
        raise ValueError("springs, frequencies and design_branch describe a chain given by masses")
    # numbers are floats; in long or quad also as the exact text written, under ``decimal``
    result, table = _files_command(_family, dict(options, out=out), progress, ("onepp",))
    result["table"] = table
    return result


@_documented
def modes(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
          gap: float = 1.0, branch: _Optional[str] = None, precision: str = "auto",
          max_impacts: int = 4, energy_range: _Union[str, _Sequence[float], None] = None,
          out=None, progress: _Optional[_Progress] = None, masses: _Optional[_Sequence[float]] = None,
          springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
          stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
          design_branch: _Optional[int] = None) -> Result:
    """The atlas of the chain's periodic impacting families (``grazelab-cli modes``). Returns
    the JSON's fields; each family of ``families`` has ``table``, its rows as a structured
    array with the CSV's columns. The note's 1:2 chain takes its two-mass atlas; any other chain
    (``masses``: N masses, a wall, another stop; or two masses off the design) the atlas of any
    chain: ``chain`` in place of ``model``, and columns energy, period, omega, class, min_impact_speed,
    u1..uN, v1..vN and muK_re, muK_im, muK_krein for the 2N - 2 nontrivial multipliers.

    Keywords:
{chain}{precision}    max_impacts: the most impacts per period of the families followed (default 4).
    energy_range: (A, B) or "A:B": follow families with energies in [A, B] [energy] (default:
        1/100 to 10000 times the grazing end's energy).
    out: a prefix: the command line's files are kept there (without pictures).
    progress: ``progress(fraction, text)``, called on the calling thread.
    masses, springs, right_spring, stop_mass, frequencies, design_branch: the chain as in ``info``
        (any chain; ``frequencies=(2, 1)`` with two masses is the note's 1:2 design, the same bits
        as the two-mass keywords).
"""
    options = _chain_keywords(dict(precision=precision, max_impacts=max_impacts, energy_range=energy_range),
                              dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch),
                              masses, springs, right_spring, stop_mass, frequencies, design_branch)
    result, tables = _files_command(_modes, dict(options, out=out), progress)
    for entry, table in zip(result["families"], tables):
        entry["table"] = table
    if result.get("undecided_periods"):
        _warnings.warn(f"modes: {result['undecided_periods']} periods of the 1IPP family undecided in "
                       f"{result['precision']}: parts may be missing (a wider precision decides more)",
                       GrazeLabWarning, stacklevel=2)
    return result


def _files_command(call, options, progress, bare=()):
    """A typed command that writes its files only where ``out`` says (family, modes, map): call(its
    options as (flag, text) pairs, Result, progress) -> (its document as Results, its tables),
    the tables the command's own rows (no file read back); a refusal as ValueError, a file not
    written as OSError, in the module's words."""
    given = _convert.option_texts({name: value for name, value in options.items() if value is not None}, bare)
    try:
        answer = call(given, Result, progress)
    except _Refused as error:  # (what a progress callback raises goes through as it is)
        raise ValueError(_message(str(error))) from None
    except _NotWritten as error:
        raise OSError(_message(str(error))) from None
    if progress is not None:
        progress(1.0, "done")
    return answer


@_documented
def report(*, m1: float = 1.0, m2: float = 0.5, k1: float = 1.0, k2: _Optional[float] = None,
           gap: float = 1.0, branch: _Optional[str] = None, glo: _Optional[float] = None, onepp: _Optional[float] = None,
           state: _Optional[_Sequence[float]] = None, perturb: _Optional[_Sequence[float]] = None,
           contacts: _Optional[int] = None, t_end: _Optional[float] = None,
           methods: _Union[str, _Sequence[str], None] = None, quick: bool = False, out=None,
           progress: _Optional[_Progress] = None, masses: _Optional[_Sequence[float]] = None,
           springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
           stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
           design_branch: _Optional[int] = None, glo_weights: _Optional[_Sequence[float]] = None) -> Result:
    """Every comparison method against the exact solver, error against run time
    (``grazelab-cli report``). Returns ``table`` (results.csv's rows as a structured array),
    ``markdown`` (report.md) and ``log``; with ``out=DIR`` the files are written there too (the
    module draws no pictures: use grazelab-cli for them); without it no file is written.

    Keywords:
{chain}{start}    contacts, t_end: the run's length (default: 200 slow periods).
    methods: the methods to run, a list or "a,b" (default all): exact, moreau-jean,
        moreau-jean-theta1, schatzman-paoli, dopri5-events, cvode-adams, cvode-bdf, penalty.
    quick: fewer settings and runs (seconds instead of minutes).
    out: the directory to write into (created if missing).
    progress: ``progress(fraction, text)``, called on the calling thread.
    glo_weights: a chain of N masses' start on GLO_lambda, lambda these weights (fastest mode first).
{two_mass_chain}"""
    options = _chain_keywords(dict(glo=glo, onepp=onepp, state=state, perturb=perturb, contacts=contacts,
                                   t_end=t_end, methods=methods, quick=quick, glo_weights=glo_weights),
                              dict(m1=m1, m2=m2, k1=k1, k2=k2, gap=gap, branch=branch),
                              masses, springs, right_spring, stop_mass, frequencies, design_branch)
    return _table_command(_report, options, out, progress)


def stability(*, methods: _Union[str, _Sequence[str], None] = None, quick: bool = False, out=None,
              progress: _Optional[_Progress] = None, masses: _Optional[_Sequence[float]] = None,
              springs: _Optional[_Sequence[float]] = None, right_spring: _Optional[float] = None,
              stop_mass: _Optional[int] = None, frequencies: _Optional[_Sequence[int]] = None,
              design_branch: _Optional[int] = None, gap: _Optional[float] = None,
              state: _Optional[_Sequence[float]] = None, onepp: _Optional[float] = None,
              perturb: _Optional[_Sequence[float]] = None,
              glo_weights: _Optional[_Sequence[float]] = None) -> Result:
    """Every method on stiff and extreme cases (``grazelab-cli stability``): its own cases, or
    those of a chain of N masses. Returns ``table`` (matrix.csv's rows as a structured array),
    ``markdown`` (matrix.md) and ``log``; with ``out=DIR`` the files are written there too.

    Keywords:
    methods: the methods to run, a list or "a,b" (default all).
    quick: fewer settings and runs.
    out: the directory to write into (created if missing); without it no file is written.
    progress: ``progress(fraction, text)``, called on the calling thread.
    masses, springs, right_spring, stop_mass, frequencies, design_branch, gap: a chain of N masses,
        as in ``simulate``: the matrix of that chain and its stiff and extreme variants, from the
        start ``state`` (2N numbers), ``glo_weights`` or ``onepp``, with ``perturb``.
"""
    options = dict(methods=methods, quick=quick, gap=gap, state=state, onepp=onepp, perturb=perturb,
                   glo_weights=glo_weights)
    if masses is not None:
        options.update(_mass_chain_options(masses, springs, right_spring, stop_mass, frequencies, design_branch, {}))
    else:
        given = [name for name, value in dict(springs=springs, right_spring=right_spring, stop_mass=stop_mass,
                                              frequencies=frequencies, design_branch=design_branch, gap=gap,
                                              state=state, onepp=onepp, perturb=perturb,
                                              glo_weights=glo_weights).items() if value is not None]
        if given:
            raise ValueError(f"{', '.join(given)} describe{'s' if len(given) == 1 else ''} a chain given by masses "
                             f"(without it, stability runs its own cases)")
    return _table_command(_stability, options, out, progress)


def _table_command(call, options, out, progress):
    """A typed command whose outcome is a CSV table and a Markdown text (report, stability):
    call(its options as (flag, text) pairs, progress) -> (the CSV's bytes, the text, the
    messages), its files written only where ``out`` says."""
    out = None if out is None else _os.fspath(out)
    csv, markdown, log = _files_command(lambda given, _result, heard: call(given, heard),
                                        dict(options, out=out), progress, ("quick",))
    return Result(out=out, table=_convert.csv_text_table(csv.decode("utf-8")), markdown=markdown,
                  log=[_message(line) for line in log.splitlines() if line.strip()])
