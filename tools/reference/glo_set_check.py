#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""Grazing sets printed by `grazelab-cli glo-set` against an independent 30-digit computation.

W_lambda = sum_j lambda_j GLOM_j grazes iff g(theta) = sum_j lambda_j cos(n_j theta) <= 1 for all
theta. With lambda affine along a line (the two-mode lambda, or a ray r of the three-mode plane
from its centre), g = g_c + r g_d, so the constraint at each theta is r <= (1 - g_c) / g_d where
g_d > 0: the set's end along the line is the smallest of these ratios, and at theta -> 0 (both
sides vanish) their limit -(sum c_j n_j^2) / (sum d_j n_j^2), the flat point. The reference takes
that minimum its own way: the ratio sampled 3000 times over (0, pi] at 30 digits (mpmath), each
sampled minimum refined by golden section; nothing is shared with the core, which bisects on its
certified contact search.

Checked: the two-mode intervals of 2:1, 3:1, 4:1, 3:2, 5:2, 5:3 (each end to 1e-12, inside the
CLI's bracket [certainly grazes, certainly crosses] to 1e-13) and the three-mode regions of
3:2:1, 4:2:1, 5:3:1, 4:3:1 along 12 rays. Chains from `grazelab-cli info --frequencies` (designed
springs), so the CLI detects the harmonics itself. Exit 0 when all hold, 1 otherwise.

    python3 glo_set_check.py --cli build/app/grazelab-cli/grazelab-cli
"""
import argparse
import json
import subprocess
import sys

import mpmath

mpmath.mp.dps = 30


def end_along(harmonics, centre, direction, samples=3000):
    """The largest r with sum (c_j + r d_j) cos(n_j theta) <= 1 for all theta."""
    def g(weights, theta):
        return mpmath.fsum(w * mpmath.cos(n * theta) for w, n in zip(weights, harmonics))

    def ratio(theta):
        gd = g(direction, theta)
        return (1 - g(centre, theta)) / gd if gd > 0 else mpmath.inf

    best = mpmath.inf
    curvature_d = mpmath.fsum(d * n * n for d, n in zip(direction, harmonics))
    if curvature_d < 0:  # g_d > 0 near theta = 0: the flat point's limit
        best = -mpmath.fsum(c * n * n for c, n in zip(centre, harmonics)) / curvature_d
    step = mpmath.pi / samples
    values = [ratio(step * (i + 1)) for i in range(samples)]
    for i in range(1, samples - 1):
        if values[i] <= values[i - 1] and values[i] <= values[i + 1] and values[i] < mpmath.inf:
            low, high = step * i, step * (i + 2)
            for _ in range(110):
                m1 = low + (high - low) * mpmath.mpf("0.381966011250105151795")
                m2 = high - (high - low) * mpmath.mpf("0.381966011250105151795")
                if ratio(m1) < ratio(m2):
                    high = m2
                else:
                    low = m1
            best = min(best, ratio((low + high) / 2))
    best = min(best, values[-1], values[0])
    return best


def designed(cli, masses, ratios):
    argv = [cli, "info", "--masses", ",".join(map(repr, masses)), "--frequencies", ":".join(map(str, ratios))]
    return json.loads(subprocess.run(argv, check=True, capture_output=True, text=True).stdout)["chain"]["springs"]


def glo_set(cli, masses, springs, extra=()):
    argv = [cli, "glo-set", "--masses", ",".join(map(repr, masses)), "--springs", ",".join(map(repr, springs)),
            *extra]
    return json.loads(subprocess.run(argv, check=True, capture_output=True, text=True).stdout)


def check_end(name, printed, printed_out, exact, problems):
    if abs(printed - exact) > 1e-12:
        problems.append(f"{name}: {printed!r} against {mpmath.nstr(exact, 20)}")
    low, high = min(printed, printed_out), max(printed, printed_out)
    if not (low - 1e-13 <= exact <= high + 1e-13):
        problems.append(f"{name}: the bracket [{printed!r}, {printed_out!r}] misses {mpmath.nstr(exact, 20)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cli", required=True)
    args = parser.parse_args()
    problems = []
    checked = 0
    for ratios, masses in (((2, 1), [1.0, 0.5]), ((3, 1), [1.0, 0.5]), ((4, 1), [1.0, 0.3]),
                           ((3, 2), [1.0, 0.05]), ((5, 2), [1.0, 0.3]), ((5, 3), [1.0, 0.05])):
        springs = designed(args.cli, masses, ratios)
        printed = glo_set(args.cli, masses, springs)
        if printed["harmonics"] != list(ratios):
            problems.append(f"{ratios}: harmonics {printed['harmonics']}")
            continue
        interval = printed["grazing_set"]
        # lambda = weight of the slow mode: centre (1, 0), direction (-1, 1) for the upper end,
        # (1, -1) for the lower one
        high = end_along(ratios, (1, 0), (-1, 1))
        low = -end_along(ratios, (1, 0), (1, -1))
        check_end(f"{ratios} high", interval["high"], interval["high_out"], high, problems)
        check_end(f"{ratios} low", interval["low"], interval["low_out"], low, problems)
        checked += 2
        print(f"{ratios[0]}:{ratios[1]}: [{mpmath.nstr(low, 17)}, {mpmath.nstr(high, 17)}]")
    for ratios, masses in (((3, 2, 1), [1.0, 0.2, 0.05]), ((4, 2, 1), [1.0, 0.3, 0.1]),
                           ((5, 3, 1), [1.0, 0.4, 0.2]), ((4, 3, 1), [1.0, 1.0, 0.2])):
        springs = designed(args.cli, masses, ratios)
        printed = glo_set(args.cli, masses, springs, ["--directions", "12"])
        if printed["harmonics"] != list(ratios):
            problems.append(f"{ratios}: harmonics {printed['harmonics']}")
            continue
        third = mpmath.mpf(1) / 3
        for point in printed["grazing_set"]["boundary"]:
            dx, dy = mpmath.cos(point["angle"]), mpmath.sin(point["angle"])
            exact = end_along(ratios, (third, third, third), (-dx - dy, dx, dy))
            check_end(f"{ratios} ray {point['angle']:.4f}", point["radius"], point["radius_out"], exact, problems)
            checked += 1
        print(f"{':'.join(map(str, ratios))}: {len(printed['grazing_set']['boundary'])} rays")
    for problem in problems:
        print("   ", problem)
    print(f"{checked} ends checked, {len(problems)} problems")
    return 1 if problems or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
