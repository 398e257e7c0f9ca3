// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/simulate.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/solver/two_mass_run.h"

namespace grazelab::core {

template <typename S>
std::vector<Problem> validate(const BasicRequest<S>& request) {
  std::vector<Problem> problems;
  auto add = [&](const char* field, const std::string& reason, const std::string& value) {
    problems.push_back({field, reason + " (got " + value + ")"});
  };
  if (request.maxContacts < 0) {
    add("contacts", "must not be negative", std::to_string(request.maxContacts));
  }
  if (!(request.tEnd >= 0)) add("t-end", "must be >= 0", formatScalar(request.tEnd));
  if (request.flightSearchSteps < 1) {
    add("flightSearchSteps", "must be at least 1", std::to_string(request.flightSearchSteps));
  }
  const SampleSpec& samples = request.needs.samples;
  if (!std::isfinite(samples.spacing) || samples.spacing < 0) {
    add("samples.spacing", "must be >= 0 and finite", std::to_string(samples.spacing));
  }
  for (std::size_t i = 0; i < samples.times.size(); ++i) {
    if (!std::isfinite(samples.times[i]) || samples.times[i] < 0 ||
        (i > 0 && !(samples.times[i] >= samples.times[i - 1]))) {
      add("samples.times", "must be finite, >= 0 and ascending", std::to_string(samples.times[i]));
      break;
    }
  }
  return problems;
}

template <typename S>
BasicResult<S> simulate(const BasicModel<S>& model, const BasicRequest<S>& request, std::stop_token stop) {
  TwoMassRun<S> run(model, request);
  while (!run.advance(std::numeric_limits<std::int64_t>::max(), stop)) {
  }
  return run.takeResult();
}

#define GRAZELAB_INSTANTIATE(S)                                                       \
  template std::vector<Problem> validate<S>(const BasicRequest<S>&);                  \
  template BasicResult<S> simulate<S>(const BasicModel<S>&, const BasicRequest<S>&,   \
                                      std::stop_token);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
