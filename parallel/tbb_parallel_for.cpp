// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "parallel/tbb_parallel_for.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <memory>

namespace grazelab::parallel {

core::ParallelFor tbbParallelFor(int threads) {
  // one arena per executor, shared by its copies: its threads are made once, not per loop
  auto arena = threads > 0 ? std::make_shared<tbb::task_arena>(threads)
                           : std::make_shared<tbb::task_arena>();
  return [arena](std::int64_t count, const std::function<void(std::int64_t, std::int64_t)>& body) {
    arena->execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, count),
                        [&](const tbb::blocked_range<std::int64_t>& range) {
                          body(range.begin(), range.end());
                        });
    });
  };
}

int defaultThreadCount() { return tbb::info::default_concurrency(); }

}  // namespace grazelab::parallel
