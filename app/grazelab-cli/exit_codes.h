// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

namespace grazelab::cli {

/// Exit codes shared by the commands: 0 done; 2 invalid input (one line on stderr, nothing on
/// stdout); 130 interrupted (SIGINT, SIGTERM), the output ended cleanly. 1, a file that could
/// not be written, is spelled out where it happens.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInvalidInput = 2;
inline constexpr int kExitInterrupted = 130;

}  // namespace grazelab::cli
