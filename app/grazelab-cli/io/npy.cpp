// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "io/npy.h"

#include <QRegularExpression>

#include <bit>
#include <cstring>

namespace grazelab::cli {
namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr int kMagicSize = 6;
static_assert(std::endian::native == std::endian::little, ".npy files are written little endian");

}  // namespace

QByteArray encodeNpy(const NpyArray& array) {
  QByteArray header = QStringLiteral("{'descr': '%1', 'fortran_order': False, 'shape': (%2, %3), }")
                          .arg(array.integer ? "<i8" : "<f8")
                          .arg(array.rows)
                          .arg(array.columns)
                          .toLatin1();
  // magic (6) + version (2) + header length (2) + header, padded with spaces to 64 bytes
  const int unpadded = kMagicSize + 2 + 2 + header.size() + 1;
  header += QByteArray((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  QByteArray bytes(kMagic, kMagicSize);
  bytes += char(1);
  bytes += char(0);
  bytes += char(header.size() & 0xff);
  bytes += char((header.size() >> 8) & 0xff);
  bytes += header;
  const std::size_t count = std::size_t(array.rows * array.columns);
  const char* data = array.integer ? reinterpret_cast<const char*>(array.integers.data())
                                   : reinterpret_cast<const char*>(array.reals.data());
  if (count > 0) bytes.append(data, qsizetype(count * 8));
  return bytes;
}

std::optional<NpyArray> decodeNpy(const QByteArray& bytes, QString& error) {
  if (bytes.size() < 10 || std::memcmp(bytes.constData(), kMagic, kMagicSize) != 0) {
    error = "not a .npy file";
    return std::nullopt;
  }
  if (bytes[6] != 1) {
    error = "a .npy version other than 1.0";
    return std::nullopt;
  }
  const int headerSize = int(std::uint8_t(bytes[8])) | (int(std::uint8_t(bytes[9])) << 8);
  if (bytes.size() < 10 + headerSize) {
    error = "a truncated .npy header";
    return std::nullopt;
  }
  const QString header = QString::fromLatin1(bytes.mid(10, headerSize));
  static const QRegularExpression pattern(
      R"(^\{'descr': '(<f8|<i8)', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \}\s*$)");
  const QRegularExpressionMatch match = pattern.match(header);
  if (!match.hasMatch()) {
    error = "a .npy header other than a 2-D float64 or int64 array in C order: " + header.trimmed();
    return std::nullopt;
  }
  NpyArray array;
  array.integer = match.captured(1) == "<i8";
  array.rows = match.captured(2).toLongLong();
  array.columns = match.captured(3).toLongLong();
  const std::size_t count = std::size_t(array.rows * array.columns);
  if (std::size_t(bytes.size() - 10 - headerSize) != count * 8) {
    error = QStringLiteral("%1 data bytes where the shape needs %2").arg(bytes.size() - 10 - headerSize).arg(count * 8);
    return std::nullopt;
  }
  const char* data = bytes.constData() + 10 + headerSize;
  if (count == 0) return array;  // an empty stripe: no data (and memcpy takes no null pointer)
  if (array.integer) {
    array.integers.resize(count);
    std::memcpy(array.integers.data(), data, count * 8);
  } else {
    array.reals.resize(count);
    std::memcpy(array.reals.data(), data, count * 8);
  }
  return array;
}

}  // namespace grazelab::cli
