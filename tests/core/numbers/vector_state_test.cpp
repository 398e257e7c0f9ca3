// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/numbers/vector_state.cpp: the upper halves of the AVX registers left dirty by
// code core does not control (a library's AVX code returning without vzeroupper) are clean again
// where core's hot loops begin, so that their SSE arithmetic runs at full speed. The state is
// read as the CPU reports it (XGETBV with ECX = 1: bit 2, the AVX state in use); on a CPU that
// cannot say, the tests are skipped.
#include "core/numbers/vector_state.h"

#include <gtest/gtest.h>

#include "core/model/model.h"
#include "core/solver/chain_run.h"
#include "support/cases.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#define GRAZELAB_X86_64 1
#endif

namespace grazelab::core {
namespace {

#ifdef GRAZELAB_X86_64
// the CPU has AVX, the system saves its registers (XCR0 bits 1 and 2), and the CPU reports
// which state components are in use (XGETBV with ECX = 1)
bool canSeeVectorState() {
#ifdef __AVX__
  return false;  // (a build for AVX: clearUpperVectorState does nothing, by design)
#else
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & bit_AVX) || !(c & bit_OSXSAVE)) return false;
  unsigned low = 0, high = 0;
  asm volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(0));
  if ((low & 6u) != 6u) return false;
  if (!__get_cpuid_count(0xd, 1, &a, &b, &c, &d)) return false;
  return (a & (1u << 2)) != 0;
#endif
}
bool upperHalvesDirty() {
  unsigned low = 0, high = 0;
  asm volatile("xgetbv" : "=a"(low), "=d"(high) : "c"(1));
  return (low & (1u << 2)) != 0;
}
// what a library's AVX code that returns without vzeroupper leaves behind (an AVX1 instruction:
// all ones in ymm8, whatever it held)
void dirtyUpperHalves() { asm volatile("vcmpps $15, %%ymm8, %%ymm8, %%ymm8" ::: "xmm8"); }
// the CPU reports a cleared state as clean (a CPU may report "in use" until the state is
// written back; then the tests cannot tell, and are skipped)
bool reportsCleanAfterClear() {
  clearUpperVectorState();
  return !upperHalvesDirty();
}
#else
bool canSeeVectorState() { return false; }
bool upperHalvesDirty() { return false; }
void dirtyUpperHalves() {}
#endif

TEST(VectorState, ClearedAfterAvxCode) {
  if (!canSeeVectorState() || !reportsCleanAfterClear()) GTEST_SKIP() << "this CPU does not report its AVX state";
  dirtyUpperHalves();
  if (!upperHalvesDirty()) GTEST_SKIP() << "this CPU does not report the AVX state in use";
  clearUpperVectorState();
  EXPECT_FALSE(upperHalvesDirty());
  clearUpperVectorState();  // twice: harmless on a clean state
  EXPECT_FALSE(upperHalvesDirty());
}

// An event's sink that runs AVX code (the command line's writer calls Qt's string functions)
// leaves the state dirty; the next contact is searched clean all the same, by the modal kernel
// (three masses, the certified search) and by the note's (its quartic).
TEST(VectorState, EveryContactIsSearchedClean) {
  if (!canSeeVectorState() || !reportsCleanAfterClear()) GTEST_SKIP() << "this CPU does not report its AVX state";
  const auto check = [](const ReadyChain& ready, const ChainState& start) {
    int events = 0, dirtyAtEvent = 0;
    const ChainEventSink<double> sink = [&](const ChainEvent&) {
      ++events;
      dirtyAtEvent += upperHalvesDirty() ? 1 : 0;
      dirtyUpperHalves();
    };
    clearUpperVectorState();
    runChain(ready, start, 50, 0.0, {}, sink);
    EXPECT_EQ(events, 50);
    EXPECT_EQ(dirtyAtEvent, 0);
  };
  const MassChain three{{1.0, 0.5, 0.25}, {1.0, 1.0, 1.0}, 0, 3, 1.0};
  check(readyChain(three), ChainState{Eigen::Vector3d(0.2, 0.5, 0.9), Eigen::Vector3d(0.1, -0.2, 0.6)});
  const Model notes = testing::resonantChain(0.5);
  check(readyChain(notes), ChainState{Eigen::Vector2d(0.3, 0.9), Eigen::Vector2d(0.05, 0.4)});
}

}  // namespace
}  // namespace grazelab::core
