#pragma once

#include "core/model/Plan.hpp"
#include "core/model/PlanningError.hpp"
#include "core/model/PlanningProblem.hpp"

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>
#include <optional>

namespace mcpp::ui {

// What one planning run ended with.
struct PlanningOutcome {
    std::shared_ptr<const Plan> plan; // null on failure
    QString error;
    // The planner's own error, for the window to name a robot's start or a setting in its own terms.
    std::optional<PlanningError> planningError;
    bool cancelled = false;
};

// Runs a planner on a worker thread so the window stays responsive. Progress arrives as queued signals
// in the GUI thread; cancel() sets the flag the planner checks between units of work.
class PlanningRunner : public QObject {
    Q_OBJECT

  public:
    explicit PlanningRunner(QObject* parent = nullptr);
    ~PlanningRunner() override;

    // False (and nothing started) while a run is in progress.
    bool start(PlanningProblem problem);
    void cancel();
    [[nodiscard]] bool isRunning() const;
    // Blocks until the current run ends; used on shutdown.
    void waitForFinished();

  signals:
    void progressed(const QString& stage, double fraction);
    void finished(const mcpp::ui::PlanningOutcome& outcome);

  private:
    QFutureWatcher<PlanningOutcome> watcher_;
    std::shared_ptr<std::atomic<bool>> cancelRequested_;
};

} // namespace mcpp::ui
