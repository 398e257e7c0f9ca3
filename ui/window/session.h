// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

#include "core/solver/chain_flight.h"
#include "ui/compute/params.h"

namespace grazelab::ui {

/// What reproduces a view: the scene, its parameters and, when the run was started with the
/// mouse, that start. Saved as JSON:
///   {"format": "grazelab-session", "version": 1, "scene": NAME, "params": {...},
///    "start": {"u1": ..., "u2": ..., "v1": ..., "v2": ...}}   (start only when clicked; a
///    chain of N masses has u1 ... uN and v1 ... vN)
/// Numbers are written in their shortest round-trip form, so a start reads back bit for bit.
struct Session {
  QString scene;  ///< Scene::name()
  Params params;
  std::optional<core::ChainState> start;  ///< a clicked start, in place of the scene's own
};

QByteArray sessionToJson(const Session& session);
/// Parses a session; missing parameters take `defaults`. Sets `error` and returns nothing on a
/// malformed file.
std::optional<Session> sessionFromJson(const QByteArray& json, const Params& defaults,
                                       QString* error);

/// Reads and parses a session file; sets `error` ("cannot read ..." or "PATH: why") and returns
/// nothing when it cannot.
std::optional<Session> readSessionFile(const QString& path, const Params& defaults,
                                       QString* error);

/// The session file written beside a snapshot: "plot.png" -> "plot.session.json".
QString sessionPathFor(const QString& snapshotPath);
/// The session in one line of words, for a document's title and a CSV's header
/// ("GrazeLab: Grazing family GLO_lambda (λ = 0.5, δ = -0.05, m₁ = 1, …, 60 contacts)").
QString sessionTitle(const Session& session, bool massChain = false);

}  // namespace grazelab::ui
