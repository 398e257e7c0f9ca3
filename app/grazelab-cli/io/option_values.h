// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <utility>
#include <vector>

class QCommandLineParser;

namespace grazelab::cli {

/// The options of one command as its parsers read them: from a parsed command line, or given by
/// name (the Python module's direct calls, which skip the command line's text). Either way an
/// option not given reads as its default (addOptions'), so both reach the same numbers.
class OptionValues {
 public:
  /// The options of a parsed command line (implicit: every parser takes either).
  OptionValues(const QCommandLineParser& parser);  // NOLINT(google-explicit-constructor)
  /// Options by name without the dashes ("m1", "t-end"), each as its text.
  explicit OptionValues(std::vector<std::pair<QString, QString>> given);

  bool isSet(const QString& name) const;
  /// The text given, else the option's default, else empty.
  QString value(const QString& name) const;

 private:
  const QCommandLineParser* m_parser = nullptr;
  std::vector<std::pair<QString, QString>> m_given;
};

/// The default text of an option of `info` and `simulate` (empty when it has none).
QString defaultOptionValue(const QString& name);

}  // namespace grazelab::cli
