#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
"""The explorer's default scene from Python: GLO(0.5) pushed off the grazing start by
dv2 = -0.05, 60 contacts; its free-flight time at each contact and its Poincaré points on the
contact plane H (the two lower right panels of the README's screenshot), with Matplotlib if it is
installed. Run from the repository's root after the README's build:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/grazing_scene.py [--out FILE.png]
"""

import argparse
import math

import numpy as np

import grazelab as gl


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="grazing_scene.png", help="the picture (PNG, SVG or PDF)")
    args = parser.parse_args()

    run = gl.simulate(m2=0.5, glo=0.5, perturb=(0, 0, 0, -0.05), contacts=60)
    events = run.events
    T2 = run.model.T2
    # the free flight that ends at each contact (the first from t = 0)
    flight = np.diff(events["t"], prepend=0.0)
    print(f"{len(events)} contacts ({run.contacts.impacts} impacts), trust {run.trust.verdict} "
          f"(estimated error {run.trust.estimated_state_error:.2g}); "
          f"free flights {flight.min():.4f} to {flight.max():.4f}, T2 = {T2:.4f}")
    assert np.all(flight <= T2), "a free flight longer than T2 in a resonant chain"

    try:
        import matplotlib
        import matplotlib.pyplot as plt
    except ImportError:
        print("Matplotlib is not installed (Debian: python3-matplotlib): no picture")
        return
    matplotlib.rcParams.update({"font.size": 11, "axes.titleweight": "bold"})
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.6), layout="constrained")

    index = np.arange(len(events))
    left.plot(index, flight, "s", markersize=4, color="#1f77b4", label="FFT")
    left.axhline(T2, linestyle="--", color="#e8741e", label="FFT = T₂")
    left.set(title="Free-flight time at each contact", xlabel="contact index", ylabel="FFT")
    left.legend(loc="lower left", frameon=False)
    left.grid(alpha=0.3)

    groups = 5
    colours = plt.cm.viridis(np.linspace(0, 0.85, groups))
    size = math.ceil(len(events) / groups)
    for g in range(groups):
        part = slice(g * size, (g + 1) * size)
        # the map comes round again after about 40 contacts: earlier contacts drawn on top
        right.plot(events["u1"][part], events["v1_pre"][part], "s", markersize=4, color=colours[g],
                   zorder=3 + groups - g, label=f"contacts {g * size}–{min((g + 1) * size, len(events)) - 1}")
    start = run.initial.state
    right.plot(start.u1, start.v1, "s", markersize=9, markerfacecolor="none", color="black",
               zorder=10, label="GLO(λ) data")
    right.set(title="Poincaré points on H (u₂ = d)", xlabel="u₁ at contact", ylabel="v₁ at contact")
    right.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), frameon=False)
    right.grid(alpha=0.3)

    figure.suptitle("GLO(0.5) pushed off by δv₂ = −0.05: 60 exact contacts (grazelab.simulate)")
    figure.savefig(args.out, dpi=110)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
