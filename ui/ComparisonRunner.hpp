#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/PlanningProblem.hpp"
#include "io/ComparisonExport.hpp"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mcpp::ui {

// What a comparison ended with: a row per planner (as batch mode's comparison.csv) and the plans made.
struct ComparisonOutcome {
    std::vector<io::ComparisonRow> rows;
    std::vector<std::shared_ptr<const Plan>> plans; // by row; null where the planner failed or was skipped
    std::vector<PlannerChoice> choices;             // by row: the planner and parameters it ran with
    // By row: what the planner refused the problem for, to be named in the window's terms; none where it
    // planned, was skipped, or failed for another reason.
    std::vector<std::optional<PlanningError>> errors;
    // By row: what the plan's waypoint files would warn of (flights longer than a battery lasts), which
    // the plan itself does not say; empty where none or not planned.
    std::vector<std::vector<std::string>> fileWarnings;
    bool cancelled = false;

    // A row's warnings: its plan's, then its waypoint files'.
    [[nodiscard]] std::vector<std::string> warningsOf(std::size_t row) const;
};

// What a plan's waypoint files would warn of, and how many of their flights are longer than a battery
// (ComparisonRow::flightsOverBattery: none where no robot has a flight time).
struct WaypointFileFindings {
    std::vector<std::string> warnings;
    std::optional<std::size_t> flightsOverBattery;
};

// Those findings, worked out on the comparison's thread.
using FileWarnings = std::function<WaypointFileFindings(const Plan&)>;

// Runs several planners on one problem, one after another on a worker thread, so the window stays
// responsive; progress names the planner. cancel() stops the running planner and skips the rest.
class ComparisonRunner : public QObject {
    Q_OBJECT

  public:
    explicit ComparisonRunner(QObject* parent = nullptr);
    ~ComparisonRunner() override;

    // problem.planner is replaced by each choice in turn. False (nothing started) while a run is going on.
    // fileWarnings, when given, is asked of each plan made.
    bool start(PlanningProblem problem, std::vector<PlannerChoice> choices, FileWarnings fileWarnings = {});
    void cancel();
    [[nodiscard]] bool isRunning() const;
    void waitForFinished();

  signals:
    // planner: index in the choices; fraction of that planner's run.
    void progressed(int planner, int planners, const QString& name, const QString& stage, double fraction);
    // After each planner: the outcome so far, with a row for each planner done (all the choices).
    void plannerFinished(const mcpp::ui::ComparisonOutcome& outcomeSoFar);
    void finished(const mcpp::ui::ComparisonOutcome& outcome);

  private:
    QFutureWatcher<ComparisonOutcome> watcher_;
    std::shared_ptr<std::atomic<bool>> cancelRequested_;
    int runs_ = 0; // runs started, read and written on the GUI thread
};

} // namespace mcpp::ui
