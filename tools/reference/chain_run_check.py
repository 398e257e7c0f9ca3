#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Runs of N-mass chains printed by `grazelab-cli simulate --masses ...` against an independent
30-digit computation (mpmath), event by event.

For each event the CLI printed, the reference starts from the CLI's own state after the event
before (so that errors do not compound along a chaotic run) and finds the next event its own
way: the chain's modes by mpmath's symmetric eigen-solver (Jacobi's method), the flight in
closed form, u_s - d sampled 600 times per fastest period, every sign change bisected and every
sampled maximum refined by golden section (a maximum within 1e-20 of the stop is a touch: a
grazing when the springs pull the mass off the stop, a stick when they press it on). A stuck
phase is the chain with u_s = d held, as one system: the other masses' rest by solving
K_rr u = -K_rs d, their modes by the eigen-solver on the reduced matrices, the force on mass s
sampled the same way and its fall through zero bisected (the release). Nothing is shared with
the core's certified window search or its split of the chain at the clamp.

Checked on designed resonant chains (3:2:1, 4:3:1, 5:3:1, 4:3:2:1: springs from
`grazelab-cli info --frequencies`), detuned and random chains of 2 to 5 masses, stops on the
last and on interior masses, random starts and near-grazing ones, chains of extreme scale (masses
near 1e6 with springs near 1e-3 and a gap of 1e-4; masses near 1e-5, springs near 1e4, gap 1e3)
and of six masses: each contact time to 1e-10 of
the chain's slowest period, its type, the stopped mass's velocity to 1e-9 of the chain's speed
scale (gap times its fastest frequency); on resonant chains
each flight after an impact shorter than T. Starts pressed on the stop (sticks at once, on the
first, interior and last masses): each release's time to 1e-10 of the slowest period and the
released velocities to 1e-9. 1IPP orbits from `family --onepp` of the designed chains: the
reference's flight from each admissible row's post-impact data first meets the stop at its T
(to 1e-9 of the slowest period). A chain given in decimals double rounds (0.7, 1.3, ...): the
reference takes them as decimals. With --precision quad: the CLI in binary128 against 45 digits,
every time to 1e-28 of the slowest period: the designed chains with their springs designed by the
CLI in binary128 (--frequencies; the reference takes them from its output), two near-grazing
starts on 3:2:1, the decimal chain (which the CLI must read in binary128), random, pressed, flat
and extreme chains. Exit 0 when all hold, 1 otherwise (a ctest test).

    python3 chain_run_check.py --cli build/app/grazelab-cli/grazelab-cli [--runs 16]
"""
import argparse
import csv
import decimal
import json
import os
import random
import subprocess
import sys
import tempfile

import mpmath

from chain_modes_check import reference_modes

mpmath.mp.dps = 30


def modes(masses, springs, right_spring):
    """The chain's frequencies and M-orthonormal shapes, by chain_modes_check's solver at 30 digits
    (mpmath's symmetric eigen-solver, apart from the core)."""
    pairs = reference_modes(masses, springs, right_spring)
    return [omega for omega, _ in pairs], [shape for _, shape in pairs]


class Flight:
    """u_s(t) - d of the flight from (u, v), in closed form."""

    def __init__(self, chain, u, v):
        self.omega, shapes = chain["modes"]
        masses = chain["masses"]
        s = chain["stop"]
        self.gap = mpmath.mpf(chain["gap"])
        self.shapes = shapes
        self.a, self.b, self.q, self.qdot = [], [], [], []
        for j, shape in enumerate(shapes):
            q = mpmath.fsum(mpmath.mpf(masses[i]) * shape[i] * mpmath.mpf(u[i]) for i in range(len(u)))
            qdot = mpmath.fsum(mpmath.mpf(masses[i]) * shape[i] * mpmath.mpf(v[i]) for i in range(len(v)))
            self.q.append(q)
            self.qdot.append(qdot)
            self.a.append(shape[s] * q)
            self.b.append(shape[s] * qdot / self.omega[j])

    def displacements(self, t):
        return [mpmath.fsum(shape[i] * (q * mpmath.cos(w * t) + qdot / w * mpmath.sin(w * t))
                            for shape, q, qdot, w in zip(self.shapes, self.q, self.qdot, self.omega))
                for i in range(len(self.shapes[0]))]

    def velocities(self, t):
        return [mpmath.fsum(shape[i] * (-q * w * mpmath.sin(w * t) + qdot * mpmath.cos(w * t))
                            for shape, q, qdot, w in zip(self.shapes, self.q, self.qdot, self.omega))
                for i in range(len(self.shapes[0]))]

    def f(self, t):
        return mpmath.fsum(a * mpmath.cos(w * t) + b * mpmath.sin(w * t)
                           for a, b, w in zip(self.a, self.b, self.omega)) - self.gap

    def df(self, t):
        return mpmath.fsum(w * (b * mpmath.cos(w * t) - a * mpmath.sin(w * t))
                           for a, b, w in zip(self.a, self.b, self.omega))

    def first_contact(self, until):
        """(time, 'impact' | 'grazing') of the first contact in (0, until], or None."""
        step = 2 * mpmath.pi / max(self.omega) / 600
        t0 = step / 1000  # the flight may start on the stop: begin just after it
        previous_t, previous = t0, self.f(t0)
        before = None
        t = t0
        while t < until:
            t = min(t + step, until)
            now = self.f(t)
            if previous < 0 <= now:
                return mpmath.findroot(self.f, (previous_t, t), solver="bisect", tol=1e-50), "impact"
            if before is not None and previous >= before and previous >= now and previous > -1e-6:
                low, high = previous_t - step, t
                for _ in range(120):
                    m1 = low + (high - low) * mpmath.mpf("0.381966011250105")
                    m2 = high - (high - low) * mpmath.mpf("0.381966011250105")
                    if self.f(m1) < self.f(m2):
                        low = m1
                    else:
                        high = m2
                top = (low + high) / 2
                peak = self.f(top)
                if peak > 1e-20:  # two crossings within one sample: the first one
                    return mpmath.findroot(self.f, (previous_t - step, top), solver="bisect", tol=1e-50), "impact"
                if peak > -1e-20:
                    return top, "grazing"
            before, previous_t, previous = previous, t, now
        return None


def stiffness(chain):
    n = len(chain["masses"])
    k = mpmath.zeros(n, n)
    for i in range(n):
        right = mpmath.mpf(chain["springs"][i + 1]) if i + 1 < n else mpmath.mpf(chain["right_spring"])
        k[i, i] = mpmath.mpf(chain["springs"][i]) + right
        if i + 1 < n:
            k[i, i + 1] = k[i + 1, i] = -right
    return k


def force_on_stop(chain, u):
    """-(K u)_s: the springs' force on the stopped mass (positive: pressed on the stop)."""
    k = stiffness(chain)
    s = chain["stop"]
    return -mpmath.fsum(k[s, i] * mpmath.mpf(u[i]) for i in range(len(u)))


def pressed_at_start(chain, u, v):
    """Whether mass s, at rest on the stop, is held there: the first of the springs' force on it,
    that force's rate (from the velocities) and its second rate (from the accelerations) that is
    not zero, positive (pressed on). Its own derivatives in mpmath, apart from the CLI's, from
    the start's own numbers: "zero" is zero to the reference's digits (a neighbour placed in
    double leaves a force of 1e-16: the mass is held; the CLI, which cannot resolve that force
    in double, raises the run until it can)."""
    k = stiffness(chain)
    n = len(u)
    s = chain["stop"]
    masses = [mpmath.mpf(m) for m in chain["masses"]]
    force = force_on_stop(chain, u)
    scale = mpmath.fsum(abs(k[s, i] * mpmath.mpf(u[i])) for i in range(n))
    zero = mpmath.mpf(10) ** (5 - mpmath.mp.dps)
    if abs(force) > zero * scale:
        return force > 0
    rate = -mpmath.fsum(k[s, i] * mpmath.mpf(v[i]) for i in range(n))
    if abs(rate) > zero * mpmath.fsum(abs(k[s, i] * mpmath.mpf(v[i])) for i in range(n)):
        return rate > 0
    accelerations = [-mpmath.fsum(k[i, j] * mpmath.mpf(u[j]) for j in range(n)) / masses[i] for i in range(n)]
    return -mpmath.fsum(k[s, i] * accelerations[i] for i in range(n)) > 0


class Stuck:
    """The chain with u_s = d held: the other masses as one system (M_r, K_rr), about their rest."""

    def __init__(self, chain, u, v):
        n = len(chain["masses"])
        s = chain["stop"]
        self.s = s
        self.gap = mpmath.mpf(chain["gap"])
        self.rest_index = [i for i in range(n) if i != s]
        k = stiffness(chain)
        self.k_row = [k[s, i] for i in self.rest_index]
        self.k_ss = k[s, s]
        r = len(self.rest_index)
        k_rr = mpmath.matrix(r, r)
        k_rs = mpmath.matrix(r, 1)
        for a, i in enumerate(self.rest_index):
            k_rs[a] = k[i, s]
            for b, j in enumerate(self.rest_index):
                k_rr[a, b] = k[i, j]
        self.rest = mpmath.lu_solve(k_rr, -k_rs * self.gap)
        masses = [mpmath.mpf(chain["masses"][i]) for i in self.rest_index]
        inv_root = [1 / mpmath.sqrt(m) for m in masses]
        a = mpmath.matrix(r, r)
        for p in range(r):
            for q in range(r):
                a[p, q] = inv_root[p] * k_rr[p, q] * inv_root[q]
        values, vectors = mpmath.eigsy(a)
        self.omega = [mpmath.sqrt(values[j]) for j in range(r)]
        self.shapes = [[inv_root[p] * vectors[p, j] for p in range(r)] for j in range(r)]
        self.q, self.qdot = [], []
        for shape in self.shapes:
            self.q.append(mpmath.fsum(masses[p] * shape[p] * (mpmath.mpf(u[i]) - self.rest[p])
                                      for p, i in enumerate(self.rest_index)))
            self.qdot.append(mpmath.fsum(masses[p] * shape[p] * mpmath.mpf(v[i]) for p, i in enumerate(self.rest_index)))

    def state(self, t):
        u = [self.gap] * (len(self.rest_index) + 1)
        v = [mpmath.mpf(0)] * (len(self.rest_index) + 1)
        for p, i in enumerate(self.rest_index):
            u[i] = self.rest[p] + mpmath.fsum(shape[p] * (q * mpmath.cos(w * t) + qdot / w * mpmath.sin(w * t))
                                              for shape, q, qdot, w in zip(self.shapes, self.q, self.qdot, self.omega))
            v[i] = mpmath.fsum(shape[p] * (-q * w * mpmath.sin(w * t) + qdot * mpmath.cos(w * t))
                               for shape, q, qdot, w in zip(self.shapes, self.q, self.qdot, self.omega))
        return u, v

    def force(self, t):
        u, _ = self.state(t)
        return -(mpmath.fsum(k * u[i] for k, i in zip(self.k_row, self.rest_index)) + self.k_ss * self.gap)

    def release(self, until):
        """The first time the force on mass s falls through zero, or None before `until`."""
        step = 2 * mpmath.pi / max(self.omega) / 600
        previous_t, previous = mpmath.mpf(0), self.force(0)
        t = mpmath.mpf(0)
        while t < until:
            t = t + step
            now = self.force(t)
            if previous > 0 >= now:
                return mpmath.findroot(self.force, (previous_t, t), solver="bisect", tol=1e-50)
            previous_t, previous = t, now
        return None


PRECISION = "double"  # the CLI's --precision; quad reads its numbers as mpmath numbers
TOLERANCE = 1e-10     # contact and release times, in slowest periods


def as_text(x):
    """A number as the CLI is given it: a double as its exact decimal value (the CLI reads its
    numbers in the run's precision, and this text is that double in every precision, where repr's
    shortest text is not); an mpmath number (a chain given in decimals, "0.7") to 50 digits."""
    return mpmath.nstr(x, 50) if isinstance(x, mpmath.mpf) else str(decimal.Decimal(x))


def cli_run(cli, chain, state, contacts, precision=None):
    precision = precision or PRECISION
    argv = [cli, "simulate", "--masses", ",".join(as_text(m) for m in chain["masses"]),
            "--stop-mass", str(chain["stop"] + 1),
            "--state", ",".join(as_text(x) for x in state),
            "--contacts", str(contacts), "--gap", as_text(chain["gap"]), "--precision", precision]
    if chain.get("ratios"):
        # the springs designed by the CLI in the run's precision (in binary128 for its masses
        # there): the reference takes them from its output
        argv += ["--frequencies", ":".join(map(str, chain["ratios"])), "--springs", as_text(chain["springs"][0])]
    else:
        argv += ["--springs", ",".join(as_text(k) for k in chain["springs"])]
    if chain["right_spring"]:
        argv += ["--right-spring", as_text(chain["right_spring"])]
    text = subprocess.run(argv, check=True, capture_output=True, text=True).stdout
    return json.loads(text, parse_float=mpmath.mpf if precision == "quad" else float)


def designed_springs(cli, masses, ratios):
    argv = [cli, "info", "--masses", ",".join(repr(m) for m in masses), "--frequencies", ":".join(map(str, ratios))]
    done = subprocess.run(argv, capture_output=True, text=True)
    return json.loads(done.stdout)["chain"]["springs"] if done.returncode == 0 else None


def check(cli, chain, state, contacts, precision=None, complete=False):
    """The CLI's run against the reference, event by event; with `complete`, a run that ends
    before its contacts (undecided, say) is a problem too."""
    printed = cli_run(cli, chain, state, contacts, precision)
    count = len(chain["masses"])
    for event in printed["events"]:  # the csv's columns u1..uN, v1_pre..vN_pre, v<s>_post as lists
        event["u"] = [event[f"u{i + 1}"] for i in range(count)]
        event["v_pre"] = [event[f"v{i + 1}_pre"] for i in range(count)]
        event["v_post"] = event[f"v{chain['stop'] + 1}_post"]
    contacts_made = printed["contacts"]["total"]
    if chain.get("ratios"):
        chain["springs"] = printed["chain"]["springs"]
    chain["modes"] = modes(chain["masses"], chain["springs"], chain["right_spring"])
    slowest = 2 * mpmath.pi / min(chain["modes"][0])
    # velocities relative to the chain's own scale (gap times its fastest frequency): a chain of
    # heavy soft masses moves at 1e-8, a light stiff one at 1e8
    speed_scale = float(chain["gap"] * max(chain["modes"][0]))
    problems = []
    if complete and contacts_made < contacts:
        problems.append(f"ended by {printed['stop_reason']} after {contacts_made} contacts of {contacts}")
    n = len(chain["masses"])
    s = chain["stop"]
    u, v = state[:n], state[n:]
    t = 0.0
    period = printed["chain"]["period"]
    stuck = None  # the stick the next event must release
    for k, event in enumerate(printed["events"]):
        if event["type"] == "stick" and event["t"] == t and u[s] == chain["gap"] and v[s] == 0:
            # a start pressed on the stop: held at once
            if not pressed_at_start(chain, u, v):
                problems.append(f"event {k}: a stick at the start, but the springs pull mass {s + 1} off the stop")
                break
            stuck = (u, v)
            continue
        if event["type"] == "release":
            if stuck is None:
                problems.append(f"event {k}: a release without a stick before it")
                break
            phase = Stuck(chain, *stuck)
            when = phase.release(mpmath.mpf(event["t"] - t) + slowest)
            if when is None:
                problems.append(f"event {k}: the reference finds no release, the CLI one at t = {event['t']}")
                break
            error = abs(t + when - event["t"]) / slowest
            if error > TOLERANCE:
                problems.append(f"event {k}: release at t = {event['t']!r} against {mpmath.nstr(t + when, 17)} "
                                f"({mpmath.nstr(error, 3)} of the slowest period)")
                break
            _, released = phase.state(when)
            for i in range(n):
                if abs(event["v_pre"][i] - float(released[i])) > 1e-9 * (speed_scale + abs(float(released[i]))):
                    problems.append(f"event {k}: released v{i + 1} = {event['v_pre'][i]!r} against "
                                    f"{mpmath.nstr(released[i], 17)}")
            stuck = None
            u, v, t = event["u"], event["v_pre"], event["t"]
            continue
        flight = Flight(chain, u, v)
        found = flight.first_contact(mpmath.mpf(event["t"] - t) + slowest)
        if found is None:
            problems.append(f"event {k}: the reference finds none, the CLI one at t = {event['t']}")
            break
        when, kind = found
        if kind == "grazing" and pressed_at_start(chain, flight.displacements(when), flight.velocities(when)):
            kind = "stick"
        error = abs(t + when - event["t"]) / slowest
        if error > TOLERANCE:
            problems.append(f"event {k}: t = {event['t']!r} against {mpmath.nstr(t + when, 17)} "
                            f"({mpmath.nstr(error, 3)} of the slowest period)")
            break
        if kind != event["type"]:
            problems.append(f"event {k}: {event['type']} against the reference's {kind}")
            break
        speed = flight.df(when)
        if abs(event["v_pre"][s] - float(speed)) > 1e-9 * (speed_scale + abs(float(speed))):
            problems.append(f"event {k}: v_s {event['v_pre'][s]!r} against {mpmath.nstr(speed, 17)}")
        if period and k > 0 and printed["events"][k - 1]["type"] == "impact" and not event["t"] - t < period:
            problems.append(f"event {k}: a flight of {event['t'] - t} after an impact, not < T = {period}")
        u = event["u"]
        v = list(event["v_pre"])
        v[s] = event["v_post"]
        t = event["t"]
        if kind == "stick":
            stuck = (u, v)
    return problems, contacts_made


def report(label, problems, contacts):
    """Prints one run's line and its problems; returns (contacts, 1 if it failed else 0)."""
    print(f"{label}: {contacts} contacts {'ok' if not problems else 'FAILED'}")
    for problem in problems:
        print("   ", problem)
    return contacts, int(bool(problems))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--runs", type=int, default=16)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--precision", choices=("double", "quad"), default="double",
                        help="quad: the CLI in binary128 against 45 digits, times to 1e-28 of the slowest "
                             "period (the designed chains designed in binary128; their detuned copies left "
                             "out for time)")
    args = parser.parse_args()
    global PRECISION, TOLERANCE
    if args.precision == "quad":
        PRECISION, TOLERANCE = "quad", 1e-28
        mpmath.mp.dps = 45
    rng = random.Random(args.seed)
    cases = []
    for masses, ratios in (([1.0, 0.2, 0.05], (3, 2, 1)), ([1.0, 1.0, 0.2], (4, 3, 1)),
                           ([1.0, 0.4, 0.2], (5, 3, 1)), ([1.0, 0.6, 0.36, 0.216], (4, 3, 2, 1))):
        springs = designed_springs(args.cli, masses, ratios)
        cases.append(dict(masses=masses, springs=springs, right_spring=0, stop=len(masses) - 1, gap=1.0, ratios=ratios))
        # the same chain detuned, and stopped on an interior mass
        detuned = list(springs)
        detuned[1] *= 1.0137
        cases.append(dict(masses=masses, springs=detuned, right_spring=0, stop=len(masses) - 2, gap=1.0))
    while len(cases) < args.runs:
        n = rng.randint(2, 5)
        cases.append(dict(masses=[10 ** rng.uniform(-1, 1) for _ in range(n)],
                          springs=[10 ** rng.uniform(-1, 1) for _ in range(n)],
                          right_spring=rng.choice([0, 10 ** rng.uniform(-1, 1)]),
                          stop=rng.randrange(n), gap=10 ** rng.uniform(-1, 1)))
    failures = 0
    total = 0
    quad = args.precision == "quad"
    for index, chain in enumerate(cases[:args.runs]):
        if quad and index < 8 and index % 2 == 1:
            continue  # the detuned copies of the designed chains (see --precision)
        n = len(chain["masses"])
        # a start below the stop with enough energy to reach it: the stopped mass pushed at it
        state = [rng.uniform(-0.5, 0.5) * chain["gap"] for _ in range(n)] + [rng.uniform(-0.5, 0.5) for _ in range(n)]
        state[chain["stop"]] = min(state[chain["stop"]], 0.5 * chain["gap"])
        state[n + chain["stop"]] = 3 * chain["gap"] * max(1.0, 1 / chain["masses"][chain["stop"]]) ** 0.5
        counted, failed = report(f"run {index}: {n} masses, stop on {chain['stop'] + 1}",
                                 *check(args.cli, chain, state, 4 if quad else 12))
        total, failures = total + counted, failures + failed
    # a chain given in decimals that double rounds (0.7, 1.3, ...) with a right wall, stopped on
    # an interior mass: the CLI reads them in the run's precision, so that in binary128 it meets
    # the reference's decimal chain to 1e-28 (read in double, it would be 1e-17 away)
    decimal_chain = dict(masses=[mpmath.mpf(x) for x in ("0.7", "1.3", "0.45")],
                         springs=[mpmath.mpf(x) for x in ("1.1", "0.9", "2.3")],
                         right_spring=mpmath.mpf("0.35"), stop=1, gap=mpmath.mpf("0.3"))
    counted, failed = report("decimal chain: 3 masses, stop on 2, walled",
                             *check(args.cli, decimal_chain, [0.1, 0.05, -0.2, 0.3, 1.9, -0.4], 4 if quad else 12,
                                    complete=True))
    total, failures = total + counted, failures + failed
    # near-grazing starts: a pure mode j of the designed 3:2:1 chain whose top is pushed past the
    # stop by eps (two crossings sqrt(2 eps) / w apart), at rest position with its velocity
    chain = dict(cases[0])
    chain["modes"] = modes(chain["masses"], chain["springs"], chain["right_spring"])
    omega, shapes = chain["modes"]
    s = chain["stop"]
    for j in range(1 if quad else len(omega)):
        for eps in (1e-4, 1e-7):
            shape = [x / shapes[j][s] for x in shapes[j]]
            state = [0.0] * len(shape) + [float((1 + eps) * chain["gap"] * omega[j] * x) for x in shape]
            counted, failed = report(f"near grazing: mode {j + 1} pushed {eps}", *check(args.cli, dict(chain), state, 6))
            total, failures = total + counted, failures + failed
    # starts pressed on the stop: mass s at rest on it, a neighbour pushed past it (the first
    # stick at once, its release, and whatever follows), stops on the first, interior, last mass;
    # two cases of every three (each pressed run costs the reference some seconds)
    for index, chain in enumerate(cases[:args.runs]):
        if index % 3 == 2 or (quad and index < 8):
            continue
        n = len(chain["masses"])
        s = chain["stop"]
        neighbour = s - 1 if s > 0 else s + 1
        if neighbour >= n:
            continue
        state = [rng.uniform(-0.5, 0.5) * chain["gap"] for _ in range(n)] + [rng.uniform(-0.5, 0.5) for _ in range(n)]
        state[s] = chain["gap"]
        state[n + s] = 0.0
        state[neighbour] = 3 * chain["gap"] + 1
        counted, failed = report(f"pressed start {index}: {n} masses, stop on {s + 1}",
                                 *check(args.cli, dict(chain), state, 4 if quad else 8))
        total, failures = total + counted, failures + failed
    # flat starts: mass s at rest on the stop with no force and no jerk (everything at rest, its
    # neighbour at d too): the sign of its fourth derivative decides whether it leaves (a
    # flight, leaving as t^4) or is held (a stick). Only where that start is exactly flat in
    # double: the last mass with no right wall, its neighbour placed at d exactly (a neighbour
    # placed by a rounded formula leaves a force of 1e-16, undecided in double and resolved
    # one precision up: pulled off by it, such a mass can chatter at 1e-8 time units, which this
    # reference's root finding cannot follow). Not on the designed chains: taken as exactly
    # commensurate they come back flat at T, where the springs' rounding moves the reference's
    # return by 1e-4 of a period (ChainRun.AFlatStartLeavesByItsFourthDerivativeOrIsHeld)
    for index, chain in enumerate(cases[:args.runs]):
        n = len(chain["masses"])
        if index < 8 and index % 2 == 1:
            chain = dict(chain, stop=n - 1)  # the detuned chains, stopped on their last mass
        s = chain["stop"]
        if (index < 8 and index % 2 == 0) or n < 2 or s != n - 1 or chain["right_spring"]:
            continue
        if quad and index < 8:
            continue
        d = chain["gap"]
        state = [rng.uniform(-1.5, 1.5) * d for _ in range(n)] + [0.0] * n
        state[s] = d
        state[s - 1] = d
        counted, failed = report(f"flat start {index}: {n} masses, stop on {s + 1}",
                                 *check(args.cli, dict(chain), state, 3 if quad else 6, complete=True))
        total, failures = total + counted, failures + failed
    # 1IPP orbits from `family --onepp` of the designed chains: the reference's flight from each
    # row's post-impact data first meets the stop at that row's T (so the orbit is periodic)
    for chain in [c for c in cases[:8] if c["stop"] == len(c["masses"]) - 1 and not quad]:
        n = len(chain["masses"])
        s = chain["stop"]
        with tempfile.TemporaryDirectory() as folder:
            prefix = os.path.join(folder, "f")
            subprocess.run([args.cli, "family", "--onepp", "--masses", ",".join(map(repr, chain["masses"])),
                            "--springs", ",".join(map(repr, chain["springs"])), "--count", "40", "--out", prefix],
                           check=True, capture_output=True)
            rows = [r for r in csv.DictReader(open(prefix + ".csv")) if r["admissible"] == "1"]
        chain = dict(chain)
        chain["modes"] = modes(chain["masses"], chain["springs"], chain["right_spring"])
        slowest = 2 * mpmath.pi / min(chain["modes"][0])
        bad = 0
        for row in rows[::4]:
            u = [float(row[f"u{i + 1}"]) for i in range(n)]
            v = [0.0] * n
            v[s] = float(row["V"])
            found = Flight(chain, u, v).first_contact(mpmath.mpf(row["T"]) * 1.01)
            if found is None or found[1] != "impact" or abs(found[0] - mpmath.mpf(row["T"])) > 1e-9 * slowest:
                bad += 1
                print(f"    1IPP T = {row['T']}: the reference's first contact {found}")
        total += len(rows[::4])
        print(f"1IPP orbits of {n} masses: {len(rows[::4])} {'ok' if not bad else 'FAILED'}")
        failures += bool(bad)
    # extreme scales and six masses (their own random stream: the runs above stay as they were):
    # heavy soft chains with a tiny gap, light stiff ones with a huge gap, six masses stopped on
    # the last, the first and an interior mass; the stopped mass thrown at the stop at 3 gap
    # times the fastest frequency, so that every mode can carry it there
    extreme = random.Random(args.seed + 1)
    spread = lambda centre: centre * 10 ** extreme.uniform(-1, 1)
    for label, chain in (
            ("heavy and soft", dict(masses=[spread(1e6) for _ in range(4)], springs=[spread(1e-3) for _ in range(4)],
                                    right_spring=0, stop=3, gap=1e-4)),
            ("light and stiff", dict(masses=[spread(1e-5) for _ in range(3)], springs=[spread(1e4) for _ in range(3)],
                                     right_spring=spread(1e4), stop=1, gap=1e3)),
            ("six masses", dict(masses=[spread(1) for _ in range(6)], springs=[spread(1) for _ in range(6)],
                                right_spring=0, stop=5, gap=1.0)),
            ("six masses, walled", dict(masses=[spread(1) for _ in range(6)], springs=[spread(1) for _ in range(6)],
                                        right_spring=spread(1), stop=0, gap=0.3)),
            ("six masses, interior", dict(masses=[spread(1) for _ in range(6)], springs=[spread(1) for _ in range(6)],
                                          right_spring=0, stop=3, gap=2.0))):
        n = len(chain["masses"])
        omega = modes(chain["masses"], chain["springs"], chain["right_spring"])[0]
        fastest, slowest = float(max(omega)), float(min(omega))
        state = ([extreme.uniform(-0.5, 0.5) * chain["gap"] for _ in range(n)]
                 + [extreme.uniform(-0.5, 0.5) * chain["gap"] * slowest for _ in range(n)])
        state[chain["stop"]] = min(state[chain["stop"]], 0.5 * chain["gap"])
        state[n + chain["stop"]] = 3 * chain["gap"] * fastest
        counted, failed = report(f"{label}: {n} masses, stop on {chain['stop'] + 1}",
                                 *check(args.cli, chain, state, 4 if quad else 10))
        total, failures = total + counted, failures + failed
    print(f"{total} contacts checked, {failures} runs failed")
    return 1 if failures or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
