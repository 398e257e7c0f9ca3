// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>

#include <optional>

#include "io/json_value.h"

namespace grazelab::cli {

/// A JSON text read into the values the command line writes (Qt's parser reads it): whole
/// numbers below 2^53 as Integers, other numbers as Numbers, names owned. Nothing when the text
/// is not JSON.
std::optional<JsonValue> readJson(const QByteArray& text);

}  // namespace grazelab::cli
