// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QObject>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>

#include "ui/compute/sim_types.h"

namespace grazelab::ui {

/// The one-slot mailbox shared by the controller (GUI thread) and the worker (its own thread).
/// submit() overwrites the waiting request and stops the running one (or lets a young one
/// finish: SimController::setGrace); the worker takes the waiting request when it wakes. A burst
/// of values therefore runs a few jobs, not one per value.
struct SimMailbox {
  std::mutex mutex;
  std::optional<SimRequest> waiting;  ///< the newest request not yet started
  std::stop_source running;           ///< stop source of the job being run
  std::uint64_t runningId = 0;        ///< id of the job being run; 0 when the worker is idle
  std::chrono::steady_clock::time_point runningSince;  ///< when that job started
  /// that job's whole run has been sent: what it computes now (the error estimate, a sweep,
  /// a map) is of no use once a newer request exists, so it gets no grace
  bool runningRunSent = false;
};

/// Runs requests on the thread it lives on (see SimController). Stateless between jobs apart
/// from the shared mailbox; results leave as values through updated().
class SimWorker : public QObject {
  Q_OBJECT

 public:
  explicit SimWorker(std::shared_ptr<SimMailbox> mailbox);

  /// Takes the waiting request, if any, and runs it to its end or until it is stopped.
  void wake();

  /// Runs one request in chunks of about `chunkSeconds` of work and reports after each chunk
  /// (the caller decides where the reports go). Used by the worker and, synchronously, by the
  /// headless snapshot mode and the tests. `mapCache`: the maps computed before, whose last
  /// complete one is given again at once (none: every map is computed).
  static void run(const SimRequest& request, std::stop_token stop, double chunkSeconds,
                  const std::function<void(const SimUpdate&)>& report,
                  std::shared_ptr<core::experiments::MapCache> mapCache = nullptr);

 signals:
  void updated(const grazelab::ui::SimUpdate& update);

 private:
  std::shared_ptr<SimMailbox> m_mailbox;
  /// the maps this worker has computed: the last complete one is given again at once
  std::shared_ptr<core::experiments::MapCache> m_mapCache = std::make_shared<core::experiments::MapCache>();
};

}  // namespace grazelab::ui
