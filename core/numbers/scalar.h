// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/float128.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace grazelab::core {

/// IEEE binary128 (113-bit significand), through Boost.Multiprecision's wrapper of libquadmath.
using Quad = boost::multiprecision::float128;

/// The arithmetic a run is computed in: the exact solver is one algorithm templated on it.
enum class Precision { Double, Long, Quad };

/// "double", "long", "quad".
std::string_view toString(Precision precision);
/// Parses "double" / "long" / "quad"; nothing for anything else.
std::optional<Precision> parsePrecision(std::string_view text);

/// The scalar type of a precision.
template <Precision P>
using ScalarOf = std::conditional_t<P == Precision::Double, double,
                                    std::conditional_t<P == Precision::Long, long double, Quad>>;

/// The precision whose scalar is S.
template <typename S>
constexpr Precision precisionOf() {
  if constexpr (std::is_same_v<S, double>) return Precision::Double;
  if constexpr (std::is_same_v<S, long double>) return Precision::Long;
  return Precision::Quad;
}

/// Unit roundoff of S (2^-52, 2^-63, 2^-112).
template <typename S>
S epsilon() {
  return std::numeric_limits<S>::epsilon();
}

template <typename S>
S pi() {
  return boost::math::constants::pi<S>();
}

template <typename S>
S twoPi() {
  return boost::math::constants::two_pi<S>();
}

/// Significant digits that make every value of S round-trip through text: 17, 21, 36.
template <typename S>
inline constexpr int kRoundTripDigits = std::numeric_limits<S>::max_digits10;

/// A number read from text, or why not.
template <typename S>
struct ParsedScalar {
  std::optional<S> value;
  std::string error;  ///< "is not a number", "is out of range (overflows)", ...
};

/// Reads a decimal number in precision S (the whole text must be the number; "inf" and "nan"
/// are read as such, and left for validation to reject with a reason). A number too large for
/// S, or nonzero but too small for it, is an error "out of range", not silently inf or 0.
template <typename S>
ParsedScalar<S> parseScalar(std::string_view text);

/// Text that reads back to the same value: shortest round-trip digits for double and long
/// double, 36 significant digits for binary128.
template <typename S>
std::string formatScalar(S value);

/// Nearest double (for display and for quantities that only steer the algorithm).
template <typename S>
double toDouble(const S& value) {
  return static_cast<double>(value);
}

/// True when the value is finite (works for every precision).
template <typename S>
bool isFinite(const S& value) {
  using std::isfinite;
  using boost::multiprecision::isfinite;
  return isfinite(value);
}

/// x * 2^e, rounded once, as ldexp. For double the power of two is built from its bits and
/// multiplied (the same correctly rounded result, without a library call) while it is a normal
/// number; scaling to physical units after every event made the ldexp calls 6 % of a run.
template <typename S>
S timesPowerOfTwo(const S& x, int e) {
  using std::ldexp;
  return ldexp(x, e);
}
template <>
inline double timesPowerOfTwo<double>(const double& x, int e) {
  if (e >= -1022 && e <= 1023) return x * std::bit_cast<double>(std::uint64_t(e + 1023) << 52);
  return std::ldexp(x, e);
}

}  // namespace grazelab::core
