#include "io/PlanFile.hpp"

#include "core/coverage/PathMeasurement.hpp"
#include "core/coverage/StraightRunMerging.hpp"
#include "core/model/MemoryBudget.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/TurnTimeModel.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/AtomicFile.hpp"
#include "io/internal/CompressedReader.hpp"
#include "io/internal/CompressedWriter.hpp"
#include "io/internal/TextFiles.hpp"

#include <QCryptographicHash>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace mcpp::io {

namespace {

using internal::CompressedReader;
using internal::CompressedWriter;

// Files of the versions before are read as well: 3 without the paths' counts of walked waypoints (none had
// its straight runs merged), 4 without the times in the field, 5 without the paths' take-off points, 6
// without the shared parts' ratio and the kind of bound.
constexpr const char* formatName = "MCPP-PLAN ";
constexpr int oldestFormatVersion = 3;
constexpr std::uint32_t endMarker = 0x4e414c50; // "PLAN": the last thing written

// Size and time of last change of a file: a different file at the same path changes them. Empty when they
// cannot be read (a path GDAL reads through a virtual file system, a file gone).
std::string fileIdentity(const std::string& path) {
    if (path.empty())
        return "-";
    std::error_code sizeError;
    std::error_code timeError;
    const auto size = std::filesystem::file_size(path, sizeError);
    const auto changed = std::filesystem::last_write_time(path, timeError);
    if (sizeError || timeError)
        return {};
    return std::to_string(size) + " " + std::to_string(changed.time_since_epoch().count());
}

std::string absoluteNormal(const std::string& path) {
    return std::filesystem::absolute(path).lexically_normal().string();
}

void putParameters(CompressedWriter& out, const ParameterValues& parameters) {
    out.put(static_cast<std::uint64_t>(parameters.all().size()));
    for (const auto& [key, value] : parameters.all()) {
        out.put(key);
        out.put(static_cast<std::uint8_t>(value.index()));
        std::visit(
            [&](const auto& held) {
                using Held = std::decay_t<decltype(held)>;
                if constexpr (std::is_same_v<Held, bool>)
                    out.put(static_cast<std::uint8_t>(held));
                else
                    out.put(held);
            },
            value);
    }
}

ParameterValues getParameters(CompressedReader& in) {
    ParameterValues parameters;
    for (std::size_t count = in.getCount(10); count > 0; --count) {
        std::string key = in.getString();
        switch (in.get<std::uint8_t>()) {
        case 0:
            parameters.set(key, in.get<std::uint8_t>() != 0);
            break;
        case 1:
            parameters.set(key, in.get<int>());
            break;
        case 2:
            parameters.set(key, in.get<double>());
            break;
        case 3:
            parameters.set(key, in.getString());
            break;
        default:
            throw CompressedReader::DamagedData("a parameter of unknown type");
        }
    }
    return parameters;
}

// As two lists (offsets, then neighbours), the way a reader of the format finds them, made cell by cell:
// a grid keeps none to write at once.
void putNeighbours(CompressedWriter& out, const CellGraph& graph) {
    out.put(static_cast<std::uint64_t>(graph.size() + 1));
    std::size_t listed = 0;
    out.put(0);
    for (std::size_t id = 0; id < graph.size(); ++id) {
        listed += graph.neighbours(static_cast<int>(id)).size();
        out.put(static_cast<int>(listed));
    }
    out.put(static_cast<std::uint64_t>(listed));
    for (std::size_t id = 0; id < graph.size(); ++id)
        for (const int neighbour : graph.neighbours(static_cast<int>(id)))
            out.put(neighbour);
}

void putCells(CompressedWriter& out, const CellGraph& graph) {
    const GridFrame& frame = graph.frame();
    out.put(frame.originX);
    out.put(frame.originY);
    out.put(frame.bottomCellSize);
    out.put(frame.columns);
    out.put(frame.rows);
    out.put(frame.levels);
    out.put(static_cast<std::uint64_t>(graph.size()));
    for (const Cell& cell : graph.cells()) {
        out.put(cell.column);
        out.put(cell.row);
        out.put(int{cell.span});
        out.put(int{cell.level});
        out.put(cell.minX);
        out.put(cell.minY);
        out.put(cell.size);
        out.put(cell.classValue);
        out.put(cell.turnSecondsPer90Degrees);
        out.put(double{cell.speedMetresPerSecond});
        out.put(double{cell.passableAreaSquareMetres});
        out.put(cell.freeSubCells);
        out.put(cell.expectedTurnsPerSubCell);
    }
    putNeighbours(out, graph);
    out.put(static_cast<std::uint64_t>(graph.fieldsOfView.size()));
    for (const RoundedFieldOfView& rounded : graph.fieldsOfView) {
        out.put(rounded.classValue);
        out.put(rounded.originalMetres);
        out.put(rounded.roundedMetres);
        out.put(rounded.level);
    }
    out.put(graph.passableAreaSquareMetres);
}

void checkAdjacency(const std::vector<int>& offsets, const std::vector<int>& neighbours, std::size_t cells) {
    if (offsets.size() != cells + 1 || offsets.front() != 0 ||
        static_cast<std::size_t>(offsets.back()) != neighbours.size())
        throw CompressedReader::DamagedData("neighbour lists that do not match the cells");
    for (std::size_t i = 0; i + 1 < offsets.size(); ++i)
        if (offsets[i] > offsets[i + 1])
            throw CompressedReader::DamagedData("neighbour lists out of order");
    for (const int neighbour : neighbours)
        if (neighbour < 0 || static_cast<std::size_t>(neighbour) >= cells)
            throw CompressedReader::DamagedData("a neighbour that is not a cell");
}

CellGraph getCells(CompressedReader& in) {
    GridFrame frame;
    frame.originX = in.get<double>();
    frame.originY = in.get<double>();
    frame.bottomCellSize = in.get<double>();
    frame.columns = in.get<int>();
    frame.rows = in.get<int>();
    frame.levels = in.get<int>();
    if (!std::isfinite(frame.originX) || !std::isfinite(frame.originY) || !(frame.bottomCellSize > 0.0) ||
        !std::isfinite(frame.bottomCellSize) || frame.columns < 0 || frame.rows < 0 || frame.levels < 1)
        throw CompressedReader::DamagedData("a grid with no place on the map");
    if (frame.levels > mostQuadTreeLevels)
        throw CompressedReader::DamagedData("a quadtree of more levels than any planner makes");
    // A grid no plan of this machine could have (planning refuses such maps) would make the outlines of a
    // restored plan allocate without bound.
    if (static_cast<double>(frame.columns) * frame.rows * static_cast<double>(leastBytesPerBottomCell()) >
        static_cast<double>(memoryBudgetBytes()))
        throw CompressedReader::DamagedData("a grid larger than this machine can plan");
    // A cell's square is kept in the file for other readers; the graph works it out from the frame again.
    std::vector<CellRecord> cells(in.getCount(69));
    std::vector<float> turnSeconds;
    std::vector<float> expectedTurns;
    turnSeconds.reserve(cells.size());
    expectedTurns.reserve(cells.size());
    for (CellRecord& record : cells) {
        Cell cell;
        cell.column = in.get<int>();
        cell.row = in.get<int>();
        const int span = in.get<int>();
        const int level = in.get<int>();
        cell.minX = in.get<double>();
        cell.minY = in.get<double>();
        cell.size = in.get<double>();
        cell.classValue = in.get<std::int32_t>();
        cell.turnSecondsPer90Degrees = in.get<float>();
        cell.speedMetresPerSecond = static_cast<float>(in.get<double>());
        cell.passableAreaSquareMetres = static_cast<float>(in.get<double>());
        cell.freeSubCells = in.get<std::uint8_t>();
        cell.expectedTurnsPerSubCell = in.get<float>();
        if (level < 1 || level > frame.levels || level > 255)
            throw CompressedReader::DamagedData("a cell on no level of the quadtree");
        cell.level = static_cast<std::uint8_t>(level);
        // Spans are powers of two up to the largest a quadtree makes; 0 would divide by zero in lookups.
        if (span <= 0 || span > largestSpan || (span & (span - 1)) != 0)
            throw CompressedReader::DamagedData("a cell of a size no quadtree makes");
        cell.span = static_cast<std::uint16_t>(span);
        if (cell.column < 0 || cell.row < 0 || std::int64_t{cell.column} + cell.span > frame.columns ||
            std::int64_t{cell.row} + cell.span > frame.rows || !std::isfinite(cell.minX) ||
            !std::isfinite(cell.minY) || !(cell.size > 0.0) || !std::isfinite(cell.size) ||
            !(cell.turnSecondsPer90Degrees >= 0.0F) || !std::isfinite(cell.turnSecondsPer90Degrees) ||
            !(cell.expectedTurnsPerSubCell >= 0.0F) || !std::isfinite(cell.expectedTurnsPerSubCell))
            throw CompressedReader::DamagedData("a cell with no place on the grid");
        record = recordOf(cell);
        turnSeconds.push_back(cell.turnSecondsPer90Degrees);
        expectedTurns.push_back(cell.expectedTurnsPerSubCell);
    }
    std::vector<int> offsets = in.getAll<int>();
    std::vector<int> neighbours = in.getAll<int>();
    checkAdjacency(offsets, neighbours, cells.size());
    CellGraph graph(frame, std::move(cells), NeighbourTopology(std::move(offsets), std::move(neighbours)));
    graph.setTurnSeconds(std::move(turnSeconds));
    graph.setExpectedTurns(expectedTurns);
    graph.fieldsOfView.resize(in.getCount(24));
    for (RoundedFieldOfView& rounded : graph.fieldsOfView) {
        rounded.classValue = in.get<std::int32_t>();
        rounded.originalMetres = in.get<double>();
        rounded.roundedMetres = in.get<double>();
        rounded.level = in.get<int>();
    }
    graph.passableAreaSquareMetres = in.get<double>();
    return graph;
}

// Waypoints are most of a plan. Most lie at a sub-cell centre of their cell and take its speed: such a
// point is saved as its cell and a tag naming the sub-cell. Whatever does not follow exactly, bit for bit,
// is saved as it is. Their times follow from the path (cumulativeSeconds); files written before waypoints
// stopped holding them may hold them all, and those are skipped.
enum WaypointTag : std::uint8_t { explicitPoint = 4, explicitLandCover = 8 };

std::uint8_t waypointTag(const Waypoint& waypoint, const CellGraph& graph) {
    if (waypoint.cell < 0 || static_cast<std::size_t>(waypoint.cell) >= graph.size())
        return explicitPoint | explicitLandCover;
    const Cell& cell = graph.cell(waypoint.cell);
    std::uint8_t tag = explicitPoint;
    for (const SubCell subCell : subCellsCounterClockwise) {
        const MapPoint centre = cell.subCellCentre(subCell);
        if (centre.x == waypoint.x && centre.y == waypoint.y)
            tag = static_cast<std::uint8_t>(subCell);
    }
    if (waypoint.speedMetresPerSecond != cell.speedMetresPerSecond)
        tag |= explicitLandCover;
    return tag;
}

void putWaypoints(CompressedWriter& out, const std::vector<Waypoint>& waypoints, const CellGraph& graph) {
    out.put(std::uint8_t{1}); // the times follow from the path
    out.put(static_cast<std::uint64_t>(waypoints.size()));
    for (const Waypoint& waypoint : waypoints) {
        const std::uint8_t tag = waypointTag(waypoint, graph);
        out.put(waypoint.cell);
        out.put(tag);
        if ((tag & explicitPoint) != 0) {
            out.put(waypoint.x);
            out.put(waypoint.y);
        }
        if ((tag & explicitLandCover) != 0) {
            // The land cover is the cell's (files before waypoints lost theirs may hold another).
            const bool inGraph = waypoint.cell >= 0 && static_cast<std::size_t>(waypoint.cell) < graph.size();
            out.put(inGraph ? graph.cell(waypoint.cell).classValue : std::int32_t{0});
            out.put(double{waypoint.speedMetresPerSecond});
        }
    }
}

std::vector<Waypoint> getWaypoints(CompressedReader& in, const CellGraph& graph) {
    const bool derivedTimes = in.get<std::uint8_t>() != 0;
    // Grown as they are read: a damaged count cannot claim ten times the memory the bytes stand for.
    const std::size_t count = in.getCount(5);
    std::vector<Waypoint> waypoints;
    waypoints.reserve(std::min<std::size_t>(count, std::size_t{1} << 16U));
    for (std::size_t index = 0; index < count; ++index) {
        Waypoint& waypoint = waypoints.emplace_back();
        waypoint.cell = in.get<int>();
        const auto tag = in.get<std::uint8_t>();
        const bool inGraph = waypoint.cell >= 0 && static_cast<std::size_t>(waypoint.cell) < graph.size();
        if (waypoint.cell < -1 ||
            (!inGraph && (tag & (explicitPoint | explicitLandCover)) != (explicitPoint | explicitLandCover)))
            throw CompressedReader::DamagedData("a waypoint in no cell");
        if ((tag & explicitPoint) != 0) {
            waypoint.x = in.get<double>();
            waypoint.y = in.get<double>();
        } else {
            const MapPoint centre = graph.cell(waypoint.cell).subCellCentre(static_cast<SubCell>(tag & 3U));
            waypoint.x = centre.x;
            waypoint.y = centre.y;
        }
        if ((tag & explicitLandCover) != 0) {
            in.get<std::int32_t>(); // the land cover, which is the cell's
            waypoint.speedMetresPerSecond = static_cast<float>(in.get<double>());
        } else {
            waypoint.speedMetresPerSecond = graph.cell(waypoint.cell).speedMetresPerSecond;
        }
        if (!derivedTimes)
            in.get<double>(); // a time, which follows from the path
    }
    return waypoints;
}

void putPaths(CompressedWriter& out, const std::vector<CoveragePath>& paths, const CellGraph& graph) {
    out.put(static_cast<std::uint64_t>(paths.size()));
    for (const CoveragePath& path : paths) {
        out.put(path.robot);
        out.put(path.lengthMetres);
        out.put(path.timeSeconds);
        out.put(path.turnSeconds);
        out.put(path.connectorSeconds);
        out.put(path.turns);
        out.put(path.repeatedSubCellVisits);
        out.put(static_cast<std::uint8_t>(path.closed));
        out.put(static_cast<std::uint64_t>(path.walkedWaypoints));
        putWaypoints(out, path.waypoints, graph);
        if (path.runsMerged())
            out.putAll(std::vector<std::uint8_t>(path.runFollows.begin(), path.runFollows.end()));
        out.put(static_cast<std::uint8_t>(path.takeOff.has_value()));
        if (path.takeOff) {
            out.put(path.takeOff->x);
            out.put(path.takeOff->y);
        }
    }
}

std::vector<CoveragePath> getPaths(CompressedReader& in, const CellGraph& graph, bool withWalkedCounts,
                                   bool withTakeOffs) {
    std::vector<CoveragePath> paths(in.getCount(54));
    if (paths.size() > mostRobots) // more than region outlines can number
        throw CompressedReader::DamagedData("more robots than one plan takes");
    for (CoveragePath& path : paths) {
        path.robot = in.get<int>();
        path.lengthMetres = in.get<double>();
        path.timeSeconds = in.get<double>();
        path.turnSeconds = in.get<double>();
        path.connectorSeconds = in.get<double>();
        path.turns = in.get<int>();
        path.repeatedSubCellVisits = in.get<int>();
        path.closed = in.get<std::uint8_t>() != 0;
        if (withWalkedCounts)
            path.walkedWaypoints = static_cast<std::size_t>(in.get<std::uint64_t>());
        path.waypoints = getWaypoints(in, graph);
        if (path.runsMerged()) {
            const std::vector<std::uint8_t> runFollows = in.getAll<std::uint8_t>();
            const bool walkFits =
                path.walkedWaypoints >= path.waypoints.size() &&
                path.walkedWaypoints <= path.waypoints.size() + mostWalkedWaypointsPerCell * graph.size();
            if (!walkFits || runFollows.size() != path.waypoints.size())
                throw CompressedReader::DamagedData("a path whose merged runs do not add up");
            path.runFollows.assign(runFollows.begin(), runFollows.end());
        }
        if (withTakeOffs && in.get<std::uint8_t>() != 0) {
            const double x = in.get<double>();
            const double y = in.get<double>();
            if (!std::isfinite(x) || !std::isfinite(y))
                throw CompressedReader::DamagedData("a take-off point that is not a number");
            path.takeOff = MapPoint{x, y};
        }
        if (path.robot < 0 || static_cast<std::size_t>(path.robot) >= paths.size())
            throw CompressedReader::DamagedData("a path of no robot");
    }
    return paths;
}

void putMetrics(CompressedWriter& out, const PlanMetrics& metrics) {
    out.put(static_cast<std::uint64_t>(metrics.robots.size()));
    for (const RobotMetrics& robot : metrics.robots) {
        out.put(robot.robot);
        out.put(robot.cells);
        out.put(robot.areaSquareMetres);
        out.put(robot.lengthMetres);
        out.put(robot.timeSeconds);
        out.put(robot.turnSeconds);
        out.put(robot.connectorSeconds);
        out.put(robot.costSeconds);
        out.put(robot.turns);
    }
    for (const double figure :
         {metrics.makespanSeconds, metrics.lowerBoundSeconds, metrics.ratio, metrics.passableAreaSquareMetres,
          metrics.coveredAreaSquareMetres, metrics.coveredFraction, metrics.unreachableAreaSquareMetres,
          metrics.repeatedFraction, metrics.fieldMakespanSeconds, metrics.fieldLowerBoundSeconds})
        out.put(figure);
    for (const RobotMetrics& robot : metrics.robots)
        out.put(robot.fieldSeconds);
    // What the ratio is measured against, so that a reopened plan's ratio is read as it was planned.
    out.put(metrics.sharedPartsRatio);
    out.put(static_cast<std::uint8_t>(metrics.boundOfDetectionPasses));
    out.put(static_cast<std::uint64_t>(metrics.stageMilliseconds.size()));
    for (const auto& [stage, milliseconds] : metrics.stageMilliseconds) {
        out.put(stage);
        out.put(milliseconds);
    }
}

PlanMetrics getMetrics(CompressedReader& in, int formatVersion) {
    PlanMetrics metrics;
    metrics.robots.resize(in.getCount(60));
    for (RobotMetrics& robot : metrics.robots) {
        robot.robot = in.get<int>();
        robot.cells = in.get<int>();
        robot.areaSquareMetres = in.get<double>();
        robot.lengthMetres = in.get<double>();
        robot.timeSeconds = in.get<double>();
        robot.turnSeconds = in.get<double>();
        robot.connectorSeconds = in.get<double>();
        robot.costSeconds = in.get<double>();
        robot.turns = in.get<int>();
    }
    for (double* figure :
         {&metrics.makespanSeconds, &metrics.lowerBoundSeconds, &metrics.ratio,
          &metrics.passableAreaSquareMetres, &metrics.coveredAreaSquareMetres, &metrics.coveredFraction,
          &metrics.unreachableAreaSquareMetres, &metrics.repeatedFraction})
        *figure = in.get<double>();
    if (formatVersion >= 5) {
        metrics.fieldMakespanSeconds = in.get<double>();
        metrics.fieldLowerBoundSeconds = in.get<double>();
        for (RobotMetrics& robot : metrics.robots)
            robot.fieldSeconds = in.get<double>();
    }
    if (formatVersion >= 7) {
        metrics.sharedPartsRatio = in.get<double>();
        if (!std::isfinite(metrics.sharedPartsRatio) || metrics.sharedPartsRatio < 0.0)
            throw CompressedReader::DamagedData("a shared parts' ratio that is not a ratio");
        metrics.boundOfDetectionPasses = in.get<std::uint8_t>() != 0;
    }
    for (std::size_t count = in.getCount(16); count > 0; --count) {
        std::string stage = in.getString();
        metrics.stageMilliseconds.emplace_back(std::move(stage), in.get<double>());
    }
    return metrics;
}

void putIssues(CompressedWriter& out, const std::vector<PlanIssue>& issues) {
    out.put(static_cast<std::uint64_t>(issues.size()));
    for (const PlanIssue& issue : issues) {
        out.put(static_cast<std::uint8_t>(issue.severity == IssueSeverity::Warning));
        out.put(issue.code);
        out.put(issue.message);
    }
}

std::vector<PlanIssue> getIssues(CompressedReader& in) {
    std::vector<PlanIssue> issues(in.getCount(17));
    for (PlanIssue& issue : issues) {
        issue.severity = in.get<std::uint8_t>() != 0 ? IssueSeverity::Warning : IssueSeverity::Information;
        issue.code = in.getString();
        issue.message = in.getString();
    }
    return issues;
}

// The land left out beyond every flight's reach: the raster's frame, then each run's row, first column and
// end column.
void putLandBeyondReach(CompressedWriter& out, const PixelRuns& land) {
    for (const double figure : {land.originX, land.originY, land.pixelWidth, land.pixelHeight})
        out.put(figure);
    std::vector<std::int32_t> runs;
    runs.reserve(3 * land.runs.size());
    for (const PixelRuns::Run& run : land.runs)
        runs.insert(runs.end(), {run.row, run.firstColumn, run.endColumn});
    out.putAll(runs);
}

// Runs as the planner finds them: by row, then column, none overlapping, on a frame of finite metres. A
// damaged file's runs would otherwise be drawn over and over.
PixelRuns getLandBeyondReach(CompressedReader& in) {
    PixelRuns land;
    for (double* figure : {&land.originX, &land.originY, &land.pixelWidth, &land.pixelHeight})
        *figure = in.get<double>();
    if (!std::isfinite(land.originX) || !std::isfinite(land.originY) || !(land.pixelWidth > 0.0) ||
        !(land.pixelHeight > 0.0) || !std::isfinite(land.pixelWidth) || !std::isfinite(land.pixelHeight))
        throw CompressedReader::DamagedData("land beyond reach on a frame that is not one");
    const std::vector<std::int32_t> runs = in.getAll<std::int32_t>();
    if (runs.size() % 3 != 0)
        throw CompressedReader::DamagedData("land beyond reach in broken runs");
    for (std::size_t index = 0; index < runs.size(); index += 3) {
        const PixelRuns::Run run{runs[index], runs[index + 1], runs[index + 2]};
        const bool after = land.runs.empty() || run.row > land.runs.back().row ||
                           (run.row == land.runs.back().row && run.firstColumn >= land.runs.back().endColumn);
        if (run.row < 0 || run.firstColumn < 0 || run.endColumn <= run.firstColumn || !after)
            throw CompressedReader::DamagedData("land beyond reach in runs out of order");
        land.runs.push_back(run);
    }
    return land;
}

void checkRegions(const RegionAllocation& regions, std::size_t cells, std::size_t robots) {
    if (regions.robotOfCell.size() != cells || regions.startCell.size() != robots ||
        regions.costSeconds.size() != robots)
        throw CompressedReader::DamagedData("regions that do not match the cells and robots");
    for (const int robot : regions.robotOfCell)
        if (robot < -1 || robot >= static_cast<int>(robots))
            throw CompressedReader::DamagedData("a cell of no robot");
    for (const int cell : regions.startCell)
        if (cell < -1 || cell >= static_cast<int>(cells))
            throw CompressedReader::DamagedData("a start in no cell");
}

// Turn times that the plan's turn model gives from the cells' speeds are kept as that model rather than cell
// by cell: a robot of its own speed (an aircraft's cruise speed) then turns at its price, as when planned.
void followTurnModel(Plan& plan) {
    const TurnTimeModel model = TurnTimeModel::from(plan.parameters);
    CellGraph& graph = plan.cells;
    for (std::size_t id = 0; id < graph.size(); ++id) {
        const auto cell = static_cast<int>(id);
        if (graph.turnSeconds(cell) !=
            static_cast<float>(model.secondsPer90Degrees(graph.record(cell).speedMetresPerSecond)))
            return;
    }
    graph.applyTurnTime(model);
}

Plan readPlan(CompressedReader& in, int formatVersion) {
    Plan plan;
    plan.planner = in.getString();
    plan.parameters = getParameters(in);
    plan.cells = getCells(in);
    followTurnModel(plan);
    plan.regions.robotOfCell = in.getAll<int>();
    plan.regions.startCell = in.getAll<int>();
    plan.regions.costSeconds = in.getAll<double>();
    plan.paths = getPaths(in, plan.cells, formatVersion >= 4, formatVersion >= 6);
    checkRegions(plan.regions, plan.cells.size(), plan.paths.size());
    plan.metrics = getMetrics(in, formatVersion);
    // Before MCPP-PLAN 7 the kind of bound was not saved: CPPIED's was always of detection passes.
    if (formatVersion < 7)
        plan.metrics.boundOfDetectionPasses = plan.planner == "cppied";
    for (const RobotMetrics& robot : plan.metrics.robots)
        if (robot.robot < 0 || static_cast<std::size_t>(robot.robot) >= plan.paths.size())
            throw CompressedReader::DamagedData("figures of no robot");
    plan.issues = getIssues(in);
    if (formatVersion >= 8)
        plan.landBeyondReach = getLandBeyondReach(in);
    // Not saved as a figure: the warning that says it is.
    plan.metrics.ownSpeedsIgnored =
        std::any_of(plan.issues.begin(), plan.issues.end(),
                    [](const PlanIssue& issue) { return issue.code == "own-speeds-ignored"; });
    if (in.get<std::uint32_t>() != endMarker || !in.atEnd())
        throw CompressedReader::DamagedData("unexpected bytes at the end");
    return plan;
}

// The version a file's first line names, or -1 for a line of no version this reads.
int formatVersionOf(const std::string& line) {
    for (int version = oldestFormatVersion; version <= planFormatVersion; ++version)
        if (line == formatName + std::to_string(version))
            return version;
    return -1;
}

// The header: the format line and the fingerprint line, then the compressed plan.
std::string header(const std::string& fingerprint) {
    return formatName + std::to_string(planFormatVersion) + "\n" + fingerprint + "\n";
}

} // namespace

std::string planFilePath(const std::string& missionPath) {
    std::filesystem::path path(missionPath);
    return path.replace_extension(".mcpp-plan").string();
}

std::string inputFilesIdentity(const std::vector<std::string>& paths) {
    std::string identity;
    for (const std::string& path : paths) {
        const std::string file = fileIdentity(path);
        if (file.empty())
            return {};
        identity += (path.empty() ? std::string() : absoluteNormal(path)) + " " + file + "\n";
    }
    return identity;
}

std::string planInputsFingerprint(const Mission& mission, const std::string& missionPath) {
    Mission inputs = mission;
    inputs.rasterPath = absoluteNormal(resolveRasterPath(mission, missionPath));
    for (std::string* area : {&inputs.area.includePath, &inputs.area.excludePath})
        if (!area->empty())
            *area = absoluteNormal(resolveMissionPath(*area, missionPath));
    inputs.exports = {};
    // Vehicles shape the files, not the plan, except for the cruise speeds the plan drives the robots at: the
    // fleet's, or each robot's where they differ; and where time in the field is measured, all of them and
    // how the files command speeds (fieldTimeInputs), restored below.
    inputs.exports.vehicle.cruiseSpeedMetresPerSecond = fleetCruiseSpeed(mission);
    const std::vector<double> cruiseSpeeds = robotCruiseSpeeds(mission);
    // A battery planner's batteries may come from the vehicles' flight times.
    const std::vector<double> batteries = plannerBatteries(mission);
    const std::vector<double> recharges = plannerRecharges(mission); // and their charging, from turnarounds
    // An aircraft may take off beside its path (flyingRobots): which robots fly shapes the plan.
    const std::vector<bool> flying = flyingRobots(mission);
    for (std::size_t robot = 0; robot < inputs.robots.size();
         ++robot) { // names shape the files, not the plan
        inputs.robots[robot].name.clear();
        inputs.robots[robot].vehicle = {};
        if (flying[robot])
            inputs.robots[robot].vehicle.type = VehicleType::Multirotor; // any aircraft alike
        if (cruiseSpeeds[robot] != inputs.exports.vehicle.cruiseSpeedMetresPerSecond)
            inputs.robots[robot].vehicle.cruiseSpeedMetresPerSecond = cruiseSpeeds[robot];
        if (robot < batteries.size() && batteries[robot] > 0.0)
            inputs.robots[robot].batterySeconds = batteries[robot];
        if (robot < recharges.size() && recharges[robot] > 0.0)
            inputs.robots[robot].vehicle.turnaroundSeconds = recharges[robot];
    }
    if (fieldTimeInputs(mission).measured()) {
        inputs.exports = mission.exports;
        inputs.exports.densePaths = false;
        inputs.exports.cellPolygons = false;
        for (std::size_t robot = 0; robot < inputs.robots.size(); ++robot)
            inputs.robots[robot].vehicle = mission.robots[robot].vehicle;
    }
    const std::string files =
        inputFilesIdentity({inputs.rasterPath, inputs.area.includePath, inputs.area.excludePath});
    if (files.empty())
        return {};
    const std::string text = missionToJson(inputs) + "\n" + files;
    return QCryptographicHash::hash(QByteArray::fromStdString(text), QCryptographicHash::Sha256)
        .toHex()
        .toStdString();
}

Status savePlanFile(const Plan& plan, const std::string& fingerprint, const std::string& path) {
    CompressedWriter out;
    out.put(plan.planner);
    putParameters(out, plan.parameters);
    putCells(out, plan.cells);
    out.putAll(plan.regions.robotOfCell);
    out.putAll(plan.regions.startCell);
    out.putAll(plan.regions.costSeconds);
    putPaths(out, plan.paths, plan.cells);
    putMetrics(out, plan.metrics);
    putIssues(out, plan.issues);
    putLandBeyondReach(out, plan.landBeyondReach);
    out.put(endMarker);
    return writeFileAtomically(path, header(fingerprint) + out.finish());
}

Result<std::optional<Plan>> loadPlanFile(const std::string& path, const std::string& fingerprint) {
    using Loaded = Result<std::optional<Plan>>;
    std::ifstream file(path, std::ios::binary);
    if (!file)
        return Loaded::failure(path + ": cannot read the saved plan");
    std::string format;
    std::string savedFingerprint;
    std::getline(file, format);
    std::getline(file, savedFingerprint);
    const int version = formatVersionOf(format);
    if (version < 0)
        return Loaded::failure(path + ": not a plan file of this version of mcpp (first line \"" +
                               format.substr(0, 40) + "\")");
    if (savedFingerprint != fingerprint)
        return std::optional<Plan>();
    // The rest in one read: the compressed plan, inflated a chunk at a time.
    const auto start = file.tellg();
    file.seekg(0, std::ios::end);
    std::string bytes(static_cast<std::size_t>(file.tellg() - start), '\0');
    file.seekg(start);
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        return Loaded::failure(path + ": cannot read the saved plan");
    auto plan = parsePlanBody(bytes, path, version);
    if (!plan)
        return Loaded::failure(plan.error());
    return std::optional<Plan>(std::move(plan.value()));
}

Result<Plan> parsePlanBody(std::string_view compressed, const std::string& path, int formatVersion) {
    try {
        CompressedReader in(compressed);
        return readPlan(in, formatVersion);
    } catch (const CompressedReader::DamagedData& damage) {
        return Result<Plan>::failure(path + ": the saved plan is damaged (" + damage.what() + ")");
    } catch (const std::bad_alloc&) {
        return Result<Plan>::failure(path +
                                     ": the saved plan is damaged (it claims more memory than there is)");
    }
}

} // namespace mcpp::io
