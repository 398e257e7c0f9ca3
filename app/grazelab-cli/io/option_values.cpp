// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/option_values.h"

#include <QCommandLineParser>

namespace grazelab::cli {

OptionValues::OptionValues(const QCommandLineParser& parser) : m_parser(&parser) {}

OptionValues::OptionValues(std::vector<std::pair<QString, QString>> given)
    : m_given(std::move(given)) {}

bool OptionValues::isSet(const QString& name) const {
  if (m_parser) return m_parser->isSet(name);
  for (const auto& [key, text] : m_given) {
    if (key == name) return true;
  }
  return false;
}

QString OptionValues::value(const QString& name) const {
  if (m_parser) return m_parser->value(name);
  for (const auto& [key, text] : m_given) {
    if (key == name) return text;
  }
  return defaultOptionValue(name);
}

}  // namespace grazelab::cli
