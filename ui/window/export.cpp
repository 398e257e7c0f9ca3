// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/window/export.h"

#include "ui/pictures/picture_file.h"

#include <QChart>
#include <QChartView>
#include <QLegend>
#include <QPointer>
#include <QPainter>
#include <QApplication>
#include <QScrollArea>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMenuBar>
#include <QScatterSeries>
#include <QValueAxis>
#include <QXYSeries>
#include <QWidget>

#include <optional>
#include <utility>

namespace grazelab::ui {
namespace {

// Qt Charts clips each legend to its shape; in a PDF painter that clip comes out empty (the
// legends lost every label but the first, and their swatches). Off while the page is drawn:
// the legend's items lie inside it anyway.
class LegendClipping {
 public:
  explicit LegendClipping(QWidget* widget) {
    for (QChartView* view : widget->findChildren<QChartView*>()) m_legends.append(view->chart()->legend());
    if (auto* view = qobject_cast<QChartView*>(widget)) m_legends.append(view->chart()->legend());
    for (QLegend* legend : m_legends) legend->setFlag(QGraphicsItem::ItemClipsChildrenToShape, false);
  }
  ~LegendClipping() {
    for (QLegend* legend : m_legends) legend->setFlag(QGraphicsItem::ItemClipsChildrenToShape, true);
  }
  LegendClipping(const LegendClipping&) = delete;
  LegendClipping& operator=(const LegendClipping&) = delete;

 private:
  QList<QPointer<QLegend>> m_legends;
};

// Qt's PDF engine does not clip a scroll area's content to its viewport: the parameter panel's
// rows below its visible part were drawn over the status bar. While the page is drawn, each
// visible scroll area's content is hidden and its viewport goes in as a picture of what it
// shows (3x), the rest as vectors.
class ScrollAreasAsPictures {
 public:
  explicit ScrollAreasAsPictures(QWidget* root) : m_focus(QApplication::focusWidget()) {
    for (QScrollArea* area : root->findChildren<QScrollArea*>()) {
      QWidget* content = area->widget();
      if (!area->isVisibleTo(root) || !content || !content->isVisibleTo(root)) continue;
      QWidget* viewport = area->viewport();
      m_pictures.append({QRect(viewport->mapTo(root, QPoint(0, 0)), viewport->size()),
                         renderImage(viewport, 3)});
      content->hide();
      m_hidden.append(content);
    }
  }
  ~ScrollAreasAsPictures() {
    for (QWidget* content : m_hidden) {
      if (content) content->show();
    }
    // hiding moved the focus out of the panel: it goes back where the user had it
    if (m_focus) m_focus->setFocus(Qt::OtherFocusReason);
  }
  ScrollAreasAsPictures(const ScrollAreasAsPictures&) = delete;
  ScrollAreasAsPictures& operator=(const ScrollAreasAsPictures&) = delete;

  void paint(QPainter& painter) const {
    for (const auto& [rect, image] : m_pictures) painter.drawImage(QRectF(rect), image);
  }

 private:
  QList<QPair<QRect, QImage>> m_pictures;
  QList<QPointer<QWidget>> m_hidden;
  QPointer<QWidget> m_focus;
};

// Qt 6.4's SVG generator writes no clipping at all: a chart's series ran past its plot area
// (the stop line of a time window across the neighbouring view, a zoomed curve over its axis
// title) and a menu bar's background covered its text. While an SVG is drawn each series
// holds only what its axes show — a line cut to the plot's rectangle (a piece that leaves and
// comes back in goes on in a series of its own, in the same pen, kept out of the legend; one
// series would join the pieces across the plot), markers inside it — and the menu bar, which
// is no content, is hidden.
class SeriesInTheirAxes {
 public:
  explicit SeriesInTheirAxes(QWidget* root) {
    QList<QChartView*> views = root->findChildren<QChartView*>();
    if (auto* view = qobject_cast<QChartView*>(root)) views.append(view);
    for (QChartView* view : views) {
      for (QAbstractSeries* abstract : view->chart()->series()) {
        auto* series = qobject_cast<QXYSeries*>(abstract);
        if (!series || !series->isVisible()) continue;
        const QRectF shown = axesRange(*series);
        if (!shown.isValid()) continue;
        const QList<QPointF> points = series->points();
        const QList<QList<QPointF>> pieces = qobject_cast<QScatterSeries*>(series)
                                                 ? QList<QList<QPointF>>{markersIn(points, shown)}
                                                 : linePieces(points, shown);
        if (pieces.size() == 1 && pieces.front() == points) continue;
        m_kept.append({series, points});
        series->replace(pieces.isEmpty() ? QList<QPointF>{} : pieces.front());
        for (qsizetype i = 1; i < pieces.size(); ++i) addPiece(*view->chart(), *series, pieces[i]);
      }
    }
    for (QMenuBar* bar : root->findChildren<QMenuBar*>()) {
      if (bar->isVisible()) {
        bar->hide();
        m_bars.append(bar);
      }
    }
  }
  ~SeriesInTheirAxes() {
    for (auto& [chart, piece] : m_pieces) {
      if (chart && piece) {
        chart->removeSeries(piece);
        delete piece;
      }
    }
    for (auto& [series, points] : m_kept) {
      if (series) series->replace(points);
    }
    for (QMenuBar* bar : m_bars) {
      if (bar) bar->show();
    }
  }
  SeriesInTheirAxes(const SeriesInTheirAxes&) = delete;
  SeriesInTheirAxes& operator=(const SeriesInTheirAxes&) = delete;

 private:
  static QRectF axesRange(QXYSeries& series) {
    const QValueAxis* x = nullptr;
    const QValueAxis* y = nullptr;
    for (QAbstractAxis* axis : series.attachedAxes()) {
      auto* value = qobject_cast<QValueAxis*>(axis);
      if (value && value->orientation() == Qt::Horizontal) x = value;
      if (value && value->orientation() == Qt::Vertical) y = value;
    }
    if (!x || !y) return {};
    return QRectF(QPointF(x->min(), y->min()), QPointF(x->max(), y->max()));
  }
  static QList<QPointF> markersIn(const QList<QPointF>& points, const QRectF& shown) {
    QList<QPointF> inside;
    for (const QPointF& p : points) {
      if (shown.contains(p)) inside.append(p);
    }
    return inside;
  }
  // The segment a-b cut to the rectangle (Liang-Barsky); nothing when it misses it.
  static std::optional<std::pair<QPointF, QPointF>> cut(const QPointF& a, const QPointF& b, const QRectF& r) {
    double t0 = 0, t1 = 1;
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0) return std::nullopt;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
      if (t0 > t1) return std::nullopt;
    }
    return std::pair{a + t0 * (b - a), a + t1 * (b - a)};
  }
  // The polyline's pieces inside the rectangle, in order.
  static QList<QList<QPointF>> linePieces(const QList<QPointF>& points, const QRectF& shown) {
    QList<QList<QPointF>> pieces;
    if (points.size() == 1 && shown.contains(points.front())) pieces.append(points);
    for (qsizetype i = 1; i < points.size(); ++i) {
      const auto inside = cut(points[i - 1], points[i], shown);
      if (!inside) continue;
      // a piece goes on where the last one ended (the segment started inside)
      if (pieces.isEmpty() || pieces.back().back() != inside->first) pieces.append({inside->first});
      pieces.back().append(inside->second);
    }
    return pieces;
  }
  void addPiece(QChart& chart, QXYSeries& like, const QList<QPointF>& points) {
    auto* piece = new QLineSeries;
    piece->setPen(like.pen());
    piece->append(points);
    chart.addSeries(piece);
    for (QAbstractAxis* axis : like.attachedAxes()) piece->attachAxis(axis);
    for (QLegendMarker* marker : chart.legend()->markers(piece)) marker->setVisible(false);
    m_pieces.append({&chart, piece});
  }

  QList<QPair<QPointer<QChart>, QPointer<QLineSeries>>> m_pieces;
  QList<QPair<QPointer<QXYSeries>, QList<QPointF>>> m_kept;
  QList<QPointer<QMenuBar>> m_bars;
};

}  // namespace

QImage renderImage(QWidget* widget, qreal pixelRatio, QRect area) {
  if (area.isEmpty()) area = widget->rect();
  QImage image(area.size() * pixelRatio, QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(pixelRatio);
  image.fill(widget->palette().color(QPalette::Window));
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  widget->render(&painter, QPoint(), QRegion(area));
  return image;
}

bool saveSnapshot(QWidget* widget, const QString& path, const QByteArray& sessionJson,
                  const QString& title, QString* error, QRect area) {
  if (area.isEmpty()) area = widget->rect();
  // the area drawn in the widget's own coordinates, moved to the picture's corner
  const auto draw = [widget, area](QPainter& painter) {
    painter.translate(-area.topLeft());
    widget->render(&painter, area.topLeft(), QRegion(area));
  };
  const auto format = pictures::pictureFormat(path);
  if (!format) {
    if (error) *error = QStringLiteral("unknown picture type for %1: use .png, .svg or .pdf").arg(path);
    return false;
  }
  const pictures::PictureMetadata metadata{title, QStringLiteral("GrazeLabSession"), sessionJson};
  switch (*format) {
    case pictures::PictureFormat::Png: return pictures::writePng(path, renderImage(widget, 2.0, area), metadata, error);
    case pictures::PictureFormat::Svg:
      return pictures::writeSvg(path, area.size(), [widget, draw](QPainter& painter) {
        // no clipping in Qt 6.4's SVG (see SeriesInTheirAxes): the panel as a picture of what
        // it shows, as in a PDF, and each series held to its axes
        const SeriesInTheirAxes held(widget);
        const ScrollAreasAsPictures shown(widget);
        draw(painter);
        shown.paint(painter);
      }, metadata, error, widget->logicalDpiY());
    case pictures::PictureFormat::Pdf:
      return pictures::writePdf(path, area.size(), [widget, draw](QPainter& painter) {
        const LegendClipping unclipped(widget);
        const ScrollAreasAsPictures shown(widget);
        draw(painter);
        shown.paint(painter);
      }, metadata, error);
  }
  return false;
}

bool saveFileAtomically(const QString& path, const QByteArray& data, QString* error) {
  return pictures::saveFileAtomically(path, data, error);
}

}  // namespace grazelab::ui
