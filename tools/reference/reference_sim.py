#!/usr/bin/env python3
"""Independent high-precision reference simulator for the GrazeLab 2-dof chain.

    wall --k1-- [m1] --k2-- [m2] |<-- gap d -->| rigid stop

This module implements the mathematics of docs/model.md (sections 1-5) from
scratch in Python with mpmath, at a configurable decimal precision (default 40 digits).
It shares no code, no algorithm for contact finding and no floating-point type with the
C++ core: it exists to check `grazelab-cli simulate` (see compare.py beside this file).

Method
------
- Modes: the 2x2 generalized eigenproblem K p = w^2 M p in closed form, P^T M P = I,
  P[2][j] > 0, mode 1 = FAST, mode 2 = slow (docs/model.md section 2, "Labelling").
  With `--branch` the chain is exactly 1:2 resonant and w1 is set to exactly 2 w2.
- Free flight: closed-form modal solution; u2(t) - d is evaluated in the
  cancellation-free form  (u2(0) - d) + sum_j P[2][j] (q_j (cos(wj t) - 1) + q_j'/wj sin(wj t))
  with cos x - 1 = -2 sin^2(x/2).
- Next contact: the flight is scanned on a dense grid (default 2000 points per slow period
  T2; more if the fast mode is faster than 2 w2) in double precision as a cheap *filter*
  only; every grid interval the filter cannot rule out (u2 near or above d, or a local
  maximum of u2, i.e. v2 changing sign from + to -) is re-evaluated in mpmath at full
  precision. A local maximum is located by bracketing root finding on v2 (Illinois with a
  bisection guard); if u2 there is above d + tol the first crossing before it is an
  impact, if it is within tol of d it is a tangential touch (grazing or sticking).
  For a resonant chain one scan covers (0, T2 + 3h]: every free motion is T2-periodic, so
  no contact there means no contact ever. A detuned chain is scanned up to
  `--max-flight` slow periods (or t-end).
- Events (docs/model.md section 4): impact (v2 -> -v2), grazing (touch with v2 = 0 and
  u1 <= d: flight goes on with u2 := d, v2 := 0), sticking (touch or start on H with v2 = 0
  and u1 > d, or u1 = d and v1 > 0): mass 1 oscillates alone,
  m1 u1'' + (k1 + k2) u1 = k2 d, closed form, until u1 falls back to d; release starts a
  flight with u2 = d, v2 = 0.
- Initial data: GLO_lambda, 1IPP of period T, or an explicit state, plus an optional
  perturbation. An initial state on H with v2 > 0 is an impact at t = 0; an initial state
  on H with v2 = 0 pressed on the stop is a stick event at t = 0; other states on H are
  departures (no event at t = 0).

Tolerances (relative to the position scale ps = max(d, energy bound on |u|) and the
velocity scale vs = w_slow * ps): a touch is tangential if |max u2 - d| <= ps * 10^-(dps-8);
a crossing with v2 below vs * 10^-((dps-8)/2) is treated as a touch. At dps = 40 this resolves
near-grazing impacts down to v2 ~ 1e-16 vs. A touch with |u1 - d| <= ps * 10^-(dps-8) sticks
only if v1 > vs * 10^-((dps-8)/2) (the fourth-order touch of GLO_4/3 is located only to
~1e-20 in time, which leaves v1 ~ 1e-20 of noise there).

Output
------
JSON on stdout in the shape of `grazelab-cli simulate --format json` (docs/design.md):
`model`, `events` [{t, type, u1, u2, v1_pre, v2_pre, v2_post}], `final` {t, u1, u2, v1, v2},
`energy` {initial, max_rel_drift}, `timing`, plus a `reference` block describing the run.
ALL REAL NUMBERS ARE WRITTEN AS JSON NUMBERS (not strings) WITH `--digits` SIGNIFICANT
DIGITS (default 30, at most dps). A standard JSON parser reading them into binary64 loses
the extra digits; read them with `json.loads(text, parse_float=decimal.Decimal)` (or
`parse_float=mpmath.mpf`) to keep them. Integers (counts) are plain JSON integers.

`--nudge EPS` (reference only) adds EPS * s to u1 and EPS * w2 * s to v1, s = max(gap, |u1|,
|u2|), at full precision after `--perturb`: two runs with and without it measure how much
the motion amplifies a binary64-sized error (compare.py uses this, see README.md).

Counting: `--contacts N` stops after N events of type impact, grazing or stick
(a release is not a contact and does not count).

Inputs: decimal strings are parsed directly into mpmath (0.1 is 0.1 to dps digits).
`--double-inputs` first rounds every real input to the nearest binary64 (what a C++
program reading the same strings sees); k2 from `--branch` is then the exactly resonant k2
of those binary64 inputs. `--k2-from-double` instead computes k2 from the 1:2 design
formula in Python floats and uses that exact binary value: the chain is then detuned by
~1e-16 (w1 != 2 w2), it is simulated as a detuned chain, and `resonant` is false (see
README.md: the C++ core keeps w1 = 2 w2 exactly, so this is not its comparator). Negative values may follow an option as a separate argument (`--glo -0.5`).

Exit status: 0 on success, 2 on invalid input (one line on stderr, nothing on stdout).
"""

import argparse
import json
import math
import sys
import time

import mpmath
from mpmath import mp, mpf

EVENT_IMPACT = "impact"
EVENT_GRAZING = "grazing"
EVENT_STICK = "stick"
EVENT_RELEASE = "release"


class InputError(ValueError):
    """Invalid input: reported on stderr with exit status 2."""


def resonant_kappa(beta, branch):
    """kappa = k2/k1 of the 1:2 resonant chain (docs/model.md section 2), in mpmath."""
    if beta > mpf(9) / 16:
        raise InputError(
            "m2/m1 = %s > 9/16: no 1:2 resonant chain exists (use --k2 for a detuned chain)"
            % mp.nstr(beta, 17))
    sign = 1 if branch == "upper" else -1
    return beta * ((17 - 8 * beta) + sign * 5 * mp.sqrt(9 - 16 * beta)) / (8 * (1 + beta) ** 2)


def resonant_kappa_double(beta, branch):
    """The same formula evaluated in binary64 Python floats."""
    if beta > 9.0 / 16.0:
        raise InputError("m2/m1 > 9/16: no 1:2 resonant chain exists")
    sign = 1.0 if branch == "upper" else -1.0
    return beta * ((17.0 - 8.0 * beta) + sign * 5.0 * math.sqrt(9.0 - 16.0 * beta)) / (
        8.0 * (1.0 + beta) ** 2)


class Chain:
    """Model, modes and derived quantities (docs/model.md sections 1-2), all in mpmath.

    Index convention: w[0], P[.][0] = mode 1 (FAST); w[1], P[.][1] = mode 2 (slow).
    P[k][j] with k = 0 for mass 1, k = 1 for mass 2.
    """

    def __init__(self, m1, m2, k1, gap, k2=None, branch="upper", k2_from_double=False):
        for name, value in (("m1", m1), ("m2", m2), ("k1", k1), ("gap", gap)):
            if not mp.isfinite(value) or value <= 0:
                raise InputError("%s must be a finite positive number" % name)
        self.m1, self.m2, self.k1, self.gap = m1, m2, k1, gap
        self.branch = None
        if k2 is None:
            self.branch = branch
            if k2_from_double:
                kappa = resonant_kappa_double(float(m2) / float(m1), branch)
                k2 = mpf(float(k1) * kappa)
            else:
                k2 = k1 * resonant_kappa(m2 / m1, branch)
        if not mp.isfinite(k2) or k2 <= 0:
            raise InputError("k2 must be a finite positive number")
        self.k2 = k2

        # eigenvalues of K p = w^2 M p: m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0
        b = m1 * k2 + m2 * (k1 + k2)
        disc = b * b - 4 * m1 * m2 * k1 * k2
        w2fast = (b + mp.sqrt(disc)) / (2 * m1 * m2)
        w2slow = k1 * k2 / (m1 * m2 * w2fast)  # Vieta, no cancellation
        wfast, wslow = mp.sqrt(w2fast), mp.sqrt(w2slow)

        # exact 1:2 resonance: by construction (branch) or detected to working precision
        noise = mpf(10) ** (-(mp.dps - 6))
        self.resonant = abs(wfast - 2 * wslow) <= noise * wslow
        if self.resonant:
            wfast = 2 * wslow
            w2fast = wfast * wfast
        self.w = [wfast, wslow]

        # eigenvectors from the second row: -k2 p1 + (k2 - w^2 m2) p2 = 0
        self.P = [[mpf(0), mpf(0)], [mpf(0), mpf(0)]]
        for j, wsq in enumerate((w2fast, w2slow)):
            ratio = 1 - wsq * m2 / k2
            p2 = 1 / mp.sqrt(m1 * ratio * ratio + m2)
            self.P[0][j] = ratio * p2
            self.P[1][j] = p2
        # P^-1 = P^T M
        self.Pinv = [[self.P[0][j] * m1, self.P[1][j] * m2] for j in range(2)]
        self.T = [2 * mp.pi / self.w[0], 2 * mp.pi / self.w[1]]
        p21, p22 = self.P[1][0], self.P[1][1]
        self.lambda_star = 4 * p22 ** 2 / (p21 ** 2 + 4 * p22 ** 2)

    @property
    def T2(self):
        return self.T[1]

    def energy(self, u1, u2, v1, v2):
        k1, k2 = self.k1, self.k2
        return (self.m1 * v1 * v1 + self.m2 * v2 * v2
                + (k1 + k2) * u1 * u1 - 2 * k2 * u1 * u2 + k2 * u2 * u2) / 2

    def glo_state(self, lam):
        """GLO_lambda data on the grazing-start plane (docs/model.md section 5)."""
        P, d = self.P, self.gap
        u1 = d * ((1 - lam) * P[0][0] / P[1][0] + lam * P[0][1] / P[1][1])
        return [u1, d, mpf(0), mpf(0)]

    def onepp_state(self, period):
        """Post-impact data of the 1IPP orbit of period T (docs/model.md section 5)."""
        g = [mpf(0), mpf(0)]
        for j in range(2):
            half = self.w[j] * period / 2
            s = mp.sin(half)
            if abs(s) <= mpf(10) ** (-(mp.dps // 2)):
                raise InputError("1IPP period T is a multiple of T%d" % (j + 1))
            phi = mp.cos(half) / (s * self.w[j])  # sin x / (w (1 - cos x)) = cot(x/2) / w
            for k in range(2):
                g[k] += self.m2 * self.P[k][j] * self.P[1][j] * phi
        velocity = self.gap / g[1]
        if velocity >= 0:
            raise InputError("1IPP of period T is not physical (post-impact V >= 0)")
        return [self.gap * g[0] / g[1], self.gap, mpf(0), velocity]


class Flight:
    """Closed-form free flight from a state at local time 0 (docs/model.md section 3)."""

    def __init__(self, chain, state):
        self.chain = chain
        u1, u2, v1, v2 = state
        self.state0 = list(state)
        Pinv, w = chain.Pinv, chain.w
        self.q = [Pinv[j][0] * u1 + Pinv[j][1] * u2 for j in range(2)]
        self.r = [(Pinv[j][0] * v1 + Pinv[j][1] * v2) / w[j] for j in range(2)]
        self.offset = u2 - chain.gap
        # binary64 copies for the scanning filter
        self.qd = [float(x) for x in self.q]
        self.rd = [float(x) for x in self.r]
        self.wd = [float(x) for x in w]
        self.p2d = [float(chain.P[1][j]) for j in range(2)]
        self.offd = float(self.offset)

    def _trig(self, t):
        """Per mode (cos(wj t) - 1, sin(wj t), cos(wj t)), cancellation-free."""
        ch = self.chain
        out = []
        if ch.resonant:
            # slow angle theta = w2 t, fast angle exactly 2 theta
            chh, sh = mp.cos_sin(ch.w[1] * t / 2)
            s = 2 * sh * chh
            cm1 = -2 * sh * sh
            c = 1 + cm1
            out.append((-2 * s * s, 2 * s * c, 1 - 2 * s * s))
            out.append((cm1, s, c))
        else:
            for j in range(2):
                chh, sh = mp.cos_sin(ch.w[j] * t / 2)
                cm1 = -2 * sh * sh
                out.append((cm1, 2 * sh * chh, 1 + cm1))
        return out

    def state(self, t):
        """Full state (u1, u2, v1, v2) at local time t; u is u(0) + du (no cancellation)."""
        ch = self.chain
        trig = self._trig(t)
        du = [mpf(0), mpf(0)]
        v = [mpf(0), mpf(0)]
        for j, (cm1, s, c) in enumerate(trig):
            dq = self.q[j] * cm1 + self.r[j] * s
            dqdt = ch.w[j] * (self.r[j] * c - self.q[j] * s)
            for k in range(2):
                du[k] += ch.P[k][j] * dq
                v[k] += ch.P[k][j] * dqdt
        return [self.state0[0] + du[0], self.state0[1] + du[1], v[0], v[1]]

    def fg(self, t):
        """(u2(t) - d, v2(t)) in mpmath."""
        ch = self.chain
        trig = self._trig(t)
        f = self.offset
        g = mpf(0)
        for j, (cm1, s, c) in enumerate(trig):
            p2 = ch.P[1][j]
            f += p2 * (self.q[j] * cm1 + self.r[j] * s)
            g += p2 * ch.w[j] * (self.r[j] * c - self.q[j] * s)
        return f, g

    def fg_double(self, t):
        """(u2(t) - d, v2(t)) in binary64: the scanning filter only."""
        f = self.offd
        g = 0.0
        for j in range(2):
            x = self.wd[j] * t
            c, s = math.cos(x), math.sin(x)
            f += self.p2d[j] * (self.qd[j] * (c - 1.0) + self.rd[j] * s)
            g += self.p2d[j] * self.wd[j] * (self.rd[j] * c - self.qd[j] * s)
        return f, g


def bracket_root(func, a, b, fa, fb, xtol, max_iter=600):
    """Root of func in [a, b] with fa, fb of opposite signs (fb may be 0).

    Illinois (modified regula falsi) with a bisection step whenever the bracket failed to
    halve in three steps; returns when the bracket is below xtol or func is exactly 0.
    """
    if fb == 0:
        return b
    if fa == 0:
        return a
    side = 0
    width = b - a
    steps = 0
    for _ in range(max_iter):
        if b - a <= xtol:
            break
        steps += 1
        if steps >= 3 and b - a > width / 2:
            c = (a + b) / 2
            steps = 0
            width = b - a
        else:
            if b - a <= width / 2:
                steps = 0
                width = b - a
            c = (a * fb - b * fa) / (fb - fa)
            if not (a < c < b):
                c = (a + b) / 2
        fc = func(c)
        if fc == 0:
            return c
        if (fc > 0) == (fb > 0):
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
    return a if abs(fa) < abs(fb) else b


class Simulator:
    """Event-driven exact simulation (docs/model.md section 4)."""

    def __init__(self, chain, samples_per_period=2000, max_flight_periods=1000):
        self.chain = chain
        self.samples = samples_per_period
        self.max_flight_periods = max_flight_periods
        self.events = []
        self.work = {"mp_evaluations": 0, "double_evaluations": 0}

    # -- scales and tolerances --------------------------------------------------------
    def set_scales(self, state):
        ch = self.chain
        energy = ch.energy(*state)
        # smallest eigenvalue of K bounds |u|^2 <= 2 E / lambda_min(K)
        a, b, c = ch.k1 + ch.k2, -ch.k2, ch.k2
        lam_min = ((a + c) - mp.sqrt((a - c) ** 2 + 4 * b * b)) / 2
        bound = mp.sqrt(2 * energy / lam_min) if energy > 0 else mpf(0)
        self.pos_scale = max(ch.gap, bound, abs(state[0]), abs(state[1]))
        self.vel_scale = ch.w[1] * self.pos_scale
        self.tol_pos = self.pos_scale * mpf(10) ** (-(mp.dps - 8))
        self.tol_vel = self.vel_scale * mpf(10) ** (-mpf(mp.dps - 8) / 2)
        self.xtol = ch.T2 * mpf(10) ** (-(mp.dps - 2))
        self.filter_f = 1e-8 * float(self.pos_scale)
        self.filter_g = 1e-8 * float(self.vel_scale)

    def pressed_on_stop(self, u1, v1):
        """Sticking condition for a state on H with v2 = 0."""
        excess = u1 - self.chain.gap
        if excess > self.tol_pos:
            return True
        # u1 = d within tol: the spring pushes mass 2 into the stop only if v1 > 0 beyond the
        # noise of a tangency's location (a fourth-order touch, GLO_4/3, leaves v1 ~ 1e-20)
        return abs(excess) <= self.tol_pos and v1 > self.tol_vel

    # -- contact finding ----------------------------------------------------------------
    def next_contact(self, flight, t_limit=None):
        """First contact of a flight: (local time, kind) with kind 'cross' or 'touch'.

        Returns None if there is none within the scan horizon (and before t_limit).
        """
        ch = self.chain
        ratio = float(ch.w[0] / ch.w[1])
        per_period = self.samples * max(1, int(math.ceil(ratio / 2.0)))
        h = ch.T2 / per_period
        hd = float(h)
        if ch.resonant:
            n_max = per_period + 3
        else:
            n_max = int(self.max_flight_periods * per_period) + 3
        if t_limit is not None:
            n_max = min(n_max, int(mp.floor(t_limit / h)) + 2)
        cache = {}

        def mp_fg(i):
            if i not in cache:
                cache[i] = flight.fg(i * h)
                self.work["mp_evaluations"] += 1
            return cache[i]

        def f_only(t):
            self.work["mp_evaluations"] += 1
            return flight.fg(t)[0]

        def g_only(t):
            self.work["mp_evaluations"] += 1
            return flight.fg(t)[1]

        fd_prev, gd_prev = flight.fg_double(0.0)
        cache[0] = (flight.offset, flight.state0[3])
        for i in range(1, n_max + 1):
            fd, gd = flight.fg_double(i * hd)
            self.work["double_evaluations"] += 1
            flagged = fd > -self.filter_f or (gd_prev > -self.filter_g and gd < self.filter_g)
            fd_prev, gd_prev = fd, gd
            if not flagged:
                continue
            found = self.refine_interval(i, h, mp_fg, f_only, g_only)
            if found is not None:
                return found
        return None

    def refine_interval(self, i, h, mp_fg, f_only, g_only):
        """Full-precision decision on the grid interval [(i-1) h, i h]."""
        a, b = (i - 1) * h, i * h
        fa, ga = mp_fg(i - 1)
        fb, gb = mp_fg(i)
        tol = self.tol_pos
        if ga > 0 and gb <= 0:
            # a local maximum of u2 inside: locate it on v2 = 0
            tm = bracket_root(g_only, a, b, ga, gb, self.xtol)
            fm = f_only(tm)
            if fm > tol:
                left, fleft = self.negative_left(i, h, mp_fg, a, fa)
                return bracket_root(f_only, left, tm, fleft, fm, self.xtol), "cross"
            if fm >= -tol:
                return tm, "touch"
            if fb > tol:
                return bracket_root(f_only, tm, b, fm, fb, self.xtol), "cross"
            return None
        if fb > tol:
            left, fleft = self.negative_left(i, h, mp_fg, a, fa)
            return bracket_root(f_only, left, b, fleft, fb, self.xtol), "cross"
        return None

    def negative_left(self, i, h, mp_fg, a, fa):
        """A left bracket end with u2 < d (steps back over grid points sitting on H)."""
        j = i - 1
        while fa >= 0 and j > 0:
            j -= 1
            a = j * h
            fa = mp_fg(j)[0]
        if fa >= 0:
            if fa == 0 and j == 0:
                return a, -self.tol_pos  # departure from H itself: root strictly after 0
            raise RuntimeError("no sign change found while bracketing a contact")
        return a, fa

    # -- simulation ---------------------------------------------------------------------
    def add_event(self, t, kind, state, v2_pre, v2_post):
        self.events.append({"t": t, "type": kind, "u1": state[0], "u2": state[1],
                            "v1_pre": state[2], "v2_pre": v2_pre, "v2_post": v2_post})
        energy = self.chain.energy(state[0], state[1], state[2], v2_post)
        drift = abs(energy - self.energy0) / self.energy0 if self.energy0 > 0 else abs(energy)
        self.max_drift = max(self.max_drift, drift)

    def sticking(self, t0, u1, v1, t_end):
        """Sticking phase from (u1, v1) at absolute time t0; returns (release time, v1)
        or, if t_end comes first, (None, state at t_end)."""
        ch = self.chain
        omega = mp.sqrt((ch.k1 + ch.k2) / ch.m1)
        centre = ch.k2 * ch.gap / (ch.k1 + ch.k2)
        x0, y0 = u1 - centre, v1 / omega
        amp = mp.sqrt(x0 * x0 + y0 * y0)
        phase = mp.atan2(y0, x0)
        level = (ch.gap - centre) / amp
        duration = (phase + mp.acos(level)) / omega
        if t_end is not None and t0 + duration > t_end:
            s = t_end - t0
            cs, sn = mp.cos(omega * s), mp.sin(omega * s)
            return None, [centre + x0 * cs + y0 * sn, ch.gap,
                          omega * (y0 * cs - x0 * sn), mpf(0)]
        v1_release = -omega * amp * mp.sqrt((1 - level) * (1 + level))
        return t0 + duration, v1_release

    def run(self, state, max_contacts=None, t_end=None):
        ch = self.chain
        d = ch.gap
        state = list(state)
        if state[1] > d:
            raise InputError("initial state is past the stop (u2 > gap)")
        self.set_scales(state)
        self.energy0 = ch.energy(*state)
        self.max_drift = mpf(0)
        self.termination = None
        t = mpf(0)
        contacts = 0

        def count_done():
            return max_contacts is not None and contacts >= max_contacts

        # initial state on H
        mode = "flight"
        if state[1] == d:
            if state[3] > 0:
                v2 = state[3]
                state[3] = -v2
                self.add_event(t, EVENT_IMPACT, state, v2, -v2)
                contacts += 1
            elif state[3] == 0 and self.pressed_on_stop(state[0], state[2]):
                self.add_event(t, EVENT_STICK, state, mpf(0), mpf(0))
                contacts += 1
                mode = "stick"

        while True:
            if count_done():
                self.termination = "contacts"
                break
            if t_end is not None and t >= t_end:
                self.termination = "t_end"
                break
            if mode == "stick":
                t_rel, value = self.sticking(t, state[0], state[2], t_end)
                if t_rel is None:
                    state, t = value, t_end
                    self.termination = "t_end"
                    break
                t = t_rel
                state = [d, d, value, mpf(0)]
                self.add_event(t, EVENT_RELEASE, state, mpf(0), mpf(0))
                mode = "flight"
                continue
            flight = Flight(ch, state)
            limit = None if t_end is None else t_end - t
            found = self.next_contact(flight, limit)
            if found is None or (t_end is not None and t + found[0] > t_end):
                if t_end is not None:
                    state = flight.state(t_end - t)
                    t = t_end
                    self.termination = "t_end"
                else:
                    self.termination = ("no further contact" if ch.resonant
                                        else "no contact within --max-flight")
                break
            tc, kind = found
            new = flight.state(tc)
            t = t + tc
            v2_pre = new[3]
            new[1] = d
            if kind == "cross" and v2_pre > self.tol_vel:
                new[3] = -v2_pre
                self.add_event(t, EVENT_IMPACT, new, v2_pre, -v2_pre)
                contacts += 1
                state = new
                continue
            # tangential touch: v2 = 0 by definition
            new[3] = mpf(0)
            state = new
            if self.pressed_on_stop(new[0], new[2]):
                self.add_event(t, EVENT_STICK, new, mpf(0), mpf(0))
                mode = "stick"
            else:
                self.add_event(t, EVENT_GRAZING, new, mpf(0), mpf(0))
            contacts += 1
        self.final_t = t
        self.final_state = state
        return self.events


# -- command line ------------------------------------------------------------------------

VALUE_OPTIONS = {"--m1", "--m2", "--k1", "--k2", "--gap", "--branch", "--glo", "--onepp",
                 "--state", "--perturb", "--nudge", "--contacts", "--t-end", "--dps", "--digits",
                 "--format", "--samples", "--max-flight"}


def join_values(argv):
    """Turn `--opt VALUE` into `--opt=VALUE` so that values may start with '-'."""
    out = []
    i = 0
    while i < len(argv):
        arg = argv[i]
        if arg in VALUE_OPTIONS and i + 1 < len(argv):
            out.append(arg + "=" + argv[i + 1])
            i += 2
        else:
            out.append(arg)
            i += 1
    return out


def build_parser():
    p = argparse.ArgumentParser(
        prog="reference_sim.py",
        description="High-precision reference simulation of the GrazeLab chain (mpmath).")
    p.add_argument("command", nargs="?", default="simulate", choices=["simulate", "info"])
    p.add_argument("--m1", default="1")
    p.add_argument("--m2", default="0.5")
    p.add_argument("--k1", default="1")
    p.add_argument("--gap", default="1")
    p.add_argument("--k2", default=None, help="stiffness as given (no resonance imposed)")
    p.add_argument("--branch", default="upper", choices=["upper", "lower"])
    init = p.add_mutually_exclusive_group()
    init.add_argument("--glo", default=None, metavar="LAMBDA")
    init.add_argument("--onepp", default=None, metavar="T")
    init.add_argument("--state", default=None, metavar="u1,u2,v1,v2")
    p.add_argument("--perturb", default=None, metavar="du1,du2,dv1,dv2")
    p.add_argument("--nudge", default=None, metavar="EPS",
                   help="add EPS*s to u1 and EPS*w2*s to v1 (s = max(gap, |u1|, |u2|)) at "
                        "full precision, after --perturb: for sensitivity estimates")
    p.add_argument("--contacts", type=int, default=None)
    p.add_argument("--t-end", default=None)
    p.add_argument("--format", default="json", choices=["json"])
    p.add_argument("--dps", type=int, default=40, help="decimal digits of working precision")
    p.add_argument("--digits", type=int, default=30, help="significant digits printed")
    p.add_argument("--samples", type=int, default=2000, help="scan points per slow period")
    p.add_argument("--max-flight", default="1000",
                   help="detuned chains: longest free flight scanned, in slow periods T2")
    p.add_argument("--k2-from-double", action="store_true",
                   help="k2 from the design formula in binary64, converted exactly")
    p.add_argument("--double-inputs", action="store_true",
                   help="round every real input to binary64 first (as a C++ reader would)")
    return p


def parse_real(text, name, double_inputs):
    try:
        if double_inputs:
            value = mpf(float(text))
        else:
            value = mpf(text.strip())
    except (ValueError, TypeError):
        raise InputError("%s: '%s' is not a number" % (name, text))
    if not mp.isfinite(value):
        raise InputError("%s: '%s' is not finite" % (name, text))
    return value


def parse_vector(text, name, double_inputs):
    parts = text.split(",")
    if len(parts) != 4:
        raise InputError("%s needs four comma-separated numbers" % name)
    return [parse_real(x, name, double_inputs) for x in parts]


def fmt(x, digits):
    """A JSON number with `digits` significant digits."""
    if isinstance(x, bool) or isinstance(x, int):
        return x
    return RawNumber(mp.nstr(mpf(x), digits, strip_zeros=True, min_fixed=-4, max_fixed=6))


class RawNumber(str):
    """A string emitted verbatim as a JSON number by dump_json."""


def dump_json(obj, indent=0):
    pad = "  " * indent
    if isinstance(obj, RawNumber):
        text = str(obj)
        if text in ("+inf", "-inf", "nan"):
            return "null"
        return text
    if isinstance(obj, bool):
        return "true" if obj else "false"
    if obj is None:
        return "null"
    if isinstance(obj, (int,)):
        return str(obj)
    if isinstance(obj, str):
        return json.dumps(obj)
    if isinstance(obj, dict):
        items = ["%s  %s: %s" % (pad, json.dumps(k), dump_json(v, indent + 1))
                 for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}" if items else "{}"
    if isinstance(obj, list):
        if all(not isinstance(v, (dict, list)) for v in obj):
            return "[" + ", ".join(dump_json(v, indent + 1) for v in obj) + "]"
        items = [pad + "  " + dump_json(v, indent + 1) for v in obj]
        return "[\n" + ",\n".join(items) + "\n" + pad + "]" if items else "[]"
    raise TypeError(type(obj))


def model_json(chain, digits):
    n = lambda x: fmt(x, digits)
    return {
        "m1": n(chain.m1), "m2": n(chain.m2), "k1": n(chain.k1), "k2": n(chain.k2),
        "gap": n(chain.gap),
        "omega1": n(chain.w[0]), "omega2": n(chain.w[1]),
        "T1": n(chain.T[0]), "T2": n(chain.T[1]),
        "resonant": bool(chain.resonant),
        "branch": chain.branch,
        "P": [[n(chain.P[0][0]), n(chain.P[0][1])], [n(chain.P[1][0]), n(chain.P[1][1])]],
        "lambda_star": n(chain.lambda_star),
    }


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = build_parser().parse_args(join_values(argv))
    if args.dps < 15:
        raise InputError("--dps must be at least 15")
    mp.dps = args.dps
    digits = max(1, min(args.digits, args.dps))
    di = args.double_inputs
    m1 = parse_real(args.m1, "--m1", di)
    m2 = parse_real(args.m2, "--m2", di)
    k1 = parse_real(args.k1, "--k1", di)
    gap = parse_real(args.gap, "--gap", di)
    k2 = None if args.k2 is None else parse_real(args.k2, "--k2", di)
    chain = Chain(m1, m2, k1, gap, k2=k2, branch=args.branch,
                  k2_from_double=args.k2_from_double)
    if args.command == "info":
        sys.stdout.write(dump_json({"model": model_json(chain, digits)}) + "\n")
        return 0

    if args.glo is not None:
        state = chain.glo_state(parse_real(args.glo, "--glo", di))
    elif args.onepp is not None:
        period = parse_real(args.onepp, "--onepp", di)
        if period <= 0:
            raise InputError("--onepp: the period must be positive")
        state = chain.onepp_state(period)
    elif args.state is not None:
        state = parse_vector(args.state, "--state", di)
    else:
        raise InputError("no initial data: give --glo, --onepp or --state")
    if args.perturb is not None:
        delta = parse_vector(args.perturb, "--perturb", di)
        state = [a + b for a, b in zip(state, delta)]
    if args.nudge is not None:
        # full-precision nudge of u1 and v1 (never rounded to binary64): sensitivity probes
        eps = parse_real(args.nudge, "--nudge", False)
        scale = max(chain.gap, abs(state[0]), abs(state[1]))
        state[0] += eps * scale
        state[2] += eps * chain.w[1] * scale
    t_end = None if args.t_end is None else parse_real(args.t_end, "--t-end", di)
    if t_end is not None and t_end < 0:
        raise InputError("--t-end must be >= 0")
    max_contacts = args.contacts
    if max_contacts is not None and max_contacts < 0:
        raise InputError("--contacts must be >= 0")
    if max_contacts is None and t_end is None:
        max_contacts = 20

    sim = Simulator(chain, samples_per_period=args.samples,
                    max_flight_periods=parse_real(args.max_flight, "--max-flight", False))
    initial = list(state)
    started = time.perf_counter()
    events = sim.run(state, max_contacts=max_contacts, t_end=t_end)
    seconds = time.perf_counter() - started

    n = lambda x: fmt(x, digits)
    final = sim.final_state
    out = {
        "model": model_json(chain, digits),
        "initial": {"u1": n(initial[0]), "u2": n(initial[1]),
                    "v1": n(initial[2]), "v2": n(initial[3])},
        "events": [{"t": n(e["t"]), "type": e["type"], "u1": n(e["u1"]), "u2": n(e["u2"]),
                    "v1_pre": n(e["v1_pre"]), "v2_pre": n(e["v2_pre"]), "v2_post": n(e["v2_post"])}
                   for e in events],
        "final": {"t": n(sim.final_t), "u1": n(final[0]), "u2": n(final[1]),
                  "v1": n(final[2]), "v2": n(final[3])},
        "energy": {"initial": n(sim.energy0), "max_rel_drift": n(sim.max_drift)},
        "timing": {"seconds": n(seconds),
                   "contacts_per_second": n(len(events) / seconds if seconds > 0 else 0)},
        "reference": {"dps": mp.dps, "digits": digits, "samples_per_T2": args.samples,
                      "termination": sim.termination,
                      "mp_evaluations": sim.work["mp_evaluations"],
                      "double_evaluations": sim.work["double_evaluations"],
                      "numbers": "JSON numbers with 'digits' significant digits"},
    }
    sys.stdout.write(dump_json(out) + "\n")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputError as error:
        sys.stderr.write("reference_sim.py: %s\n" % error)
        sys.exit(2)
