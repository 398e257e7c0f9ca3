// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QChartView>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QSet>
#include <QSize>
#include <QStringList>
#include <QString>
#include <QTimer>

#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ui/plots/decimate.h"
#include "ui/plots/scene_view.h"
#include "ui/compute/sim_types.h"

class QGraphicsTextItem;
class QLabel;
class QValueAxis;
class QXYSeries;

namespace grazelab::ui {

class WrappedLegend;

/// How a series is reduced to the pixels before it reaches Qt Charts (ui/decimate.h).
enum class Decimation { None, Trace, Scatter, Path };

/// A chart with two value axes, zoom (rubber band, wheel, + and -), pan (middle button or
/// Shift + drag, arrow keys) and reset (R). It keeps the full data of every series and hands
/// Qt Charts only what the pixels can show, re-decimating after each zoom, pan or resize.
/// While the user has not zoomed or panned, the axes follow the data.
class PlotView : public QChartView, public SceneView {
  Q_OBJECT

 public:
  /// The least room a plot takes in the window's grid.
  static constexpr QSize kMinimumSize{200, 160};
  /// The extent of some points (empty: low > high).
  struct Extent {
    double xLow = std::numeric_limits<double>::infinity();
    double xHigh = -std::numeric_limits<double>::infinity();
    double yLow = std::numeric_limits<double>::infinity();
    double yHigh = -std::numeric_limits<double>::infinity();
    void take(const QPointF& point);  ///< widens it to a finite point (others are ignored)
    void take(const Extent& other);
  };
  /// One series and the full-resolution data behind it.
  struct Entry {
    QXYSeries* series = nullptr;
    std::vector<QPointF> data;  ///< the points, when the view holds them itself
    /// or the points read in place from records `owner` keeps alive (a run's samples)
    PointSpan inPlace;
    std::shared_ptr<const void> owner;
    PointSpan points() const { return owner ? inPlace : PointSpan(data); }
    Decimation decimation = Decimation::None;
    bool inBounds = true;  ///< counts for the automatic axis ranges
    QString csvName;       ///< the series' name in a CSV export, when not its legend name
    double baseWidth = 0;   ///< the desk look: line width or marker size
    /// what has been drawn of `data`, kept while points are only appended
    std::shared_ptr<IncrementalDecimation> reduced;
    bool replaced = true;  ///< `data` were set anew since the last refresh (not appended to)
    /// what the series was last given: of how many points, on which frame (a refresh that
    /// would give it the same skips it: Qt Charts lays a series out again on every replace)
    std::size_t drawnCount = 0;
    std::optional<PixelFrame> drawnFrame;
    /// the finite points' extent, over the first `boundsCounted` points
    Extent bounds;
    std::size_t boundsCounted = 0;
  };

  ~PlotView() override;
  PlotView(const QString& title, const QString& xTitle, const QString& yTitle,
           QWidget* parent = nullptr);

  QWidget* widget() override { return this; }

  /// Forgets zoom and pan: the axes follow the data again.
  void resetView();
  /// While a run grows, axes that must widen widen by a quarter of the span on each side, so
  /// that they (and the drawing of every point) change a few times over the run, not at every
  /// update; the final result is fitted tightly.
  void setGrowing(bool growing) { m_growing = growing; }
  /// The data shown is now final: axes that had room to grow are fitted to it (redrawn only
  /// when that moves them).
  void settle();
  /// The axes measure unrelated things (a contact index against a flight time): neither
  /// axis's least span follows the other's scale.
  void setAxesIndependent(bool independent) { m_axesIndependent = independent; }
  /// Forgets zoom and pan at the next update, without redrawing the data shown now (a new
  /// result is on its way: refitting and repainting the old one would only delay it).
  void followDataFromNextUpdate() { m_followData = true; }
  bool followsData() const { return m_followData; }

  const std::vector<Entry>& entries() const { return m_entries; }
  /// Refreshes that had to decimate some series from the start (its data replaced, or the
  /// axes or the plot's size changed) rather than only the points appended since.
  int decimationsFromScratch() const { return m_decimationsFromScratch; }
  /// The names in the plot's legend, in its order.
  const QStringList& legendNames() const;
  /// Whether the legend shows every name whole, on as many lines as it needs (false when it
  /// had to be cut to 40 % of the chart's height, or is not laid out yet).
  bool legendFits() const;
  /// The texts Qt Charts draws cut short ("..."): titles, axis titles, tick labels. Empty when
  /// every text shows whole.
  QStringList cutTexts() const;
  /// Number of points currently handed to Qt Charts, summed over series.
  qsizetype drawnPointCount() const;
  /// Appends the plotted data at full resolution as CSV rows "plot,series,x,y" (no header).
  /// Every drawn point: plot = the title, series = its legend name, x and y as the axes say.
  void appendCsv(CsvTable& table) const override;
  QString viewTitle() const override { return title(); }
  QString title() const;
  /// The chart's title and axis titles, kept whole: each is wrapped onto more lines where the
  /// view is too narrow for it (Qt Charts would cut it to "…").
  void setTitles(const QString& title, const QString& xTitle, const QString& yTitle);
  void setXTitle(const QString& xTitle);

  /// Applies pending data now instead of at the next turn of the event loop.
  void refreshNow();

  /// Presentation mode: text of `textPixels` (titles a little larger), lines at least 3 px,
  /// markers half again as large; off restores the desk look.
  void setPresentation(bool on, int textPixels) override;
  bool presentation() const { return m_presentation; }

  /// Marks the plot as showing the last valid result, not the panel's parameters (greyed
  /// plot area and a note in its corner), or clears the mark.
  void setStale(bool stale);
  bool isStale() const { return m_stale; }
  /// In place of bare -1..1 axes: the sentence in the middle, no axes; empty clears it.
  void setEmptyNote(const QString& why) override;
  QString emptyNote() const;
  /// A click waits for the double-click interval before it is sent as clickedAt.
  bool clickPending() const { return m_clickTimer.isActive(); }

 signals:
  /// The user double-clicked the plot: enlarge it (or put it back).
  void enlargeRequested(grazelab::ui::PlotView* plot);
  /// A left click without a drag inside the plot area, at data coordinates `value`; sent once
  /// the double-click interval has passed without a second click (a double-click enlarges the
  /// plot and starts nothing).
  void clickedAt(QPointF value);
  /// The user clicked or focused this plot (it becomes the "current plot").
  void activated(grazelab::ui::PlotView* plot);
  /// The series were replaced with new decimated data.
  void refreshed();

 protected:
  int addEntry(QXYSeries* series, Decimation decimation, bool inBounds = true);
  void setData(int index, std::vector<QPointF> data);
  /// The series' name in a CSV export, in place of its legend name (which may be empty or
  /// shared with another series).
  void setCsvName(int index, const QString& name);
  /// Leaves a series out of the legend (a cursor, an empty bin) or puts it back; a series
  /// without a name is never in it.
  void setInLegend(QXYSeries* series, bool shown);
  /// Adds points after those of the entry (a run going on): the next refresh draws only them,
  /// plus what the pixels show, unless the axes moved.
  void appendData(int index, std::span<const QPointF> points);
  /// Shows `points` read in place from records that `owner` keeps alive (a run): no copy.
  /// `grown`: the points shown before, with more after them (the run went on), so that the
  /// next refresh draws only the new ones.
  void showInPlace(int index, PointSpan points, std::shared_ptr<const void> owner, bool grown);
  /// The plot shows a new run (not the one it was showing, grown): the next fit is tight.
  void startNewRun() { m_newRun = true; }
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
  /// Shows only [first, second] of the x axis while the view follows its data (a window of a
  /// long run); nothing: the whole extent.
  void setXWindow(std::optional<std::pair<double, double>> window);
  /// Half the largest marker (with its outline) of the scatters that set the axes [pixels].
  double largestMarkerRadius() const;

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
  /// The legend, drawn as wrapped text under the plot (Qt Charts' own legend keeps one row
  /// and cut the labels of narrow plots to "sto..."): one coloured symbol and name per
  /// visible marker of Qt's legend, which stays the model (hidden).
  void updateLegend();
  /// The ranges the axes should show when they follow the data: fixed, fitted, or (while the
  /// run grows) the present ones if the data still fit.
  QRectF wantedRange();
  Extent dataBounds();
  void userMovedView();

  std::vector<Entry> m_entries;
  std::vector<QPointF> m_extraBounds;
  std::vector<int> m_joinedScatters;
  IncrementalScatterSets m_joinedReduced;
  bool m_growing = false;
  bool m_axesIndependent = false;
  bool m_newRun = true;
  int m_decimationsFromScratch = 0;
  std::optional<QRectF> m_fixedRange;
  std::optional<std::pair<double, double>> m_xWindow;
  QSizeF m_tickedArea;  ///< the plot area the ticks were chosen for
  bool m_stale = false;
  bool m_presentation = false;
  struct Fonts {
    QFont title, labels, axisTitles, legend;
  };
  /// Wraps the titles to the view's current size.
  void fitTitles();
  QString m_title, m_xTitle, m_yTitle;  ///< whole, as set
  std::optional<Fonts> m_deskFonts;  ///< the fonts before presentation mode
  QLabel* m_staleNote = nullptr;
  QLabel* m_emptyNote = nullptr;  ///< setEmptyNote's sentence
  QGraphicsItem* m_grid = nullptr;  ///< the grid (PlotGrid), owned by the chart
  void placeStaleNote();
  std::unique_ptr<WrappedLegend> m_legend;
  QTimer m_refreshTimer;
  QTimer m_clickTimer;      ///< a click waiting to be told apart from a double-click
  QPointF m_clickedValue;   ///< where it fell, in the data's coordinates
  bool m_followData = true;
  bool m_panning = false;
  QPoint m_lastPanPosition;
  QPoint m_pressPosition;  ///< where the left button went down (a click or a rubber band)
};

}  // namespace grazelab::ui
