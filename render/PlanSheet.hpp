#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "core/outlines/RegionOutlines.hpp"
#include "render/PlanFrame.hpp"
#include "render/PlanLegend.hpp"

#include <QPainter>
#include <QRect>
#include <QSize>
#include <string>
#include <vector>

namespace mcpp::render {

// What a sheet shows beside the plan, when the caller has it.
struct SheetExtras {
    const RegionOutlines* outlines = nullptr; // the plan's region outlines; traced here when null
    std::vector<std::string> robotNames;      // by robot; empty names read "Robot n"
    std::vector<double> flightReach;          // by robot, metres: rings round aircraft starts
    const AreaOutline* area = nullptr;        // the area of interest's and no-go zones' edges, if any
    std::vector<FieldTime> fieldTimes;        // by robot, where done in the field later than its path
};

// The exported picture of a plan as a map sheet: a title, the map (the plan's frame, planFrame) fitted into
// maxMapSize with a scale bar
// and a north arrow, and the legend beside it (classes, robots with names and times, overlays).
class PlanSheet {
  public:
    PlanSheet(const ClassGrid& grid, const ClassTable& classes, const Plan& plan, SheetExtras extras,
              QSize maxMapSize);
    // The map's size fitted into maxSize, keeping its aspect.
    [[nodiscard]] static QSize fittedMapSize(const ClassGrid& grid, QSize maxSize);
    // Loads the font database, which the first sheet of a process otherwise waits for; safe on any thread
    // once the QGuiApplication exists.
    static void prepareFonts();
    [[nodiscard]] QSize size() const { return size_; }
    [[nodiscard]] QRect mapArea() const { return map_; }
    [[nodiscard]] QRectF legendArea() const { return legend_; }
    [[nodiscard]] const QString& title() const { return title_; }
    [[nodiscard]] const std::vector<LegendSection>& legend() const { return sections_; }
    void paint(QPainter& painter) const;

  private:
    const ClassGrid& grid_;
    const ClassTable& classes_;
    const Plan& plan_;
    SheetExtras extras_;
    // Found once for the legend and the map: a scan of every cell's pixels.
    std::vector<ImpassableCrossing> crossings_;
    std::vector<LegendSection> sections_;
    QString title_;
    std::vector<FrameRing> rings_; // the robots' flight-reach rings (flightReachRings)
    ClassGrid frame_;              // the part of the raster the map shows (planFrame)
    QFont font_;
    QFont titleFont_;
    QSize size_;
    QRect map_;
    QRectF legend_;
};

} // namespace mcpp::render
