// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/sim_worker.h"

#include "parallel/tbb_parallel_for.h"

#include <utility>

namespace grazelab::ui {

SimWorker::SimWorker(std::shared_ptr<SimMailbox> mailbox) : m_mailbox(std::move(mailbox)) {}

void SimWorker::wake() {
  std::optional<SimRequest> request;
  std::stop_token stop;
  {
    const std::lock_guard lock(m_mailbox->mutex);
    if (!m_mailbox->waiting) return;  // an earlier wake-up already took it
    request = std::move(m_mailbox->waiting);
    m_mailbox->waiting.reset();
    m_mailbox->running = std::stop_source();
    m_mailbox->runningId = request->id;
    m_mailbox->runningSince = std::chrono::steady_clock::now();
    m_mailbox->runningRunSent = false;
    stop = m_mailbox->running.get_token();
  }
  const std::uint64_t id = request->id;
  run(*request, stop, 0.030, [this, id](const SimUpdate& update) {
    if (update.runDone) {
      const std::lock_guard lock(m_mailbox->mutex);
      if (m_mailbox->runningId == id) m_mailbox->runningRunSent = true;
    }
    emit updated(update);
  }, m_mapCache);
  const std::lock_guard lock(m_mailbox->mutex);
  if (m_mailbox->runningId == id) m_mailbox->runningId = 0;
}

void SimWorker::run(const SimRequest& described, std::stop_token stop, double chunkSeconds,
                    const std::function<void(const SimUpdate&)>& report,
                    std::shared_ptr<core::experiments::MapCache> mapCache) {
  // the scene's own computations first (curves, surveys, the start), here and not on the GUI
  // thread; what they give travels with every update
  SimRequest prepared = described;
  if (prepared.prepare) {
    // what the scene has so far goes out as it comes, with an empty run
    const auto partial = [&described, &report](const SceneJob& sofar, double progress) {
      auto request = std::make_shared<SimRequest>(described);
      request->prepare = nullptr;
      request->job = sofar;
      SimUpdate update;
      update.id = described.id;
      update.request = std::move(request);
      update.result = std::make_shared<const core::Result>();
      update.progress = progress;
      update.scenePartial = true;
      report(update);
    };
    prepared.job = prepared.prepare(stop, partial);
    prepared.prepare = nullptr;
  }
  const auto asked = std::make_shared<const SimRequest>(std::move(prepared));
  const auto stamped = [&asked](const core::experiments::Update& update) {
    SimUpdate sent;
    static_cast<core::experiments::Update&>(sent) = update;
    sent.id = asked->id;
    sent.request = asked;
    return sent;
  };
  if (!asked->job.ok || stop.stop_requested()) {
    // nothing to run: the final update says why (or that it was stopped before it began)
    auto nothing = std::make_shared<core::Result>();
    nothing->stop = stop.stop_requested() ? core::StopReason::Cancelled : core::StopReason::InvalidInput;
    nothing->message = asked->job.message.toStdString();
    core::experiments::Update last;
    last.progress = 1.0;
    last.final = true;
    last.result = std::move(nothing);
    report(stamped(last));
    return;
  }
  // then the experiment, by core's one function (the tests and benchmarks call it alike)
  core::experiments::Options options;
  options.chunkSeconds = chunkSeconds;
  options.parallelFor = parallel::tbbParallelFor(0);
  options.mapCache = std::move(mapCache);
  core::experiments::run(asked->job.spec, stop, options,
                         [&](const core::experiments::Update& update) { report(stamped(update)); });
}

}  // namespace grazelab::ui
