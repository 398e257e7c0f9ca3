// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// The note's chain (m1 = k1 = d = 1, m2 = 1/2, k2 from the 1:2 design) started on GLO_0.5 with
// mass 2 pushed into the stop: its first contacts, exactly, from the installed core library.
#include <cstdio>

#include "core/model/model.h"
#include "core/model/linear_modes.h"
#include "core/orbits/special_orbits.h"
#include "core/orbits/starts.h"
#include "core/solver/simulate.h"
#include "core/version.h"

int main() {
  using namespace grazelab::core;
  const Model model = *designedModel(1.0, 0.5, 1.0, 1.0, Branch::Upper);
  Request request;
  request.initial = gloData(model, computeModes(model), 0.5);
  request.initial.v2 -= 0.05;
  request.maxContacts = 5;
  request.needs.events = true;
  const Result result = simulate(model, request);
  std::printf("GrazeLab %s: %zu contacts\n", grazelab::kVersion, result.events.size());
  for (const Event& event : result.events) std::printf("t = %.17g  v2- = %.17g\n", event.t, event.before.v2);
  return result.events.size() == 5 ? 0 : 1;
}
