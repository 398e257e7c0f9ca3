// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// The parts every document shares (the note's model, a chain, an error estimate), written once
// for any value type V: JsonValue, which the command line writes as text (io/json_value.h), or
// the Python module's objects, made as the document is built (PyValue, python/value_to_python.h), so that the two
// faces cannot differ. V has JsonValue's factories: null, of, number, array and object (a braced
// list of {name, value} or a vector of fields).

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/model/mass_chain.h"
#include "core/numbers/scalar.h"
#include "core/orbits/special_orbits.h"
#include "core/solver/trust.h"
#include "io/cli_input.h"

namespace grazelab::cli::values {

/// A section of a run's document that is the same in every run of its chain (the chain, the
/// note's model): `make()`, unless V keeps such sections (V::chainSection: the Python module's
/// objects, made once per chain and then copied, a tenth of the cost), by the section's `name`,
/// the chain in its precision (`ready`) and the `variant` asked for (the precision's name).
template <typename V, typename Make>
V chainSection(const char* name, const void* ready, const std::string& variant, Make&& make) {
  if constexpr (requires { V::chainSection(name, ready, variant, make); }) {
    return V::chainSection(name, ready, variant, make);
  } else {
    return make();
  }
}

/// The note's model of a two-mass chain with its derived quantities (k2 and where it comes from,
/// w1, w2, T1, T2, P, lambda*), and the precision asked for.
template <typename V, typename S>
V model(const ModelInput<S>& input, const std::string& precision) {
  const core::BasicModel<S>& model = input.model;
  const core::TwoMassForm<S>& chain = input.chain;
  const S omegaFast = chain.ratio * chain.omegaSlow;
  // M-normalised mode shapes: columns (rho_j, 1) / (sqrt(m1) sqrt(rho_j^2 + beta))
  using std::sqrt;
  S p[2][2];
  const S rho[2] = {chain.rhoFast, chain.rhoSlow};
  for (int j = 0; j < 2; ++j) {
    const S scale = S(1) / (sqrt(model.m1) * sqrt(rho[j] * rho[j] + chain.beta));
    p[0][j] = rho[j] * scale;
    p[1][j] = scale;
  }
  const std::string source =
      model.design ? "1:2 design, " + std::string(core::toString(*model.design)) + " branch"
                   : std::string("given");
  return V::object(
      {{"m1", V::number(model.m1)},
       {"m2", V::number(model.m2)},
       {"k1", V::number(model.k1)},
       {"k2", V::number(model.k2)},
       {"gap", V::number(model.gap)},
       {"k2_source", V::of(source)},
       {"mass_ratio", V::number(chain.beta)},
       {"omega1", V::number(omegaFast)},
       {"omega2", V::number(chain.omegaSlow)},
       {"T1", V::number(S(core::twoPi<S>() / omegaFast))},
       {"T2", V::number(S(core::twoPi<S>() / chain.omegaSlow))},
       {"resonant", V::of(chain.resonant)},
       {"detuning", V::number(chain.detuning)},
       {"mode_labelling", V::of("mode 1 is the fast mode, mode 2 the slow one (omega1 = 2 omega2)")},
       {"P", V::array({V::array({V::number(p[0][0]), V::number(p[0][1])}),
                       V::array({V::number(p[1][0]), V::number(p[1][1])})})},
       {"precision", V::of(precision)},
       {"lambda_star", chain.resonant ? V::number(core::lambdaStar(chain)) : V::null()}});
}

/// A run's error estimate: estimated_state_error, estimated_time_error, horizon, horizon_method
/// (null when not estimated), verdict, reason.
template <typename V>
V trust(const core::Trust& trust) {
  const bool estimated = trust.verdict != core::Verdict::Unchecked;
  auto estimate = [&](double value) { return estimated ? V::number(value) : V::null(); };
  return V::object({{"estimated_state_error", estimate(trust.stateError)},
                    {"estimated_time_error", estimate(trust.timeError)},
                    {"horizon", estimate(trust.horizon)},
                    {"horizon_method", estimated ? V::of(trust.horizonMethod) : V::null()},
                    {"verdict", V::of(std::string(core::toString(trust.verdict)))},
                    {"reason", V::of(trust.reason)}});
}

/// A chain of N masses as the documents name it: masses, springs, right_spring (null: none),
/// stop_mass, gap and the common `period` of a commensurate chain (null: none), to the digits of
/// the chain's precision.
template <typename V, typename S>
V massChain(const core::BasicMassChain<S>& chain, const S& period) {
  const auto numbers = [](const std::vector<S>& values) {
    std::vector<V> items;
    items.reserve(values.size());
    for (const S& value : values) items.push_back(V::number(value));
    return V::array(std::move(items));
  };
  return V::object({{"masses", numbers(chain.masses)},
                    {"springs", numbers(chain.springs)},
                    {"right_spring", chain.rightSpring > 0 ? V::number(chain.rightSpring) : V::null()},
                    {"stop_mass", V::of(std::int64_t(chain.stopped()))},
                    {"gap", V::number(chain.gap)},
                    {"period", period > 0 ? V::number(period) : V::null()}});
}

}  // namespace grazelab::cli::values
