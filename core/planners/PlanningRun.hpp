#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "core/model/ProgressReporter.hpp"
#include "core/model/StartPointCheck.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mcpp {

// One planner run in progress: the problem, the plan being filled, the starts (which snapping may move)
// and the timing of each stage.
class PlanningRun {
  public:
    PlanningRun(const PlanningProblem& problem, ParameterValues parameters, const ProgressReporter& progress,
                Plan& plan, std::int64_t bytesPerBottomCell)
        : problem_(problem), parameters_(std::move(parameters)), progress_(progress), plan_(plan),
          starts_(problem.starts), bytesPerBottomCell_(bytesPerBottomCell) {}

    [[nodiscard]] const PlanningProblem& problem() const { return problem_; }
    // Every declared parameter, checked, defaults filled in.
    [[nodiscard]] const ParameterValues& parameters() const { return parameters_; }
    [[nodiscard]] const ProgressReporter& progress() const { return progress_; }
    [[nodiscard]] Plan& plan() { return plan_; }
    [[nodiscard]] const std::vector<MapPoint>& starts() const { return starts_; }
    // The planner's peak memory per cell of the finest grid (PlannerDescription::bytesPerBottomCell).
    [[nodiscard]] std::int64_t bytesPerBottomCell() const { return bytesPerBottomCell_; }
    // By robot, its seconds in the field for a second of its path, measured on an earlier plan of the
    // problem (PlanningProblem::fieldSeconds); empty: 1 each. A planner that balancesFieldTime evens out
    // path times times these.
    [[nodiscard]] const std::vector<double>& fieldPaces() const { return fieldPaces_; }
    void setFieldPaces(std::vector<double> paces) { fieldPaces_ = std::move(paces); }
    // Where runs of the same problem and parameters keep the cells the first of them built (rounds of
    // evening out time in the field); null: cells are built for this run alone.
    [[nodiscard]] std::optional<CellGraph>* keptCells() const { return keptCells_; }
    void keepCellsIn(std::optional<CellGraph>* cells) { keptCells_ = cells; }
    // Whether a planner may weigh cells by the trips out to them of robots that fly them in flights
    // (TripWeighting); off for a division on the paths alone.
    [[nodiscard]] bool tripsWeighed() const { return tripsWeighed_; }
    void weighTrips(bool weighed) { tripsWeighed_ = weighed; }

    // Runs one stage of the planner and records how long it took under its name.
    template <typename Work> auto stage(const char* name, Work&& work) {
        progress_.throwIfCancelled();
        const auto begin = std::chrono::steady_clock::now();
        auto result = work();
        const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - begin;
        plan_.metrics.stageMilliseconds.emplace_back(name, elapsed.count());
        return result;
    }

    // The cell of the plan's graph holding each start (spec 4): a start on no cell, or in a cell another
    // robot already holds, is an error or, with snapping, moved to the nearest free cell with a warning.
    // leftOutBecause: why the decomposition leaves cells out, for a start in one; by default the blocked
    // threshold's rule.
    // A flying robot (PlanningProblem::flyingRobots) whose start is such takes off there instead, its path
    // beginning at the nearest free cell, with a note.
    [[nodiscard]] std::vector<int> locateStarts(const std::string& leftOutBecause = {});
    // By robot, where it takes off when its start is not on its path (set by locateStarts).
    [[nodiscard]] const std::vector<std::optional<MapPoint>>& takeOffPoints() const { return takeOffs_; }
    void addIssue(IssueSeverity severity, std::string code, std::string message) {
        plan_.issues.push_back({severity, std::move(code), std::move(message)});
    }

    // Planners that fly on batteries plan sorties from the start's cell: their robots do not take off
    // elsewhere.
    void allowTakeOffs(bool allowed) { takeOffsAllowed_ = allowed; }

  private:
    [[nodiscard]] double reachMetres(std::size_t robot) const;
    void takeOffAt(int robot, MapPoint given, MapPoint pathStart, const std::string& why);
    [[nodiscard]] std::optional<StartPointProblem> startCellProblem(MapPoint start, int cell,
                                                                    const std::vector<int>& ownerOfCell,
                                                                    const std::string& leftOutBecause) const;
    [[nodiscard]] int placeBlockedStart(std::size_t robot, std::vector<int>& ownerOfCell,
                                        const std::string& leftOutBecause);

    const PlanningProblem& problem_;
    ParameterValues parameters_;
    const ProgressReporter& progress_;
    Plan& plan_;
    std::vector<MapPoint> starts_;
    std::vector<std::optional<MapPoint>> takeOffs_;
    bool takeOffsAllowed_ = true;
    std::int64_t bytesPerBottomCell_;
    std::vector<double> fieldPaces_;
    std::optional<CellGraph>* keptCells_ = nullptr;
    bool tripsWeighed_ = true;
};

} // namespace mcpp
