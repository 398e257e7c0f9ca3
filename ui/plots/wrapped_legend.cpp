// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/wrapped_legend.h"

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QScatterSeries>
#include <QXYSeries>

#include <algorithm>
#include <cmath>

namespace grazelab::ui {

WrappedLegend::WrappedLegend(QChart* chart) : m_chart(chart), m_text(new QGraphicsTextItem(chart)) {
  m_chart->legend()->setVisible(false);
  m_text->setAcceptedMouseButtons(Qt::NoButton);
}

void WrappedLegend::setShown(QXYSeries* series, bool shown) {
  if (shown) m_leftOut.remove(series);
  else m_leftOut.insert(series);
}

void WrappedLegend::update() {
  // an entry never breaks inside: <nobr>, and word joiners around the dash of a range
  const QFont font = m_chart->legend()->font();
  const QFontMetricsF legendMetrics(font);
  const double width = std::max(40.0, m_chart->size().width() - 12);
  QString html;
  m_names.clear();
  for (QAbstractSeries* abstract : m_chart->series()) {
    auto* series = qobject_cast<QXYSeries*>(abstract);
    if (!series || series->name().isEmpty() || m_leftOut.contains(series)) continue;
    QString symbol = series->pen().style() == Qt::SolidLine ? QStringLiteral("━") : QStringLiteral("╍");
    QColor color = series->pen().color();
    if (auto* scatter = qobject_cast<QScatterSeries*>(series)) {
      // hollow markers (a transparent fill) show their outline colour
      const QColor fill = scatter->color();
      color = fill.alpha() == 0 ? scatter->pen().color() : fill;
      symbol = scatter->markerShape() == QScatterSeries::MarkerShapeRectangle
                   ? (fill.alpha() == 0 ? QStringLiteral("□") : QStringLiteral("■"))
               : scatter->markerShape() == QScatterSeries::MarkerShapeTriangle ? QStringLiteral("▲")
               : fill.alpha() == 0 ? QStringLiteral("○")
                                   : QStringLiteral("●");
    }
    color.setAlpha(255);
    m_names.append(series->name());
    if (!html.isEmpty()) html += QStringLiteral(" &nbsp; ");
    // an entry wider than the whole legend breaks between its words, never inside one (kept
    // whole, the text engine broke it anywhere: "grazi / ng")
    // (a chart not laid out yet is a few pixels wide: every entry would count as too wide)
    const bool whole = m_chart->size().width() < 120 ||
                       legendMetrics.horizontalAdvance(symbol + QLatin1Char(' ') + series->name()) <= width;
    html += QString::fromLatin1(whole ? "<nobr><span style=\"color:%1\">%2</span>&nbsp;%3</nobr>"
                                      : "<span style=\"color:%1\">%2</span>&nbsp;%3")
                .arg(color.name(), symbol,
                     series->name()
                         .toHtmlEscaped()
                         .replace(QStringLiteral("–"), QStringLiteral("\u2060–\u2060"))
                         .replace(QStringLiteral("-"), QStringLiteral("\u2011"))  // no break at a hyphen
                         .replace(QStringLiteral("/"), QStringLiteral("/\u2060"))  // nor after a slash
                         // and, in an entry kept whole, at no space either (<nobr> alone let
                         // "● |V| = 0.31" break after the "|", a break opportunity of its own)
                         .replace(QLatin1Char(' '), whole ? QStringLiteral("&nbsp;") : QStringLiteral(" "))
                         .replace(QLatin1Char('|'), whole ? QStringLiteral("|\u2060") : QStringLiteral("|")));
  }
  const bool changed = html != m_html || m_text->font() != font ||
                       std::abs(m_text->textWidth() - width) > 0.5;
  if (changed) {
    m_html = html;
    m_text->setFont(font);
    m_text->setTextWidth(width);
    m_text->setHtml(QStringLiteral("<div align=\"center\">%1</div>").arg(html));
  }
  // a chart not laid out yet (a few pixels wide) would wrap every word onto a line of its
  // own; the legend never takes more than 40 % of the chart's height
  const double chartHeight = m_chart->size().height();
  const bool laidOut = m_chart->size().width() >= 120 && chartHeight >= 90;
  const double full = m_text->boundingRect().height();
  const double height = html.isEmpty() || !laidOut ? 0.0 : std::min(full, 0.4 * chartHeight);
  m_fits = html.isEmpty() || (laidOut && height >= full);
  m_text->setVisible(height > 0);
  // clear of the card's rounded bottom edge (a last line sat on it)
  m_text->setPos(6, chartHeight - height - 6);
  // room under the axes for the text: the chart lays out again only when its height changes
  QMargins margins = m_chart->margins();
  margins.setBottom(8 + int(std::ceil(height)));
  if (m_chart->margins() != margins) m_chart->setMargins(margins);
}

}  // namespace grazelab::ui
