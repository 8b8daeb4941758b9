#include "ui/PlannerSettingsPanel.hpp"

#include "core/parameters/ParameterResolution.hpp"
#include "core/planners/PlannerRegistry.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mcpp::ui {
namespace {

// Enough decimals to show the default and the smallest useful step of the range.
int decimalsFor(const ParameterSpec& spec) {
    const double span = std::isfinite(spec.maximum - spec.minimum) ? spec.maximum - spec.minimum : 1000.0;
    return std::clamp(static_cast<int>(std::ceil(-std::log10(span / 1000.0))), 0, 6);
}

// The help, the key and what it takes, and the switches it needs by the names the panel shows.
QString tooltipOf(const ParameterSpec& spec, const std::vector<ParameterSpec>& specs) {
    std::string switchNote;
    const std::vector<const ParameterSpec*> switches = switchesNeeded(specs, spec);
    for (std::size_t i = 0; i < switches.size(); ++i)
        switchNote += (i == 0 ? "; only with " : " and ") + switches[i]->label;
    if (!switchNote.empty())
        switchNote += " on";
    return QString::fromStdString(spec.help + " (" + spec.key + ": " + spec.expected() + switchNote + ")");
}

} // namespace

PlannerSettingsPanel::PlannerSettingsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("plannerSettingsPanel"));
    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    planner_ = new QComboBox(this);
    planner_->setObjectName(QStringLiteral("plannerCombo"));
    for (const PlannerDescription& description : plannerDescriptions()) {
        planner_->addItem(QString::fromStdString(description.label),
                          QString::fromStdString(description.name));
        planner_->setItemData(planner_->count() - 1, QString::fromStdString(description.summary),
                              Qt::ToolTipRole);
    }
    planner_->setToolTip(tr("The coverage planner to run"));
    top->addRow(tr("Planner"), planner_);
    layout->addLayout(top);
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("plannerSummary"));
    summary_->setWordWrap(true);
    summary_->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(summary_);
    form_ = new QFormLayout;
    layout->addLayout(form_);
    layout->addStretch(1);
    connect(planner_, &QComboBox::currentIndexChanged, this, &PlannerSettingsPanel::plannerPicked);
    setChoice(defaultPlannerChoice());
}

void PlannerSettingsPanel::setChoice(const PlannerChoice& choice) {
    updating_ = true;
    shown_ = choice;
    int index = planner_->findData(QString::fromStdString(choice.planner));
    if (index < 0) { // keep a mission's unknown planner visible rather than silently replacing it
        planner_->addItem(QString::fromStdString(choice.planner), QString::fromStdString(choice.planner));
        index = planner_->count() - 1;
    }
    planner_->setCurrentIndex(index);
    // An edit made here comes back through the document while its editor still handles the key or click
    // that made it: the form is rebuilt only for another planner, never under an editor in use.
    if (formPlanner_ != choice.planner) {
        rebuildForm(findPlannerDescription(choice.planner).value_or(PlannerDescription{}));
        formPlanner_ = choice.planner;
    }
    showValues();
    updating_ = false;
}

QWidget* PlannerSettingsPanel::editorOf(const std::string& key) const {
    for (const auto& [spec, editor] : editors_)
        if (spec.key == key)
            return editor;
    return nullptr;
}

void PlannerSettingsPanel::rebuildForm(const PlannerDescription& description) {
    while (form_->rowCount() > 0)
        form_->removeRow(0);
    editors_.clear();
    // Summaries are one line for --help, without a full stop; here they read as a sentence.
    QString summary = QString::fromStdString(description.summary);
    if (!summary.isEmpty())
        summary[0] = summary[0].toUpper();
    summary_->setText(summary + QStringLiteral(".") +
                      (description.singleRobot ? tr(" One robot only.") : QString()));
    specs_ = description.parameters;
    for (const ParameterSpec& spec : description.parameters) {
        QWidget* editor = makeEditor(spec);
        editor->setToolTip(tooltipOf(spec, description.parameters));
        editors_.emplace_back(spec, editor);
        if (spec.type == ParameterType::Boolean)
            form_->addRow(QString(), editor);
        else
            form_->addRow(QString::fromStdString(spec.label), editor);
    }
}

QWidget* PlannerSettingsPanel::makeEditor(const ParameterSpec& spec) {
    QWidget* editor = nullptr;
    switch (spec.type) {
    case ParameterType::Boolean: {
        auto* check = new QCheckBox(QString::fromStdString(spec.label), this);
        connect(check, &QCheckBox::toggled, this, [this, spec](bool on) { parameterEdited(spec, on); });
        editor = check;
        break;
    }
    case ParameterType::Integer: {
        auto* spin = new QSpinBox(this);
        const auto bound = [](double value) {
            return static_cast<int>(std::clamp(value, double(std::numeric_limits<int>::min()),
                                               double(std::numeric_limits<int>::max())));
        };
        spin->setRange(bound(spec.minimum), bound(spec.maximumIncluded ? spec.maximum : spec.maximum - 1));
        connect(spin, &QSpinBox::valueChanged, this,
                [this, spec](int value) { parameterEdited(spec, value); });
        editor = spin;
        break;
    }
    case ParameterType::Real: {
        auto* spin = new QDoubleSpinBox(this);
        const int decimals = decimalsFor(spec);
        const double smallest = std::pow(10.0, -decimals);
        spin->setDecimals(decimals);
        const double step = std::max(smallest, std::isfinite(spec.maximum - spec.minimum)
                                                   ? (spec.maximum - spec.minimum) / 100.0
                                                   : 1.0);
        // An automatic value sits one step below the range, where the box shows its word instead: one
        // step up from it is the range's start.
        const double lowest = std::isfinite(spec.minimum) ? spec.minimum : -1e9;
        spin->setRange(spec.automatic.empty() ? lowest : lowest - step,
                       std::isfinite(spec.maximum)
                           ? (spec.maximumIncluded ? spec.maximum : spec.maximum - smallest)
                           : 1e9);
        spin->setSingleStep(step);
        if (!spec.unit.empty())
            spin->setSuffix(QStringLiteral(" ") + QString::fromStdString(spec.unit));
        if (!spec.automatic.empty())
            spin->setSpecialValueText(QString::fromStdString(spec.automatic));
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spec](double value) {
            const bool automatic = !spec.automatic.empty() && value < spec.minimum;
            parameterEdited(spec, automatic ? automaticParameterValue : value);
        });
        editor = spin;
        break;
    }
    case ParameterType::Choice: {
        auto* combo = new QComboBox(this);
        for (const std::string& choice : spec.choices)
            combo->addItem(QString::fromStdString(choice));
        connect(combo, &QComboBox::currentTextChanged, this,
                [this, spec](const QString& text) { parameterEdited(spec, text.toStdString()); });
        editor = combo;
        break;
    }
    }
    editor->setObjectName(QString::fromStdString("parameter_" + spec.key));
    return editor;
}

void PlannerSettingsPanel::showValues() {
    const bool wasUpdating = updating_;
    updating_ = true;
    for (const auto& [spec, editor] : editors_) {
        const ParameterValue* given = shown_.parameters.find(spec.key);
        const ParameterValue value = given != nullptr ? *given : spec.defaultValue;
        if (auto* check = qobject_cast<QCheckBox*>(editor))
            check->setChecked(std::get<bool>(value));
        else if (auto* spin = qobject_cast<QSpinBox*>(editor))
            spin->setValue(std::get<int>(value));
        else if (auto* real = qobject_cast<QDoubleSpinBox*>(editor))
            real->setValue(spec.isAutomatic(value)              ? real->minimum()
                           : std::holds_alternative<int>(value) ? std::get<int>(value)
                                                                : std::get<double>(value));
        else if (auto* combo = qobject_cast<QComboBox*>(editor))
            combo->setCurrentText(QString::fromStdString(std::get<std::string>(value)));
    }
    greyOutSwitchedOff();
    updating_ = wasUpdating;
}

// A parameter that has no effect without a switch (ParameterSpec::onlyWith) is greyed out, with its label,
// while that switch, or one that switch needs, is off.
void PlannerSettingsPanel::greyOutSwitchedOff() {
    for (const auto& [spec, editor] : editors_) {
        const bool inEffect = parameterInEffect(specs_, shown_.parameters, spec);
        editor->setEnabled(inEffect);
        if (QWidget* label = form_->labelForField(editor)) // boolean rows have none: the box holds it
            label->setEnabled(inEffect);
    }
}

void PlannerSettingsPanel::plannerPicked(int index) {
    if (updating_ || index < 0)
        return;
    const std::string name = planner_->itemData(index).toString().toStdString();
    shown_ = switchPlanner(shown_, name);
    updating_ = true;
    rebuildForm(findPlannerDescription(name).value_or(PlannerDescription{}));
    formPlanner_ = name;
    showValues();
    updating_ = false;
    emit choiceEdited(shown_);
}

void PlannerSettingsPanel::parameterEdited(const ParameterSpec& spec, ParameterValue value) {
    if (updating_)
        return;
    shown_.parameters.set(spec.key, std::move(value));
    greyOutSwitchedOff();
    emit choiceEdited(shown_);
}

} // namespace mcpp::ui
