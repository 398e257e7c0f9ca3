// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QChartView>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QTimer>

#include <optional>
#include <vector>

#include "ui/plots/scene_view.h"
#include "ui/sim_types.h"

class QLabel;
class QValueAxis;
class QXYSeries;

namespace grazelab::ui {

/// How a series is reduced to the pixels before it reaches Qt Charts (ui/decimate.h).
enum class Decimation { None, Trace, Scatter, Path };

/// A chart with two value axes, zoom (rubber band, wheel, + and -), pan (middle button or
/// Shift + drag, arrow keys) and reset (R). It keeps the full data of every series and hands
/// Qt Charts only what the pixels can show, re-decimating after each zoom, pan or resize.
/// While the user has not zoomed or panned, the axes follow the data.
class PlotView : public QChartView, public SceneView {
  Q_OBJECT

 public:
  /// One series and the full-resolution data behind it.
  struct Entry {
    QXYSeries* series = nullptr;
    std::vector<QPointF> data;
    Decimation decimation = Decimation::None;
    bool inBounds = true;  ///< counts for the automatic axis ranges
    double baseWidth = 0;   ///< the desk look: line width or marker size
  };

  PlotView(const QString& title, const QString& xTitle, const QString& yTitle,
           QWidget* parent = nullptr);

  QWidget* widget() override { return this; }

  /// Forgets zoom and pan: the axes follow the data again.
  void resetView();
  bool followsData() const { return m_followData; }

  const std::vector<Entry>& entries() const { return m_entries; }
  /// Number of points currently handed to Qt Charts, summed over series.
  qsizetype drawnPointCount() const;
  /// Appends the plotted data at full resolution as CSV rows "plot,series,x,y" (no header).
  void appendCsv(QString& csv) const;
  QString title() const;

  /// Applies pending data now instead of at the next turn of the event loop.
  void refreshNow();

  /// The animation's time and state: time-based plots mark it (a line on u2(t), a dot on a
  /// phase portrait); others ignore it. Drawn at once, without re-decimating the data.
  void setTimeCursor(double t, const core::State& state) override;

  /// Presentation mode: text of `textPixels` (titles a little larger), lines at least 3 px,
  /// markers half again as large; off restores the desk look.
  void setPresentation(bool on, int textPixels) override;

  /// Marks the plot as showing the last valid result, not the panel's parameters (greyed
  /// plot area and a note in its corner), or clears the mark.
  void setStale(bool stale);
  bool isStale() const { return m_stale; }

 signals:
  /// The user double-clicked the plot: enlarge it (or put it back).
  void enlargeRequested(grazelab::ui::PlotView* plot);
  /// A left click without a drag inside the plot area, at data coordinates `value`.
  void clickedAt(QPointF value);
  /// The user clicked or focused this plot (it becomes the "current plot").
  void activated(grazelab::ui::PlotView* plot);
  /// The series were replaced with new decimated data.
  void refreshed();

 protected:
  int addEntry(QXYSeries* series, Decimation decimation, bool inBounds = true);
  void setData(int index, std::vector<QPointF> data);
  /// Scatter entries drawn over each other as one cloud (colour classes): decimated jointly,
  /// one point per cell chosen at random among all of them (decimateScatterSets).
  void joinScatters(std::vector<int> indices);
  /// Called after setData()s: schedules one refresh (coalesced through a zero timer).
  void scheduleRefresh();
  /// Extra vertical/horizontal span to include in the automatic ranges (e.g. the stop line).
  void includeInBounds(double x, double y);
  void clearExtraBounds();
  /// Axes that stay put while the data change (a family's curve, on which a point moves); the
  /// user's zoom still overrides them until R. nullopt: the axes follow the data.
  void setFixedRange(std::optional<QRectF> range);

  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void focusInEvent(QFocusEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

  QValueAxis* m_axisX = nullptr;
  QValueAxis* m_axisY = nullptr;

 private:
  void refresh();
  void fitAxes();
  void userMovedView();

  std::vector<Entry> m_entries;
  std::vector<QPointF> m_extraBounds;
  std::vector<int> m_joinedScatters;
  std::optional<QRectF> m_fixedRange;
  bool m_stale = false;
  bool m_presentation = false;
  struct Fonts {
    QFont title, labels, axisTitles, legend;
  };
  std::optional<Fonts> m_deskFonts;  ///< the fonts before presentation mode
  QLabel* m_staleNote = nullptr;
  QTimer m_refreshTimer;
  bool m_followData = true;
  bool m_panning = false;
  QPoint m_lastPanPosition;
  QPoint m_pressPosition;  ///< where the left button went down (a click or a rubber band)
};

}  // namespace grazelab::ui
