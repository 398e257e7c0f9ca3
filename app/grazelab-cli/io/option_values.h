// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <boost/container/small_vector.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

class QCommandLineParser;

namespace grazelab::cli {

/// One option given by name (without the dashes: "m1", "t-end"): its text, or its numbers as
/// doubles (the Python module's direct calls: a Python float is the double its shortest decimal
/// text reads as in double, so reading it in double needs no text at all).
struct GivenOption {
  std::string name;
  QString text;
  boost::container::small_vector<double, 4> numbers;  ///< (a state's four without an allocation)
  bool numeric = false;  ///< given as `numbers`, not as `text`
};

/// The options of one command as its parsers read them: from a parsed command line, or given by
/// name (the Python module's direct calls, which skip the command line's text). Either way an
/// option not given reads as its default (addOptions'), so both reach the same numbers.
class OptionValues {
 public:
  /// The options of a parsed command line (implicit: every parser takes either).
  OptionValues(const QCommandLineParser& parser);  // NOLINT(google-explicit-constructor)
  /// Options by name, each as its text.
  explicit OptionValues(std::vector<std::pair<QString, QString>> given);
  /// Options by name, each as its text or its numbers.
  explicit OptionValues(std::vector<GivenOption> given);
  /// `base` (kept by reference: it must outlive this) with the options `given` added, each
  /// replacing base's of the same name, and the options named in `dropped` taken out.
  OptionValues(const OptionValues& base, std::vector<GivenOption> given, std::vector<std::string> dropped);

  bool isSet(const char* name) const { return isSet(std::string_view(name)); }
  bool isSet(std::string_view name) const;
  bool isSet(const QString& name) const;
  /// The text given, else the option's default, else empty. Numbers given as numbers read as
  /// their shortest decimal texts (the same numbers in any precision), joined by ','.
  QString value(const char* name) const { return value(std::string_view(name)); }
  QString value(std::string_view name) const;
  QString value(const QString& name) const;
  /// value() as UTF-8, without a QString on the way for numbers given as numbers (a start's
  /// description in a short run from Python).
  std::string text(std::string_view name) const;
  /// The numbers of an option given as numbers; none when it was given as text or not at all.
  std::optional<std::span<const double>> numbers(std::string_view name) const;

 private:
  const GivenOption* given(std::string_view name) const;
  /// the bits of the names in `m_given` (nameBit): a name whose bit is not among them was not
  /// given, told without a search (most names asked for are not: options at their defaults)
  static std::uint64_t nameBit(std::string_view name);
  void markGivenNames();

  bool dropped(std::string_view name) const;

  const QCommandLineParser* m_parser = nullptr;
  const OptionValues* m_base = nullptr;
  std::vector<GivenOption> m_given;
  std::vector<std::string> m_dropped;
  std::uint64_t m_givenNames = 0;
};

/// The default text of an option of `info` and `simulate` (empty when it has none).
QString defaultOptionValue(std::string_view name);
QString defaultOptionValue(const QString& name);

/// A double as the shortest decimal text that reads back as it (as Python's repr), whole
/// numbers below 2^53 without a fraction or exponent (as the Python module writes them).
std::string shortestText(double value);

}  // namespace grazelab::cli
