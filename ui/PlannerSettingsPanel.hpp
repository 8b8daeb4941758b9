#pragma once

#include "core/planners/PlannerSettings.hpp"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace mcpp::ui {

// The planner and its parameters. Emits settingsEdited only for the user's own edits.
class PlannerSettingsPanel : public QWidget {
    Q_OBJECT

  public:
    explicit PlannerSettingsPanel(QWidget* parent = nullptr);
    void setSettings(const PlannerSettings& settings);
    [[nodiscard]] PlannerSettings settings() const;

  signals:
    void settingsEdited(const mcpp::PlannerSettings& settings);

  private:
    void emitEdited();

    QComboBox* planner_;
    QDoubleSpinBox* purityTolerance_;
    QDoubleSpinBox* blockedThreshold_;
    QCheckBox* closedTour_;
    QSpinBox* rebalanceIterations_;
    QCheckBox* snapStarts_;
    PlannerSettings shown_;
    bool updating_ = false;
};

} // namespace mcpp::ui
