#include "ui/PlanningRunner.hpp"

#include "core/model/PlanningError.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <chrono>
#include <exception>

namespace mcpp::ui {

PlanningRunner::PlanningRunner(QObject* parent) : QObject(parent) {
    connect(&watcher_, &QFutureWatcher<PlanningOutcome>::finished, this,
            [this] { emit finished(watcher_.result()); });
}

PlanningRunner::~PlanningRunner() {
    disconnect(&watcher_, nullptr, this, nullptr);
    cancel();
    waitForFinished();
}

bool PlanningRunner::isRunning() const {
    return watcher_.isRunning();
}

void PlanningRunner::cancel() {
    if (cancelRequested_)
        cancelRequested_->store(true);
}

void PlanningRunner::waitForFinished() {
    watcher_.waitForFinished();
}

bool PlanningRunner::start(PlanningProblem problem) {
    if (isRunning())
        return false;
    cancelRequested_ = std::make_shared<std::atomic<bool>>(false);
    // The destructor waits for the run, so the worker may use `this`; queued calls to a deleted runner are
    // dropped.
    auto cancelFlag = cancelRequested_;
    auto work = [this, cancelFlag, problem = std::move(problem)]() -> PlanningOutcome {
        using Clock = std::chrono::steady_clock;
        auto lastReport = Clock::now() - std::chrono::seconds(1);
        std::string lastStage;
        // Throttled so a chatty planner cannot flood the GUI thread's event queue.
        ProgressReporter progress(
            [&](std::string_view stage, double fraction) {
                const auto now = Clock::now();
                if (stage == lastStage && now - lastReport < std::chrono::milliseconds(50))
                    return;
                lastReport = now;
                lastStage = std::string(stage);
                const QString stageText =
                    QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size()));
                QMetaObject::invokeMethod(
                    this, [this, stageText, fraction] { emit progressed(stageText, fraction); },
                    Qt::QueuedConnection);
            },
            cancelFlag.get());
        PlanningOutcome outcome;
        try {
            const auto planner = makePlanner(problem.planner.planner);
            if (!planner) {
                outcome.error = QObject::tr("Unknown planner \"%1\".")
                                    .arg(QString::fromStdString(problem.planner.planner));
                return outcome;
            }
            outcome.plan = std::make_shared<const Plan>(planner->plan(problem, progress));
        } catch (const PlanningError& error) {
            outcome.cancelled = error.kind() == PlanningError::Kind::Cancelled;
            outcome.error = QString::fromStdString(error.what());
            outcome.planningError = error;
        } catch (const std::bad_alloc&) {
            outcome.error = QObject::tr("Out of memory while planning; try a coarser raster or larger FOVs.");
        } catch (const std::exception& error) {
            outcome.error = QObject::tr("Planning failed: %1").arg(QString::fromStdString(error.what()));
        }
        return outcome;
    };
    watcher_.setFuture(QtConcurrent::run(std::move(work)));
    return true;
}

} // namespace mcpp::ui
