#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The multipliers, stability classes and Krein signatures of 1IPP orbits of N-mass chains printed
by `grazelab-cli orbit --masses ... --onepp --period T` against an independent 50-digit
computation (docs/model.md section 12).

Independent of the product's formulas: the orbit's data are solved from the flow itself (the
state after the impact, u_s = d and v = V e_s, mapped by the flow over T to the same u and to
v = -V e_s: a linear system in u and V), the flow over T is mpmath's matrix exponential of
[[0, I], [-M^-1 K, 0]] (not the modal closed form), the saltation matrix is built from M and K,
and the multipliers and eigenvectors are mpmath's general eigen-solver on the full 2N x 2N
monodromy, its two eigenvalues nearest 1 (the trivial pair) left out.

Random chains of 2 to 6 masses (masses and springs from 0.3 to 3, half with a right wall, the
stop on any mass, gaps from 0.5 to 2), periods across their slowest period. For every orbit the
command line finds, in double and in binary128: each multiplier (matched one to one) within
1e-10 (double) and 1e-25 (binary128) of the reference, relative beyond the unit circle, and within
the error bar printed beside it; the class the same (unless printed "undecided", which at most a
tenth may be); the Krein signature of each multiplier on the circle the same (unless printed 0;
in binary128 never 0). Exit 0 when all hold and enough orbits were checked, 1 otherwise (a ctest
test).

    python3 chain_orbit_check.py --cli build/app/grazelab-cli/grazelab-cli [--chains 24]
"""
import argparse
import json
import random
import subprocess
import sys

import mpmath

mpmath.mp.dps = 50


def exact(x):
    """The number the command line reads from x's decimal text (repr), to 50 digits."""
    return mpmath.mpf(repr(x))


def matrices(masses, springs, right_spring):
    n = len(masses)
    M = mpmath.diag([exact(m) for m in masses])
    K = mpmath.zeros(n, n)
    for i in range(n):
        K[i, i] += exact(springs[i])
        if i > 0:
            K[i - 1, i - 1] += exact(springs[i])
            K[i - 1, i] = K[i, i - 1] = -exact(springs[i])
    K[n - 1, n - 1] += exact(right_spring)
    return M, K


def slowest_period(M, K):
    n = M.rows
    a = mpmath.matrix(n, n)
    for i in range(n):
        for j in range(n):
            a[i, j] = K[i, j] / mpmath.sqrt(M[i, i] * M[j, j])
    values, _ = mpmath.eigsy(a)
    return 2 * mpmath.pi / mpmath.sqrt(min(values))


def reference_orbit(masses, springs, right_spring, stop, gap, T):
    """(multipliers, their eigenvectors' Krein form sign, V) of the 1IPP orbit of period T, or
    None when its data leave into the stop (V >= 0)."""
    n = len(masses)
    M, K = matrices(masses, springs, right_spring)
    Minv_K = mpmath.inverse(M) * K
    A = mpmath.zeros(2 * n, 2 * n)
    for i in range(n):
        A[i, n + i] = 1
        for j in range(n):
            A[n + i, j] = -Minv_K[i, j]
    flow = mpmath.expm(A * exact(T))
    s = stop - 1
    d = exact(gap)
    # unknowns: u_i (i != s) and V; (Phi_uu - I) u + Phi_uv e_s V = 0 with u_s = d
    others = [i for i in range(n) if i != s]
    system = mpmath.zeros(n, n)
    rhs = mpmath.zeros(n, 1)
    for row in range(n):
        for col, i in enumerate(others):
            system[row, col] = flow[row, i] - (1 if row == i else 0)
        system[row, n - 1] = flow[row, n + s]
        rhs[row] = -(flow[row, s] - (1 if row == s else 0)) * d
    solution = mpmath.lu_solve(system, rhs)
    u = mpmath.zeros(n, 1)
    for col, i in enumerate(others):
        u[i] = solution[col]
    u[s] = d
    V = solution[n - 1]
    if V >= 0:
        return None
    acceleration = -(Minv_K * u)[s]
    salt = mpmath.eye(2 * n)
    salt[s, s] = -1
    salt[n + s, n + s] = -1
    salt[n + s, s] = 2 * acceleration / (-V)
    monodromy = salt * flow
    values, vectors = mpmath.eig(monodromy)
    order = sorted(range(2 * n), key=lambda i: abs(values[i] - 1))
    kept = order[2:]
    out = []
    for i in kept:
        w = [vectors[k, i] for k in range(2 * n)]
        form = sum(mpmath.conj(w[k]) * M[k, k] * w[n + k] for k in range(n))
        out.append((values[i], int(mpmath.sign(mpmath.im(form)))))
    return out, V


def reference_class(multipliers):
    off = [m for m, _ in multipliers if abs(abs(m) - 1) > mpmath.mpf(10) ** -30]
    if not off:
        return "elliptic"
    largest = max(off, key=abs)
    if abs(mpmath.im(largest)) > mpmath.mpf(10) ** -30:
        return "complex-quadruplet"
    return "hyperbolic" if mpmath.re(largest) > 0 else "flip-hyperbolic"


def check(cli, chain, T, precision, reference, problems):
    masses, springs, right_spring, stop, gap = chain
    argv = [cli, "orbit", "--masses", ",".join(repr(m) for m in masses),
            "--springs", ",".join(repr(k) for k in springs), "--stop-mass", str(stop), "--gap", repr(gap),
            "--onepp", "--period", repr(T), "--precision", precision]
    if right_spring:
        argv += ["--right-spring", repr(right_spring)]
    ran = subprocess.run(argv, capture_output=True, text=True)
    if ran.returncode != 0:
        return None  # refused (a period whose flight meets the stop early, ...): nothing claimed
    orbit = json.loads(ran.stdout, parse_float=mpmath.mpf)
    printed = [(mpmath.mpc(mpmath.mpf(re), mpmath.mpf(im)), mpmath.mpf(err), krein)
               for (re, im), err, krein in zip(orbit["multipliers"], orbit["multiplier_errors"], orbit["krein"])]
    bound = mpmath.mpf("1e-10") if precision == "double" else mpmath.mpf("1e-25")
    where = f"{' '.join(argv[1:])}"
    if len(printed) != len(reference):
        problems.append(f"{where}: {len(printed)} multipliers, the reference {len(reference)}")
        return True
    remaining = list(printed)  # matched one to one, each reference value to its nearest left
    for value, krein in sorted(reference, key=lambda r: -abs(abs(r[0]) - 1)):
        nearest = min(remaining, key=lambda p: abs(p[0] - value))
        remaining.remove(nearest)
        error = abs(nearest[0] - value)
        if error > bound * max(1, abs(value)) or error > nearest[1]:
            problems.append(f"{where}: multiplier {mpmath.nstr(nearest[0], 17)} against {mpmath.nstr(value, 25)}: "
                            f"error {mpmath.nstr(error, 3)} (its bar {mpmath.nstr(nearest[1], 3)}, the bound {bound})")
        on_circle = abs(abs(value) - 1) < mpmath.mpf(10) ** -30 and abs(mpmath.im(value)) > mpmath.mpf(10) ** -20
        if on_circle and nearest[2] != 0 and nearest[2] != krein:
            problems.append(f"{where}: Krein signature {nearest[2]} of {mpmath.nstr(value, 17)}, the reference's {krein}")
        if on_circle and nearest[2] == 0 and precision == "quad":
            problems.append(f"{where}: no Krein signature for {mpmath.nstr(value, 17)} in binary128 (the reference's {krein})")
    expected = reference_class(reference)
    if orbit["stability"] != "undecided" and orbit["stability"] != expected:
        problems.append(f"{where}: class {orbit['stability']}, the reference's {expected}")
    return orbit["stability"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True)
    parser.add_argument("--chains", type=int, default=24)
    parser.add_argument("--periods", type=int, default=5)
    parser.add_argument("--seed", type=int, default=20261202)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    problems = []
    checked = 0
    refused = 0
    undecided = 0
    classes = {}
    for c in range(args.chains):
        n = 2 + c % 5
        masses = [round(10 ** rng.uniform(-0.5, 0.5), 4) for _ in range(n)]
        springs = [round(10 ** rng.uniform(-0.5, 0.5), 4) for _ in range(n)]
        right_spring = round(10 ** rng.uniform(-0.5, 0.5), 4) if rng.random() < 0.5 else 0
        stop = rng.randint(1, n)
        if n == 2 and stop == 2 and not right_spring:
            stop = 1  # (the note's shape is orbit's two-mass command, checked by periodic_ref.py)
        gap = round(rng.uniform(0.5, 2), 3)
        M, K = matrices(masses, springs, right_spring)
        slow = slowest_period(M, K)
        for _ in range(args.periods):
            T = round(float(slow * rng.uniform(0.03, 0.99)), 6)
            reference = reference_orbit(masses, springs, right_spring, stop, gap, T)
            if reference is None:
                continue
            chain = (masses, springs, right_spring, stop, gap)
            for precision in ("double", "quad"):
                said = check(args.cli, chain, T, precision, reference[0], problems)
                if said is None:
                    refused += 1
                    continue
                checked += 1
                undecided += said == "undecided"
                cls = reference_class(reference[0])
                classes[cls] = classes.get(cls, 0) + 1
    print(f"{checked} orbits checked in double and binary128 ({undecided} said undecided; {refused} periods "
          f"refused, whose data have V < 0 but no admissible orbit: the flight meets the stop before T); "
          f"classes {classes}")
    for problem in problems:
        print(problem)
    if checked < 20 or len(classes) < 3:
        print("too few orbits, or too few classes, to say anything")
        return 1
    if undecided > checked // 10:
        print("more than a tenth of the orbits said undecided: the class check says too little")
        return 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
