// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// core/orbits/chain_monodromy.h in double and long double (binary128: chain_monodromy_quad.cpp).
#include "core/orbits/chain_monodromy_impl.h"

namespace grazelab::core {

std::string_view toString(ChainStability stability) {
  switch (stability) {
    case ChainStability::Elliptic: return "elliptic";
    case ChainStability::Hyperbolic: return "hyperbolic";
    case ChainStability::FlipHyperbolic: return "flip-hyperbolic";
    case ChainStability::ComplexQuadruplet: return "complex-quadruplet";
    case ChainStability::Undecided: return "undecided";
  }
  return "undecided";
}

GRAZELAB_CHAIN_MONODROMY(double)
GRAZELAB_CHAIN_MONODROMY(long double)

}  // namespace grazelab::core
