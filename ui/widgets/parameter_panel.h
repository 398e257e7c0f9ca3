// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QMap>
#include <QWidget>

#include <optional>

#include <map>
#include <utility>

#include "core/solver/chain_flight.h"
#include "ui/compute/params.h"

class QBoxLayout;
class QCheckBox;
class QComboBox;
class QLabel;

namespace grazelab::ui {

class ChainEditor;
class Scene;
class SliderSpin;

/// The editable parameters: slider + spin box pairs, the 1:2 design switch and branch, the
/// perturbation direction, the feasible mass-ratio range and a plain message when the values
/// admit no chain. It only edits a Params value; the window decides what to compute.
class ParameterPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ParameterPanel(QWidget* parent = nullptr);

  /// Shows the parameters the scene exposes and hides the others.
  void setScene(const Scene& scene);
  /// Shows these values without emitting paramsChanged.
  void setParams(const Params& params);
  /// The slider ends that depend on the chain (SceneJob::sliderRanges); others keep their spec.
  void setSliderRanges(const std::map<ParamKey, std::pair<double, double>>& ranges);
  const Params& params() const { return m_params; }

  /// Says that a run starts from a clicked state (nothing: the scene's own start again).
  void setClickedStart(const std::optional<core::ChainState>& start);
  QString clickedStartText() const;
  /// Notes on the start the run uses (a push lost in rounding); empty hides them.
  void setNotes(const QStringList& notes);
  QString notes() const;

  /// A plain-words problem with the current values (empty hides it).
  void setMessage(const QString& message);
  QString message() const;
  /// Why the last typed value was refused, until a value is taken (empty when none was).
  QString refusal() const;
  /// Forgets the last refused input (the window moved on: defaults restored, a clicked start).
  void clearRefusal();

  SliderSpin* control(ParamKey key) const { return m_controls.value(key); }
  /// The N-mass scenes' chain editor (shown only for them).
  ChainEditor* chainEditor() const { return m_chainEditor; }
  /// What the worker says the N-mass chain is (SceneJob::chain).
  void setChainSummary(const QString& text, int designs, bool refused);

 signals:
  void paramsChanged(const grazelab::ui::Params& params);
  /// A typed value was refused and the previous one kept.
  void inputRefused(const QString& reason);

 protected:
  /// The messages have style sheets, which stop Qt from handing them the panel's font: given
  /// again on every change (presentation mode scales it).
  void changeEvent(QEvent* event) override;

 private:
  void changed();
  void updateFeasibility();

  Params m_params;
  QMap<ParamKey, SliderSpin*> m_controls;
  QList<ParamKey> m_sceneKeys;
  QCheckBox* m_design = nullptr;
  QComboBox* m_branch = nullptr;
  QComboBox* m_direction = nullptr;
  QLabel* m_directionLabel = nullptr;
  QLabel* m_feasibility = nullptr;
  QLabel* m_message = nullptr;
  QLabel* m_refusal = nullptr;
  QLabel* m_clickedStart = nullptr;
  QLabel* m_notes = nullptr;
  QLabel* m_sceneText = nullptr;
  QWidget* m_startBox = nullptr;
  QWidget* m_chainBox = nullptr;       ///< the two-mass chain
  QWidget* m_massChainBox = nullptr;   ///< the chain of N masses
  ChainEditor* m_chainEditor = nullptr;
  QBoxLayout* m_chainLayout = nullptr;
  QBoxLayout* m_massChainLayout = nullptr;
  bool m_massChainScene = false;
  QWidget* m_runBox = nullptr;
};

}  // namespace grazelab::ui
