#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The kIPP orbits of N-mass chains found by `grazelab-cli orbit --impacts K --energy E --guess ...
--masses ...` (Newton on the return map, docs/model.md section 12) against an independent 50-digit
computation: the orbit itself, its period, its multipliers, class and Krein signatures.

Independent of the product's formulas: the orbit is solved again by a 50-digit Newton of its own,
from the state the command line printed, at the same energy: the unknowns are the 2N - 2 section
coordinates (u_j, v_j of every mass j != s; u_s = d and v_s = -sqrt(2 (E - rest) / m_s)), the
residual is the state after K impacts minus the start, every impact time is mpmath.findroot's root
of u_s(t) = d started from the printed event times, the flow is the general eigen-decomposition of
A = [[0, I], [-M^-1 K, 0]] (mpmath.eig, made once per chain and checked against mpmath.expm), the
Jacobian finite differences (step 1e-20 of the scales). Along every flight u_s stays below d
(199 samples) and v_s > 0 at each impact. The monodromy is the product over the legs of the
saltation matrix (identity but S[u_s][u_s] = S[v_s][v_s] = -1, S[v_s][u_s] = 2 a_s / v_s-) and
the flight's matrix; its multipliers and eigenvectors are mpmath.eig's at 50 digits, the two
nearest 1 (the trivial pair) left out.

The orbits: random chains of 3 to 5 masses (masses and springs from 0.3 to 3, half with a right
wall, the stop on any mass, gaps from 0.5 to 2). (1) For up to two period doublings of each
chain's 1IPP family (`family --onepp --count 300`) at T*, the 1IPP orbits of period T*(1 +- 1e-5)
and T*(1 +- 4e-5) (solved here from mpmath.expm, as chain_orbit_check.py does) moved along the
real eigenvector of their multiplier nearest -1 (projected on the section along the flow; lengths
over the gap, speeds over the slowest frequency times the gap), by 30 amounts +-0.4 (i/15)^2,
smallest first, seed `--impacts 2` at the 1IPP orbit's energy; the 2IPP orbits it prints with a
period within 1e-2 of 2T are checked (one printed with its two impacts within 1e-7 of each other
must have them distinct at 50 digits), and a period stops at its first 2IPP orbit checked (the
other amounts find it again or the 1IPP orbit twice; `--all-seeds` runs them all). (2) At two
random periods per chain, the 1IPP orbit moved by up to 1e-3 (scaled) in each coordinate seeds
`--impacts 1` (checked, and equal to the closed-form orbit to 1e-12) and `--impacts 2`, which
must not print the 1IPP orbit run twice (its two impacts are checked distinct at 50 digits).
Every orbit is checked in double and again in binary128 (`--precision quad`
seeded from the double orbit's state): its state (relative, in the scaled units) and period within
1e-9 (double) and 1e-24 (binary128) of the reference; each multiplier (matched one to one) within
the same bound relative to max(1, |mu|), and separately within its printed error bar; the class
the same (unless printed "undecided"); the Krein signature of each multiplier on the circle off
the real axis the same where printed nonzero. Exit 0 when all hold and at least 6 2IPP orbits
were checked, 1 otherwise.

Measured on 2 cores while another build ran (load average 2 to 4.5): the defaults (7 chains, 14
period doublings, about 1100 runs of the command line, most of the time) take 105 to 160 s and
check 29 orbits, 24 of them 2IPP; `--chains 8` 140 to 210 s; `--all-seeds` about 1.5 times longer.

    python3 chain_kipp_check.py --cli build/app/grazelab-cli/grazelab-cli [--chains 7] [--seed S]
"""
import argparse
import json
import os
import random
import shlex
import subprocess
import sys
import tempfile
import time

import mpmath

# the chain's numbers as the command line reads them, its matrices and its slowest period: the
# 1IPP check's own (it sets 50 digits too)
from chain_orbit_check import exact, matrices, slowest_period

mpmath.mp.dps = 50

TINY = mpmath.mpf(10) ** -30


class Failed(Exception):
    pass


class Chain:
    """A chain's matrices and its flow from one eigen-decomposition of A (50 digits)."""

    def __init__(self, masses, springs, right_spring, stop, gap):
        self.masses, self.springs, self.right_spring, self.stop, self.gap = masses, springs, right_spring, stop, gap
        n = self.n = len(masses)
        s = self.s = stop - 1
        self.d = exact(gap)
        self.M, self.K = matrices(masses, springs, right_spring)
        self.Minv_K = mpmath.inverse(self.M) * self.K
        A = mpmath.zeros(2 * n, 2 * n)
        for i in range(n):
            A[i, n + i] = 1
            for j in range(n):
                A[n + i, j] = -self.Minv_K[i, j]
        self.A = A
        self.omega = 2 * mpmath.pi / slowest_period(self.M, self.K)
        self.scale = [self.d] * n + [self.omega * self.d] * n
        self.others = [i for i in range(n) if i != s]
        self.zscale = [self.d for _ in self.others] + [self.omega * self.d for _ in self.others]
        self.lam, self.R = mpmath.eig(A)
        self.Rinv = mpmath.inverse(self.R)

    def cli_args(self):
        argv = ["--masses", ",".join(repr(m) for m in self.masses),
                "--springs", ",".join(repr(k) for k in self.springs),
                "--stop-mass", str(self.stop), "--gap", repr(self.gap)]
        if self.right_spring:
            argv += ["--right-spring", repr(self.right_spring)]
        return argv

    def describe(self):
        return " ".join(self.cli_args())

    def coefficients(self, x):
        return self.Rinv * x

    def at(self, c, t, row):
        return mpmath.re(mpmath.fsum(self.R[row, j] * c[j] * mpmath.exp(self.lam[j] * t) for j in range(2 * self.n)))

    def flow(self, x, t):
        c = self.coefficients(x)
        return mpmath.matrix([self.at(c, t, r) for r in range(2 * self.n)])

    def flow_matrix(self, t):
        e = mpmath.diag([mpmath.exp(l * t) for l in self.lam])
        return (self.R * e * self.Rinv).apply(mpmath.re)

    def energy(self, x):
        n = self.n
        u = mpmath.matrix([x[i] for i in range(n)])
        return (sum(self.M[i, i] * x[n + i] ** 2 for i in range(n)) + (u.T * self.K * u)[0]) / 2

    def state(self, z, E):
        """The state on the section of coordinates z at energy E (v_s < 0), or None."""
        n, s = self.n, self.s
        x = mpmath.zeros(2 * n, 1)
        x[s] = self.d
        for col, i in enumerate(self.others):
            x[i] = z[col]
            x[n + i] = z[len(self.others) + col]
        kinetic = E - self.energy(x)
        if kinetic <= 0:
            return None
        x[n + s] = -mpmath.sqrt(2 * kinetic / self.M[s, s])
        return x

    def section(self, x):
        return mpmath.matrix([x[i] for i in self.others] + [x[self.n + i] for i in self.others])

    def distance(self, x, y):
        """Scaled max-norm distance of two states."""
        return max(abs(x[i] - y[i]) / self.scale[i] for i in range(2 * self.n))

    def size(self, x):
        return max(abs(x[i]) / self.scale[i] for i in range(2 * self.n))


def path(ch, x0, flights):
    """The legs (tau, pre-impact state) and the state after len(flights) impacts from x0, each
    impact time the root of u_s(t) = d nearest its guess."""
    n, s = ch.n, ch.s
    x = x0
    legs = []
    for guess in flights:
        c = ch.coefficients(x)
        try:
            tau = mpmath.findroot(lambda t: ch.at(c, t, s) - ch.d, mpmath.mpf(guess), solver="newton",
                                  df=lambda t: ch.at(c, t, n + s))
        except (ValueError, ZeroDivisionError) as e:
            raise Failed(f"no impact time near {mpmath.nstr(guess, 12)}: {str(e).splitlines()[0]}")
        if tau <= 0:
            raise Failed(f"impact time {mpmath.nstr(tau, 12)} <= 0")
        before = ch.flow(x, tau)
        legs.append((tau, x, before))
        x = before.copy()
        x[n + s] = -x[n + s]
    return x, legs


def residual(ch, E, z, flights):
    x0 = ch.state(z, E)
    if x0 is None:
        raise Failed("the section point has no state of that energy")
    xk, legs = path(ch, x0, flights)
    r = ch.section(xk) - z
    return r, legs, x0


def reference_newton(ch, E, z, flights):
    """The 50-digit orbit at energy E near section point z: (z, x0, legs)."""
    m = len(z)
    for _ in range(16):
        r, legs, x0 = residual(ch, E, z, flights)
        flights = [leg[0] for leg in legs]
        size = max(abs(r[i]) / ch.zscale[i] for i in range(m))
        if size < mpmath.mpf(10) ** -42:
            return z, x0, legs
        J = mpmath.zeros(m, m)
        for i in range(m):
            h = mpmath.mpf(10) ** -20 * ch.zscale[i]
            zi = z.copy()
            zi[i] += h
            ri, _, _ = residual(ch, E, zi, flights)
            for row in range(m):
                J[row, i] = (ri[row] - r[row]) / h
        z = z - mpmath.lu_solve(J, r)
    raise Failed(f"the 50-digit Newton does not close (residual {mpmath.nstr(size, 3)} after 16 steps)")


def admissible(ch, legs):
    """Why the legs are no admissible path (u_s reaching d inside a flight, v_s <= 0 at an impact), or None."""
    n, s = ch.n, ch.s
    for number, (tau, start, before) in enumerate(legs):
        if before[n + s] <= 0:
            return f"impact {number + 1}: v_s = {mpmath.nstr(before[n + s], 5)} <= 0"
        c = ch.coefficients(start)
        for i in range(1, 200):
            t = tau * i / 200
            if ch.at(c, t, s) >= ch.d:
                return f"flight {number + 1}: u_s - d = {mpmath.nstr(ch.at(c, t, s) - ch.d, 5)} >= 0 at {i}/200 of it"
    return None


def monodromy(ch, legs):
    n, s = ch.n, ch.s
    product = mpmath.eye(2 * n)
    for tau, _, before in legs:
        u = mpmath.matrix([before[i] for i in range(n)])
        acceleration = -(ch.Minv_K * u)[s]
        salt = mpmath.eye(2 * n)
        salt[s, s] = -1
        salt[n + s, n + s] = -1
        salt[n + s, s] = 2 * acceleration / before[n + s]
        product = salt * ch.flow_matrix(tau) * product
    return product


def multipliers(ch, mono):
    """[(multiplier, Krein sign)] but the trivial pair; raises Failed when the pair is not apart."""
    n = ch.n
    values, vectors = mpmath.eig(mono)
    order = sorted(range(2 * n), key=lambda i: abs(values[i] - 1))
    if abs(values[order[1]] - 1) > mpmath.mpf(10) ** -15 or (
            2 * n > 2 and abs(values[order[2]] - 1) < mpmath.mpf(10) ** -15):
        raise Failed("the trivial pair is not set apart from the others at 50 digits: "
                     + ", ".join(mpmath.nstr(values[i], 8) for i in order[:3]))
    out = []
    for i in order[2:]:
        w = [vectors[k, i] for k in range(2 * n)]
        form = sum(mpmath.conj(w[k]) * ch.M[k, k] * w[n + k] for k in range(n))
        out.append((values[i], int(mpmath.sign(mpmath.im(form)))))
    return out


def reference_class(mults):
    off = [m for m, _ in mults if abs(abs(m) - 1) > TINY]
    if not off:
        return "elliptic"
    largest = max(off, key=abs)
    if abs(mpmath.im(largest)) > TINY:
        return "complex-quadruplet"
    return "hyperbolic" if mpmath.re(largest) > 0 else "flip-hyperbolic"


def reference_onepp(ch, T):
    """The 1IPP orbit of period T from mpmath.expm: (x0, E, monodromy eigenvalues and vectors), or
    None when its data leave into the stop or its flight meets the stop before T."""
    n, s, d = ch.n, ch.s, ch.d
    flow = mpmath.expm(ch.A * exact(T))
    system = mpmath.zeros(n, n)
    rhs = mpmath.zeros(n, 1)
    for row in range(n):
        for col, i in enumerate(ch.others):
            system[row, col] = flow[row, i] - (1 if row == i else 0)
        system[row, n - 1] = flow[row, n + s]
        rhs[row] = -(flow[row, s] - (1 if row == s else 0)) * d
    solution = mpmath.lu_solve(system, rhs)
    x0 = mpmath.zeros(2 * n, 1)
    for col, i in enumerate(ch.others):
        x0[i] = solution[col]
    x0[s] = d
    V = solution[n - 1]
    if V >= 0:
        return None
    x0[n + s] = V
    before = flow * x0
    legs = [(exact(T), x0, before)]
    if admissible(ch, legs) is not None:
        return None
    difference = ch.flow_matrix(exact(T)) - flow
    drift = max(abs(difference[i, j]) for i in range(2 * n) for j in range(2 * n))
    if drift > mpmath.mpf(10) ** -35:
        raise Failed(f"the eigen-decomposed flow is {mpmath.nstr(drift, 3)} off mpmath.expm at T = {T}")
    values, vectors = mpmath.eig(monodromy(ch, legs))
    return x0, ch.energy(x0), values, vectors


def flip_direction(ch, x0, values, vectors):
    """The section coordinates (scaled, max norm 1) of the real eigenvector of the multiplier
    nearest -1, projected on the section along the flow."""
    n, s = ch.n, ch.s
    i = min(range(2 * n), key=lambda j: abs(values[j] + 1))
    w = [vectors[k, i] for k in range(2 * n)]
    big = max(w, key=abs)
    w = mpmath.matrix([mpmath.re(c / big) for c in w])
    f = ch.A * x0
    w = w - (w[s] / f[s]) * f
    z = ch.section(w)
    z = [z[j] / ch.zscale[j] for j in range(len(z))]
    top = max(abs(c) for c in z)
    return [c / top for c in z]


def call(argv):
    """subprocess.run, waiting (up to a minute) while the command line is being relinked."""
    for attempt in range(30):
        try:
            return subprocess.run(argv, capture_output=True, text=True, timeout=300)
        except OSError:  # missing, not yet executable, or busy
            if attempt == 29:
                raise
            time.sleep(2)


def run_orbit(cli, ch, k, energy, guess, precision):
    """(argv, parsed JSON or None, stderr)."""
    argv = [cli, "orbit", "--impacts", str(k), "--energy", energy, "--guess", ",".join(guess)] + ch.cli_args() + [
        "--precision", precision]
    ran = call(argv)
    if ran.returncode != 0:
        return argv, None, ran.stderr.strip()
    return argv, json.loads(ran.stdout, parse_float=mpmath.mpf), ""


def printed_state(ch, orbit):
    n = ch.n
    x = mpmath.zeros(2 * n, 1)
    for i in range(n):
        x[i] = mpmath.mpf(orbit["state"]["u"][i])
        x[n + i] = mpmath.mpf(orbit["state"]["v"][i])
    return x


def printed_impacts(ch, orbit):
    """The states just after each printed impact."""
    n, s = ch.n, ch.s
    out = []
    for e in orbit["events"]:
        x = mpmath.zeros(2 * n, 1)
        for i in range(n):
            x[i] = mpmath.mpf(e["u"][i])
            x[n + i] = mpmath.mpf(e["v_before"][i])
        x[n + s] = mpmath.mpf(e["v_after"])
        out.append(x)
    return out


def guess_text(ch, x):
    z = ch.section(x)
    return [repr(float(c)) for c in z]


class Reference:
    def __init__(self, ch, E, k, orbit, where):
        """The 50-digit orbit from the printed one's state: raises Failed."""
        self.ch, self.E, self.k = ch, E, k
        x = printed_state(ch, orbit)
        times = [mpmath.mpf(e["t"]) for e in orbit["events"]]
        if len(times) != k or any(e["type"] != "impact" for e in orbit["events"]):
            raise Failed(f"events {[e['type'] for e in orbit['events']]} printed for {k} impacts")
        flights = [times[0]] + [times[i] - times[i - 1] for i in range(1, k)]
        self.z, self.x0, self.legs = reference_newton(ch, E, ch.section(x), flights)
        self.period = sum(leg[0] for leg in self.legs)
        why = admissible(ch, self.legs)
        if why is not None:
            raise Failed(f"the 50-digit orbit is not admissible: {why}")
        self.mults = multipliers(ch, monodromy(ch, self.legs))
        self.cls = reference_class(self.mults)
        # the states after each impact: distinct for a true k-impact orbit
        after = [self.x0]
        for _, _, before in self.legs[:-1]:
            y = before.copy()
            y[ch.n + ch.s] = -y[ch.n + ch.s]
            after.append(y)
        self.after = after
        self.separation = min((ch.distance(after[i], after[j]) for i in range(k) for j in range(i)),
                              default=mpmath.inf)


def compare(ref, orbit, precision, where, problems, tally):
    """Check a printed orbit against the reference; return its class as printed."""
    ch = ref.ch
    worst = tally.worst.setdefault(precision, {"state": 0, "period": 0, "multiplier": 0, "over bar": 0})
    bound = mpmath.mpf("1e-9") if precision == "double" else mpmath.mpf("1e-24")
    if orbit["impacts"] != ref.k:
        problems.append(f"{where}: {orbit['impacts']} impacts printed, {ref.k} asked")
        return None
    x = printed_state(ch, orbit)
    error = ch.distance(x, ref.x0) / max(1, ch.size(ref.x0))
    worst["state"] = max(worst["state"], error)
    if error > bound:
        problems.append(f"{where}: state {error} (relative, scaled) off the 50-digit orbit "
                        f"(u_s - d printed {mpmath.nstr(x[ch.s] - ch.d, 3)}); the bound {bound}")
    error = abs(mpmath.mpf(orbit["period"]) - ref.period) / ref.period
    worst["period"] = max(worst["period"], error)
    if error > bound:
        problems.append(f"{where}: period {orbit['period']} against {mpmath.nstr(ref.period, 30)}: "
                        f"{mpmath.nstr(error, 3)} relative, the bound {bound}")
    error = abs(mpmath.mpf(orbit["energy"]) - ref.E) / ref.E
    if error > bound:
        problems.append(f"{where}: energy {orbit['energy']} printed for {mpmath.nstr(ref.E, 20)}")
    printed = [(mpmath.mpc(mpmath.mpf(re), mpmath.mpf(im)), mpmath.mpf(err), krein)
               for (re, im), err, krein in zip(orbit["multipliers"], orbit["multiplier_errors"], orbit["krein"])]
    if len(printed) != len(ref.mults):
        problems.append(f"{where}: {len(printed)} multipliers, the reference {len(ref.mults)}")
        return orbit["stability"]
    remaining = list(printed)
    for value, krein in sorted(ref.mults, key=lambda r: -abs(abs(r[0]) - 1)):
        nearest = min(remaining, key=lambda p: abs(p[0] - value))
        remaining.remove(nearest)
        error = abs(nearest[0] - value)
        worst["multiplier"] = max(worst["multiplier"], error / max(1, abs(value)))
        worst["over bar"] = max(worst["over bar"], error / nearest[1] if nearest[1] > 0 else mpmath.inf)
        if error > bound * max(1, abs(value)):
            problems.append(f"{where}: multiplier {mpmath.nstr(nearest[0], 17)} against {mpmath.nstr(value, 25)}: "
                            f"error {mpmath.nstr(error, 3)} beyond the bound {bound} (x max(1,|mu|))")
        if error > nearest[1]:
            problems.append(f"{where}: multiplier {mpmath.nstr(nearest[0], 17)} against {mpmath.nstr(value, 25)}: "
                            f"error {mpmath.nstr(error, 3)} beyond its printed bar {mpmath.nstr(nearest[1], 3)}")
        on_circle = abs(abs(value) - 1) < TINY and abs(mpmath.im(value)) > mpmath.mpf(10) ** -20
        if on_circle and nearest[2] != 0 and nearest[2] != krein:
            problems.append(f"{where}: Krein signature {nearest[2]} of {mpmath.nstr(value, 17)}, the reference's {krein}")
    if orbit["stability"] != "undecided" and orbit["stability"] != ref.cls:
        problems.append(f"{where}: class {orbit['stability']}, the reference's {ref.cls}")
    return orbit["stability"]


class Tally:
    def __init__(self):
        self.orbits = 0
        self.by_impacts = {}
        self.classes = {}
        self.undecided = 0
        self.refused = {}
        self.seen = []  # (E, period, impact states) of orbits checked
        self.worst = {}  # precision: the largest errors seen (relative), and of a multiplier over its bar


def check(cli, ch, E, energy_text, k, argv, orbit, tally, problems):
    """Check a double orbit, then the binary128 one seeded from it."""
    where = shlex.join(argv[1:])
    try:
        ref = Reference(ch, E, k, orbit, where)
    except Failed as e:
        problems.append(f"{where}: {e}")
        return None
    if k >= 2 and ref.separation < mpmath.mpf(10) ** -20:
        printed = printed_impacts(ch, orbit)
        apart = min(ch.distance(printed[i], printed[j]) for i in range(k) for j in range(i))
        problems.append(f"{where}: printed as a {k}-impact orbit (admissible {orbit.get('admissible')}, its impacts "
                        f"{mpmath.nstr(apart, 3)} apart, scaled) but it is one shorter orbit run {k} times: the "
                        f"50-digit Newton from its state closes on it (impacts {mpmath.nstr(ref.separation, 3)} apart), "
                        f"{mpmath.nstr(ch.distance(printed_state(ch, orbit), ref.x0), 3)} from the printed state")
        return None
    said = compare(ref, orbit, "double", where, problems, tally)
    argv_q, orbit_q, message = run_orbit(cli, ch, k, energy_text, guess_text(ch, printed_state(ch, orbit)), "quad")
    where_q = shlex.join(argv_q[1:])
    if orbit_q is None:
        problems.append(f"{where_q}: refused in binary128 from the double orbit's state: {message}")
    else:
        said_q = compare(ref, orbit_q, "quad", where_q, problems, tally)
        tally.undecided += said_q == "undecided"
    tally.undecided += said == "undecided"
    tally.orbits += 1
    tally.by_impacts[k] = tally.by_impacts.get(k, 0) + 1
    tally.classes[ref.cls] = tally.classes.get(ref.cls, 0) + 1
    tally.seen.append((E, ref.period, ref.after))
    return ref


def seen_before(ch, tally, E, orbit):
    x = printed_state(ch, orbit)
    T = mpmath.mpf(orbit["period"])
    for E2, T2, states in tally.seen:
        if E2 == E and abs(T - T2) < mpmath.mpf(10) ** -8 * T2 and min(ch.distance(x, y) for y in states) < 1e-6:
            return True
    return False


def refuse(tally, part, message):
    key = part + ": " + (message.split(":")[-1].strip()[:50] if message else "?")
    tally.refused[key] = tally.refused.get(key, 0) + 1


def onepp_at(ch, T, problems):
    """The reference 1IPP orbit of period T as (x0, E read as the command line reads its text,
    that text, multipliers, eigenvectors); None when there is none (a reference failure noted)."""
    try:
        one = reference_onepp(ch, T)
    except Failed as e:
        problems.append(f"{ch.describe()}: reference: {e}")
        return None
    if one is None:
        return None
    x0, E, values, vectors = one
    energy_text = repr(float(E))
    return x0, exact(float(E)), energy_text, values, vectors


def doubled_orbits(cli, ch, tally, problems, bifurcations, amounts, all_seeds):
    """2IPP orbits near the 1IPP family's period doublings."""
    for T_star in bifurcations:
        for factor in ("-4e-5", "-1e-5", "1e-5", "4e-5"):
            T = float(T_star * (1 + float(factor)))
            one = onepp_at(ch, T, problems)
            if one is None:
                continue
            x0, E, energy_text, values, vectors = one
            direction = flip_direction(ch, x0, values, vectors)
            z0 = ch.section(x0)
            for a in amounts:
                guess = [repr(float(z0[j] + a * direction[j] * ch.zscale[j])) for j in range(len(z0))]
                argv, orbit, message = run_orbit(cli, ch, 2, energy_text, guess, "double")
                if orbit is None:
                    refuse(tally, "2 from a flip", message)
                    continue
                if abs(mpmath.mpf(orbit["period"]) / (2 * exact(T)) - 1) > 0.01:
                    continue
                impacts = printed_impacts(ch, orbit)
                if len(impacts) == 2 and ch.distance(impacts[0], impacts[1]) < 1e-7:
                    # printed as two impacts but one orbit twice, to double's eyes: decide at 50 digits
                    check(cli, ch, E, energy_text, 2, argv, orbit, tally, problems)
                    continue
                if seen_before(ch, tally, E, orbit):
                    continue
                found = check(cli, ch, E, energy_text, 2, argv, orbit, tally, problems)
                if found is not None and not all_seeds:
                    break  # the one orbit born there found (the other amounts find it again or the 1IPP twice)


def newton_from_onepp(cli, ch, tally, problems, periods, rng):
    """1IPP orbits found again by Newton from 1e-3 off; --impacts 2 from there prints no repeated orbit."""
    for T in periods:
        one = onepp_at(ch, T, problems)
        if one is None:
            continue
        x0, E, energy_text, _, _ = one
        z0 = ch.section(x0)
        guess = [repr(float(z0[j] + mpmath.mpf("1e-3") * rng.uniform(-1, 1) * ch.zscale[j])) for j in range(len(z0))]
        argv, orbit, message = run_orbit(cli, ch, 1, energy_text, guess, "double")
        if orbit is None:
            refuse(tally, "1 from 1e-3 off", message)
        else:
            ref = check(cli, ch, E, energy_text, 1, argv, orbit, tally, problems)
            if ref is not None and abs(ref.period / exact(T) - 1) < 0.01:
                # the energy was rounded to double: the orbit is the closed form's of a period that near T
                off = ch.distance(ref.x0, x0) / max(1, ch.size(x0))
                if off > mpmath.mpf("1e-12"):
                    problems.append(f"{shlex.join(argv[1:])}: the 50-digit Newton orbit is {mpmath.nstr(off, 3)} "
                                    f"off the closed form's of period {T} (reference disagreement)")
        argv, orbit, message = run_orbit(cli, ch, 2, energy_text, guess, "double")
        if orbit is None:
            refuse(tally, "2 from 1e-3 off", message)
        elif not seen_before(ch, tally, E, orbit):
            check(cli, ch, E, energy_text, 2, argv, orbit, tally, problems)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--chains", type=int, default=7)
    parser.add_argument("--periods", type=int, default=2, help="random periods per chain for the 1IPP Newton")
    parser.add_argument("--seeds", type=int, default=30, help="amounts along the flip eigenvector")
    parser.add_argument("--all-seeds", action="store_true",
                        help="run every amount at every period (by default a period stops at its first 2IPP orbit)")
    parser.add_argument("--seed", type=int, default=20261203)
    args = parser.parse_args()
    started = time.time()
    rng = random.Random(args.seed)
    half = args.seeds // 2
    amounts = sorted([mpmath.mpf("0.4") * (mpmath.mpf(i) / half) ** 2 * sign
                      for i in range(1, half + 1) for sign in (1, -1)], key=abs)
    problems = []
    tally = Tally()
    doublings = 0
    with tempfile.TemporaryDirectory() as tmp:
        for c in range(args.chains):
            n = 3 + c % 3
            masses = [round(10 ** rng.uniform(-0.5, 0.5), 4) for _ in range(n)]
            springs = [round(10 ** rng.uniform(-0.5, 0.5), 4) for _ in range(n)]
            right_spring = round(10 ** rng.uniform(-0.5, 0.5), 4) if rng.random() < 0.5 else 0
            stop = rng.randint(1, n)
            gap = round(rng.uniform(0.5, 2), 3)
            ch = Chain(masses, springs, right_spring, stop, gap)
            slow = slowest_period(ch.M, ch.K)
            periods = [round(float(slow * rng.uniform(0.03, 0.99)), 6) for _ in range(args.periods)]
            prefix = os.path.join(tmp, f"family{c}")
            ran = call([args.cli, "family", "--onepp"] + ch.cli_args() + ["--count", "300", "--out", prefix])
            bifurcations = []
            if ran.returncode != 0:
                problems.append(f"family --onepp {ch.describe()} --count 300: exit {ran.returncode}: {ran.stderr.strip()}")
            else:
                with open(prefix + ".json") as f:
                    family = json.load(f)
                bifurcations = [b["T"] for b in family["bifurcations"] if b["kind"] == "period-doubling"][:2]
            doublings += len(bifurcations)
            doubled_orbits(args.cli, ch, tally, problems, bifurcations, amounts, args.all_seeds)
            newton_from_onepp(args.cli, ch, tally, problems, periods, rng)
    seconds = time.time() - started
    twos = tally.by_impacts.get(2, 0)
    print(f"{tally.orbits} orbits checked in double and binary128 ({twos} 2IPP, {tally.by_impacts.get(1, 0)} 1IPP; "
          f"{doublings} period doublings seeded; {tally.undecided} printed undecided); classes {tally.classes}; "
          f"guesses refused {sum(tally.refused.values())} ({tally.refused}); {seconds:.0f} s")
    for precision, worst in tally.worst.items():
        print(f"  largest in {precision}: " + ", ".join(f"{key} {mpmath.nstr(value, 2)}" for key, value in worst.items()))
    for problem in problems:
        print(problem)
    if twos < 6:
        print(f"too few 2IPP orbits checked ({twos}, fewer than 6) to say anything")
        return 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
