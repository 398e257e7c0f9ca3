// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QObject>
#include <QThread>

#include <cstdint>
#include <memory>

#include "ui/compute/sim_types.h"

namespace grazelab::ui {

class SimWorker;
struct SimMailbox;

/// Runs simulations off the GUI thread, latest wins.
///
/// Threading model: the controller lives on the GUI thread and owns a QThread; the worker has
/// no parent and is moved to that thread (deleted by deleteLater when the thread finishes).
/// submit() stamps the request with an increasing id, stops the running job through its
/// std::stop_source (safe from any thread), puts the request in a one-slot mailbox and queues a
/// wake-up for the worker. Updates come back by queued signal; any whose id is not the latest
/// are dropped here, so the display only ever sees the newest request's results, with one
/// exception that keeps a drag alive: a running job younger than the grace is not stopped at
/// once but given the rest of the grace to finish, and its whole run is shown, marked
/// superseded, while the newest request computes (runs of N masses, which report their runs
/// whole so far, show them as they come too). Without it a drag whose every value costs
/// more than the time between two values would show nothing until the mouse stops. Partial
/// updates bring only what is new (SimUpdate::chunk): the controller keeps the run so far and
/// appends each chunk to it, so a run of n contacts costs O(n) to hand over, not O(n^2).
class SimController : public QObject {
  Q_OBJECT

 public:
  explicit SimController(QObject* parent = nullptr);
  /// Cancels, stops the thread and waits for it: a running QThread must not be destroyed.
  ~SimController() override;

  /// When synchronous, submit() runs the request on the calling thread before returning
  /// (headless snapshots, benchmarks of the pure compute time).
  void setSynchronous(bool synchronous) { m_synchronous = synchronous; }
  bool synchronous() const { return m_synchronous; }

  /// Queues a request (its id is overwritten) and returns the id given to it.
  std::uint64_t submit(SimRequest request);
  /// Stops the running request; its partial result still arrives, marked final and cancelled.
  void cancel();

  std::uint64_t latestId() const { return m_latestId; }
  /// How long a running job may go on after a newer request came (from its own start): a job
  /// that ends within it is shown (superseded), one that does not is stopped then. Default
  /// kDefaultGraceMs; 0 stops every superseded job at once.
  void setGrace(int milliseconds) { m_graceMs = milliseconds; }
  /// Two frames of the 33 ms budget: a drag then shows a result at least every ~40 ms plus
  /// one job's cost, while a long job (a 10^6-contact run) is stopped as early as before.
  static constexpr int kDefaultGraceMs = 40;
  bool busy() const { return m_busy; }

 signals:
  /// An update of the latest request (partial or final).
  void updated(const grazelab::ui::SimUpdate& update);
  /// cancel() dropped a request before it started: nothing more will arrive for it.
  void idle();

 private:
  void receive(const SimUpdate& update);
  /// Stops job `id` if it is still the one running and a newer request exists.
  void stopIfSuperseded(std::uint64_t id);

  QThread m_thread;
  SimWorker* m_worker = nullptr;
  /// the maps computed when synchronous (the worker keeps its own otherwise)
  std::shared_ptr<core::experiments::MapCache> m_mapCache = std::make_shared<core::experiments::MapCache>();
  std::shared_ptr<SimMailbox> m_mailbox;
  std::uint64_t m_latestId = 0;
  /// the newest request whose whole run was handed on (superseded or not): an older one that
  /// ends later is never shown over it
  std::uint64_t m_shownRunId = 0;
  /// the newest request any update was handed on for: an older job's runs so far are never
  /// shown over it
  std::uint64_t m_shownId = 0;
  int m_graceMs = kDefaultGraceMs;
  /// the run so far of request m_runId, grown by each partial update, dropped at the final.
  /// Views read its items in place (no copy of a run): it grows only into room it already
  /// has (appendChunkInPlace), so nothing a view holds moves.
  std::shared_ptr<core::Result> m_run;
  std::uint64_t m_runId = 0;
  bool m_busy = false;
  bool m_synchronous = false;
};

/// Whether the update carries a whole run, not stopped nor refused (what a superseded job
/// shows): the two-mass run, or every run of N masses so far.
bool isWholeRun(const SimUpdate& update);
/// Whether the update carries runs of N masses as far as they have gone, none stopped (what a
/// superseded job shows too: each such update holds its runs whole so far, not a chunk).
bool isRunsSoFar(const SimUpdate& update);

/// Appends a partial update's chunk (new items and present totals) to the run so far.
void appendChunk(core::Result& run, const core::Result& chunk);

/// Appends `chunk` to `run` without moving any item already in it, for readers that hold the
/// run and read its items where they are: when an item list has no room left for the chunk,
/// the run is copied into a new one with room to grow (the readers keep the old one, intact,
/// until they take the new one). Returns the run that holds the chunk.
std::shared_ptr<core::Result> appendChunkInPlace(std::shared_ptr<core::Result> run,
                                                 const core::Result& chunk);

}  // namespace grazelab::ui
