// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <optional>
#include <type_traits>

#include "core/model/mass_chain.h"
#include "core/model/model.h"
#include "core/solver/chain_run.h"
#include "core/solver/trust.h"

namespace grazelab::core {

/// A map's chain made ready once for all its points, in each precision, with the shadows of its
/// error estimates (a shadow points into the chain it shadows: the struct stays where it was
/// made). Made per point, the modes (a binary128 eigensolve) were most of a short run's cost.
/// Used by the two-mass map (maps.cpp) and the map of N masses (chain_map.cpp) alike.
struct MapChains {
  /// The note's chain of `model` (a two-mass map whose axes leave the model alone): the shadow in
  /// S is the chain read one precision up from the model.
  explicit MapChains(const Model& model)
      : inDouble(readyChain(model)),
        inLong(readyChain(convertModel<long double>(model))),
        inQuad(readyChain(convertModel<Quad>(model))) {
    ofDouble.emplace(chainShadow<double>(inLong));
    ofLong.emplace(chainShadow<long double>(inQuad));
    ofQuad.emplace(chainShadow<Quad>(inQuad));
  }
  /// A chain of N masses, its numbers those of the map (a parameter axis moves them by double
  /// steps): a point raised runs this same chain in a higher precision; the shadows (with
  /// `estimateHorizon`) are the chain widened one precision up, as a run's own.
  MapChains(const MassChain& chain, bool estimateHorizon)
      : inDouble(readyChain(chain)),
        inLong(readyChain(chainCast<long double>(chain))),
        inQuad(readyChain(chainCast<Quad>(chain))) {
    if (estimateHorizon) {
      ofDouble.emplace(widenedShadow(inDouble, widenedDouble));
      ofLong.emplace(widenedShadow(inLong, widenedLong));
      ofQuad.emplace(widenedShadow(inQuad, widenedQuad));
    }
  }
  MapChains(const MapChains&) = delete;
  MapChains& operator=(const MapChains&) = delete;

  template <typename S>
  const BasicReadyChain<S>& ready() const {
    if constexpr (std::is_same_v<S, double>) return inDouble;
    else if constexpr (std::is_same_v<S, long double>) return inLong;
    else return inQuad;
  }
  /// none when the map estimates no horizon
  template <typename S>
  const ChainShadow<S>* shadow() const {
    if constexpr (std::is_same_v<S, double>) return ofDouble ? &*ofDouble : nullptr;
    else if constexpr (std::is_same_v<S, long double>) return ofLong ? &*ofLong : nullptr;
    else return ofQuad ? &*ofQuad : nullptr;
  }

  BasicReadyChain<double> inDouble;
  BasicReadyChain<long double> inLong;
  BasicReadyChain<Quad> inQuad;

 private:
  std::optional<BasicReadyChain<ShadowScalar<double>>> widenedDouble;
  std::optional<BasicReadyChain<ShadowScalar<long double>>> widenedLong;
  std::optional<BasicReadyChain<ShadowScalar<Quad>>> widenedQuad;
  std::optional<ChainShadow<double>> ofDouble;
  std::optional<ChainShadow<long double>> ofLong;
  std::optional<ChainShadow<Quad>> ofQuad;
};

}  // namespace grazelab::core
