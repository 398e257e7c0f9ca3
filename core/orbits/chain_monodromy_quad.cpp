// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// core/orbits/chain_monodromy.h in binary128, apart: its eigen-solver on std::complex<Quad> is
// most of the compile (minutes under the sanitizers), now beside the other precisions'.
#include "core/orbits/chain_monodromy_impl.h"

namespace grazelab::core {

GRAZELAB_CHAIN_MONODROMY(Quad)

}  // namespace grazelab::core
