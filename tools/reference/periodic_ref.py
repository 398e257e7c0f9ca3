#!/usr/bin/env python3
"""Independent high-precision reference for periodic impacting orbits of the GrazeLab chain.

    wall --k1-- [m1] --k2-- [m2] |<-- gap d -->| rigid stop

docs/model.md section 10 (and ../shared/MODEL.md section 10): the return map P on the
section H+ = {u2 = d, v2 < 0} (just after an impact) at fixed energy E, in coordinates
x = (u1, v1), with v2 = -sqrt((2E - m1 v1^2 - k1 u1^2 - k2 (d - u1)^2) / m2).
A kIPP orbit is a fixed point of P^k with exactly k impacts and nothing else.

Independence from the C++ core: only the equations are shared. Arithmetic is mpmath
(default 50 digits); the chain, its modes, the exact free flight and the first-contact search
are those of reference_sim.py (closed-form modes, dense binary64 filter + full-precision
bracketing, no quartic); the 1IPP data is its closed form (model.md section 5). Nothing here
uses the monodromy/saltation matrices of the C++ code: every derivative of the return map is
a *central finite difference of the map itself* at fixed energy, with step
h = 10^-(dps/3) of the position scale d (and w2 d for velocities), so that truncation (h^2)
and rounding (10^-dps / h) are both ~10^-(2 dps/3): ~1e-33 at 50 digits. The impact times
of the perturbed flights are polished by Newton on u2(t) - d from the base flight's times
(the same impact, continued); the base flights use the full first-contact search.

Functions (all numbers mpmath mpf):
  trace1(chain, T)                  1IPP orbit of period T: tr DP, det DP, E, admissibility
  one_pp_flips(chain, Tlo, Thi, n)  tr = -2 (flip) and tr = +2 (fold/branch) along the 1IPP
                                    family, by sign changes and golden-section extrema
  find_orbit(chain, k, E, u1, v1)   Newton on P^k(x) - x at fixed E (finite-difference Jacobian)
  family2(chain, E_list, guess, k)  natural-parameter continuation in E (tangent predictor)
  locate_trace(chain, k, Ea, xa, Eb, xb, target)
                                    bisection in E of tr D(P^k) - target along a family
                                    (a fold, where Newton stops converging, is approached
                                    from the side where the family exists)
  follow_arclength(chain, k, E, x, ds, steps, direction)
                                    pseudo-arclength continuation (passes folds in E)

Command line (JSON on stdout, numbers with --digits significant digits):
  periodic_ref.py onepp  --m2 0.5 --branch upper --period-over-t2 0.7
  periodic_ref.py flips  --m2 0.5 --branch lower --tlo 0.7 --thi 0.76 --n 60
  periodic_ref.py orbit  --m2 0.55 --branch lower --impacts 2 --energy 2.4382 --guess -1.62,0.43
  periodic_ref.py family --m2 0.55 --branch lower --impacts 2 --energies 2.4,2.43,2.46 --guess -1.62,0.43
  periodic_ref.py locate --m2 0.55 --branch lower --impacts 4 --ea 1.3968775582671 \
      --guess=-1.0624169323695,0 --eb 1.4221194714681 --guess-b=-1.0786296849167,0 --target 2
  periodic_ref.py arc    --m2 0.55 --branch lower --impacts 2 --energy 2.4382 \
      --guess=-1.62,0.43 --ds 0.02 --steps 20 --direction -1
Exit status 0, or 2 on invalid input / failure (one line on stderr).
"""

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from mpmath import mp, mpf  # noqa: E402

import reference_sim as rs  # noqa: E402
from reference_sim import Chain, Flight, InputError, Simulator, bracket_root  # noqa: E402


class MapError(Exception):
    """The return map is not defined at this point (off the energy shell, no impact, a
    tangential contact instead of an impact, Newton failure...)."""


# -- scales -------------------------------------------------------------------------------

def fd_step():
    """Relative step of the central differences: 10^-(dps/3)."""
    return mpf(10) ** (-(mp.dps // 3))


def time_tol(chain):
    return chain.T2 * mpf(10) ** (-(mp.dps - 4))


# -- the section H+ at fixed energy --------------------------------------------------------

def v2_on_shell(chain, E, u1, v1):
    """v2 < 0 of the point (u1, v1) of H+ on the energy level E."""
    d = chain.gap
    rad = (2 * E - chain.m1 * v1 * v1 - chain.k1 * u1 * u1 - chain.k2 * (d - u1) ** 2) / chain.m2
    if rad <= 0:
        raise MapError("point (u1, v1) is off the energy shell E (v2^2 = %s)" % mp.nstr(rad, 5))
    return -mp.sqrt(rad)


def next_impact(chain, state, t_guess=None):
    """First impact of the free flight from `state` (local time 0).

    Without t_guess: full search (reference_sim's Simulator.next_contact: binary64 filter,
    full-precision bracketing), then Newton polish on u2(t) - d. With t_guess: Newton on
    u2(t) - d from t_guess only (the continuation of a known impact; no search for earlier
    contacts). Returns (tc, post-impact state, v2_pre > 0).
    """
    flight = Flight(chain, state)
    if t_guess is None:
        sim = Simulator(chain)
        sim.set_scales(state)
        found = sim.next_contact(flight)
        if found is None:
            raise MapError("no contact")
        tc, kind = found
        if kind != "cross":
            raise MapError("tangential contact (grazing) at t = %s" % mp.nstr(tc, 12))
        # polish the bracketed root (already within ~T2 10^-(dps-2)) by Newton steps that
        # decrease |u2 - d|; keep the bracketed root otherwise
        f, g = flight.fg(tc)
        for _ in range(3):
            if g <= 0 or f == 0:
                break
            tn = tc - f / g
            fn, gn = flight.fg(tn)
            if abs(fn) >= abs(f):
                break
            tc, f, g = tn, fn, gn
    else:
        tc = t_guess
        tol = time_tol(chain)
        for _ in range(60):
            f, g = flight.fg(tc)
            if g <= 0:
                raise MapError("Newton on the impact time met v2 <= 0")
            dt = f / g
            tc -= dt
            if abs(dt) <= tol:
                break
        else:
            raise MapError("Newton on the impact time did not converge")
        f, g = flight.fg(tc)  # one more step: quadratic convergence, costs one evaluation
        tc -= f / g
    s = flight.state(tc)
    v2pre = s[3]
    if v2pre <= 0:
        raise MapError("impact with v2_pre <= 0")
    return tc, [s[0], chain.gap, s[2], -v2pre], v2pre


def interior_maxima(chain, state, t_end, samples=1000):
    """Local maxima of u2 on the open flight (0, t_end): list of (t, u2 - d).

    v2 is scanned in binary64 on `samples` points per T2 (a filter), and each + to - sign
    change is located at full precision by bracketing (reference_sim.bracket_root).
    """
    flight = Flight(chain, state)
    n = max(8, int(mp.ceil(samples * t_end / chain.T2)))
    h = t_end / n
    hd = float(h)
    xtol = time_tol(chain)
    out = []
    g_prev = float(state[3])
    for i in range(1, n + 1):
        g = flight.fg_double(i * hd)[1] if i < n else float(flight.fg(t_end)[1])
        # >= 0: a sample landing exactly on a maximum (v2 = 0 in binary64, the midpoint of a
        # symmetric flight) must still flag the interval after it
        if g_prev >= 0 and g <= 0 and not (g_prev == 0 and g == 0):
            a, b = (i - 1) * h, i * h
            ga, gb = flight.fg(a)[1], flight.fg(b)[1]
            # the binary64 filter's zero may be either side at full precision: widen by a sample
            if not ga > 0 and i > 1:
                a = (i - 2) * h
                ga = flight.fg(a)[1]
            if not gb <= 0 and i < n:
                b = min((i + 1) * h, t_end)
                gb = flight.fg(b)[1]
            if ga > 0 and gb <= 0:
                tm = bracket_root(lambda t: flight.fg(t)[1], a, b, ga, gb, xtol)
                if mpf(0) < tm < t_end and all(abs(tm - t0) > 4 * xtol for t0, _ in out):
                    out.append((tm, flight.fg(tm)[0]))
        g_prev = g
    return out


# -- the return map and its Jacobian -----------------------------------------------------------

def map_k(chain, E, x, k, times=None):
    """P^k at fixed energy E from x = (u1, v1) on H+.

    Returns (image (u1, v1), list of impacts {t (flight time), u1, v1, v2_pre}, states after
    each impact). `times`: the flight times of a nearby base orbit (Newton continuation only).
    """
    u1, v1 = x
    state = [u1, chain.gap, v1, v2_on_shell(chain, E, u1, v1)]
    starts = []
    impacts = []
    for i in range(k):
        starts.append(state)
        tc, state, v2pre = next_impact(chain, state, None if times is None else times[i])
        impacts.append({"t": tc, "u1": state[0], "v1": state[2], "v2_pre": v2pre})
    return (state[0], state[2]), impacts, starts


def jacobian(chain, E, x, k, times):
    """Central-difference Jacobian of P^k at fixed E in (u1, v1)."""
    h = fd_step()
    L = max(chain.gap, abs(x[0]))
    steps = (h * L, h * L * chain.w[1])
    J = [[mpf(0), mpf(0)], [mpf(0), mpf(0)]]
    for j in range(2):
        xp, xm = list(x), list(x)
        xp[j] += steps[j]
        xm[j] -= steps[j]
        fp = map_k(chain, E, xp, k, times)[0]
        fm = map_k(chain, E, xm, k, times)[0]
        for i in range(2):
            J[i][j] = (fp[i] - fm[i]) / (2 * steps[j])
    return J


def jac_summary(J):
    tr = J[0][0] + J[1][1]
    det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
    disc = tr * tr - 4 * det
    if disc >= 0:
        r = mp.sqrt(disc)
        mults = [(tr + r) / 2, (tr - r) / 2]
    else:
        mults = [mp.mpc(tr / 2, mp.sqrt(-disc) / 2), mp.mpc(tr / 2, -mp.sqrt(-disc) / 2)]
    if abs(tr) < 2:
        cls = "elliptic"
    elif tr > 2:
        cls = "hyperbolic"
    else:
        cls = "flip-hyperbolic"
    return tr, det, mults, cls


# -- 1IPP family ----------------------------------------------------------------------------

def trace1(chain, T, check=True):
    """The 1IPP orbit of period T: trace of DP at fixed energy, energy, admissibility.

    The derivatives are those of the impact continuing the one at T (so a trace is given
    also where the orbit is not admissible: `admissible` says whether it is a real orbit).
    With check=False only the trace, det and energy are computed (no contact search).
    """
    state = chain.onepp_state(T)  # InputError if T is a multiple of T1, T2 or V >= 0
    d = chain.gap
    E = chain.energy(*state)
    x = (state[0], state[2])
    J = jacobian(chain, E, x, 1, [T])
    tr, det, mults, cls = jac_summary(J)
    out = {"T": T, "T_over_T2": T / chain.T2, "E": E, "u1": state[0], "V": state[3],
           "impact_speed": -state[3], "trace": tr, "det": det, "class": cls}
    if not check:
        return out
    # admissibility: the full first-contact search must find an impact at T, and no
    # interior maximum of u2 may reach the stop
    reason = None
    try:
        sim = Simulator(chain)
        sim.set_scales(state)
        found = sim.next_contact(Flight(chain, state))
        if found is None:
            reason = "no contact"
            t_first = None
        else:
            t_first, kind = found
            if abs(t_first - T) > chain.T2 * mpf(10) ** (-(mp.dps // 2)):
                reason = "first contact at t = %s (%s), not at T" % (
                    mp.nstr(t_first / chain.T2, 15) + " T2", kind)
            elif kind != "cross":
                reason = "contact at T is tangential"
    except RuntimeError as error:
        reason = "contact search failed: %s" % error
        t_first = None
    maxima = interior_maxima(chain, state, T)
    clearance = min((-f / d for _, f in maxima), default=None)
    if reason is None and clearance is not None and clearance <= 0:
        reason = "an interior maximum of u2 reaches the stop"
    back = map_k(chain, E, x, 1, [T])[0]
    out.update({
        "admissible": reason is None, "reason": reason,
        "first_contact_t": t_first,
        "min_clearance_rel": clearance,
        "n_interior_maxima": len(maxima),
        "return_error": max(abs(back[0] - x[0]) / d, abs(back[1] - x[1]) / (chain.w[1] * d)),
    })
    return out


def _trace_or_none(chain, T):
    try:
        return trace1(chain, T, check=False)["trace"]
    except (InputError, MapError):
        return None


def golden_extremum(func, a, b, sign, tol):
    """Minimum (sign=+1) or maximum (sign=-1) of func on [a, b] by golden section."""
    invphi = (mp.sqrt(5) - 1) / 2
    c = b - invphi * (b - a)
    e = a + invphi * (b - a)
    fc, fe = sign * func(c), sign * func(e)
    while b - a > tol:
        if fc < fe:
            b, e, fe = e, c, fc
            c = b - invphi * (b - a)
            fc = sign * func(c)
        else:
            a, c, fc = c, e, fe
            e = a + invphi * (b - a)
            fe = sign * func(e)
    return (c, sign * fc) if fc < fe else (e, sign * fe)


def one_pp_flips(chain, Tlo, Thi, n, progress=None):
    """tr DP = -2 (flip) and +2 (fold / branch point) along the 1IPP family on [Tlo, Thi].

    tr(T) is sampled at n + 1 equally spaced periods; every sign change of tr + 2 and of
    tr - 2 between neighbours is located by Illinois/bisection (reference_sim.bracket_root)
    to ~T2 10^-(2 dps/3 - 3) (1e-30 T2 at 50 digits). At each interior sample where the
    sampled trace has a local minimum (maximum), tr is minimised (maximised) over the two
    neighbouring intervals by golden section; if the minimum dips below -2 (the maximum
    rises above 2) without a sampled sign change, the close pair on both sides is located
    too. Returns (events, samples, extrema).
    """
    Ts = [Tlo + (Thi - Tlo) * i / n for i in range(n + 1)]
    trs = []
    for i, T in enumerate(Ts):
        trs.append(_trace_or_none(chain, T))
        if progress:
            progress(i, n)
    xtol = chain.T2 * mpf(10) ** (-(2 * mp.dps // 3 - 3))
    events = []

    def add_root(a, b, target, via):
        fa = trs_f(a, target)
        fb = trs_f(b, target)
        if fa is None or fb is None or (fa > 0) == (fb > 0):
            return
        func = lambda T: trs_f(T, target)
        T = bracket_root(func, a, b, fa, fb, xtol)
        res = trace1(chain, T)
        kind = "flip" if target < 0 else "fold-or-branch"
        if abs(res["trace"] - target) > mpf(10) ** (-(mp.dps // 4)):
            kind = "discontinuity"  # a sign change through a pole or a jump, not a root
        events.append({"kind": kind, "target": target, "T": T, "T_over_T2": T / chain.T2,
                       "E": res["E"], "trace": res["trace"], "det": res["det"],
                       "admissible": res["admissible"], "reason": res["reason"],
                       "min_clearance_rel": res["min_clearance_rel"],
                       "impact_speed": res["impact_speed"], "found_by": via})

    def trs_f(T, target):
        tr = _trace_or_none(chain, T)
        return None if tr is None else tr - target

    for i in range(n):
        a, b = trs[i], trs[i + 1]
        if a is None or b is None:
            continue
        for target in (-2, 2):
            if (a - target > 0) != (b - target > 0):
                add_root(Ts[i], Ts[i + 1], target, "sign change between samples")

    extrema = []
    gtol = chain.T2 * mpf(10) ** (-12)
    for i in range(1, n):
        a, m, b = trs[i - 1], trs[i], trs[i + 1]
        if a is None or m is None or b is None:
            continue
        for sign, target in ((1, -2), (-1, 2)):
            if not (sign * m < sign * a and sign * m < sign * b):
                continue
            func = lambda T: trs_f(T, 0)
            Tx, trx = golden_extremum(lambda T: _safe(func, T, sign), Ts[i - 1], Ts[i + 1],
                                      sign, gtol)
            beyond = sign * (trx - target) < 0
            extrema.append({"kind": "min" if sign > 0 else "max", "T": Tx,
                            "T_over_T2": Tx / chain.T2, "trace": trx,
                            "beyond_target": target if beyond else None})
            if beyond:
                sampled = [(s - target > 0) for s in (a, m, b)]
                if len(set(sampled)) == 1:  # no sampled sign change: a close pair
                    add_root(Ts[i - 1], Tx, target, "golden-section extremum")
                    add_root(Tx, Ts[i + 1], target, "golden-section extremum")
    events.sort(key=lambda e: e["T"])
    samples = [{"T_over_T2": T / chain.T2, "trace": tr} for T, tr in zip(Ts, trs)]
    return events, samples, extrema


def _safe(func, T, sign):
    v = func(T)
    return v if v is not None else sign * mpf(10) ** 30


# -- k-impact orbits -------------------------------------------------------------------------

def _solve2(A, b):
    det = A[0][0] * A[1][1] - A[0][1] * A[1][0]
    if det == 0:
        raise MapError("singular Newton matrix")
    return [(b[0] * A[1][1] - b[1] * A[0][1]) / det, (A[0][0] * b[1] - A[1][0] * b[0]) / det]


def _residual(chain, x, img):
    d = chain.gap
    return max(abs(img[0] - x[0]) / d, abs(img[1] - x[1]) / (chain.w[1] * d))


def find_orbit(chain, k, E, u1, v1, max_iter=80, tol=None):
    """Fixed point of P^k at fixed energy E by Newton from the guess (u1, v1).

    The map is evaluated with the full first-contact search at every iterate; its Jacobian
    by central differences (the perturbed flights continue the iterate's impacts). Newton
    steps are taken as long as they decrease the residual; otherwise the step is damped
    the Levenberg-Marquardt way (A^T A + mu diag(A^T A)) dx = -A^T F, mu raised until the
    residual decreases and lowered again (to 0, plain Newton) after each success: near
    the square-root singularity of the map (an impact speed tending to 0) plain damped
    Newton can stall where this still converges. Variables and residual are scaled by d
    (positions) and w2 d (velocities). Raises MapError if it fails.
    """
    E, x = mpf(E), [mpf(u1), mpf(v1)]
    d, w = chain.gap, chain.w[1]
    tol = mpf(10) ** (-(mp.dps - 8)) if tol is None else tol
    rounding = mpf(10) ** (-(mp.dps // 2))

    def evaluate(xx):
        img, imp, _ = map_k(chain, E, xx, k)
        F = [(img[0] - xx[0]) / d, (img[1] - xx[1]) / (w * d)]
        return F, F[0] ** 2 + F[1] ** 2, img, imp

    try:
        F, merit, img, impacts = evaluate(x)
    except (MapError, RuntimeError) as error:
        raise MapError("the guess is outside the domain of P^%d: %s" % (k, error))
    res = _residual(chain, x, img)
    iters = 0
    history = [res]
    mu = mpf(0)
    while res > tol and iters < max_iter:
        iters += 1
        try:
            J = jacobian(chain, E, x, k, [imp["t"] for imp in impacts])
        except (MapError, RuntimeError) as error:
            raise MapError("no derivative at Newton iterate %d (u1 = %s, v1 = %s, too close "
                           "to a grazing?): %s" % (iters, mp.nstr(x[0], 10), mp.nstr(x[1], 10),
                                                   error))
        # A = D(P^k) - I in the scaled variables (u1/d, v1/(w d))
        A = [[J[0][0] - 1, J[0][1] * w], [J[1][0] / w, J[1][1] - 1]]
        AtA = [[A[0][i] * A[0][j] + A[1][i] * A[1][j] for j in range(2)] for i in range(2)]
        AtF = [A[0][i] * F[0] + A[1][i] * F[1] for i in range(2)]
        accepted = False
        for _ in range(60):
            try:
                if mu == 0:
                    dy = _solve2(A, [-F[0], -F[1]])
                else:
                    M = [[AtA[0][0] * (1 + mu), AtA[0][1]], [AtA[1][0], AtA[1][1] * (1 + mu)]]
                    dy = _solve2(M, [-AtF[0], -AtF[1]])
                xn = [x[0] + dy[0] * d, x[1] + dy[1] * w * d]
                Fn, meritn, imgn, impn = evaluate(xn)
                if meritn < merit or res < rounding:
                    accepted = True
                    break
            except (MapError, RuntimeError):
                pass
            mu = max(4 * mu, mpf(10) ** -3)
        if not accepted:
            raise MapError("Newton: no acceptable step from residual %s" % mp.nstr(res, 3))
        mu = mu / 10 if mu > mpf(10) ** -12 else mpf(0)
        step = max(abs(dy[0]), abs(dy[1]))
        x, F, merit, img, impacts = xn, Fn, meritn, imgn, impn
        res = _residual(chain, x, img)
        history.append(res)
        if step < mpf(10) ** (-(mp.dps - 4)) and res < rounding:
            break  # rounding level reached
    if res > rounding:
        raise MapError("Newton did not converge (residual %s after %d iterations)"
                       % (mp.nstr(res, 3), iters))
    return describe_orbit(chain, k, E, x, iters, history)


def describe_orbit(chain, k, E, x, iters=0, history=()):
    """Everything about the fixed point x of P^k at energy E."""
    d = chain.gap
    img, impacts, starts = map_k(chain, E, x, k)
    J = jacobian(chain, E, x, k, [imp["t"] for imp in impacts])
    tr, det, mults, cls = jac_summary(J)
    clearances = []
    for s, imp in zip(starts, impacts):
        m = interior_maxima(chain, s, imp["t"])
        clearances.append(min((-f / d for _, f in m), default=None))
    finite = [c for c in clearances if c is not None]
    # symmetry under R(u1, v1) = (u1, -v1)
    pts = [(imp["u1"], imp["v1"]) for imp in impacts]
    close = mpf(10) ** (-(mp.dps // 2))
    same = lambda p, q: abs(p[0] - q[0]) / d + abs(p[1] - q[1]) / (chain.w[1] * d) < close
    fixed = sum(1 for p in pts if abs(p[1]) / (chain.w[1] * d) < close)
    invariant = all(any(same((p[0], -p[1]), q) for q in pts) for p in pts)
    if not invariant:
        symmetry = "none"
    elif fixed == k:
        symmetry = "A"
    elif fixed == 0:
        symmetry = "B"
    else:
        symmetry = "mixed (%d on v1 = 0)" % fixed
    # a repeated shorter orbit: two impacts coincide. Looser than `close`: where D(P^k) - I
    # is nearly singular (the repeated orbit near its own flip) Newton fixes x only to about
    # the square root of the residual
    loose = mpf(10) ** (-(mp.dps // 5))
    repeated = any(abs(pts[i][0] - pts[j][0]) / d + abs(pts[i][1] - pts[j][1]) / (chain.w[1] * d)
                   < loose for i in range(k) for j in range(i))
    admissible = (not repeated) and all(c is None or c > 0 for c in clearances)
    v2 = v2_on_shell(chain, E, x[0], x[1])
    return {
        "impacts_per_period": k, "E": E,
        "state": {"u1": x[0], "u2": d, "v1": x[1], "v2": v2},
        "period": sum(imp["t"] for imp in impacts),
        "period_over_T2": sum(imp["t"] for imp in impacts) / chain.T2,
        "trace": tr, "det": det, "multipliers": mults, "class": cls,
        "jacobian": J,
        "impacts": impacts,
        "impact_speeds": [imp["v2_pre"] for imp in impacts],
        "min_impact_speed": min(imp["v2_pre"] for imp in impacts),
        "flight_clearances_rel": clearances,
        "min_clearance_rel": min(finite) if finite else None,
        "symmetry": symmetry, "repeated_shorter_orbit": repeated,
        "admissible": admissible,
        "residual": _residual(chain, x, img),
        "energy_error": abs(chain.energy(img[0], d, img[1], v2_on_shell(chain, E, *img)) - E),
        "newton_iterations": iters, "residual_history": list(history),
    }


def energy_tangent(chain, k, E, x, times):
    """dx/dE along the family through the fixed point x of P^k at energy E:
    (D(P^k) - I) dx/dE = -dP^k/dE, both by central differences."""
    J = jacobian(chain, E, x, k, times)
    hE = fd_step() * max(1, abs(E))
    fp = map_k(chain, E + hE, x, k, times)[0]
    fm = map_k(chain, E - hE, x, k, times)[0]
    dPdE = [(fp[i] - fm[i]) / (2 * hE) for i in range(2)]
    A = [[J[0][0] - 1, J[0][1]], [J[1][0], J[1][1] - 1]]
    return _solve2(A, [-dPdE[0], -dPdE[1]])


def family2(chain, E_list, guess, k=2):
    """Natural-parameter continuation of a k-impact family through the energies E_list.

    The first orbit is solved from `guess` = (u1, v1); each next one by Newton from the
    tangent predictor x + (E - E_prev) dx/dE of the previous orbit (dx/dE from
    (D(P^k) - I) dx/dE = -dP^k/dE, by central differences). Stops at the first failure
    (recorded with its reason): a fold in E, a grazing, a step too long for Newton.
    """
    out = []
    prev = None
    for E in E_list:
        E = mpf(E)
        if prev is None:
            g = [mpf(guess[0]), mpf(guess[1])]
        else:
            Ep, orb = prev
            xp = [orb["state"]["u1"], orb["state"]["v1"]]
            try:
                t = energy_tangent(chain, k, Ep, xp, [imp["t"] for imp in orb["impacts"]])
                g = [xp[i] + (E - Ep) * t[i] for i in range(2)]
            except (MapError, RuntimeError):
                g = xp
        try:
            orb = find_orbit(chain, k, E, g[0], g[1])
        except (MapError, RuntimeError) as error:
            out.append({"E": E, "failed": str(error)})
            break
        out.append(orb)
        prev = (E, orb)
    return out


def locate_trace(chain, k, Ea, xa, Eb, xb, target=2, etol=None):
    """Bisection in E of tr D(P^k) - target between two orbits of one family.

    (Ea, xa): an orbit (or guess) where tr - target has one sign; Eb: the other end, xb a
    guess there (or None). Each trial energy is solved by Newton from the linear
    interpolation of the two bracketing orbits (or, with no orbit on the far side, from
    the extrapolation of the last two on the near side). A trial where Newton fails is
    taken as beyond a fold (the family does not exist there) and the interval shrinks
    towards the known side: at a fold the result is the last energy where the family
    exists, where tr -> target. Returns (orbit at the located energy, info).
    """
    etol = mpf(10) ** (-(mp.dps // 2 - 2)) if etol is None else etol
    oa = find_orbit(chain, k, Ea, *xa)
    sa = oa["trace"] - target
    ob = None
    if xb is not None:
        try:
            ob = find_orbit(chain, k, Eb, *xb)
        except (MapError, RuntimeError):
            ob = None
    if ob is not None and (ob["trace"] - target > 0) == (sa > 0):
        raise MapError("tr - target has the same sign at both ends")
    xs = lambda o: [o["state"]["u1"], o["state"]["v1"]]
    lo, hi = (oa, mpf(Ea)), (ob, mpf(Eb))  # lo: known side; hi: other sign or no orbit
    lo_prev = None
    failures = 0
    while abs(hi[1] - lo[1]) > etol:
        Em = (lo[1] + hi[1]) / 2
        if hi[0] is not None:
            a, b = xs(lo[0]), xs(hi[0])
            s = (Em - lo[1]) / (hi[1] - lo[1])
        elif lo_prev is not None:
            a, b = xs(lo_prev[0]), xs(lo[0])
            s = (Em - lo_prev[1]) / (lo[1] - lo_prev[1])
        else:
            a = b = xs(lo[0])
            s = 0
        guess = [a[i] + s * (b[i] - a[i]) for i in range(2)]
        try:
            om = find_orbit(chain, k, Em, *guess)
        except (MapError, RuntimeError):
            om = None
        if om is None:
            hi = (None, Em)
            failures += 1
        elif (om["trace"] - target > 0) == (sa > 0):
            lo_prev, lo = lo, (om, Em)
        else:
            hi = (om, Em)
    best = lo[0]
    if hi[0] is None:
        kind = "fold: the family ends (Newton fails beyond)"
        if abs(best["trace"] - target) > mpf(10) ** -3:
            kind = "Newton failed before tr reached the target: not located"
    else:
        kind = "crossing of tr = target (the family continues)"
    info = {"bracket": [lo[1], hi[1]], "kind": kind, "newton_failures": failures}
    return best, info


def follow_arclength(chain, k, E, x, ds, steps, direction=1, ds_max=None, callback=None):
    """Pseudo-arclength continuation of a k-impact family in y = (u1/d, v1/(w2 d), E).

    Not needed for the brief's spot checks (family2 does those) but it passes folds in E,
    which natural-parameter continuation cannot. Jacobian [D(P^k) - I | dP^k/dE] by central
    differences; tangent = null vector of that 2x3 matrix (cross product of its rows),
    oriented as the previous one; corrector: Newton on (P^k(y) - x, (y - y_pred).t = 0).
    Step x1.5 after an easy correction, halved on failure, stop below 1e-8. The points
    are not checked for admissibility (solve one with find_orbit to get its clearances).
    `direction` +1 / -1 picks the initial sense (+1: E increasing).
    Returns a list of dicts {E, u1, v1, trace, period, min_impact_speed}.
    """
    d, w = chain.gap, chain.w[1]
    ds, ds_max = mpf(ds), mpf(ds_max) if ds_max is not None else 4 * mpf(ds)

    def G(y, times=None):
        xx = [y[0] * d, y[1] * w * d]
        img, imp, _ = map_k(chain, y[2], xx, k, times)
        return [(img[0] - xx[0]) / d, (img[1] - xx[1]) / (w * d)], imp

    def DG(y, times):
        h = fd_step()
        D = [[None] * 3 for _ in range(2)]
        for j in range(3):
            hj = h * max(1, abs(y[j]))
            yp, ym = list(y), list(y)
            yp[j] += hj
            ym[j] -= hj
            fp, fm = G(yp, times)[0], G(ym, times)[0]
            for i in range(2):
                D[i][j] = (fp[i] - fm[i]) / (2 * hj)
        return D

    def tangent(D, prev):
        a, b = D
        t = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        n = mp.sqrt(sum(v * v for v in t))
        t = [v / n for v in t]
        if sum(t[i] * prev[i] for i in range(3)) < 0:
            t = [-v for v in t]
        return t

    orb = find_orbit(chain, k, E, *x)
    y = [orb["state"]["u1"] / d, orb["state"]["v1"] / (w * d), orb["E"]]
    F, imp = G(y)
    t = tangent(DG(y, [i["t"] for i in imp]), [0, 0, direction])
    out = []
    while len(out) < steps and ds > mpf(10) ** -8:
        yp = [y[i] + ds * t[i] for i in range(3)]
        try:
            yn = list(yp)
            Fn, impn = G(yn)
            for it in range(30):
                D = DG(yn, [i["t"] for i in impn])
                g = sum((yn[i] - yp[i]) * t[i] for i in range(3))
                dy = mp.lu_solve(mp.matrix([D[0], D[1], t]), mp.matrix([-Fn[0], -Fn[1], -g]))
                yn = [yn[i] + dy[i] for i in range(3)]
                Fn, impn = G(yn)
                if (max(abs(v) for v in dy) < mpf(10) ** (-(mp.dps - 6))
                        and max(abs(Fn[0]), abs(Fn[1])) < mpf(10) ** (-(mp.dps - 8))):
                    break
            else:
                if max(abs(Fn[0]), abs(Fn[1])) > mpf(10) ** (-(mp.dps // 2)):
                    raise MapError("corrector did not converge")
        except (MapError, RuntimeError, ZeroDivisionError):
            ds /= 2
            continue
        D = DG(yn, [i["t"] for i in impn])
        t = tangent(D, t)
        y, imp = yn, impn
        tr = D[0][0] + D[1][1] + 2
        rec = {"E": y[2], "u1": y[0] * d, "v1": y[1] * w * d, "trace": tr,
               "period": sum(i["t"] for i in imp),
               "min_impact_speed": min(i["v2_pre"] for i in imp)}
        out.append(rec)
        if callback:
            callback(rec, ds)
        if it < 4:
            ds = min(ds * 3 / 2, ds_max)
    return out


# -- command line ---------------------------------------------------------------------------

VALUE_OPTIONS = {"--m1", "--m2", "--k1", "--gap", "--branch", "--tlo", "--thi", "--n", "--dps",
                 "--digits", "--impacts", "--energy", "--guess", "--period", "--period-over-t2",
                 "--energies", "--ea", "--eb", "--guess-b", "--target", "--ds", "--steps",
                 "--direction"}


def join_values(argv):
    """Turn `--opt VALUE` into `--opt=VALUE` so that values may start with '-'."""
    out = []
    i = 0
    while i < len(argv):
        if argv[i] in VALUE_OPTIONS and i + 1 < len(argv):
            out.append(argv[i] + "=" + argv[i + 1])
            i += 2
        else:
            out.append(argv[i])
            i += 1
    return out


def build_parser():
    p = argparse.ArgumentParser(
        prog="periodic_ref.py",
        description="High-precision reference for periodic impacting orbits (mpmath).")
    p.add_argument("command", choices=["onepp", "flips", "orbit", "family", "locate", "arc"])
    p.add_argument("--m1", default="1")
    p.add_argument("--m2", default="0.5")
    p.add_argument("--k1", default="1")
    p.add_argument("--gap", default="1")
    p.add_argument("--branch", default="upper", choices=["upper", "lower"])
    p.add_argument("--dps", type=int, default=50)
    p.add_argument("--digits", type=int, default=25)
    p.add_argument("--period", default=None, help="onepp: T in time units")
    p.add_argument("--period-over-t2", default=None, help="onepp: T / T2")
    p.add_argument("--tlo", default="0.501", help="flips: lowest period, in units of T2")
    p.add_argument("--thi", default="0.999", help="flips: highest period, in units of T2")
    p.add_argument("--n", type=int, default=400, help="flips: number of sample intervals")
    p.add_argument("--samples", action="store_true", help="flips: also print the samples")
    p.add_argument("--impacts", type=int, default=1)
    p.add_argument("--energy", default=None)
    p.add_argument("--energies", default=None, help="family: comma-separated energies")
    p.add_argument("--guess", default=None, metavar="u1,v1")
    p.add_argument("--ea", default=None, help="locate: energy of the known orbit (--guess)")
    p.add_argument("--eb", default=None, help="locate: other end of the energy interval")
    p.add_argument("--guess-b", default=None, metavar="u1,v1", help="locate: guess at --eb")
    p.add_argument("--target", default="2", help="locate: trace value (2 or -2)")
    p.add_argument("--ds", default="0.02", help="arc: first arclength step")
    p.add_argument("--steps", type=int, default=50, help="arc: number of steps")
    p.add_argument("--direction", type=int, default=1, choices=[1, -1],
                   help="arc: +1 starts towards increasing E, -1 decreasing")
    return p


def _pair(text, name):
    parts = (text or "").split(",")
    if len(parts) != 2:
        raise InputError("%s needs two comma-separated numbers u1,v1" % name)
    return [rs.parse_real(x, name, False) for x in parts]


def _json(obj, digits):
    if isinstance(obj, dict):
        return {k: _json(v, digits) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_json(v, digits) for v in obj]
    if isinstance(obj, mp.mpc):
        return {"re": rs.fmt(obj.real, digits), "im": rs.fmt(obj.imag, digits)}
    if isinstance(obj, mpf):
        return rs.fmt(obj, digits)
    return obj


def _orbit_json(orb):
    orb = dict(orb)
    orb.pop("residual_history", None)
    return orb


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    args = build_parser().parse_args(join_values(argv))
    if args.dps < 20:
        raise InputError("--dps must be at least 20")
    mp.dps = args.dps
    digits = max(1, min(args.digits, args.dps))
    real = lambda text, name: rs.parse_real(text, name, False)
    chain = Chain(real(args.m1, "--m1"), real(args.m2, "--m2"), real(args.k1, "--k1"),
                  real(args.gap, "--gap"), branch=args.branch)
    started = time.perf_counter()
    out = {"model": rs.model_json(chain, digits),
           "reference": {"dps": mp.dps, "fd_step": mp.nstr(fd_step(), 3),
                         "method": "central differences of the exact return map at fixed E"}}
    if args.command == "onepp":
        if (args.period is None) == (args.period_over_t2 is None):
            raise InputError("onepp needs exactly one of --period, --period-over-t2")
        T = (real(args.period, "--period") if args.period is not None
             else real(args.period_over_t2, "--period-over-t2") * chain.T2)
        if T <= 0:
            raise InputError("the period must be positive")
        out["orbit"] = trace1(chain, T)
    elif args.command == "flips":
        if args.n < 2:
            raise InputError("--n must be at least 2")
        tlo, thi = real(args.tlo, "--tlo") * chain.T2, real(args.thi, "--thi") * chain.T2
        if not 0 < tlo < thi:
            raise InputError("need 0 < --tlo < --thi")
        events, samples, extrema = one_pp_flips(chain, tlo, thi, args.n)
        out["events"] = events
        out["extrema"] = extrema
        if args.samples:
            out["samples"] = samples
    elif args.command in ("orbit", "family"):
        if args.impacts < 1:
            raise InputError("--impacts must be at least 1")
        guess = _pair(args.guess, "--guess")
        try:
            if args.command == "orbit":
                if args.energy is None:
                    raise InputError("orbit needs --energy")
                out["orbit"] = _orbit_json(find_orbit(chain, args.impacts,
                                                      real(args.energy, "--energy"), *guess))
            else:
                if args.energies is None:
                    raise InputError("family needs --energies E1,E2,...")
                Es = [real(e, "--energies") for e in args.energies.split(",")]
                out["family"] = [_orbit_json(o) for o in family2(chain, Es, guess,
                                                                  args.impacts)]
        except MapError as error:
            raise InputError(str(error))
    elif args.command == "locate":
        if args.ea is None or args.eb is None:
            raise InputError("locate needs --ea, --eb and --guess")
        guess = _pair(args.guess, "--guess")
        gb = _pair(args.guess_b, "--guess-b") if args.guess_b else None
        try:
            orb, info = locate_trace(chain, args.impacts, real(args.ea, "--ea"), guess,
                                     real(args.eb, "--eb"), gb, real(args.target, "--target"))
        except MapError as error:
            raise InputError(str(error))
        out["orbit"] = _orbit_json(orb)
        out["locate"] = info
    elif args.command == "arc":
        if args.energy is None:
            raise InputError("arc needs --energy and --guess")
        guess = _pair(args.guess, "--guess")
        try:
            out["family"] = follow_arclength(chain, args.impacts, real(args.energy, "--energy"),
                                             guess, real(args.ds, "--ds"), args.steps,
                                             args.direction)
        except MapError as error:
            raise InputError(str(error))
    out["timing"] = {"seconds": mpf(time.perf_counter() - started)}
    sys.stdout.write(rs.dump_json(_json(out, digits)) + "\n")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except InputError as error:
        sys.stderr.write("periodic_ref.py: %s\n" % error)
        sys.exit(2)
