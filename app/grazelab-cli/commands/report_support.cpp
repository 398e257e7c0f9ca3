// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "commands/report_support.h"

#include <QCoreApplication>
#include <QDir>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QSaveFile>

namespace grazelab::cli {

QString scientific(double value, int digits) {
  if (!std::isfinite(value)) return {};
  return QString::number(value, 'e', digits - 1);
}

QString humanSeconds(double seconds) {
  if (seconds < 1e-3) return QString::number(seconds * 1e3, 'g', 2) + " ms";
  if (seconds < 1) return QString::number(seconds * 1e3, 'g', 3) + " ms";
  return QString::number(seconds, 'g', 3) + " s";
}

std::optional<std::vector<core::methods::MethodKind>> parseMethodsOption(
    const OptionValues& options, QString& error) {
  using core::methods::MethodKind;
  std::vector<MethodKind> methods;
  if (!options.isSet("methods")) {
    methods.assign(std::begin(core::methods::kAllMethods), std::end(core::methods::kAllMethods));
    return methods;
  }
  QStringList known;
  for (MethodKind kind : core::methods::kAllMethods) {
    known << QString::fromUtf8(core::methods::methodName(kind).data(),
                               qsizetype(core::methods::methodName(kind).size()));
  }
  for (const QString& name : options.value("methods").split(',', Qt::SkipEmptyParts)) {
    const auto kind = core::methods::parseMethod(name.trimmed().toStdString());
    if (!kind) {
      error = QStringLiteral("--methods: '%1' is not a method (one of %2)").arg(name, known.join(", "));
      return std::nullopt;
    }
    if (std::find(methods.begin(), methods.end(), *kind) == methods.end()) methods.push_back(*kind);
  }
  if (methods.empty()) {
    error = QStringLiteral("--methods: name at least one of %1").arg(known.join(", "));
    return std::nullopt;
  }
  return methods;
}

std::optional<QString> prepareOutputDirectory(const OptionValues& options, QString& error) {
  if (!options.isSet("out") || options.value("out").isEmpty()) {
    error = "--out DIR is required: the directory the files are written to";
    return std::nullopt;
  }
  const QString path = options.value("out");
  const QFileInfo info(path);
  if (info.exists() && !info.isDir()) {
    error = QStringLiteral("--out: '%1' exists and is not a directory").arg(path);
    return std::nullopt;
  }
  if (!QDir().mkpath(path)) {
    error = QStringLiteral("--out: cannot create the directory '%1'").arg(path);
    return std::nullopt;
  }
  return QDir(path).absolutePath();
}

bool writeAtomically(const QString& path, const QByteArray& bytes, QString& error) {
  QSaveFile file(path);
  if (file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.commit()) {
    return true;
  }
  error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
  return false;
}

void progress(const Io& io, const char* command, const QString& text, double fraction) {
  std::fprintf(io.messages, "grazelab-cli %s: %s\n", command, qPrintable(text));
  std::fflush(io.messages);
  io.reportProgress(fraction, text.toStdString());
}

QString versionString() {
  return QStringLiteral("GrazeLab %1").arg(QCoreApplication::applicationVersion());
}

}  // namespace grazelab::cli
