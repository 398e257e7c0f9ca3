// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/numbers/vector_state.h"

namespace grazelab::core {

void clearUpperVectorState() noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
  // vzeroupper is an invalid instruction without AVX (or with AVX the system does not save)
  static const bool hasAvx = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
  }();
  if (hasAvx) asm volatile("vzeroupper");
#endif
}

}  // namespace grazelab::core
