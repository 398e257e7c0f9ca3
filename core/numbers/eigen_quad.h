// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once
// Eigen on binary128 (core::Quad). Boost 1.74's boost/multiprecision/eigen.hpp lacks the
// infinity() and quiet_NaN() that Eigen 3.4's hypot asks of NumTraits; GenericNumTraits takes
// them, like everything else, from std::numeric_limits<Quad>, which Boost provides.
#include <Eigen/Core>

#include "core/numbers/scalar.h"

namespace Eigen {

template <>
struct NumTraits<grazelab::core::Quad> : GenericNumTraits<grazelab::core::Quad> {
  using Real = grazelab::core::Quad;
  using NonInteger = grazelab::core::Quad;
  using Literal = grazelab::core::Quad;
  using Nested = grazelab::core::Quad;
  enum {
    IsInteger = 0,
    IsSigned = 1,
    IsComplex = 0,
    RequireInitialization = 1,
    // software arithmetic: tens of cycles an operation
    ReadCost = 1,
    AddCost = 20,
    MulCost = 40,
  };
};

}  // namespace Eigen
