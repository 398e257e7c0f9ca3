// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace grazelab::cli {

/// A 2-D array in NumPy's .npy format (version 1.0, C order, little endian): float64 ('<f8')
/// or int64 ('<i8'). NumPy (numpy.load), Julia (NPZ.jl) and MATLAB (readNPY) read it as is.
struct NpyArray {
  bool integer = false;       ///< '<i8' when true, '<f8' otherwise
  std::int64_t rows = 0;
  std::int64_t columns = 0;
  std::vector<double> reals;           ///< rows x columns, when !integer
  std::vector<std::int64_t> integers;  ///< rows x columns, when integer
};

/// The bytes of the file: the header (padded to 64 bytes, ending in '\n') and the data.
QByteArray encodeNpy(const NpyArray& array);

/// Reads what encodeNpy wrote (2-D, '<f8' or '<i8', C order); nothing and a reason otherwise.
std::optional<NpyArray> decodeNpy(const QByteArray& bytes, QString& error);

}  // namespace grazelab::cli
