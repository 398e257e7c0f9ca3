// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <optional>
#include <vector>

#include "core/model/state.h"
#include "core/experiments/maps.h"
#include "ui/pictures/heat_map.h"
#include "ui/plots/scene_view.h"
#include "ui/compute/sim_types.h"

class QComboBox;
class QLabel;
class QToolButton;

namespace grazelab::ui {

/// The landscape scene's map (issue 10): a quantity of the map on the grazing-start plane
/// (u1, v1 with u2 = d, v2 = 0) as a viridis colour map, drawn as the worker's rows come in,
/// with the grazing family GLO(λ), λ in [0, 4/3], and GLOM1, GLOM2 marked and the current run's
/// Poincaré points (u1, v1 at each contact: the same plane) over it. A click asks for a run
/// from that point; a dragged rectangle asks for that region computed anew; Back returns.
class LandscapeView : public QWidget, public SceneView {
  Q_OBJECT

 public:
  explicit LandscapeView(QWidget* parent = nullptr);

  QWidget* widget() override { return this; }
  /// The map alone: not the quantity box, the Back button or the status line above it.
  QRect pictureArea() const override { return mapArea().toAlignedRect(); }
  void show(const SimUpdate& update) override;
  void setPresentation(bool on, int textPixels) override;
  /// The map's finished cells (x = u1, y = v1 of the start, value = the quantity shown) and
  /// the grazing family drawn over it.
  void appendCsv(CsvTable& table) const override;
  QString viewTitle() const override { return tr("Landscape map"); }

  /// The map shown (nothing before the first one arrives).
  const std::optional<MapProgress>& map() const { return m_map; }
  core::Quantity quantity() const { return m_quantity; }
  void setQuantity(core::Quantity quantity);
  /// Whether Back has somewhere to go (the window keeps the regions; it sets this).
  void setBackEnabled(bool enabled);
  /// The value coordinates (u1, v1) of a widget position (nothing outside the map).
  std::optional<QPointF> valueAt(QPointF position) const;
  /// The widget position of value coordinates (u1, v1).
  QPointF positionOf(QPointF value) const;

 signals:
  /// A click on the map: run from (u1, gap, v1, 0).
  void startRequested(const grazelab::core::State& start);
  /// A rectangle dragged on the map: compute [u1From, u1To] x [v1From, v1To] anew.
  void regionRequested(QRectF region);
  void backRequested();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  QRectF mapArea() const;  ///< where the map, its axes and colour bar are painted
  QRectF plotRect() const;  ///< the cells' rectangle inside mapArea()
  /// positionOf in the cells' rectangle `plot` (plotRect(): its margins come from the colour
  /// bar's range, a pass over every cell; a paint takes it once, not once a point drawn)
  QPointF positionIn(const QRectF& plot, QPointF value) const;
  pictures::HeatMapData heatMapDataOf(const MapProgress& map) const;  ///< the chosen quantity's cells

  QComboBox* m_quantityBox = nullptr;
  QToolButton* m_back = nullptr;
  QLabel* m_status = nullptr;
  core::Quantity m_quantity = core::Quantity::FftFirst;
  std::optional<MapProgress> m_map;
  double m_T2 = 0;  ///< the chain's slow period: times on the map are shown in its units
  double m_gap = 1;
  QString m_cost;  ///< what the map cost (or how far it is), for the key under it
  std::vector<QPointF> m_family;      ///< GLO(λ) data (u1, v1) for λ in [0, 4/3]
  QPointF m_glom1, m_glom2;           ///< GLOM1 and GLOM2 data
  std::vector<QPointF> m_section;     ///< the run's (u1, v1) at each contact
  std::optional<QPointF> m_start;     ///< the run's start, when it lies on the plane
  std::optional<QPointF> m_pressAt;   ///< where a press began (a click or a drag)
  QPointF m_dragTo;
  int m_textPixels = 0;               ///< presentation text size (0: the desk look)
  struct CacheKey {
    const void* points = nullptr;
    core::MapSpec spec;  ///< with the grid's address: a freed grid's address may come back
    std::int64_t rowsDone = -1;
    core::Quantity quantity = core::Quantity::FftFirst;
    friend bool operator==(const CacheKey&, const CacheKey&) = default;
  };
  CacheKey m_cacheKey;  ///< what m_data and m_image show
  pictures::HeatMapData m_data;
  QImage m_image;
};

}  // namespace grazelab::ui
