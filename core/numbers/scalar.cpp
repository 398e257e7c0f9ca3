// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/numbers/scalar.h"

#include <quadmath.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>

namespace grazelab::core {
namespace {

// strtod and its siblings, chosen by type
double readNumber(const char* text, char** end, double*) { return std::strtod(text, end); }
long double readNumber(const char* text, char** end, long double*) {
  return std::strtold(text, end);
}
Quad readNumber(const char* text, char** end, Quad*) { return Quad(strtoflt128(text, end)); }

bool mentionsNonzeroDigit(std::string_view mantissa) {
  for (char c : mantissa) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

}  // namespace

std::string_view toString(Precision precision) {
  switch (precision) {
    case Precision::Double:
      return "double";
    case Precision::Long:
      return "long";
    case Precision::Quad:
      return "quad";
  }
  return "double";
}

std::optional<Precision> parsePrecision(std::string_view text) {
  for (Precision precision : {Precision::Double, Precision::Long, Precision::Quad}) {
    if (toString(precision) == text) return precision;
  }
  return std::nullopt;
}

template <typename S>
ParsedScalar<S> parseScalar(std::string_view text) {
  // trim; strto* would skip leading blanks but not trailing ones
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (text.empty()) return {std::nullopt, "is empty, not a number"};
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  const S value = readNumber(copy.c_str(), &end, static_cast<S*>(nullptr));
  if (end != copy.c_str() + copy.size()) return {std::nullopt, "is not a number"};
  const std::string lower = [&] {
    std::string out;
    for (char c : copy) out += char(std::tolower(static_cast<unsigned char>(c)));
    return out;
  }();
  const bool spelledNonFinite = lower.find("inf") != std::string::npos ||
                                lower.find("nan") != std::string::npos;
  if (!spelledNonFinite && !isFinite(value)) {
    return {std::nullopt, "is out of range (too large for " +
                              std::string(toString(precisionOf<S>())) + " precision)"};
  }
  if (value == 0 && mentionsNonzeroDigit(lower)) {
    return {std::nullopt, "is out of range (too small: it would be read as 0)"};
  }
  return {value, {}};
}

template <typename S>
std::string formatScalar(S value) {
  if constexpr (std::is_same_v<S, Quad>) {
    char buffer[64];
    quadmath_snprintf(buffer, sizeof buffer, "%.36Qg", value.backend().value());
    return buffer;
  } else {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
  }
}

template ParsedScalar<double> parseScalar<double>(std::string_view);
template ParsedScalar<long double> parseScalar<long double>(std::string_view);
template ParsedScalar<Quad> parseScalar<Quad>(std::string_view);
template std::string formatScalar<double>(double);
template std::string formatScalar<long double>(long double);
template std::string formatScalar<Quad>(Quad);

}  // namespace grazelab::core
