// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

// What the scenes of a chain of N masses share: the chain the panel describes (its springs as
// given, or designed for its resonance), and the run and the chain in words.
#include <QString>

#include <optional>
#include <stop_token>

#include "core/experiments/chain_series.h"
#include "core/model/mass_chain.h"
#include "core/orbits/chain_glo.h"
#include "core/model/chain_design.h"
#include "ui/compute/params.h"
#include "ui/compute/sim_types.h"

namespace grazelab::ui {

/// The chain of `given` with the gap `gap`: its springs as given, or designed for its resonance
/// (the design asked for); or why there is none, in words (nothing either when stopped).
struct ChainChoice {
  std::optional<core::MassChain> chain;
  QString problem;
  int designs = 0;  ///< how many designs its resonance has for these masses (0: as given)
  /// the design it took (its runs raised in precision take its springs refined there)
  std::optional<core::DesignChoice> design;
};
ChainChoice chooseChain(const MassChainParams& given, double gap, std::stop_token stop);

/// What the chain is, in words: springs, frequencies, their ratio and the common period, then
/// `more` (a scene's own sentence), then the table of its modes.
QString chainSummaryOf(const core::MassChain& chain, const MassChainParams& given, int designs,
                       const core::ChainModes& modes, const core::SpectrumRatios& ratios,
                       const QString& more = {});

/// A job refused with `why`, said in the status line and under the chain editor.
SceneJob refusedChainJob(const QString& why);
/// A job refused for its start (weights, a period) on a chain that is fine: the panel keeps the
/// chain's summary and says why at its foot, so that no control moves.
SceneJob refusedStartJob(const QString& why);

/// Why GLO(λ) of the panel's weights cannot be made, in words.
QString gloStartProblemInWords(core::GloStartProblem problem);

}  // namespace grazelab::ui
