#pragma once

#include "core/parameters/PlannerChoice.hpp"
#include "core/planners/PlannerDescription.hpp"

#include <QWidget>
#include <optional>
#include <string>
#include <utility>
#include <vector>

class QComboBox;
class QFormLayout;
class QLabel;

namespace mcpp::ui {

// The planner and its parameters, as each planner declares them: the form is rebuilt from the declaration
// when the planner changes, so a new planner needs no code here. Emits choiceEdited only for the user's
// edits.
class PlannerSettingsPanel : public QWidget {
    Q_OBJECT

  public:
    explicit PlannerSettingsPanel(QWidget* parent = nullptr);
    void setChoice(const PlannerChoice& choice);
    [[nodiscard]] const PlannerChoice& choice() const { return shown_; }
    // The editor of a parameter (a spin box, check box or combo box), or nullptr.
    [[nodiscard]] QWidget* editorOf(const std::string& key) const;

  signals:
    void choiceEdited(const mcpp::PlannerChoice& choice);

  private:
    void rebuildForm(const PlannerDescription& description);
    [[nodiscard]] QWidget* makeEditor(const ParameterSpec& spec);
    void showValues();
    void greyOutSwitchedOff();
    void plannerPicked(int index);
    void parameterEdited(const ParameterSpec& spec, ParameterValue value);

    QComboBox* planner_;
    QLabel* summary_;
    QFormLayout* form_;
    std::vector<std::pair<ParameterSpec, QWidget*>> editors_;
    std::vector<ParameterSpec> specs_;       // the planner's declaration the form shows
    std::optional<std::string> formPlanner_; // the planner whose editors the form holds
    PlannerChoice shown_;
    bool updating_ = false;
};

} // namespace mcpp::ui
