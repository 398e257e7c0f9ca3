// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <stop_token>
#include <string>

#include "core/methods/method.h"

namespace grazelab::core::methods {

/// The reference of every error GrazeLab reports: the exact solver in binary128 on the same
/// start, run on the chain scaled 3x in length, 5x in mass and 1/sqrt(3) in time (the physics
/// is scale-free, the roundings are not), so that even the binary128 run of the plain chain is
/// measured against something with other roundings.
template <typename R>
struct BasicReference {
  BasicMethodRun<R> run;    ///< in the task's units (double)
  double period = 0;        ///< T2 [time]
  double positionScale = 0; ///< X = d (docs/model.md section 8)
  double velocityScale = 0; ///< V = w1 X
  double seconds = 0;       ///< its cost
  int stop = 1;             ///< the stopped mass, 0-based
};
using Reference = BasicReference<Result>;
using ChainReference = BasicReference<ChainRun>;

/// Runs the reference of a task (with events kept). Its status says whether it completed. For
/// any chain, T2 is its slowest period, X its gap and V its fastest frequency times X.
Reference makeReference(const Task& task, const WorkBudget& budget = {},
                        std::stop_token stop = {});
ChainReference makeReference(const ChainTask& task, const WorkBudget& budget = {},
                             std::stop_token stop = {});

/// A method's errors against the reference (docs/model.md section 8). Errors that cannot be formed
/// (a run that did not reach the end, no matched contact) are NaN, and the status says why.
struct Errors {
  double state = 0;         ///< final state: max |du| / X, |dv| / V
  double contactTime = 0;   ///< max |t - t_ref| / T2 over matched contacts
  double impactSpeed = 0;   ///< max |vs- - vs-_ref| / V over matched impacts
  std::int64_t matched = 0;
  std::int64_t missed = 0;  ///< reference contacts with no counterpart
  std::int64_t extra = 0;   ///< the method's contacts with no counterpart
  double energyDrift = 0;   ///< the method's max |E - E0| / E0
};

/// Matches contacts one to one in time order: a pair is a method contact within a quarter of
/// T2, and within half the distance to the neighbouring reference contacts, of a reference one.
/// Contacts past the end of a run that stopped early are neither missed nor extra.
Errors compare(const Reference& reference, const MethodRun& run);
Errors compare(const ChainReference& reference, const ChainMethodRun& run);

}  // namespace grazelab::core::methods
