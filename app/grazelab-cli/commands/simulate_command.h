// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QString>

#include <stop_token>

#include "io/cli_input.h"
#include "io/cli_io.h"
#include "core/solver/trust.h"
#include "io/option_values.h"

namespace grazelab::cli {

/// `grazelab-cli simulate` (docs/design.md "Command line"): the run streamed to io.out in its
/// format, in the precision asked for or, with auto, raised from its input to long double and
/// binary128 where a contact needs it. Exit 0; 2 on invalid input (`error`, nothing on stdout);
/// 130 when `stop` ended it (the output closed with complete records).
int runSimulate(const OptionValues& options, const PrecisionOption& precision,
                core::TrustMode trust, const Io& io, std::stop_token stop, QString& error);

}  // namespace grazelab::cli
