// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/plot_view.h"

#include "ui/plots/csv_table.h"

#include <QApplication>
#include <QChart>
#include <QFontMetricsF>
#include <QKeyEvent>
#include <QLegend>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QMouseEvent>
#include <QScatterSeries>
#include <QValueAxis>
#include <QWheelEvent>
#include <QXYSeries>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "ui/plots/decimate.h"
#include "ui/plots/plot_grid.h"
#include "ui/plots/plot_style.h"
#include "ui/plots/wrapped_legend.h"

namespace grazelab::ui {
namespace {

// a range that is never empty, padded by 2 % on each side; a spread below 1e-3 of the plot's
// scale (round-off around a constant) is shown as flat rather than blown up; an exact constant
// (one point repeated) in a window `flatWidth` wide, a tenth of the plot's scale (a repeated
// point at v = 0 was framed by ticks of +-0.00000005 that read as a spread)
std::pair<double, double> padded(double low, double high, double scale, double flatWidth) {
  if (!(low <= high)) return {-1.0, 1.0};
  double span = high - low;
  const double least = std::max(1e-3 * scale, 1e-12);
  if (span < least) {
    const double middle = 0.5 * (low + high);
    span = span == 0 ? std::max(least, flatWidth) : least;
    low = middle - 0.5 * span;
    high = middle + 0.5 * span;
  }
  return {low - 0.02 * span, high + 0.02 * span};
}

// Ticks at round values (0, 100, 200 rather than -21.02, 120.9) without widening the range,
// labelled with as many decimals as the step needs. (A QCategoryAxis gives exact labels too,
// but relayouting it costs ~3 ms per axis and update, too much for a live drag.)
double niceStep(double low, double high) {
  const double span = high - low;
  if (!(span > 0) || !std::isfinite(span)) return 0;
  const double rough = span / 4.0;  // four to eight ticks: labels stay apart on a projector
  const double magnitude = std::pow(10.0, std::floor(std::log10(rough)));
  const double ratio = rough / magnitude;
  return (ratio < 1.5 ? 1.0 : ratio < 3.5 ? 2.0 : ratio < 7.5 ? 5.0 : 10.0) * magnitude;
}

// [low, high] widened to multiples of a quarter of its tick step (at most 1/12 of the span
// on each side); a range too small to snap (span at round-off of its values) is left alone
void snapOutward(double& low, double& high) {
  const double step = niceStep(low, high);
  if (!(step > 0)) return;
  const double quantum = 0.25 * step;
  const double snappedLow = std::floor(low / quantum) * quantum;
  const double snappedHigh = std::ceil(high / quantum) * quantum;
  if (!(snappedLow < snappedHigh) || !std::isfinite(snappedLow) || !std::isfinite(snappedHigh)) return;
  if (snappedHigh - snappedLow > 1e9 * (high - low)) return;
  low = snappedLow;
  high = snappedHigh;
}

// The next nice step above `step` (1, 2, 5 times a power of ten).
double nextNiceStep(double step) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double ratio = step / magnitude;
  return (ratio < 1.5 ? 2.0 : ratio < 3.5 ? 5.0 : 10.0) * magnitude;
}

// How the labels of ticks `step` apart over [low, high] print: whole steps as whole numbers up
// to a billion (a contact-index axis to 10^6 read "0.0002, 2e+05": the anchor below, printed by
// %g); fractions as decimals below a million
QString tickFormat(double low, double high, double step) {
  const double largest = std::max(std::abs(low), std::abs(high));
  const bool plain = (step >= 1e-9 && largest < 1e6) || (step >= 1 && largest < 1e9);
  const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
  return plain ? QStringLiteral("%.%1f").arg(decimals) : QStringLiteral("%.3g");
}

// Sets range and tick interval together. The order matters: Qt Charts lays the ticks out on
// each change, and a small interval over a large range would create millions of tick items.
// `pixels` is the axis' length on screen (0 when not laid out yet): the step grows until every
// label fits beside its neighbours (Qt Charts elides labels that do not: "-…", "100…").
void setRangeWithTicks(QValueAxis* axis, double low, double high, double pixels) {
  double step = niceStep(low, high);
  if (step <= 0) {
    axis->setRange(low, high);
    return;
  }
  const QFontMetricsF metrics(axis->labelsFont());
  const bool horizontal = axis->orientation() == Qt::Horizontal;
  for (int widen = 0; widen < 4 && pixels > 0; ++widen) {
    const QString format = tickFormat(low, high, step);
    // the widest label is at one end, or a negative one in between
    double widest = 0;
    for (double value : {low, high, -step, step}) {
      widest = std::max(widest, metrics.horizontalAdvance(QString::asprintf(qPrintable(format), value)));
    }
    const double each = horizontal ? widest + metrics.height() : 1.6 * metrics.height();
    const double ticks = std::floor((high - low) / step) + 1;
    if (ticks * each <= pixels) break;
    // never fewer than two labelled ticks inside the axis: one number is no scale
    const double wider = nextNiceStep(step);
    if (std::floor(high / wider) - std::ceil(low / wider) + 1 < 2) break;
    step = wider;
  }
  const QString format = tickFormat(low, high, step);
  if (axis->labelFormat() != format) axis->setLabelFormat(format);
  if (axis->tickType() != QValueAxis::TicksDynamic) {
    axis->setTickInterval(std::max(step, axis->max() - axis->min()));
    axis->setTickType(QValueAxis::TicksDynamic);
  }
  // Qt Charts accumulates the tick values, so the one at zero lands at about -1e-17 and reads
  // "-0.0" (or "-1.4e-20"); anchoring the ticks a billionth of a step above zero keeps that
  // tick on the positive side, invisibly
  const double anchor = 1e-9 * step;
  if (axis->tickAnchor() != anchor) axis->setTickAnchor(anchor);
  if (step >= axis->tickInterval()) {
    axis->setTickInterval(step);
    axis->setRange(low, high);
  } else {
    axis->setRange(low, high);
    axis->setTickInterval(step);
  }
}

// `text` as is when it fits in `width`, else its words on lines that fit, as HTML (Qt Charts
// draws titles as rich text and sizes them to all their lines)
QString wrappedTitle(const QString& text, const QFont& font, double width) {
  const QFontMetricsF metrics(font);
  if (metrics.horizontalAdvance(text) <= width || width <= 0) return text;
  QStringList lines;
  QString line;
  for (const QString& word : text.split(' ', Qt::SkipEmptyParts)) {
    const QString longer = line.isEmpty() ? word : line + ' ' + word;
    if (!line.isEmpty() && metrics.horizontalAdvance(longer) > width) {
      lines << line.toHtmlEscaped();
      line = word;
    } else {
      line = longer;
    }
  }
  lines << line.toHtmlEscaped();
  return lines.join("<br>");
}

}  // namespace

PlotView::PlotView(const QString& title, const QString& xTitle, const QString& yTitle,
                   QWidget* parent)
    : QChartView(new QChart, parent) {
  QChart* chart = this->chart();
  chart->setTheme(QChart::ChartThemeLight);
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->legend()->setAlignment(Qt::AlignBottom);
  m_legend = std::make_unique<WrappedLegend>(chart);
  QFont titleFont = chart->titleFont();
  titleFont.setBold(true);
  chart->setTitleFont(titleFont);

  m_axisX = new QValueAxis;
  m_axisY = new QValueAxis;
  chart->addAxis(m_axisX, Qt::AlignBottom);
  chart->addAxis(m_axisY, Qt::AlignLeft);
  m_grid = new PlotGrid(chart, m_axisX, m_axisY);  // the chart's child: Qt Charts' own grid, hidden

  setRenderHint(QPainter::Antialiasing);
  // the whole plot repainted on each change: under QGraphicsView's minimal updates, Qt Charts'
  // axis labels, relaid out as the ranges move, left pieces of old labels on screen in a real
  // window ("(" between two ticks, half a "-1.5" under the axis; never in a rendered picture).
  // Measured with grazelab --bench under Xvfb: the default scene's edit 6.0 -> 8.0 ms median,
  // the animation still 62 fps
  setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
  setRubberBand(QChartView::RectangleRubberBand);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(kMinimumSize);  // again after each resize (resizeEvent)

  setTitles(title, xTitle, yTitle);
  // the titles wrap to the plot area as laid out: when a legend, a wrapped title or larger
  // presentation fonts change it, they are fitted again (a scene opened while presenting kept
  // titles fitted to its first layout, and Qt cut them: "log10 max (1 - ...")
  connect(chart, &QChart::plotAreaChanged, this, &PlotView::fitTitles, Qt::QueuedConnection);
  m_clickTimer.setSingleShot(true);
  connect(&m_clickTimer, &QTimer::timeout, this, [this] { emit clickedAt(m_clickedValue); });
  m_refreshTimer.setSingleShot(true);
  m_refreshTimer.setInterval(0);
  connect(&m_refreshTimer, &QTimer::timeout, this, &PlotView::refresh);
}

PlotView::~PlotView() = default;

int PlotView::addEntry(QXYSeries* series, Decimation decimation, bool inBounds) {
  chart()->addSeries(series);
  series->attachAxis(m_axisX);
  series->attachAxis(m_axisY);
  const auto* scatter = qobject_cast<QScatterSeries*>(series);
  const double base = scatter ? scatter->markerSize() : series->pen().widthF();
  Entry entry;
  entry.series = series;
  entry.decimation = decimation;
  entry.inBounds = inBounds;
  entry.baseWidth = base;
  using Kind = IncrementalDecimation::Kind;
  switch (decimation) {
    case Decimation::None: break;
    case Decimation::Trace: entry.reduced = std::make_shared<IncrementalDecimation>(Kind::Trace); break;
    case Decimation::Scatter: entry.reduced = std::make_shared<IncrementalDecimation>(Kind::Scatter); break;
    case Decimation::Path: entry.reduced = std::make_shared<IncrementalDecimation>(Kind::Path); break;
  }
  m_entries.push_back(std::move(entry));
  if (m_presentation) {
    m_presentation = false;  // applies the look to the new series too
    setPresentation(true, chart()->legend()->font().pixelSize());
  }
  return int(m_entries.size()) - 1;
}

void PlotView::setPresentation(bool on, int textPixels) {
  QChart* chart = this->chart();
  if (!m_deskFonts) {
    m_deskFonts = Fonts{chart->titleFont(), m_axisX->labelsFont(), m_axisX->titleFont(),
                        chart->legend()->font()};
  }
  auto sized = [&](QFont font, double factor) {
    font.setPixelSize(std::max(1, int(std::lround(textPixels * factor))));
    return font;
  };
  const Fonts fonts = on ? Fonts{sized(m_deskFonts->title, 1.15), sized(m_deskFonts->labels, 1.0),
                                 sized(m_deskFonts->axisTitles, 1.0), sized(m_deskFonts->legend, 1.0)}
                         : *m_deskFonts;
  chart->setTitleFont(fonts.title);
  chart->legend()->setFont(fonts.legend);
  for (QValueAxis* axis : {m_axisX, m_axisY}) {
    axis->setLabelsFont(fonts.labels);
    axis->setTitleFont(fonts.axisTitles);
  }
  // a white page with no rounded, shaded card: what a projector shows best
  chart->setBackgroundRoundness(on ? 0 : 4);
  chart->setDropShadowEnabled(!on);
  for (Entry& entry : m_entries) {
    if (auto* scatter = qobject_cast<QScatterSeries*>(entry.series)) {
      scatter->setMarkerSize(on ? std::max(8.0, 1.5 * entry.baseWidth) : entry.baseWidth);
      useLightMarker(scatter, scatter->property("grazelabOutline").value<QPen>());
    } else {
      QPen pen = entry.series->pen();
      pen.setWidthF(on ? std::max(3.0, 2.0 * entry.baseWidth) : entry.baseWidth);
      entry.series->setPen(pen);
    }
  }
  m_presentation = on;
  fitTitles();
  updateLegend();
  scheduleRefresh();
}

void PlotView::setData(int index, std::vector<QPointF> data) {
  Entry& entry = m_entries[std::size_t(index)];
  // the same points again (a mark a view sets at each update of a run): nothing to redraw
  const auto same = [](const QPointF& a, const QPointF& b) { return a.x() == b.x() && a.y() == b.y(); };
  if (!entry.owner && std::equal(entry.data.begin(), entry.data.end(), data.begin(), data.end(), same)) return;
  entry.data = std::move(data);
  entry.inPlace = {};
  entry.owner.reset();
  entry.replaced = true;
  entry.boundsCounted = 0;
}

void PlotView::appendData(int index, std::span<const QPointF> points) {
  Entry& entry = m_entries[std::size_t(index)];
  if (entry.owner) {
    // it was reading a run in place: it holds its own points from now on
    entry.inPlace = {};
    entry.owner.reset();
    entry.replaced = true;
    entry.boundsCounted = 0;
  }
  entry.data.insert(entry.data.end(), points.begin(), points.end());
}

void PlotView::showInPlace(int index, PointSpan points, std::shared_ptr<const void> owner, bool grown) {
  Entry& entry = m_entries[std::size_t(index)];
  if (!entry.data.empty()) std::vector<QPointF>().swap(entry.data);
  grown = grown && entry.owner && points.size() >= entry.inPlace.size();
  entry.inPlace = points;
  entry.owner = std::move(owner);
  if (!grown) {
    entry.replaced = true;
    entry.boundsCounted = 0;
  }
}

void PlotView::joinScatters(std::vector<int> indices) { m_joinedScatters = std::move(indices); }

void PlotView::includeInBounds(double x, double y) { m_extraBounds.push_back({x, y}); }
void PlotView::clearExtraBounds() { m_extraBounds.clear(); }
void PlotView::setFixedRange(std::optional<QRectF> range) { m_fixedRange = range; }

void PlotView::setXWindow(std::optional<std::pair<double, double>> window) {
  if (window == m_xWindow) return;
  m_xWindow = window;
  scheduleRefresh();
}

void PlotView::scheduleRefresh() {
  if (!m_refreshTimer.isActive()) m_refreshTimer.start();
}

void PlotView::refreshNow() {
  m_refreshTimer.stop();
  refresh();
}

void PlotView::settle() {
  if (!m_growing) return;
  m_growing = false;
  if (!m_followData) return;
  const QRectF range = wantedRange();
  if (range.left() != m_axisX->min() || range.right() != m_axisX->max() || range.top() != m_axisY->min() ||
      range.bottom() != m_axisY->max()) {
    refreshNow();
  }
}

void PlotView::setStale(bool stale) {
  if (stale == m_stale) return;
  m_stale = stale;
  if (!m_staleNote) {
    m_staleNote = new QLabel(tr("stale: the last valid result, not the panel's values"), this);
    m_staleNote->setObjectName(QStringLiteral("staleNote"));
    m_staleNote->setStyleSheet(QStringLiteral(
        "QLabel { background: #fff3cd; color: #7a1010; border: 1px solid #7a1010; padding: 2px; }"));
    m_staleNote->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_staleNote->setWordWrap(true);
  }
  m_staleNote->setVisible(stale);
  placeStaleNote();
  // the whole view again when it comes back: tick labels moved while it was stale were left
  // drawn in their old places (ghost ticks after a refused value and Ctrl+Shift+R)
  if (!stale) viewport()->update();
  chart()->setPlotAreaBackgroundBrush(QColor(0xe8, 0xe8, 0xe8));
  chart()->setPlotAreaBackgroundVisible(stale);
}

void PlotView::setEmptyNote(const QString& why) {
  if (why.isEmpty() && !m_emptyNote) return;
  if (!m_emptyNote) {
    m_emptyNote = new QLabel(this);
    m_emptyNote->setObjectName(QStringLiteral("emptyNote"));
    m_emptyNote->setAlignment(Qt::AlignCenter);
    m_emptyNote->setWordWrap(true);
    m_emptyNote->setAttribute(Qt::WA_TransparentForMouseEvents);
  }
  m_emptyNote->setText(why);
  m_emptyNote->setVisible(!why.isEmpty());
  m_emptyNote->setGeometry(rect().adjusted(16, 16, -16, -16));
  for (QAbstractAxis* axis : chart()->axes()) axis->setVisible(why.isEmpty());
  m_grid->setVisible(why.isEmpty());
}

QString PlotView::emptyNote() const { return m_emptyNote && m_emptyNote->isVisible() ? m_emptyNote->text() : QString(); }

void PlotView::placeStaleNote() {
  if (!m_staleNote || !m_staleNote->isVisible()) return;
  // inside the plot area's top right corner, wrapped to its width: over the title (and cut at
  // the plot's edge) it hid what the plot is
  const QRect area = mapFromScene(chart()->mapToScene(chart()->plotArea())).boundingRect();
  const int room = std::max(60, area.width() - 8);
  m_staleNote->setMaximumWidth(room);
  // its height for the width it gets: adjustSize() chose a wrapped label's height for another
  // width, and a third line was cut in a narrow plot
  const int width = std::min(room, m_staleNote->sizeHint().width());
  m_staleNote->resize(width, m_staleNote->heightForWidth(width));
  m_staleNote->move(std::max(0, area.right() - m_staleNote->width() - 4), area.top() + 4);
}

void PlotView::resetView() {
  m_followData = true;
  refreshNow();
}

void PlotView::userMovedView() {
  m_followData = false;
  scheduleRefresh();
}

QString PlotView::title() const { return m_title; }

void PlotView::setCsvName(int index, const QString& name) { m_entries[std::size_t(index)].csvName = name; }

void PlotView::setTitles(const QString& title, const QString& xTitle, const QString& yTitle) {
  m_title = title;
  m_xTitle = xTitle;
  m_yTitle = yTitle;
  fitTitles();
}

void PlotView::setXTitle(const QString& xTitle) {
  m_xTitle = xTitle;
  fitTitles();
}

QStringList PlotView::cutTexts() const {
  QStringList cut;
  for (const QGraphicsItem* item : chart()->childItems()) {
    for (const QGraphicsItem* child : item->childItems() + QList<QGraphicsItem*>{const_cast<QGraphicsItem*>(item)}) {
      if (const auto* text = dynamic_cast<const QGraphicsTextItem*>(child)) {
        if (text != m_legend->item() && text->isVisible() && text->toPlainText().endsWith("...")) {
          cut << text->toPlainText();
        }
      }
    }
  }
  return cut;
}

void PlotView::fitTitles() {
  // the plot area once laid out; before that, the view less room for ticks and margins
  // (Qt draws a title as a text document with a margin of 4 px each side: 12 px spare)
  const QRectF area = chart()->plotArea();
  const double titleWidth = width() - 2 * 4 - 12 - 12;
  const double xWidth = (area.width() > 0 ? area.width() : width() - 80) - 12;
  const double yWidth = (area.height() > 0 ? area.height() : height() - 100) - 12;
  const QString title = wrappedTitle(m_title, chart()->titleFont(), titleWidth);
  const QString x = wrappedTitle(m_xTitle, m_axisX->titleFont(), xWidth);
  // the vertical title on one line, a little smaller where it must (down to 70 %): Qt leaves a
  // turned title the width of the tick labels, and cut a second line beside labels as narrow as
  // "0" and "1" ("frequency..." in a short plot while presenting at 720p)
  QFont yFont = m_axisX->titleFont();  // the axis titles' font (the x title's is never changed)
  if (const double needed = QFontMetricsF(yFont).horizontalAdvance(m_yTitle); needed > yWidth && yWidth > 0) {
    const double scale = std::max(0.7, yWidth / needed);
    if (yFont.pixelSize() > 0) {
      yFont.setPixelSize(std::max(1, int(std::floor(yFont.pixelSize() * scale))));
    } else {
      yFont.setPointSizeF(yFont.pointSizeF() * scale);
    }
  }
  const QString y = wrappedTitle(m_yTitle, yFont, yWidth);
  // set only when changed: every new title lays the chart out again
  if (chart()->title() != title) chart()->setTitle(title);
  if (m_axisX->titleText() != x) m_axisX->setTitleText(x);
  if (m_axisY->titleFont() != yFont) m_axisY->setTitleFont(yFont);
  if (m_axisY->titleText() != y) m_axisY->setTitleText(y);
}

qsizetype PlotView::drawnPointCount() const {
  qsizetype count = 0;
  for (const Entry& entry : m_entries) count += entry.series->count();
  return count;
}

void PlotView::appendCsv(CsvTable& table) const {
  table.describe(m_title, m_xTitle, m_yTitle);
  for (const Entry& entry : m_entries) {
    const QString name = entry.csvName.isEmpty() ? entry.series->name() : entry.csvName;
    const PointSpan points = entry.points();
    for (std::size_t index = 0; index < points.size(); ++index) {
      table.add(m_title, name, points[index].x(), points[index].y());
    }
  }
}

void PlotView::Extent::take(const QPointF& point) {
  if (!std::isfinite(point.x()) || !std::isfinite(point.y())) return;
  xLow = std::min(xLow, point.x());
  xHigh = std::max(xHigh, point.x());
  yLow = std::min(yLow, point.y());
  yHigh = std::max(yHigh, point.y());
}

void PlotView::Extent::take(const Extent& other) {
  xLow = std::min(xLow, other.xLow);
  xHigh = std::max(xHigh, other.xHigh);
  yLow = std::min(yLow, other.yLow);
  yHigh = std::max(yHigh, other.yHigh);
}

PlotView::Extent PlotView::dataBounds() {
  // each entry's extent is kept and widened by the points appended since
  Extent all;
  for (Entry& entry : m_entries) {
    if (!entry.inBounds) continue;
    if (entry.boundsCounted == 0) entry.bounds = Extent{};
    const PointSpan points = entry.points();
    for (std::size_t index = entry.boundsCounted; index < points.size(); ++index) {
      entry.bounds.take(points[index]);
    }
    entry.boundsCounted = points.size();
    all.take(entry.bounds);
  }
  for (const QPointF& point : m_extraBounds) all.take(point);
  return all;
}

double PlotView::largestMarkerRadius() const {
  double radius = 0;
  for (const Entry& entry : m_entries) {
    const auto* scatter = qobject_cast<const QScatterSeries*>(entry.series);
    if (!scatter || !entry.inBounds || !scatter->isVisible() || entry.points().empty()) continue;
    radius = std::max(radius, 0.5 * scatter->markerSize() + 1.5);
  }
  return radius;
}

QRectF PlotView::wantedRange() {
  if (m_fixedRange) {
    // a fixed range, widened by 5 % of its span each side (not by pixels: the axes must not
    // move when a legend's height does): a marker on its edge (the 1IPP family's end at
    // T = T2) was cut in half by the frame
    QRectF range = *m_fixedRange;
    range.adjust(-0.05 * range.width(), -0.05 * range.height(), 0.05 * range.width(), 0.05 * range.height());
    return range;
  }
  const auto [xLow, xHigh, yLow, yHigh] = dataBounds();
  // each axis is padded on its own scale (an FFT axis near 8.9 must not inherit the 20 000 of
  // its contact-index axis), but never below 1e-3 of the plot's overall scale, so that a
  // coordinate that is zero up to round-off stays a flat line
  const double scaleX = std::max({std::abs(xLow), std::abs(xHigh), xHigh - xLow});
  const double scaleY = std::max({std::abs(yLow), std::abs(yHigh), yHigh - yLow});
  // (not across unrelated axes: 10^6 contacts made the flights' span of 0.01 a flat line at 1)
  const double overall = std::max(scaleX, scaleY);
  auto usable = [&](double scale) {
    const double floored = m_axesIndependent ? scale : std::max(scale, 1e-3 * overall);
    return std::isfinite(floored) && floored > 0 ? floored : 1.0;
  };
  const auto flatWidth = [&](double scale) { return 0.1 * usable(m_axesIndependent ? scale : overall); };
  auto [x0, x1] = padded(xLow, xHigh, usable(scaleX), flatWidth(scaleX));
  auto [y0, y1] = padded(yLow, yHigh, usable(scaleY), flatWidth(scaleY));
  // a marker on the data's edge is drawn whole: room for the largest marker's radius (and its
  // outline) beyond the padding, in pixels of the plot area (the start dot of mass 1 was cut)
  const double radius = largestMarkerRadius();
  const auto makeRoom = [radius](double& low, double& high, double pixels) {
    if (!(radius > 0) || !(pixels > 4 * radius)) return;
    const double room = (high - low) * radius / (pixels - 2 * radius);
    low -= room;
    high += room;
  };
  makeRoom(x0, x1, chart()->plotArea().width());
  makeRoom(y0, y1, chart()->plotArea().height());
  // the ends rounded outward to a quarter of the tick step: a small edit then keeps the axes
  // where they are (each axis change re-lays out every tick label as rich text, a third of
  // the GUI thread's time in a drag), and the range still depends on the data alone
  snapOutward(x0, x1);
  snapOutward(y0, y1);
  if (m_xWindow) {
    // a window of a long run: the time axis shows it, the other axis the whole run's range
    // (so that it does not jump while the window moves)
    x0 = m_xWindow->first;
    x1 = m_xWindow->second;
  }
  if (m_growing) {
    const QRectF shown(QPointF(m_axisX->min(), m_axisY->min()), QPointF(m_axisX->max(), m_axisY->max()));
    const bool fits = !m_newRun && shown.left() <= x0 && x1 <= shown.right() &&
                      shown.top() <= y0 && y1 <= shown.bottom();
    if (fits) return shown;
    const double dx = m_xWindow ? 0.0 : 0.25 * (x1 - x0);
    const double dy = 0.25 * (y1 - y0);
    x0 -= dx;
    x1 += dx;
    y0 -= dy;
    y1 += dy;
  }
  return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

void PlotView::refresh() {
  fitTitles();  // to the plot area as laid out now
  if (m_followData) {
    const QRectF range = wantedRange();
    const bool moves = range.left() != m_axisX->min() || range.right() != m_axisX->max() ||
                       range.top() != m_axisY->min() || range.bottom() != m_axisY->max();
    if (moves) {
      // empty the line series first: every axis change makes Qt Charts recompute and
      // re-stroke the path of every point a line holds, and the old points are about to be
      // replaced anyway. Scatter series keep theirs: Qt Charts reuses their marker items.
      for (Entry& entry : m_entries) {
        if (entry.series->count() > 0 && !qobject_cast<QScatterSeries*>(entry.series)) {
          entry.series->replace(QList<QPointF>());
          entry.drawnFrame.reset();  // (given again below, even on the frame it had)
        }
      }
      setRangeWithTicks(m_axisX, range.left(), range.right(), chart()->plotArea().width());
      setRangeWithTicks(m_axisY, range.top(), range.bottom(), chart()->plotArea().height());
    } else if (chart()->plotArea().size() != m_tickedArea) {
      // the same range on another size (a resize, presentation mode): ticks that fit it
      setRangeWithTicks(m_axisX, range.left(), range.right(), chart()->plotArea().width());
      setRangeWithTicks(m_axisY, range.top(), range.bottom(), chart()->plotArea().height());
    }
    m_tickedArea = chart()->plotArea().size();
  } else {
    // after a zoom or pan by the user: new ticks for the new range
    setRangeWithTicks(m_axisX, m_axisX->min(), m_axisX->max(), chart()->plotArea().width());
    setRangeWithTicks(m_axisY, m_axisY->min(), m_axisY->max(), chart()->plotArea().height());
  }
  m_newRun = false;
  placeStaleNote();
  const QRectF area = chart()->plotArea();
  PixelFrame frame{m_axisX->min(), m_axisX->max(), m_axisY->min(), m_axisY->max(),
                   std::max(1, int(area.width())), std::max(1, int(area.height()))};
  // one marker per marker-sized cell (at least 2 px: Qt Charts spends ~2 us on each marker
  // it holds, and a 2.5 px dot per pixel is 300 000 of them on a full plot): more would
  // overdraw the same pixels
  auto markerCells = [&frame](const QXYSeries* series) {
    const auto* scatter = qobject_cast<const QScatterSeries*>(series);
    const int cell = scatter ? std::max(2, int(scatter->markerSize() * 0.75)) : 1;
    PixelFrame coarse = frame;
    coarse.width = std::max(1, frame.width / cell);
    coarse.height = std::max(1, frame.height / cell);
    return coarse;
  };
  bool scratch = false;  // some series decimated from its first point
  if (!m_joinedScatters.empty()) {
    std::vector<PointSpan> sets;
    bool replaced = false;
    for (int index : m_joinedScatters) {
      sets.push_back(m_entries[std::size_t(index)].points());
      replaced = replaced || m_entries[std::size_t(index)].replaced;
    }
    const PixelFrame coarse = markerCells(m_entries[std::size_t(m_joinedScatters[0])].series);
    const std::vector<QList<QPointF>>& reduced = m_joinedReduced.update(sets, coarse, replaced);
    for (const auto& set : sets) scratch = scratch || (m_joinedReduced.startedOver() && !set.empty());
    for (std::size_t set = 0; set < reduced.size(); ++set) {
      Entry& entry = m_entries[std::size_t(m_joinedScatters[set])];
      entry.series->replace(reduced[set]);
      entry.replaced = false;
    }
  }
  for (std::size_t index = 0; index < m_entries.size(); ++index) {
    Entry& entry = m_entries[index];
    if (std::find(m_joinedScatters.begin(), m_joinedScatters.end(), int(index)) !=
        m_joinedScatters.end()) {
      continue;
    }
    if (!entry.series->isVisible()) {
      // hidden (its data still set the axes): nothing drawn, decimated afresh when shown
      if (entry.series->count() > 0) entry.series->clear();
      entry.replaced = true;
      entry.drawnFrame.reset();
      continue;
    }
    const bool replaced = entry.replaced;
    entry.replaced = false;
    const PointSpan points = entry.points();
    // the cells its points are reduced to
    PixelFrame cells = frame;
    if (entry.decimation == Decimation::Path) {
      // 2-pixel cells: Qt Charts strokes a hover shape for every line point, so each point
      // costs; a 1.2 px antialiased line looks the same
      cells.width = std::max(1, frame.width / 2);
      cells.height = std::max(1, frame.height / 2);
    } else if (entry.decimation == Decimation::Scatter) {
      cells = markerCells(entry.series);
    }
    if (!replaced && entry.drawnFrame == cells && entry.drawnCount == points.size()) continue;
    entry.drawnFrame = cells;
    entry.drawnCount = points.size();
    if (entry.decimation == Decimation::None) {
      QList<QPointF> all;
      all.reserve(qsizetype(points.size()));
      for (std::size_t index = 0; index < points.size(); ++index) all.append(points[index]);
      entry.series->replace(all);
    } else {
      entry.series->replace(entry.reduced->update(points, cells, replaced));
    }
    if (entry.reduced && entry.reduced->startedOver() && !points.empty()) scratch = true;
  }
  if (scratch) ++m_decimationsFromScratch;
  updateLegend();
  emit refreshed();
}

void PlotView::setInLegend(QXYSeries* series, bool shown) {
  m_legend->setShown(series, shown);
}

void PlotView::updateLegend() { m_legend->update(); }
const QStringList& PlotView::legendNames() const { return m_legend->names(); }
bool PlotView::legendFits() const { return m_legend->fits(); }

void PlotView::mousePressEvent(QMouseEvent* event) {
  emit activated(this);
  const bool pan = event->button() == Qt::MiddleButton ||
                   (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier));
  if (pan) {
    m_panning = true;
    m_lastPanPosition = event->position().toPoint();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
    return;
  }
  m_pressPosition = event->position().toPoint();
  QChartView::mousePressEvent(event);
}

void PlotView::mouseMoveEvent(QMouseEvent* event) {
  if (m_panning) {
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastPanPosition;
    m_lastPanPosition = position;
    chart()->scroll(-delta.x(), delta.y());
    userMovedView();
    event->accept();
    return;
  }
  QChartView::mouseMoveEvent(event);
}

void PlotView::mouseReleaseEvent(QMouseEvent* event) {
  if (m_panning) {
    m_panning = false;
    unsetCursor();
    event->accept();
    return;
  }
  // a rubber-band zoom (left) or zoom-out (right) shows up as changed ranges
  const QPointF before(m_axisX->min(), m_axisX->max());
  const QPointF beforeY(m_axisY->min(), m_axisY->max());
  QChartView::mouseReleaseEvent(event);
  if (before != QPointF(m_axisX->min(), m_axisX->max()) ||
      beforeY != QPointF(m_axisY->min(), m_axisY->max())) {
    userMovedView();
    return;
  }
  // a click, not a rubber band: where, in the data's coordinates
  const QPoint position = event->position().toPoint();
  if (event->button() == Qt::LeftButton && (position - m_pressPosition).manhattanLength() < 4 &&
      chart()->plotArea().contains(position)) {
    m_clickedValue = chart()->mapToValue(position);
    m_clickTimer.start(QApplication::doubleClickInterval());
  }
}

void PlotView::wheelEvent(QWheelEvent* event) {
  chart()->zoom(event->angleDelta().y() > 0 ? 1.25 : 0.8);
  userMovedView();
  event->accept();
}

void PlotView::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_R: resetView(); break;
    case Qt::Key_Plus:
    case Qt::Key_Equal: chart()->zoom(1.25); break;
    case Qt::Key_Minus: chart()->zoom(0.8); break;
    case Qt::Key_Left: chart()->scroll(-20, 0); break;
    case Qt::Key_Right: chart()->scroll(20, 0); break;
    case Qt::Key_Up: chart()->scroll(0, 20); break;
    case Qt::Key_Down: chart()->scroll(0, -20); break;
    default: QChartView::keyPressEvent(event); return;
  }
  if (event->key() != Qt::Key_R) userMovedView();
  event->accept();
}

void PlotView::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  if (m_emptyNote) m_emptyNote->setGeometry(rect().adjusted(16, 16, -16, -16));
  fitTitles();
  updateLegend();  // wraps to the new width
  // QChartView raises its own minimum size to the chart's and never lowers it: a legend of
  // many lines once would keep the plot (and the window) tall for good
  setMinimumSize(kMinimumSize);
  placeStaleNote();
  scheduleRefresh();
}

void PlotView::mouseDoubleClickEvent(QMouseEvent* event) {
  m_clickTimer.stop();  // its first click starts no run
  emit enlargeRequested(this);
  event->accept();
}

void PlotView::focusInEvent(QFocusEvent* event) {
  QChartView::focusInEvent(event);
  emit activated(this);
}

}  // namespace grazelab::ui
