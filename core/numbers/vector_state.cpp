// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/numbers/vector_state.h"

namespace grazelab::core {

void clearUpperVectorState() noexcept {
  // (a build for AVX encodes its own SSE arithmetic with VEX, which does not wait on the upper
  // halves, and could hold 256-bit values in them here: nothing to do, and nothing to clear)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__AVX__)
  // vzeroupper is an invalid instruction without AVX (or with AVX the system does not save)
  static const bool hasAvx = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
  }();
  if (hasAvx) asm volatile("vzeroupper");
#endif
}

}  // namespace grazelab::core
