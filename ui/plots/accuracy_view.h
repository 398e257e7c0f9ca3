// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QWidget>

#include <memory>

#include "ui/plots/scene_view.h"
#include "ui/compute/sim_types.h"

class QComboBox;
class QLabel;

namespace grazelab::ui {

class LogLogChart;

/// The Accuracy scene's view: every method's state error against its run time (the chart of
/// `grazelab-cli report`), points appearing as the worker finishes them, and a picker of the
/// run to overlay on the u2(t) trace.
class AccuracyView : public QWidget, public SceneView {
  Q_OBJECT

 public:
  explicit AccuracyView(QWidget* parent = nullptr);

  /// Shows the sweep of an update (nothing when it has none).
  QWidget* widget() override { return this; }
  void show(const SimUpdate& update) override;
  /// Presentation mode for its chart (ui/plots/log_log_chart.h).
  void setPresentation(bool on, int textPixels) override;
  /// Every finished setting: x = its run time, y = its state error, value = its contact-time
  /// error (the chart's points, with the series named by method and setting).
  void appendCsv(CsvTable& table) const override;
  QString viewTitle() const override { return tr("Error against run time"); }
  LogLogChart* chart() const { return m_chart; }
  /// The runs offered for the overlay, in the picker's order.
  int overlayCount() const;
  /// Picks the run to overlay (an index into the picker).
  void chooseOverlay(int index);

 signals:
  /// The run to draw over the exact u2(t) (empty: none), with its name.
  void overlayChosen(std::shared_ptr<const grazelab::core::Result> run, const QString& name);

 private:
  void emitOverlay();

  LogLogChart* m_chart = nullptr;
  QComboBox* m_overlay = nullptr;
  QLabel* m_summary = nullptr;
  std::shared_ptr<const AccuracyProgress> m_shown;
  /// the setting the user picked, kept across updates (by its label)
  QString m_chosenLabel;
};

/// The label of a finished setting in the picker: "moreau-jean h=0.0089: error 0.81, 2.5 ms".
QString accuracyLabel(const core::methods::WorkPrecisionPoint& point);

}  // namespace grazelab::ui
