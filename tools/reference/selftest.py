#!/usr/bin/env python3
"""Self-checks of reference_sim.py against docs/model.md, without the C++ program.

    python3 selftest.py          # exit 0 if every check passes

Checks: modes (P^T M P = I, P^T K P = diag(w^2), w_fast = 2 w_slow on both branches,
the design examples of docs/model.md section 2), free flight against an independent Taylor ODE
integration (mpmath.odefun), energy conservation to 1e-35 on impacting, sticking and
detuned runs, GLO_lambda grazing every T2 for lambda in (0, 4/3], 1IPP data returning to
itself after T, FFT <= T2 after impacts (Theorem 2.3), the near-grazing impact time
T2 - 2|v2|/|acc2|, and independence of the results from precision and sampling density.
"""

import sys
import time

from mpmath import mp, mpf

import reference_sim as ref

FAILURES = []


def check(name, ok, detail=""):
    print("%-4s %s%s" % ("ok" if ok else "FAIL", name, ("  (" + detail + ")") if detail else ""))
    if not ok:
        FAILURES.append(name)


def chain(m2="0.5", branch="upper", k2=None, gap="1"):
    return ref.Chain(mpf(1), mpf(m2), mpf(1), mpf(gap), k2=None if k2 is None else mpf(k2),
                     branch=branch)


def run(ch, state, contacts=50, t_end=None, samples=2000):
    sim = ref.Simulator(ch, samples_per_period=samples)
    events = sim.run(state, max_contacts=contacts, t_end=t_end)
    return sim, events


def check_modes():
    for m2 in ("0.5", "0.25", "1e-4", "0.5625"):
        for branch in ("upper", "lower"):
            ch = chain(m2, branch)
            P, M = ch.P, [ch.m1, ch.m2]
            K = [[ch.k1 + ch.k2, -ch.k2], [-ch.k2, ch.k2]]
            err = mpf(0)
            for i in range(2):
                for j in range(2):
                    ptmp = sum(P[k][i] * M[k] * P[k][j] for k in range(2))
                    ptkp = sum(P[k][i] * K[k][l] * P[l][j] for k in range(2) for l in range(2))
                    err = max(err, abs(ptmp - (1 if i == j else 0)),
                              abs(ptkp - (ch.w[i] ** 2 if i == j else 0)))
            check("modes m2=%s %s: P^T M P = I, P^T K P = diag(w^2), w1 = 2 w2" % (m2, branch),
                  err < mpf(10) ** -35 and ch.resonant and P[1][0] > 0 and P[1][1] > 0,
                  "err %s" % mp.nstr(err, 3))
    check("design m2=1/2 upper: k2 = 1/2", abs(chain("0.5").k2 - mpf(1) / 2) < 1e-38)
    check("design m2=1/2 lower: k2 = 2/9", abs(chain("0.5", "lower").k2 - mpf(2) / 9) < 1e-38)
    ch = chain("0.5625")
    check("design m2=9/16: k2 = 9/25, w^2 = 0.4 and 1.6",
          abs(ch.k2 - mpf(9) / 25) < 1e-38 and abs(ch.w[1] ** 2 - mpf("0.4")) < 1e-38
          and abs(ch.w[0] ** 2 - mpf("1.6")) < 1e-38)
    try:
        chain("0.6")
        check("m2/m1 > 9/16 rejected", False)
    except ref.InputError:
        check("m2/m1 > 9/16 rejected", True)


def check_flight_against_ode():
    # an independent integration of M u'' + K u = 0 by mpmath's Taylor-series ODE solver
    saved = mp.dps
    mp.dps = 30
    for label, ch in (("resonant", chain()), ("detuned", chain(k2="0.45"))):
        state = [mpf("0.3"), mpf("0.2"), mpf("-0.4"), mpf("0.7")]
        flight = ref.Flight(ch, state)
        m1, m2, k1, k2 = ch.m1, ch.m2, ch.k1, ch.k2
        rhs = lambda t, y: [y[2], y[3], (-(k1 + k2) * y[0] + k2 * y[1]) / m1,
                            (k2 * y[0] - k2 * y[1]) / m2]
        solution = mp.odefun(rhs, 0, state)
        err = mpf(0)
        for t in (mpf("0.7"), mpf("2.3"), mpf("5.1")):
            exact = flight.state(t)
            numeric = solution(t)
            err = max(err, max(abs(a - b) for a, b in zip(exact, numeric)))
        check("free flight (%s) vs Taylor ODE integration" % label, err < mpf(10) ** -25,
              "max err %s" % mp.nstr(err, 3))
    mp.dps = saved


def check_energy():
    cases = [
        ("upper GLO 0.5 dv2=-1e-3", chain(), "0.5", [0, 0, 0, "-1e-3"]),
        ("lower GLO 0.5 dv2=-1e-3", chain(branch="lower"), "0.5", [0, 0, 0, "-1e-3"]),
        ("sticking GLO 1.5", chain(), "1.5", [0, 0, 0, 0]),
    ]
    for label, ch, lam, delta in cases:
        state = [a + mpf(b) for a, b in zip(ch.glo_state(mpf(lam)), delta)]
        sim, events = run(ch, state)
        check("energy %s: drift <= 1e-35 over %d events" % (label, len(events)),
              sim.max_drift <= mpf(10) ** -35 and len(events) >= 50,
              "drift %s" % mp.nstr(sim.max_drift, 3))
    ch = chain(k2="0.45")
    sim, events = run(ch, [mpf("0.2"), mpf("0.5"), mpf("0.1"), mpf("0.8")])
    check("energy detuned k2=0.45: drift <= 1e-35", sim.max_drift <= mpf(10) ** -35,
          "drift %s" % mp.nstr(sim.max_drift, 3))


def check_glo():
    for branch in ("upper", "lower"):
        ch = chain(branch=branch)
        for lam in (mpf("0.01"), mpf("0.5"), mpf(1), mpf("1.2"), mpf(4) / 3):
            sim, events = run(ch, ch.glo_state(lam), contacts=10)
            fourth = lam == mpf(4) / 3
            # a fourth-order touch turns the 1e-40 rounding of the data into ~1e-10 in time
            tol = mpf(10) ** (-8 if fourth else -30)
            ok = len(events) == 10 and all(e["type"] == "grazing" for e in events)
            err = max(abs(e["t"] - (n + 1) * ch.T2) / ch.T2 for n, e in enumerate(events))
            check("GLO_%s %s: 10 grazings, t_n = n T2" % (mp.nstr(lam, 6), branch),
                  ok and err <= tol, "max |t_n - n T2|/T2 = %s" % mp.nstr(err, 3))


def check_onepp():
    for branch in ("upper", "lower"):
        ch = chain(branch=branch)
        for factor in ("0.95", "0.7", "0.99"):
            period = mpf(factor) * ch.T2
            state = ch.onepp_state(period)
            sim, events = run(ch, state, contacts=5)
            ok = all(e["type"] == "impact" for e in events)
            err = mpf(0)
            for n, e in enumerate(events):
                err = max(err, abs(e["t"] - (n + 1) * period) / ch.T2,
                          abs(e["u1"] - state[0]), abs(e["v1_pre"]), abs(e["v2_post"] - state[3]))
            check("1IPP T=%s T2 %s: returns to itself every T" % (factor, branch),
                  ok and err < mpf(10) ** -30, "max err %s" % mp.nstr(err, 3))


def check_fft_and_near_grazing():
    ch = chain()
    state = [a + b for a, b in zip(ch.glo_state(mpf("0.5")), [0, 0, 0, mpf("-1e-3")])]
    sim, events = run(ch, state, contacts=100)
    times = [mpf(0)] + [e["t"] for e in events]
    fft_max = max(b - a for a, b in zip(times, times[1:]))
    check("Theorem 2.3: FFT < T2 after impacts (100 contacts)",
          fft_max < ch.T2 and all(e["type"] == "impact" for e in events),
          "max FFT/T2 = %s" % mp.nstr(fft_max / ch.T2, 12))
    for eps in ("1e-9", "1e-12", "1e-15"):
        vs = ch.w[1] * ch.gap
        dv2 = -mpf(eps) * vs
        glo = ch.glo_state(mpf("0.5"))
        state = glo[:3] + [dv2]
        sim, events = run(ch, state, contacts=3)
        acc2 = ch.k2 * (glo[0] - ch.gap) / ch.m2
        predicted = ch.T2 - 2 * abs(dv2) / abs(acc2)
        e = events[0]
        err = abs(e["t"] - predicted) / ch.T2
        check("near grazing dv2 = -%s vs: impact at T2 - 2|v2|/|acc2|" % eps,
              e["type"] == "impact" and err < mpf(10) ** -20
              and abs(e["v2_pre"] + dv2) < abs(dv2) * mpf(10) ** -6,
              "t err/T2 %s, v2- = %s" % (mp.nstr(err, 3), mp.nstr(e["v2_pre"], 6)))


def check_independence():
    def events_at(dps, samples, lam="0.5", delta=("0", "0", "0", "-1e-3"), branch="upper"):
        saved = mp.dps
        mp.dps = dps
        ch = chain(branch=branch)
        state = [a + mpf(b) for a, b in zip(ch.glo_state(mpf(lam)), delta)]
        sim, events = run(ch, state, contacts=50, samples=samples)
        out = [[e["t"], e["u1"], e["v1_pre"], e["v2_post"]] for e in events], [
            e["type"] for e in events]
        mp.dps = saved
        return out

    for label, kw in (("GLO 0.5 dv2=-1e-3", {}), ("sticking GLO 1.5", {"lam": "1.5",
                                                                       "delta": ("0",) * 4}),
                      ("lower GLO 0.2 dv2=-1e-2", {"lam": "0.2", "branch": "lower",
                                                   "delta": ("0", "0", "0", "-1e-2")})):
        (a, ta) = events_at(40, 2000, **kw)
        (b, tb) = events_at(60, 2000, **kw)
        (c, tc) = events_at(40, 300, **kw)
        mp.dps = 60
        diff_dps = max(abs(x - y) for ea, eb in zip(a, b) for x, y in zip(ea, eb))
        diff_samples = max(abs(x - y) for ea, ec in zip(a, c) for x, y in zip(ea, ec))
        mp.dps = 40
        check("%s: dps 40 vs 60 and 2000 vs 300 samples agree" % label,
              ta == tb == tc and len(a) == len(b) == len(c) and diff_dps < mpf(10) ** -28
              and diff_samples < mpf(10) ** -28,
              "dps diff %s, samples diff %s" % (mp.nstr(diff_dps, 3),
                                                mp.nstr(diff_samples, 3)))


def check_sticking():
    ch = chain()
    state = ch.glo_state(mpf("1.5"))
    sim, events = run(ch, state, contacts=3)
    stick, release = events[0], events[1]
    omega = mp.sqrt((ch.k1 + ch.k2) / ch.m1)
    centre = ch.k2 * ch.gap / (ch.k1 + ch.k2)
    # u1(t) = centre + (u1(0) - centre) cos(omega t) reaches d at the release time
    u1_release = centre + (state[0] - centre) * mp.cos(omega * release["t"])
    check("sticking GLO 1.5: stick at 0, release when u1 falls to d, then impacts",
          stick["type"] == "stick" and stick["t"] == 0 and release["type"] == "release"
          and abs(u1_release - ch.gap) < mpf(10) ** -35 and release["v1_pre"] < 0
          and events[2]["type"] == "impact",
          "release t = %s" % mp.nstr(release["t"], 20))


def main():
    mp.dps = 40
    started = time.time()
    check_modes()
    check_flight_against_ode()
    check_energy()
    check_glo()
    check_onepp()
    check_fft_and_near_grazing()
    check_sticking()
    check_independence()
    print("%d failure(s), %.1f s" % (len(FAILURES), time.time() - started))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
