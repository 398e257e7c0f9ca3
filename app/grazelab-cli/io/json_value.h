// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/numbers/scalar.h"

namespace grazelab::cli {

/// A JSON document as values: what a command reports, built once and then written as the
/// command line's text or handed to Python as objects (python/native_module.cpp), so that the
/// two never differ. Numbers keep their precision: the value rounded to double, and, for a run
/// in long double or binary128, the decimal text of that precision.
struct JsonValue {
  enum class Kind { Null, Bool, Integer, Number, String, Array, Object };
  using Field = std::pair<std::string, JsonValue>;

  Kind kind = Kind::Null;
  bool boolean = false;
  std::int64_t integer = 0;
  double value = 0;    ///< Number: the value (rounded to double)
  std::string text;    ///< Number: its decimal text when wider than double (else empty); String
  std::vector<JsonValue> items;
  std::vector<Field> fields;

  static JsonValue null() { return {}; }
  static JsonValue of(bool value);
  static JsonValue of(std::int64_t value);
  static JsonValue of(std::string text);
  static JsonValue of(const char* text) { return of(std::string(text)); }
  /// A number of precision S; null when it is not finite (as the command line writes it).
  template <typename S>
  static JsonValue number(const S& value) {
    if (!core::isFinite(value)) return null();
    JsonValue out;
    out.kind = Kind::Number;
    out.value = core::toDouble(value);
    if constexpr (!std::is_same_v<S, double>) out.text = core::formatScalar(value);
    return out;
  }
  static JsonValue array(std::vector<JsonValue> items);
  static JsonValue object(std::vector<Field> fields);

  /// The decimal text of a Number, in its precision.
  std::string numberText() const;
  /// Whether some number in it is wider than double (a run in long double or binary128).
  bool holdsWideNumbers() const;
};

/// On one line: {"a": 1, "b": [1, 2], "c": "text"} (the command line's layout for all but the
/// outermost objects).
std::string oneLine(const JsonValue& value);

/// An object with a field per line, each after `fieldIndent`, the closing brace after
/// `closeIndent`; fields on one line each.
std::string fieldPerLine(const JsonValue& object, const std::string& fieldIndent,
                         const std::string& closeIndent);

}  // namespace grazelab::cli
