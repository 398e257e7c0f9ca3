// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

namespace grazelab::ui {

/// Shows every plain-text tooltip of the application as a wrapped paragraph (Qt draws a plain
/// text tooltip on one line: some of ours were 1400 px wide). Installs one event filter on the
/// application, once; safe to call again.
void wrapToolTips();

}  // namespace grazelab::ui
