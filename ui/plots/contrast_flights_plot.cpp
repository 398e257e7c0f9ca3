// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "ui/plots/contrast_flights_plot.h"

#include <QLineSeries>
#include <QScatterSeries>

#include <algorithm>

#include "ui/plots/plot_style.h"

namespace grazelab::ui {
namespace {

constexpr double kCap = 3;  // [T]: flights past it are drawn on the top edge

}  // namespace

ContrastFlightsPlot::ContrastFlightsPlot(QWidget* parent)
    : PlotView(tr("Detuned contrast"), tr("contact index"), tr("flight / T"), parent) {
  auto* flights = makeScatter(tr("flights"), colors::kTrace, 5.5);
  flights->setPen(Qt::NoPen);
  m_flights = addEntry(flights, Decimation::Scatter);
  m_bound = addEntry(makeLine(tr("T"), colors::kReference, 1.5, Qt::DashLine), Decimation::None);
  auto* past = makeScatter(tr("past 3 T"), colors::kImpact, 12);
  past->setPen(QPen(Qt::white, 1.5));
  useLightMarker(past, QPen(Qt::white, 1.5));
  m_past = addEntry(past, Decimation::Scatter);
  setAxesIndependent(true);
}

void ContrastFlightsPlot::show(const SimUpdate& update) {
  const SceneJob& job = update.request->job;
  const auto found = job.viewWords.find(PlotKind::ContrastFlights);
  const ViewWords words = found != job.viewWords.end() ? found->second : ViewWords{};
  if (job.spec.chains.size() < 2) {
    // no contrast for this chain: the scene says why
    setToolTip(words.toolTip);
    setData(m_flights, {});
    setData(m_past, {});
    setData(m_bound, {});
    setFixedRange(std::nullopt);
    setTitles(words.title, tr("contact index"), tr("flight / T"));
    setEmptyNote(words.whyEmpty);
    scheduleRefresh();
    return;
  }
  setEmptyNote(QString());
  if (update.chains.size() < 2 || update.chains.front()->period <= 0) {
    // its run not yet there: the contrast drawn so far stays, faded, its title too (a title
    // that said "computing" at each edit of a drag laid the chart out twice an edit)
    const bool drawn = !entries()[std::size_t(m_flights)].data.empty() || !entries()[std::size_t(m_past)].data.empty();
    if (drawn) {
      setFaded(true);
    } else {
      setTitles(tr("%1: computing…").arg(words.title), tr("contact index"), tr("flight / T"));
    }
    scheduleRefresh();
    return;
  }
  setFaded(false);
  const core::experiments::ChainSeries& detuned = *update.chains[1];
  const double T = update.chains.front()->period;
  std::vector<QPointF> below, past;
  double last = 1;
  for (const core::experiments::ChainFlight& flight : detuned.flights) {
    if (!flight.fromStop) continue;
    const QPointF point(double(flight.contact - 1), flight.duration / T);
    (point.y() > kCap ? past : below).emplace_back(point.x(), std::min(point.y(), kCap));
    last = std::max(last, point.x());
  }
  const std::size_t count = below.size() + past.size();
  // the title changes only when what it says does (the count past 3 T is in the tooltip)
  QString title = tr("%1: flights / the resonant T").arg(words.title);
  setFixedRange(std::nullopt);
  if (!past.empty()) {
    title = tr("%1: flights / T (past 3 T: on the top edge)").arg(words.title);
    setFixedRange(QRectF(QPointF(0, 0), QPointF(last * 1.02, kCap + 0.1)));
  }
  if (detuned.run.stop == core::StopReason::SearchBudget) {
    // its last flight never came back within the search's 1000 slowest periods: said, rather
    // than let the chart end as if the run had
    title = count == 0
                ? tr("%1: no flight from the stop ends in 1000 slow periods").arg(words.title)
            : count == 1
                ? tr("%1: 1 flight, then none in 1000 slow periods").arg(words.title)
                : tr("%1: %2 flights, then none in 1000 slow periods").arg(words.title).arg(count);
  }
  setToolTip(past.empty() ? words.toolTip
                          : tr("%1\n\n%2 of its %3 flights last longer than 3 T: drawn on the top edge.")
                                .arg(words.toolTip)
                                .arg(past.size())
                                .arg(count));
  setTitles(title, tr("contact index"), tr("flight / T"));
  setData(m_flights, std::move(below));
  setData(m_past, std::move(past));
  setData(m_bound, {QPointF(0, 1), QPointF(last, 1)});
  scheduleRefresh();
}

void ContrastFlightsPlot::setFaded(bool faded) {
  for (int entry : {m_flights, m_past}) entries()[std::size_t(entry)].series->setOpacity(faded ? 0.3 : 1.0);
}

}  // namespace grazelab::ui
