#include "ui/ComparisonRunner.hpp"

#include "core/model/PlanningError.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <chrono>
#include <exception>

namespace mcpp::ui {

std::vector<std::string> ComparisonOutcome::warningsOf(std::size_t row) const {
    std::vector<std::string> warnings;
    if (row < plans.size() && plans[row])
        warnings = plans[row]->warnings();
    if (row < fileWarnings.size())
        warnings.insert(warnings.end(), fileWarnings[row].begin(), fileWarnings[row].end());
    return warnings;
}

namespace {

// What a plan's waypoint files would warn of; none once cancelled, or where working it out fails (the plan
// stands: its files are measured again when it is shown).
WaypointFileFindings fileWarningsOf(const Plan* plan, const FileWarnings& fileWarnings,
                                    const std::atomic<bool>& cancelled) {
    if (plan == nullptr || !fileWarnings || cancelled.load())
        return {};
    try {
        return fileWarnings(*plan);
    } catch (const std::exception&) {
        return {};
    }
}

} // namespace

ComparisonRunner::ComparisonRunner(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<ComparisonOutcome>::finished, this,
            [this] { emit finished(watcher_.result()); });
}

ComparisonRunner::~ComparisonRunner() {
    disconnect(&watcher_, nullptr, this, nullptr);
    cancel();
    waitForFinished();
}

bool ComparisonRunner::isRunning() const {
    return watcher_.isRunning();
}

void ComparisonRunner::cancel() {
    if (cancelRequested_)
        cancelRequested_->store(true);
}

void ComparisonRunner::waitForFinished() {
    watcher_.waitForFinished();
}

bool ComparisonRunner::start(PlanningProblem problem, std::vector<PlannerChoice> choices,
                             FileWarnings fileWarnings) {
    if (isRunning() || choices.empty())
        return false;
    cancelRequested_ = std::make_shared<std::atomic<bool>>(false);
    auto cancelFlag = cancelRequested_;
    const int run = ++runs_;
    // The destructor waits for the run, so the worker may use `this`.
    auto work = [this, run, cancelFlag, problem = std::move(problem), choices = std::move(choices),
                 fileWarnings = std::move(fileWarnings)]() mutable {
        using Clock = std::chrono::steady_clock;
        ComparisonOutcome outcome;
        outcome.choices = choices;
        const int planners = static_cast<int>(choices.size());
        for (int index = 0; index < planners; ++index) {
            const PlannerChoice& choice = choices[static_cast<std::size_t>(index)];
            io::ComparisonRow row;
            row.planner = choice.planner;
            std::optional<PlanningError> refused;
            std::shared_ptr<const Plan> plan;
            if (cancelFlag->load()) {
                outcome.cancelled = true;
                row.outcome = io::ComparisonRow::Outcome::Skipped;
                row.message = "cancelled";
            } else {
                const QString name = QString::fromStdString(choice.planner);
                auto lastReport = Clock::now() - std::chrono::seconds(1);
                // Throttled so a chatty planner cannot flood the GUI thread's event queue.
                const ProgressReporter progress(
                    [&](std::string_view stage, double fraction) {
                        const auto now = Clock::now();
                        if (now - lastReport < std::chrono::milliseconds(50) && fraction < 1.0)
                            return;
                        lastReport = now;
                        const QString stageText =
                            QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size()));
                        QMetaObject::invokeMethod(
                            this,
                            [this, index, planners, name, stageText, fraction] {
                                emit progressed(index, planners, name, stageText, fraction);
                            },
                            Qt::QueuedConnection);
                    },
                    cancelFlag.get());
                problem.planner = choice;
                const auto started = Clock::now();
                try {
                    const auto planner = makePlanner(choice.planner);
                    if (!planner)
                        throw PlanningError(PlanningError::Kind::InvalidParameter,
                                            unknownPlannerMessage(choice.planner));
                    plan = std::make_shared<const Plan>(planner->plan(problem, progress));
                    row.metrics = plan->metrics;
                    row.planningMilliseconds =
                        std::chrono::duration<double, std::milli>(Clock::now() - started).count();
                } catch (const PlanningError& error) {
                    outcome.cancelled = outcome.cancelled || error.kind() == PlanningError::Kind::Cancelled;
                    row.outcome = error.kind() == PlanningError::Kind::Cancelled
                                      ? io::ComparisonRow::Outcome::Skipped
                                      : io::ComparisonRow::Outcome::Failed;
                    row.message = error.what();
                    if (error.kind() != PlanningError::Kind::Cancelled)
                        refused = error;
                } catch (const std::exception& error) {
                    row.outcome = io::ComparisonRow::Outcome::Failed;
                    row.message = error.what();
                }
            }
            WaypointFileFindings findings = fileWarningsOf(plan.get(), fileWarnings, *cancelFlag);
            row.flightsOverBattery = findings.flightsOverBattery; // ranks it as batch mode does
            outcome.rows.push_back(row);
            outcome.errors.push_back(refused);
            outcome.fileWarnings.push_back(std::move(findings.warnings));
            outcome.plans.push_back(plan);
            if (index + 1 < planners)
                QMetaObject::invokeMethod(
                    this,
                    [this, run, soFar = outcome] {
                        if (run == runs_) // not news of a run before the one going on
                            emit plannerFinished(soFar);
                    },
                    Qt::QueuedConnection);
        }
        return outcome;
    };
    watcher_.setFuture(QtConcurrent::run(std::move(work)));
    return true;
}

} // namespace mcpp::ui
