// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/two_mass_form.h"

#include <algorithm>

#include "core/model/resonance.h"

namespace grazelab::core {

template <typename S>
TwoMassFormOrProblem<S> makeTwoMassForm(const BasicModel<S>& model) {
  using std::abs;
  using std::hypot;
  using std::sqrt;
  TwoMassForm<S> chain;
  chain.model = model;
  chain.beta = model.m2 / model.m1;
  chain.kappa = model.design ? designKappa(chain.beta, *model.design) : S(model.k2 / model.k1);
  const S beta = chain.beta;
  const S kappa = chain.kappa;
  // K p = lambda (k1/m1) M p in the ratios: [[a, -kappa], [-c, c]] with a = 1 + kappa, c = kappa/beta
  const S a = S(1) + kappa;
  const S c = kappa / beta;
  // discriminant (a - c)^2 + 4 kappa c: a sum of squares, no cancellation; hypot avoids overflow
  const S s = hypot(a - c, S(2) * sqrt(kappa) * sqrt(c));
  chain.lambdaFast = (a + c + s) / S(2);
  chain.lambdaSlow = c / chain.lambdaFast;  // Vieta: lambdaFast lambdaSlow = c
  // mode shapes rho = u1/u2 from the row that does not cancel: row 1 gives kappa / (a - lambda),
  // row 2 gives (c - lambda) / c; a - lambda and c - lambda are (+-(a - c) +- s) / 2
  if (a >= c) {
    chain.rhoFast = -(a - c + s) / (S(2) * c);
    chain.rhoSlow = S(2) * kappa / (a - c + s);
  } else {
    chain.rhoFast = S(-2) * kappa / (c - a + s);
    chain.rhoSlow = (c - a + s) / (S(2) * c);
  }
  chain.omegaSlow = sqrt(model.k1) / sqrt(model.m1) * sqrt(chain.lambdaSlow);
  chain.p = S(1) / chain.lambdaSlow;
  chain.q = kappa / chain.lambdaSlow;
  chain.w = c / chain.lambdaSlow;
  chain.stuckOmega = sqrt(chain.p + chain.q);

  if (model.design) {
    chain.resonant = true;
  } else {
    // the exact defect D / beta^2 = (lambdaFast - 4 lambdaSlow)(4 lambdaFast - lambdaSlow) gives
    // w1/w2 - 2 = (lambdaFast - 4 lambdaSlow) / (lambdaSlow (ratio + 2)) to relative precision
    const S defect = resonanceDefect(model.m1, model.m2, model.k1, model.k2);
    chain.resonant = defect == 0;
    if (!chain.resonant) {
      const S ratio = sqrt(chain.lambdaFast / chain.lambdaSlow);
      const S fastMinusFourSlow = defect / (S(4) * chain.lambdaFast - chain.lambdaSlow);
      chain.detuning = fastMinusFourSlow / (chain.lambdaSlow * (ratio + S(2)));
      chain.ratio = S(2) + chain.detuning;
    }
  }
  // every derived number must be finite, and all but the detuning nonzero
  const S nonzero[] = {chain.lambdaFast, chain.lambdaSlow, chain.rhoFast, chain.rhoSlow,
                       chain.omegaSlow,  chain.p,          chain.q,       chain.w,
                       chain.ratio};
  bool representable = isFinite(chain.detuning);
  for (const S& value : nonzero) representable = representable && isFinite(value) && value != 0;
  if (!representable) {
    return {std::nullopt,
            "the ratios m2/m1 = " + formatScalar(beta) + " and k2/k1 = " + formatScalar(kappa) +
                " are beyond the range of this precision",
            TwoMassFormProblem::BeyondRange};
  }
  // the fast phase over one slow period is ratio * 2 pi, known to ratio * 2 pi * eps: beyond
  // 1e-6 rad the fast mode's contribution (and with it every contact time) is rounding, and
  // the detuned search would march ~ratio steps per period: refused, never answered with noise
  const S phaseError = chain.ratio * twoPi<S>() * epsilon<S>();
  if (phaseError > S(1e-6)) {
    return {std::nullopt,
            "w1/w2 = " + formatScalar(chain.ratio) +
                ": the fast mode turns so often per slow period that its phase is rounding in " +
                std::string(toString(precisionOf<S>())) + " (at most " +
                formatScalar(S(S(1e-6) / (twoPi<S>() * epsilon<S>()))) + ")",
            TwoMassFormProblem::PhaseRounding};
  }
  return {chain, {}};
}

template <typename S>
BasicState<S> Scale<S>::toScaled(const BasicState<S>& u) const {
  return {timesPowerOfTwo(u.u1, -exponent), timesPowerOfTwo(u.u2, -exponent),
          timesPowerOfTwo(S(u.v1 / omegaSlow), -exponent),
          timesPowerOfTwo(S(u.v2 / omegaSlow), -exponent)};
}

template <typename S>
BasicState<S> Scale<S>::toPhysical(const BasicState<S>& x) const {
  // the order that cannot overflow on the way when the result itself is representable
  auto velocity = [&](const S& y) {
    const S direct = timesPowerOfTwo(S(y * omegaSlow), exponent);
    return isFinite(direct) && direct != 0 ? direct : S(timesPowerOfTwo(y, exponent) * omegaSlow);
  };
  return {timesPowerOfTwo(x.u1, exponent), timesPowerOfTwo(x.u2, exponent), velocity(x.v1),
          velocity(x.v2)};
}

template <typename S>
Scale<S> chooseScale(const TwoMassForm<S>& chain, const BasicState<S>& initial) {
  using std::abs;
  using std::ilogb;
  Scale<S> scale;
  scale.omegaSlow = chain.omegaSlow;
  const S size = std::max({chain.model.gap, abs(initial.u1), abs(initial.u2),
                           S(abs(initial.v1) / chain.omegaSlow),
                           S(abs(initial.v2) / chain.omegaSlow)});
  scale.exponent = int(ilogb(size));
  using std::ldexp;
  scale.gap = ldexp(chain.model.gap, -scale.exponent);
  return scale;
}

template <typename S>
S scaledEnergy(const TwoMassForm<S>& chain, const BasicState<S>& x) {
  const S stretch = x.u2 - x.u1;
  return (chain.lambdaSlow * (x.v1 * x.v1 + chain.beta * x.v2 * x.v2) + x.u1 * x.u1 +
          chain.kappa * stretch * stretch) /
         S(2);
}

template <typename S>
S physicalEnergy(const TwoMassForm<S>& chain, const BasicState<S>& physical) {
  using std::abs;
  using std::ldexp;
  // a state at infinity (the 1IPP data where g2(T) = 0) or not a number: its energy is that too
  // (chooseScale's exponent would be ilogb's sentinel, and doubling it overflows)
  const S size = abs(physical.u1) + abs(physical.u2) + abs(physical.v1) + abs(physical.v2);
  if (!isFinite(size)) return size;
  const Scale<S> scale = chooseScale(chain, physical);
  const S e = scaledEnergy(chain, scale.toScaled(physical));
  // E = k1 L^2 e, with L^2 = 2^(2 exponent) applied exactly
  return ldexp(chain.model.k1 * e, 2 * scale.exponent);
}

double energy(const BasicModel<double>& model, const BasicState<double>& state) {
  const TwoMassFormOrProblem<double> formed = makeTwoMassForm(model);
  return formed.chain ? physicalEnergy(*formed.chain, state)
                      : std::numeric_limits<double>::infinity();
}

#define GRAZELAB_INSTANTIATE(S)                                                      \
  template TwoMassFormOrProblem<S> makeTwoMassForm<S>(const BasicModel<S>&);                     \
  template struct Scale<S>;                                                          \
  template Scale<S> chooseScale<S>(const TwoMassForm<S>&, const BasicState<S>&);          \
  template S scaledEnergy<S>(const TwoMassForm<S>&, const BasicState<S>&);                \
  template S physicalEnergy<S>(const TwoMassForm<S>&, const BasicState<S>&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
