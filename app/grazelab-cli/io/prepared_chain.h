// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <memory>
#include <mutex>
#include <stop_token>
#include <vector>

#include "core/solver/chain_run.h"
#include "core/solver/trust.h"
#include "io/cli_input.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// A chain of N masses as the commands read it (--masses, --springs, --right-spring,
/// --stop-mass, --gap, --frequencies, --design-branch): read, checked and designed once, then
/// made ready to run in each precision (its numbers read again there, its modes computed) and
/// its shadow (the run's error estimate) the first time a run asks for them. The command line
/// makes one per command; the Python module's Chain one per object, shared by every run of it.
/// Immutable once made; safe to use from several threads.
class PreparedMassChain {
 public:
  /// The chain of `options`, or the line that says why there is none; an interrupted design
  /// gives neither (`stop` was requested).
  static Parsed<std::shared_ptr<const PreparedMassChain>> make(const OptionValues& options,
                                                               std::stop_token stop = {});

  /// The chain's own options (those given of the seven above), as text.
  const std::vector<GivenOption>& givenOptions() const { return m_given; }
  /// It is the note's chain (written with the note's options, or with --masses as
  /// writesTheNotesChain says), read in each precision by the note's reader (parseModel).
  bool isTheNotesChain() const { return m_notes; }

  /// The chain as read in double, with the design its springs came from (a chain of N masses;
  /// empty for the note's chain, which isTheNotesChain reads by the note's reader).
  const MassChainInput& input() const { return m_input; }
  /// The chain in S, ready to run; or why its numbers cannot be read there (a design that
  /// cannot be refined for them).
  template <typename S>
  const Parsed<core::BasicReadyChain<S>>& ready() const;
  /// The chain as the note's two-mass form in S, as the two-mass commands read it (orbit:
  /// parseModel); or why it has none (another shape, a ratio S cannot hold).
  template <typename S>
  const Parsed<ModelInput<S>>& twoMassForm() const;
  /// The shadow of its runs in S: the chain read one precision up (in binary128, scaled); not
  /// usable when it cannot be read there (its `problem` says why).
  template <typename S>
  const core::ChainShadow<S>& shadow() const;

 private:
  PreparedMassChain(std::vector<GivenOption> given, MassChainInput input, bool notesReader);

  template <typename S>
  struct InPrecision {
    std::once_flag readyOnce, shadowOnce, formOnce;
    Parsed<core::BasicReadyChain<S>> ready;
    Parsed<ModelInput<S>> form;
    core::ChainShadow<S> shadow;
  };
  template <typename S>
  InPrecision<S>& in() const;

  std::vector<GivenOption> m_given;
  OptionValues m_options;  ///< m_given, read as options
  MassChainInput m_input;  ///< the chain in double, and how its springs came when designed
  bool m_notes = false;
  bool m_notesReader = false;  ///< ready<S>() reads the note's model (parseModel), not a chain
  mutable InPrecision<double> m_double;
  mutable InPrecision<long double> m_long;
  mutable InPrecision<core::Quad> m_quad;
};

}  // namespace grazelab::cli
