#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The modes of N-mass chains printed by `grazelab-cli info --masses ... --springs ...` against
an independent 50-digit computation (mpmath's symmetric eigen-solver, Jacobi's method, on the
same equations: M^-1/2 K M^-1/2, docs/model.md section 11).

The chains are random and stiff on purpose: masses and springs from 1e-3 to 1e3, 2 to 8
masses, half of them with a right wall, the stop on any mass. Checked: every frequency to
its double rounding (relative, the slowest included), every shape entry to 1e-15 of itself
(plus 1e-30 of the column), and each node at the stop named when and only when the 50-digit
shape entry is below what binary128 resolves (1e-30 of the largest; exact nodes of mirror-
symmetric chains included). Exit 0 when all hold, 1 otherwise (a ctest test).

    python3 chain_modes_check.py --cli build/app/grazelab-cli/grazelab-cli [--chains 60]
"""
import argparse
import json
import random
import subprocess
import sys

import mpmath


def reference_modes(masses, springs, right_spring):
    """Frequencies (fastest first) and M-orthonormal shapes, signed like the CLI's."""
    n = len(masses)
    inv_root = [1 / mpmath.sqrt(mpmath.mpf(m)) for m in masses]
    a = mpmath.zeros(n, n)
    for i in range(n):
        right = mpmath.mpf(springs[i + 1]) if i + 1 < n else mpmath.mpf(right_spring)
        a[i, i] = (mpmath.mpf(springs[i]) + right) * inv_root[i] ** 2
        if i + 1 < n:
            a[i, i + 1] = a[i + 1, i] = -right * inv_root[i] * inv_root[i + 1]
    values, vectors = mpmath.eigsy(a)
    order = sorted(range(n), key=lambda j: -values[j])
    modes = []
    for j in order:
        shape = [inv_root[i] * vectors[i, j] for i in range(n)]
        modes.append((mpmath.sqrt(values[j]), shape))
    return modes


def check_chain(cli, masses, springs, right_spring, stop_mass):
    argv = [cli, "info", "--masses", ",".join(repr(m) for m in masses),
            "--springs", ",".join(repr(k) for k in springs), "--stop-mass", str(stop_mass)]
    if right_spring:
        argv += ["--right-spring", repr(right_spring)]
    printed = json.loads(subprocess.run(argv, check=True, capture_output=True, text=True).stdout)
    problems = []
    worst_omega = 0.0
    s = stop_mass - 1
    for j, (omega, shape) in enumerate(reference_modes(masses, springs, right_spring)):
        mode = printed["modes"][j]
        error = abs(mpmath.mpf(mode["omega"]) / omega - 1)
        worst_omega = max(worst_omega, float(error))
        if error > 2.3e-16:
            problems.append(f"mode {j + 1}: omega {mode['omega']!r} against {mpmath.nstr(omega, 20)}"
                            f" (relative error {mpmath.nstr(error, 3)})")
        largest = max(abs(x) for x in shape)
        # a node is named when the entry is below what binary128 resolves (the CLI's bound
        # is 8 N ulps of 1e-34 times the eigenvector's sensitivity): one it names must be
        # below 1e-30 of the largest here, one it does not must be above this 50-digit zero
        relative = abs(shape[s]) / largest
        node = relative <= mpmath.mpf(10) ** -40
        named_wrongly = relative > 1e-30 if mode["node_at_stop"] else node
        if named_wrongly:
            problems.append(f"mode {j + 1}: node at the stop {mode['node_at_stop']}, the 50-digit "
                            f"entry is {mpmath.nstr(shape[s] / largest, 5)} of the largest")
        node = mode["node_at_stop"]
        # the CLI signs each shape by the stopped mass's entry (or a node's first moving one)
        signer = s if not node else next(i for i, x in enumerate(shape) if abs(x) > 1e-40 * largest)
        sign = 1 if shape[signer] > 0 else -1
        for i, x in enumerate(shape):
            got = mpmath.mpf(mode["shape"][i])
            if abs(got - sign * x) > 1e-15 * abs(x) + 1e-30 * largest:
                problems.append(f"mode {j + 1}, mass {i + 1}: shape {mode['shape'][i]!r} against "
                                f"{mpmath.nstr(sign * x, 20)}")
    return problems, worst_omega


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="path of grazelab-cli")
    parser.add_argument("--chains", type=int, default=60)
    parser.add_argument("--seed", type=int, default=20261126)
    args = parser.parse_args()
    mpmath.mp.dps = 50
    rng = random.Random(args.seed)
    failed = 0
    worst = 0.0
    for index in range(args.chains):
        n = 2 + index % 7
        masses = [10 ** rng.uniform(-3, 3) for _ in range(n)]
        springs = [10 ** rng.uniform(-3, 3) for _ in range(n)]
        right = 10 ** rng.uniform(-3, 3) if index % 2 == 0 else 0.0
        stop = 1 + rng.randrange(n)
        if index % 10 == 9:
            # a mirror-symmetric chain with a right wall, stopped in the middle: every
            # antisymmetric mode has an exact node at the stop
            half = [10 ** rng.uniform(-1, 1) for _ in range((n + 1) // 2)]
            masses = half + half[: n // 2][::-1]
            ks = [10 ** rng.uniform(-1, 1) for _ in range(n // 2 + 1)]
            springs = (ks + ks[::-1])[: n]
            right = ks[0]
            if n % 2 == 0:
                masses = masses[: n // 2] + masses[: n // 2][::-1]
                springs = ks[: n // 2] + [ks[n // 2]] + ks[: n // 2][::-1][:-1]
                right = ks[0]
            stop = (n + 1) // 2 if n % 2 == 1 else 1
        problems, worst_omega = check_chain(args.cli, masses, springs, right, stop)
        worst = max(worst, worst_omega)
        if problems:
            failed += 1
            print(f"chain {index}: masses {masses}, springs {springs}, right {right}, stop {stop}")
            for problem in problems:
                print("   ", problem)
    print(f"{args.chains - failed} of {args.chains} chains agree with the 50-digit modes; "
          f"worst relative frequency error {worst:.2e}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
