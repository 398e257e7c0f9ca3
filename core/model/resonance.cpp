// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/model/resonance.h"

#include <boost/multiprecision/cpp_int.hpp>

#include <cmath>

#include "core/numbers/scalar.h"

namespace grazelab::core {
namespace {

using boost::multiprecision::cpp_int;
using boost::multiprecision::cpp_rational;

// the exact value of a finite binary number: mantissa * 2^exponent, read 32 bits at a time
template <typename S>
cpp_rational exactly(const S& value) {
  using std::abs;
  using std::floor;
  using std::frexp;
  using std::ldexp;
  int exponent = 0;
  S rest = frexp(abs(value), &exponent);
  cpp_int mantissa = 0;
  while (rest != 0) {
    rest = ldexp(rest, 32);
    const S chunk = floor(rest);
    rest -= chunk;
    mantissa = (mantissa << 32) + cpp_int(static_cast<unsigned long long>(chunk));
    exponent -= 32;
  }
  cpp_rational result(mantissa);
  if (exponent >= 0) {
    result *= cpp_rational(cpp_int(1) << exponent);
  } else {
    result /= cpp_rational(cpp_int(1) << -exponent);
  }
  return value < 0 ? cpp_rational(-result) : result;
}

// a rational rounded to S (128 significant bits of the quotient, then scaled)
template <typename S>
S rounded(const cpp_rational& value) {
  using std::ldexp;
  if (value == 0) return S(0);
  cpp_int numerator = boost::multiprecision::numerator(value);
  cpp_int denominator = boost::multiprecision::denominator(value);
  const bool negative = numerator < 0;
  if (negative) numerator = -numerator;
  // shift so that the integer quotient has about 128 bits
  const long shift = long(msb(denominator)) - long(msb(numerator)) + 128;
  const cpp_int quotient = shift >= 0 ? cpp_int((numerator << shift) / denominator)
                                      : cpp_int((numerator >> -shift) / denominator);
  // quotient -> S, 32 bits at a time from the top
  S result = 0;
  const long bits = long(msb(quotient)) + 1;
  for (long top = bits; top > 0; top -= 32) {
    // the bits [low, top): the last chunk may be shorter than 32 bits (a 32-bit mask there
    // counted the bits below `top` twice: binary128's detuning was off by 7e-30)
    const long low = std::max(0L, top - 32);
    const cpp_int mask = (cpp_int(1) << (top - low)) - 1;
    const cpp_int chunk = cpp_int((quotient >> low) & mask);
    result += ldexp(S(static_cast<unsigned long long>(chunk)), int(low - shift));
  }
  return negative ? S(-result) : result;
}

}  // namespace

template <typename S>
bool designFeasible(const S& m1, const S& m2) {
  using std::fma;
  // 9 m1 - 16 m2 >= 0 with a single rounding: its sign is exact
  return fma(S(9), m1, S(-16) * m2) >= 0;
}

template <typename S>
S designKappa(const S& beta, Branch branch) {
  using std::max;
  using std::sqrt;
  const S root = sqrt(max(S(0), S(9) - S(16) * beta));
  const S onePlusBeta = S(1) + beta;
  const S upper = beta * ((S(17) - S(8) * beta) + S(5) * root) / (S(8) * onePlusBeta * onePlusBeta);
  if (branch == Branch::Upper) return upper;
  // kappa_upper kappa_lower = beta^2 / (1 + beta)^2
  return (beta / onePlusBeta) * (beta / onePlusBeta) / upper;
}

std::optional<double> resonantK2(double m1, double m2, double k1, Branch branch) {
  const bool usable = std::isfinite(m1) && std::isfinite(m2) && std::isfinite(k1) && m1 > 0 &&
                      m2 > 0 && k1 > 0;
  if (!usable || !designFeasible(m1, m2)) return std::nullopt;
  return designKappa(m2 / m1, branch) * k1;
}

std::optional<double> k2ForFrequencyRatio(double m1, double m2, double k1, double ratio,
                                          Branch branch) {
  const bool usable = std::isfinite(m1) && std::isfinite(m2) && std::isfinite(k1) &&
                      std::isfinite(ratio) && m1 > 0 && m2 > 0 && k1 > 0 && ratio > 1;
  if (!usable) return std::nullopt;
  const double beta = m2 / m1;
  const double r2 = ratio * ratio;
  const double a = r2 * (1 + beta) * (1 + beta);
  const double b = 2 * r2 * beta * (1 + beta) - beta * (1 + r2) * (1 + r2);
  const double c = r2 * beta * beta;
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return std::nullopt;
  // the two roots multiply to c / a > 0 and add to -b / a: both positive when b < 0. The larger
  // is taken as -b + sqrt(D) (no cancellation); the smaller from the product.
  if (b >= 0) return std::nullopt;
  const double upper = (-b + std::sqrt(discriminant)) / (2 * a);
  const double lower = c / (a * upper);
  return (branch == Branch::Upper ? upper : lower) * k1;
}

template <typename S>
S resonanceDefect(const S& m1, const S& m2, const S& k1, const S& k2) {
  // D m1^2 k1^2 = 4 (m1 + m2)^2 k2^2 - m2 (17 m1 - 8 m2) k1 k2 + 4 m2^2 k1^2, and
  // D / beta^2 = that / (m2 k1)^2
  const cpp_rational a = exactly(m1), b = exactly(m2), c = exactly(k1), d = exactly(k2);
  const cpp_rational sum = a + b;
  const cpp_rational numerator = 4 * sum * sum * d * d - b * (17 * a - 8 * b) * c * d +
                                 4 * b * b * c * c;
  const cpp_rational scale = b * c;
  return rounded<S>(numerator / (scale * scale));
}

std::string_view toString(Branch branch) { return branch == Branch::Upper ? "upper" : "lower"; }

std::optional<Branch> parseBranch(std::string_view text) {
  if (text == "upper") return Branch::Upper;
  if (text == "lower") return Branch::Lower;
  return std::nullopt;
}

#define GRAZELAB_INSTANTIATE(S)                                  \
  template bool designFeasible<S>(const S&, const S&);           \
  template S designKappa<S>(const S&, Branch);                   \
  template S resonanceDefect<S>(const S&, const S&, const S&, const S&);
GRAZELAB_INSTANTIATE(double)
GRAZELAB_INSTANTIATE(long double)
GRAZELAB_INSTANTIATE(Quad)
#undef GRAZELAB_INSTANTIATE

}  // namespace grazelab::core
