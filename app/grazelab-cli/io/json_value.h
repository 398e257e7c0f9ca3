// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/numbers/scalar.h"

namespace grazelab::cli {

struct JsonMember;
struct JsonItem;

/// A field's name. Names are the code's own string literals, kept as their address (no copy:
/// a document has ~50 of them; and the Python module makes each into a str once); a name made at
/// run time is owned (JsonKey::owned).
class JsonKey {
 public:
  /// A string literal (never a char array that changes or goes away); its length to its first
  /// NUL (folded at compile time for a literal).
  template <std::size_t N>
  JsonKey(const char (&literal)[N])  // NOLINT(google-explicit-constructor)
      : m_literal(literal), m_size(std::char_traits<char>::length(literal)) {}
  static JsonKey owned(std::string name) {
    JsonKey key;
    key.m_owned = std::make_shared<const std::string>(std::move(name));
    return key;
  }
  std::string_view view() const { return m_literal ? std::string_view(m_literal, m_size) : std::string_view(*m_owned); }
  /// The literal's address, or null for an owned name.
  const char* literal() const { return m_literal; }
  bool operator==(std::string_view other) const { return view() == other; }

 private:
  JsonKey() = default;
  const char* m_literal = nullptr;
  std::size_t m_size = 0;
  std::shared_ptr<const std::string> m_owned;  // (shared: a key is copied, and rarely owned)
};

/// A JSON document as values: what a command reports, built once and then written as the
/// command line's text or handed to Python as objects (python/native_module.cpp), so that the
/// two never differ. Numbers keep their precision: the value rounded to double, and, for a run
/// in long double or binary128, the decimal text of that precision.
struct JsonValue {
  enum class Kind { Null, Bool, Integer, Number, String, Array, Object };
  using Field = std::pair<JsonKey, JsonValue>;

  Kind kind = Kind::Null;
  // one of them, by kind (a document is built and dropped for every short run: kept small)
  union {
    double value = 0;      ///< Number: the value (rounded to double)
    bool boolean;          ///< Bool
    std::int64_t integer;  ///< Integer
  };
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
  static JsonValue array(std::initializer_list<JsonItem> items);
  static JsonValue object(std::vector<Field> fields);
  static JsonValue object(std::initializer_list<JsonMember> members);

  /// An object's field named `key`; null when there is none (or this is not an object).
  const JsonValue* find(std::string_view key) const;
  JsonValue* find(std::string_view key);
  /// Sets an object's field: replaced where it is, else added at the end.
  void set(JsonKey key, JsonValue value);
  /// Removes an object's field, if there is one.
  void remove(std::string_view key);
  /// A Number's or an Integer's value as a double (0 for any other kind).
  double toDouble() const;
  /// The same document: kinds, values, texts, items and fields in order (names compared as text).
  friend bool operator==(const JsonValue& a, const JsonValue& b);

  /// The decimal text of a Number, in its precision.
  std::string numberText() const;
  /// Whether some number in it is wider than double (a run in long double or binary128).
  bool holdsWideNumbers() const;
};

/// An element of a braced list: {"t", value} in an object, value in an array. It refers to its
/// key and value, temporaries of the full-expression that calls object() or array(), which live
/// until that call returns; the value is moved into the document once, so that building a
/// nested document copies no subtree (an initializer_list's elements themselves are const).
/// Never kept beyond that call.
struct JsonMember {
  JsonMember(JsonKey name, JsonValue&& v) : key(std::move(name)), value(&v) {}
  JsonKey key;
  JsonValue* value;
};
struct JsonItem {
  JsonItem(JsonValue&& v) : value(&v) {}  // NOLINT(google-explicit-constructor)
  JsonValue* value;
};

/// On one line: {"a": 1, "b": [1, 2], "c": "text"} (the command line's layout for all but the
/// outermost objects).
std::string oneLine(const JsonValue& value);

/// An object with a field per line, each after `fieldIndent`, the closing brace after
/// `closeIndent`; fields on one line each.
std::string fieldPerLine(const JsonValue& object, const std::string& fieldIndent,
                         const std::string& closeIndent);

/// A whole document for a file: objects a field per line, nested objects indented by two
/// spaces a level, arrays on one line.
std::string indented(const JsonValue& document);

}  // namespace grazelab::cli
