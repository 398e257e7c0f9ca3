// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/option_values.h"

#include <QCommandLineParser>

#include <charconv>
#include <cmath>

namespace grazelab::cli {

namespace {

// numbers given as numbers as their text: their shortest decimal texts joined by ','
std::string joinedNumbers(const GivenOption& option) {
  std::string joined;
  joined.reserve(option.numbers.size() * 8);
  for (std::size_t i = 0; i < option.numbers.size(); ++i) {
    if (i > 0) joined += ',';
    joined += shortestText(option.numbers[i]);
  }
  return joined;
}

}  // namespace

OptionValues::OptionValues(const QCommandLineParser& parser) : m_parser(&parser) {}

OptionValues::OptionValues(std::vector<std::pair<QString, QString>> given) {
  m_given.reserve(given.size());
  for (auto& [name, text] : given) m_given.push_back({name.toStdString(), std::move(text), {}, false});
  markGivenNames();
}

OptionValues::OptionValues(std::vector<GivenOption> given) : m_given(std::move(given)) { markGivenNames(); }

OptionValues::OptionValues(const OptionValues& base, std::vector<GivenOption> given, std::vector<std::string> dropped)
    : m_base(&base), m_given(std::move(given)), m_dropped(std::move(dropped)) {
  markGivenNames();
}

std::uint64_t OptionValues::nameBit(std::string_view name) {
  const unsigned first = name.empty() ? 0U : static_cast<unsigned char>(name.front());
  const unsigned last = name.empty() ? 0U : static_cast<unsigned char>(name.back());
  return std::uint64_t(1) << ((name.size() * 7 + first * 3 + last) & 63U);
}

void OptionValues::markGivenNames() {
  for (const GivenOption& option : m_given) m_givenNames |= nameBit(option.name);
}

bool OptionValues::dropped(std::string_view name) const {
  for (const std::string& gone : m_dropped) {
    if (gone == name) return true;
  }
  return false;
}

const GivenOption* OptionValues::given(std::string_view name) const {
  if ((m_givenNames & nameBit(name)) == 0) return nullptr;
  for (const GivenOption& option : m_given) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

bool OptionValues::isSet(std::string_view name) const {
  if (m_parser) return m_parser->isSet(QString::fromUtf8(name.data(), qsizetype(name.size())));
  if (given(name)) return true;
  return m_base && !dropped(name) && m_base->isSet(name);
}

bool OptionValues::isSet(const QString& name) const {
  if (m_parser) return m_parser->isSet(name);
  return isSet(std::string_view(name.toStdString()));
}

QString OptionValues::value(std::string_view name) const {
  if (m_parser) return m_parser->value(QString::fromUtf8(name.data(), qsizetype(name.size())));
  const GivenOption* option = given(name);
  if (!option && m_base && !dropped(name)) return m_base->value(name);
  if (!option) return defaultOptionValue(name);
  if (!option->numeric) return option->text;
  return QString::fromStdString(joinedNumbers(*option));
}

std::string OptionValues::text(std::string_view name) const {
  const GivenOption* option = m_parser ? nullptr : given(name);
  if (!option || !option->numeric) return value(name).toStdString();
  return joinedNumbers(*option);
}

QString OptionValues::value(const QString& name) const {
  if (m_parser) return m_parser->value(name);
  return value(std::string_view(name.toStdString()));
}

std::optional<std::span<const double>> OptionValues::numbers(std::string_view name) const {
  if (m_parser) return std::nullopt;
  const GivenOption* option = given(name);
  if (!option && m_base && !dropped(name)) return m_base->numbers(name);
  if (!option || !option->numeric) return std::nullopt;
  return std::span<const double>(option->numbers.data(), option->numbers.size());
}

QString defaultOptionValue(const QString& name) { return defaultOptionValue(std::string_view(name.toStdString())); }

std::string shortestText(double value) {
  char text[32];
  if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 0x1p53) {
    return std::to_string(static_cast<long long>(value));
  }
  const auto written = std::to_chars(text, text + sizeof text, value);
  return std::string(text, written.ptr);
}

}  // namespace grazelab::cli
