// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/compute/sim_controller.h"

#include <algorithm>

#include <QMetaObject>
#include <QTimer>

#include <chrono>

#include "ui/compute/sim_worker.h"

namespace grazelab::ui {

SimController::SimController(QObject* parent)
    : QObject(parent), m_mailbox(std::make_shared<SimMailbox>()) {
  static const int registered = qRegisterMetaType<grazelab::ui::SimUpdate>();
  Q_UNUSED(registered);
  m_worker = new SimWorker(m_mailbox);
  m_worker->moveToThread(&m_thread);
  connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
  connect(m_worker, &SimWorker::updated, this, &SimController::receive, Qt::QueuedConnection);
  m_thread.setObjectName(QStringLiteral("grazelab-sim"));
  m_thread.start();
}

SimController::~SimController() {
  // no signal may leave now: the window that listens is already half destroyed
  blockSignals(true);
  // stop the job, cut the way back, then let the thread run out its event queue and end:
  // the queued wake-ups find an empty mailbox and return at once
  cancel();
  disconnect(m_worker, nullptr, this, nullptr);
  m_thread.quit();
  m_thread.wait();
}

std::uint64_t SimController::submit(SimRequest request) {
  request.id = ++m_latestId;
  m_busy = true;
  if (m_synchronous) {
    SimWorker::run(request, {}, 1e9, [this](const SimUpdate& update) { receive(update); }, m_mapCache);
    return request.id;
  }
  int graceLeftMs = 0;
  std::uint64_t runningId = 0;
  {
    const std::lock_guard lock(m_mailbox->mutex);
    runningId = m_mailbox->runningId;
    if (runningId != 0) {
      const auto age = std::chrono::steady_clock::now() - m_mailbox->runningSince;
      graceLeftMs = m_mailbox->runningRunSent
                        ? 0
                        : m_graceMs - int(std::chrono::duration_cast<std::chrono::milliseconds>(age).count());
      if (graceLeftMs <= 0) m_mailbox->running.request_stop();
    }
    m_mailbox->waiting = std::move(request);
  }
  // a young job may finish (and be shown) while the new request waits; past the grace it stops
  if (runningId != 0 && graceLeftMs > 0) {
    QTimer::singleShot(graceLeftMs, this, [this, runningId] { stopIfSuperseded(runningId); });
  }
  QMetaObject::invokeMethod(m_worker, [worker = m_worker] { worker->wake(); }, Qt::QueuedConnection);
  return m_latestId;
}

void SimController::stopIfSuperseded(std::uint64_t id) {
  if (id == m_latestId) return;
  const std::lock_guard lock(m_mailbox->mutex);
  if (m_mailbox->runningId == id) m_mailbox->running.request_stop();
}

void SimController::cancel() {
  bool dropped = false;
  {
    const std::lock_guard lock(m_mailbox->mutex);
    dropped = m_mailbox->waiting.has_value() && m_mailbox->waiting->id == m_latestId;
    m_mailbox->waiting.reset();
    m_mailbox->running.request_stop();
  }
  if (dropped) {
    m_busy = false;
    emit idle();
  }
}

void SimController::receive(const SimUpdate& update) {
  if (update.id != m_latestId) {
    // stale: a newer request exists. Only a superseded job's whole run is shown (it ended
    // within its grace), never over a newer one's; what it would compute after (its error
    // estimate, a sweep) is not wanted: it stops.
    if (isWholeRun(update) && update.id > m_shownRunId) {
      m_shownRunId = update.id;
      m_shownId = std::max(m_shownId, update.id);
      stopIfSuperseded(update.id);
      SimUpdate shown = update;
      shown.superseded = true;
      emit updated(shown);
    } else if (isRunsSoFar(update) && update.id > m_shownRunId && update.id >= m_shownId) {
      // runs of N masses so far (each update carries them whole, not as a chunk): a drag over
      // a scene whose runs outlast the grace shows each one's beginning, not nothing
      m_shownId = update.id;
      SimUpdate shown = update;
      shown.superseded = true;
      emit updated(shown);
    }
    return;
  }
  m_shownId = update.id;
  if (update.final && !update.trustPending) m_busy = false;
  if (update.runDone && !update.chunk) m_shownRunId = update.id;
  if (!update.chunk) {
    m_run.reset();  // the final (whole) result, or a sweep's update that carries it
    emit updated(update);
    return;
  }
  if (!m_run || m_runId != update.id) {
    m_run = std::make_shared<core::Result>();
    m_runId = update.id;
  }
  m_run = appendChunkInPlace(std::move(m_run), *update.chunk);
  SimUpdate assembled = update;
  assembled.chunk.reset();
  assembled.result = m_run;
  emit updated(assembled);
}

bool isRunsSoFar(const SimUpdate& update) {
  return !update.runDone && !update.scenePartial && !update.chains.empty() &&
         std::none_of(update.chains.begin(), update.chains.end(), [](const auto& series) {
           return series->run.stop == core::StopReason::Cancelled;
         });
}

bool isWholeRun(const SimUpdate& update) {
  if (!update.runDone || update.chunk) return false;
  if (!update.chains.empty()) {
    return std::none_of(update.chains.begin(), update.chains.end(), [](const auto& series) {
      return series->run.stop == core::StopReason::Cancelled;
    });
  }
  return update.result && update.result->stop != core::StopReason::Cancelled &&
         update.result->stop != core::StopReason::InvalidInput;
}

void appendChunk(core::Result& run, const core::Result& chunk) {
  run.events.insert(run.events.end(), chunk.events.begin(), chunk.events.end());
  run.poincare.insert(run.poincare.end(), chunk.poincare.begin(), chunk.poincare.end());
  run.freeFlights.insert(run.freeFlights.end(), chunk.freeFlights.begin(), chunk.freeFlights.end());
  run.samples.insert(run.samples.end(), chunk.samples.begin(), chunk.samples.end());
  core::experiments::copyTotals(chunk, run);
}

namespace {

template <typename T>
bool hasRoom(const std::vector<T>& items, const std::vector<T>& more) {
  return items.size() + more.size() <= items.capacity();
}

// `items` with room for `more` and as many again (the copies are amortised: each item is
// copied a bounded number of times over a run)
template <typename T>
std::vector<T> roomyCopy(const std::vector<T>& items, const std::vector<T>& more) {
  std::vector<T> copy;
  copy.reserve(2 * (items.size() + more.size()));
  copy.assign(items.begin(), items.end());
  return copy;
}

}  // namespace

std::shared_ptr<core::Result> appendChunkInPlace(std::shared_ptr<core::Result> run,
                                                 const core::Result& chunk) {
  const bool room = hasRoom(run->events, chunk.events) && hasRoom(run->poincare, chunk.poincare) &&
                    hasRoom(run->freeFlights, chunk.freeFlights) &&
                    hasRoom(run->samples, chunk.samples);
  if (!room) {
    // a reader may hold `run` and read its items in place: they must not move
    auto grown = std::make_shared<core::Result>();
    grown->events = roomyCopy(run->events, chunk.events);
    grown->poincare = roomyCopy(run->poincare, chunk.poincare);
    grown->freeFlights = roomyCopy(run->freeFlights, chunk.freeFlights);
    grown->samples = roomyCopy(run->samples, chunk.samples);
    core::experiments::copyTotals(*run, *grown);
    run = std::move(grown);
  }
  // within capacity: past the end of what any reader was shown, nothing moves
  appendChunk(*run, chunk);
  return run;
}

}  // namespace grazelab::ui
