// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

namespace grazelab::core {

/// Marks the upper halves of the CPU's AVX registers clean (vzeroupper), on an x86-64 CPU that
/// has them, in a build for plain x86-64 by GCC or Clang; nothing elsewhere (a build for AVX
/// does not need it). Called where core's hot loops begin (each contact of a run, each
/// contact search, each method's run), because code it does not control may leave them dirty:
/// core is compiled for plain x86-64 (SSE), and after a library's AVX code returns without
/// vzeroupper every SSE instruction waits on those halves. Measured (docs/design.md, "Dirty
/// AVX state"): Qt 6.4's string functions leave them so (XGETBV(1) shows the AVX state in use
/// after QCommandLineParser has parsed), and the same 150 million instructions of an eight-mass
/// run took 130-160 ms in the command line against 22-30 ms in a benchmark without Qt. A clean
/// state costs the instruction nothing.
void clearUpperVectorState() noexcept;

}  // namespace grazelab::core
