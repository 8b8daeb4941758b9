#pragma once

#include "core/coverage/ImpassableCrossings.hpp"
#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"

#include <QColor>
#include <QFont>
#include <QPainter>
#include <QString>
#include <string>
#include <utility>
#include <vector>

namespace mcpp::render {

// How a legend line shows its colour: as the map draws that thing.
enum class LegendSymbol {
    Swatch,
    Obstacle,
    RegionTint,
    PathLine,
    StartMarker,
    Unreachable,
    TakenOver,
    CellOutline,
    Crossing,
    FlightReach,
    AreaEdge,
    NoGoZone
};

struct LegendItem {
    LegendSymbol symbol = LegendSymbol::Swatch;
    QColor colour;
    QString label;
    QString marker; // text inside a start marker
};

// What a section lists: found by this, not by its title, which may change.
enum class LegendSectionKind { LandCover, Robots, OnTheMap };

struct LegendSection {
    // No default: every section is made saying what it lists.
    LegendSection(LegendSectionKind sectionKind, QString sectionTitle,
                  std::vector<LegendItem> sectionItems = {})
        : kind(sectionKind), title(std::move(sectionTitle)), items(std::move(sectionItems)) {}

    LegendSectionKind kind;
    QString title;
    std::vector<LegendItem> items;
};

// What the map shows, for the window's legend and the exported pictures: the land-cover classes (obstacles
// marked), each robot by colour, number, name and time when there is a plan, and what the overlays mean
// (with the land cover `grid`, also whether any path crosses impassable land; `crossings`: the plan's, when
// the caller has found them already, else looked for here).
[[nodiscard]] std::vector<LegendSection>
planLegend(const ClassTable& classes, const Plan* plan, const std::vector<std::string>& robotNames,
           const ClassGrid* grid = nullptr, const std::vector<ImpassableCrossing>* crossings = nullptr);

// When a robot is done in the field, where that comes later than its path takes: an aircraft's trips to
// and from its start, the turnarounds between the parts of its mission.
struct FieldTime {
    double seconds = 0.0;  // 0: when its path is done
    std::size_t parts = 0; // of its mission
    bool flights = false;  // the parts are flights (an aircraft's)
};

// The robot's field time where it is done in the field more than a second after its path takes; none
// otherwise (a rover driving its mission in one go, without turnarounds).
[[nodiscard]] FieldTime fieldTimeBeyondPath(double pathSeconds, double fieldSeconds, std::size_t parts,
                                            bool flights);

// Adds to each robot's line of the legend when it is done in the field, where `times` (by robot) has it.
void addFieldTimes(std::vector<LegendSection>& sections, const std::vector<FieldTime>& times);

// Adds the line for the dashed rings round aircraft starts (PlanRenderer::setFlightReach) to the legend's
// "On the map" section (making one when there is no plan yet) when any robot's reach (by robot, metres) is
// drawn.
void addFlightReach(std::vector<LegendSection>& sections, const std::vector<double>& reaches);

// Adds the lines for the area of interest's edge and the no-go zones (PlanRenderer::setArea) to the
// legend's "On the map" section (making one when there is no plan yet), for those the area has.
void addAreaOutline(std::vector<LegendSection>& sections, const AreaOutline& area);

// The size the legend needs in this font, and the legend itself drawn from topLeft.
[[nodiscard]] QSizeF legendSize(const std::vector<LegendSection>& sections, const QFont& font);
void paintLegend(QPainter& painter, QPointF topLeft, const std::vector<LegendSection>& sections);

} // namespace mcpp::render
