#include "io/MissionScale.hpp"

#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/PlanningError.hpp"
#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mcpp::io {

namespace {

// "57 million", "830 000": a count a reader takes in at once.
std::string roundCount(double count) {
    char text[32];
    if (count >= 1e6)
        std::snprintf(text, sizeof text, "%.*f million", count >= 1e7 ? 0 : 1, count / 1e6);
    else
        std::snprintf(text, sizeof text, "%.0f", std::round(count / 1000.0) * 1000.0);
    return text;
}

bool plansOnUniformGrid(const PlannerChoice& choice) {
    const auto description = findPlannerDescription(choice.planner);
    try {
        return description &&
               !description->plansOnQuadTree(resolveParameters(description->parameters, choice.parameters));
    } catch (const PlanningError&) {
        return false; // a bad parameter is said where the problem is made
    }
}

bool fitsInMemory(const LoadedRaster& raster, const ClassTable& classes, const PlannerChoice& choice) {
    const auto memory = planningMemory(raster, classes, choice);
    return !memory || memory->estimate.fits();
}

} // namespace

std::optional<PlanningMemory> planningMemory(const LoadedRaster& raster, const ClassTable& classes,
                                             const PlannerChoice& choice) {
    const std::vector<RoundedFieldOfView> rounded = roundFieldsOfView(classes, presentClassValues(raster));
    if (rounded.empty())
        return std::nullopt;
    PlanningMemory memory;
    memory.smallestFieldOfViewMetres = rounded.front().roundedMetres;
    for (const RoundedFieldOfView& entry : rounded) {
        memory.smallestFieldOfViewMetres = std::min(memory.smallestFieldOfViewMetres, entry.roundedMetres);
        memory.levels = std::max(memory.levels, entry.level);
    }
    const auto planner = findPlannerDescription(choice.planner);
    const std::int64_t bytesPerCell = planner ? planner->bytesPerBottomCell : unmeasuredBytesPerBottomCell;
    const double fovMin = memory.smallestFieldOfViewMetres;
    if (plansOnUniformGrid(choice))
        memory.levels = 1;
    if (memory.levels > mostSizedLevels) {
        memory.estimate = estimateCellBudget(raster.grid.width(), raster.grid.height(), fovMin, memory.levels,
                                             bytesPerCell);
        return memory;
    }
    // A quadtree, and a uniform grid as one of one level, spans the top cells that hold the task area's
    // pixels (QuadTreeBuilder, UniformGridDecomposition).
    const QuadTreeGridSize size =
        quadTreeGridSize(raster.grid.width(), raster.grid.height(), fovMin, memory.levels);
    const TopCellWindow window = topCellsOver(size, raster.grid, pixelsInside(raster.grid));
    memory.estimate = estimateCellBudget(window.columns * size.topCellSize, window.rows * size.topCellSize,
                                         fovMin, memory.levels, bytesPerCell);
    return memory;
}

double MissionScale::fieldOfViewFactorFor(double points) const {
    if (coveragePoints <= points || points <= 0.0)
        return 1.0;
    // Points shrink with the square of the factor.
    const double factor = std::sqrt(coveragePoints / points);
    const double step = std::pow(10.0, std::floor(std::log10(factor)) - 1.0);
    return std::ceil(factor / step - 1e-9) * step;
}

MissionScale missionScale(const LoadedRaster& raster, const ClassTable& classes, std::size_t robots,
                          const std::vector<PlannerChoice>& planners) {
    const bool uniformGrid = std::any_of(planners.begin(), planners.end(), plansOnUniformGrid);
    MissionScale scale;
    scale.planners = std::max(1, static_cast<int>(planners.size()));
    const double pixelArea = raster.grid.pixelWidth * raster.grid.pixelHeight;
    double sweepSeconds = 0.0;
    for (const auto& [value, count] : raster.classPixelCounts) {
        const LandCoverClass* landCover = classes.find(value);
        if (landCover == nullptr || !landCover->isTraversable() || !(landCover->fieldOfViewMetres > 0.0))
            continue;
        const double area = static_cast<double>(count) * pixelArea;
        scale.passableSquareMetres += area;
        sweepSeconds += area / (landCover->fieldOfViewMetres * landCover->speedMetresPerSecond);
        if (scale.smallestFieldOfViewMetres == 0.0 ||
            landCover->fieldOfViewMetres < scale.smallestFieldOfViewMetres) {
            scale.smallestFieldOfViewMetres = landCover->fieldOfViewMetres;
            scale.smallestFieldOfViewClass = landCover->name;
        }
        if (!uniformGrid)
            scale.coveragePoints += area / (landCover->fieldOfViewMetres * landCover->fieldOfViewMetres);
    }
    if (uniformGrid && scale.smallestFieldOfViewMetres > 0.0)
        scale.coveragePoints =
            scale.passableSquareMetres / (scale.smallestFieldOfViewMetres * scale.smallestFieldOfViewMetres);
    scale.sweepSeconds = robots > 0 ? sweepSeconds / static_cast<double>(robots) : 0.0;
    return scale;
}

double largeMissionPointsFor(int planners) {
    return planners > 1 ? largeMissionPoints / 4.0 : largeMissionPoints;
}

std::optional<std::string> largeMissionWarning(const MissionScale& scale, bool atTableSpeeds,
                                               const std::function<std::string(double factor)>& remedy) {
    const double largest = largeMissionPointsFor(scale.planners);
    if (!(scale.coveragePoints > largest))
        return std::nullopt;
    std::string text =
        "a large mission: covering " + formatArea(scale.passableSquareMetres) +
        " of passable land at fields of view down to " + formatQuantity(scale.smallestFieldOfViewMetres, 3) +
        " m (" + scale.smallestFieldOfViewClass + ") takes paths through about " +
        roundCount(scale.coveragePoints) + " places: planning may take minutes" +
        (scale.planners > 1 ? " for each of the " + std::to_string(scale.planners) + " planners" : "") +
        " and writes hundreds of megabytes or more";
    if (atTableSpeeds && scale.sweepSeconds > 0.0)
        text += ", and no plan at the class table's speeds is done in under " +
                formatDuration(scale.sweepSeconds);
    const double factor = scale.fieldOfViewFactorFor(largest);
    text += ". " + remedy(factor) + " brings it to about " +
            roundCount(scale.coveragePoints / (factor * factor)) + " places";
    return text;
}

std::optional<std::string> largeMissionWarning(const Mission& mission, const LoadedRaster& raster,
                                               const ClassTable& classes,
                                               const std::vector<PlannerChoice>& planners,
                                               const std::function<std::string(double factor)>& remedy) {
    for (const PlannerChoice& choice : planners)
        if (!fitsInMemory(raster, classes, choice))
            return std::nullopt;
    const bool atTableSpeeds =
        std::none_of(mission.robots.begin(), mission.robots.end(), [&](const RobotSpec& robot) {
            return robot.vehicle.over(mission.exports.vehicle).cruiseSpeedMetresPerSecond > 0.0;
        });
    return largeMissionWarning(missionScale(raster, classes, mission.robots.size(), planners), atTableSpeeds,
                               remedy);
}

} // namespace mcpp::io
