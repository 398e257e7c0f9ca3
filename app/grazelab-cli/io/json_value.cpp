// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/json_value.h"

#include <utility>

#include "io/cli_output.h"

namespace grazelab::cli {

JsonValue JsonValue::of(bool value) {
  JsonValue out;
  out.kind = Kind::Bool;
  out.boolean = value;
  return out;
}

JsonValue JsonValue::of(std::int64_t value) {
  JsonValue out;
  out.kind = Kind::Integer;
  out.integer = value;
  return out;
}

JsonValue JsonValue::of(std::string text) {
  JsonValue out;
  out.kind = Kind::String;
  out.text = std::move(text);
  return out;
}

JsonValue JsonValue::array(std::vector<JsonValue> items) {
  JsonValue out;
  out.kind = Kind::Array;
  out.items = std::move(items);
  return out;
}

JsonValue JsonValue::array(std::initializer_list<JsonItem> items) {
  JsonValue out;
  out.kind = Kind::Array;
  out.items.reserve(items.size());
  for (const JsonItem& item : items) out.items.push_back(std::move(*item.value));
  return out;
}

JsonValue JsonValue::object(std::initializer_list<JsonMember> members) {
  JsonValue out;
  out.kind = Kind::Object;
  out.fields.reserve(members.size());
  for (const JsonMember& member : members) out.fields.emplace_back(member.key, std::move(*member.value));
  return out;
}

JsonValue JsonValue::object(std::vector<Field> fields) {
  JsonValue out;
  out.kind = Kind::Object;
  out.fields = std::move(fields);
  return out;
}

const JsonValue* JsonValue::find(std::string_view key) const {
  for (const Field& field : fields) {
    if (field.first.view() == key) return &field.second;
  }
  return nullptr;
}

JsonValue* JsonValue::find(std::string_view key) {
  return const_cast<JsonValue*>(std::as_const(*this).find(key));
}

void JsonValue::set(JsonKey key, JsonValue value) {
  if (JsonValue* existing = find(key.view())) {
    *existing = std::move(value);
    return;
  }
  fields.emplace_back(std::move(key), std::move(value));
}

void JsonValue::remove(std::string_view key) {
  std::erase_if(fields, [key](const Field& field) { return field.first.view() == key; });
}

double JsonValue::toDouble() const {
  if (kind == Kind::Number) return value;
  if (kind == Kind::Integer) return double(integer);
  return 0;
}

bool operator==(const JsonValue& a, const JsonValue& b) {
  using Kind = JsonValue::Kind;
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case Kind::Null: return true;
    case Kind::Bool: return a.boolean == b.boolean;
    case Kind::Integer: return a.integer == b.integer;
    case Kind::Number: return a.value == b.value && a.text == b.text;
    case Kind::String: return a.text == b.text;
    case Kind::Array: return a.items == b.items;
    case Kind::Object:
      if (a.fields.size() != b.fields.size()) return false;
      for (std::size_t i = 0; i < a.fields.size(); ++i) {
        if (a.fields[i].first.view() != b.fields[i].first.view() || !(a.fields[i].second == b.fields[i].second)) {
          return false;
        }
      }
      return true;
  }
  return false;
}

std::string JsonValue::numberText() const {
  return text.empty() ? core::formatScalar(value) : text;
}

bool JsonValue::holdsWideNumbers() const {
  if (kind == Kind::Number) return !text.empty();
  for (const JsonValue& item : items) {
    if (item.holdsWideNumbers()) return true;
  }
  for (const Field& field : fields) {
    if (field.second.holdsWideNumbers()) return true;
  }
  return false;
}

namespace {

void appendOneLine(std::string& out, const JsonValue& value) {
  switch (value.kind) {
    case JsonValue::Kind::Null: out += "null"; return;
    case JsonValue::Kind::Bool: out += value.boolean ? "true" : "false"; return;
    case JsonValue::Kind::Integer: out += std::to_string(value.integer); return;
    case JsonValue::Kind::Number: out += value.numberText(); return;
    case JsonValue::Kind::String: out += jsonQuoted(value.text); return;
    case JsonValue::Kind::Array: {
      out += '[';
      for (std::size_t i = 0; i < value.items.size(); ++i) {
        if (i > 0) out += ", ";
        appendOneLine(out, value.items[i]);
      }
      out += ']';
      return;
    }
    case JsonValue::Kind::Object: {
      out += '{';
      for (std::size_t i = 0; i < value.fields.size(); ++i) {
        if (i > 0) out += ", ";
        out += jsonQuoted(std::string(value.fields[i].first.view()));
        out += ": ";
        appendOneLine(out, value.fields[i].second);
      }
      out += '}';
      return;
    }
  }
}

}  // namespace

std::string oneLine(const JsonValue& value) {
  std::string out;
  appendOneLine(out, value);
  return out;
}

namespace {

void appendIndented(std::string& out, const JsonValue& value, const std::string& indent) {
  if (value.kind != JsonValue::Kind::Object || value.fields.empty()) {
    out += oneLine(value);
    return;
  }
  const std::string inner = indent + "  ";
  out += "{\n";
  for (std::size_t i = 0; i < value.fields.size(); ++i) {
    out += inner + jsonQuoted(std::string(value.fields[i].first.view())) + ": ";
    appendIndented(out, value.fields[i].second, inner);
    out += i + 1 < value.fields.size() ? ",\n" : "\n";
  }
  out += indent + "}";
}

}  // namespace

std::string indented(const JsonValue& document) {
  std::string out;
  appendIndented(out, document, "");
  return out + "\n";
}

std::string fieldPerLine(const JsonValue& object, const std::string& fieldIndent,
                         const std::string& closeIndent) {
  std::string out = "{\n";
  for (std::size_t i = 0; i < object.fields.size(); ++i) {
    out += fieldIndent + jsonQuoted(std::string(object.fields[i].first.view())) + ": ";
    appendOneLine(out, object.fields[i].second);
    out += i + 1 < object.fields.size() ? ",\n" : "\n";
  }
  return out + closeIndent + "}";
}

}  // namespace grazelab::cli
