// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>

namespace grazelab::core {

/// Smallest and largest chunk, in contacts, that chunked runs use.
inline constexpr std::int64_t kMinChunkContacts = 16;
inline constexpr std::int64_t kMaxChunkContacts = 50'000'000;

/// The next chunk size for a run done in pieces (BasicChainSimulator::advance) that should spend about
/// `targetSeconds` per piece: the last size scaled by target / measured, the change limited to
/// a factor 1/4 ... 8 per step (one slow or fast chunk must not swing it), and kept within
/// [kMinChunkContacts, kMaxChunkContacts]. `secondsTaken` below a microsecond counts as one.
std::int64_t nextChunkContacts(std::int64_t lastContacts, double secondsTaken,
                               double targetSeconds);

}  // namespace grazelab::core
