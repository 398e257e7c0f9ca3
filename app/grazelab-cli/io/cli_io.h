// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace grazelab::cli {

/// A chain's events as the Python module hands them to NumPy without a copy: packed rows of t,
/// the type in UCS-4 ('<U8'), then u1..uN, v1_pre..vN_pre and the stopped mass's vS_post, each
/// number rounded to double; in long double or binary128 also each number's decimal text, 2N + 2
/// a row, as the command line writes them. (See EventTableSink.)
struct ChainEventTable {
  std::size_t masses = 0;  ///< N
  int stopped = 0;         ///< S, 1-based
  std::size_t count = 0;   ///< rows
  std::vector<char> rows;  ///< count x rowBytes()
  std::vector<std::string> decimals;
  /// At most this many rows are kept: the next event sets `full` and calls `whenFull` (which
  /// stops the run) instead of growing the table without bound.
  std::size_t maxRows = std::size_t(-1);
  bool full = false;
  std::function<void()> whenFull;
  /// statistics only: the events are counted by the run's summary, kept nowhere (no bound on
  /// their number; the document's `events` null)
  bool discard = false;
  /// the bytes of a row: t, 8 letters, 2N + 1 numbers
  std::size_t rowBytes() const { return sizeof(double) + 8 * sizeof(char32_t) + (2 * masses + 1) * sizeof(double); }
};

/// Where a command writes. The command line: its output on stdout, its messages (notes,
/// progress, the line that says what a command wrote) on stderr. The Python module: its messages
/// into memory, progress to the caller (a typed command's outcome and refusal come back as values).
struct Io {
  std::FILE* out = stdout;
  std::FILE* messages = stderr;
  /// Progress of a long command: the fraction done (negative when not known) and one line
  /// that says where it is. May be called from any thread; optional.
  std::function<void(double fraction, const std::string& text)> progress;

  void reportProgress(double fraction, const std::string& text) const {
    if (progress) progress(fraction, text);
  }
};

}  // namespace grazelab::cli
