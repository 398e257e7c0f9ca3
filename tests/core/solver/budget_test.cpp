// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
// Tests for core/budget.cpp.
#include "core/solver/budget.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grazelab::core {
namespace {

TEST(Budget, ScalesTowardTheTarget) {
  EXPECT_EQ(nextChunkContacts(1000, 0.015, 0.030), 2000);  // twice as fast as wanted
  EXPECT_EQ(nextChunkContacts(1000, 0.060, 0.030), 500);
}

TEST(Budget, LimitsEachChange) {
  EXPECT_EQ(nextChunkContacts(1000, 1e-9, 0.030), 8000);  // at most 8 times more
  EXPECT_EQ(nextChunkContacts(1000, 10.0, 0.030), 250);   // at most 4 times less
}

TEST(Budget, StaysWithinBounds) {
  EXPECT_EQ(nextChunkContacts(20, 1.0, 0.030), kMinChunkContacts);
  EXPECT_EQ(nextChunkContacts(kMaxChunkContacts, 1e-6, 0.030), kMaxChunkContacts);
  EXPECT_EQ(nextChunkContacts(0, 0.03, 0.03), kMinChunkContacts);
}

TEST(Budget, NonsenseMeasurementsDoNotBreakIt) {
  EXPECT_EQ(nextChunkContacts(1000, std::nan(""), 0.030), 8000);
  EXPECT_EQ(nextChunkContacts(1000, 0.030, -1.0), 1000);
}

}  // namespace
}  // namespace grazelab::core
