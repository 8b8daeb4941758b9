#include "ui/PlannerSettingsPanel.hpp"

#include "core/planners/PlannerRegistry.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace mcpp::ui {

PlannerSettingsPanel::PlannerSettingsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("plannerSettingsPanel"));
    auto* layout = new QFormLayout(this);

    planner_ = new QComboBox(this);
    planner_->setObjectName(QStringLiteral("plannerCombo"));
    for (const auto& name : availablePlanners())
        planner_->addItem(QString::fromStdString(name));
    planner_->setToolTip(tr("The coverage planner to run"));
    layout->addRow(tr("Planner"), planner_);

    purityTolerance_ = new QDoubleSpinBox(this);
    purityTolerance_->setObjectName(QStringLiteral("purityToleranceSpin"));
    purityTolerance_->setRange(0.0, 0.5);
    purityTolerance_->setSingleStep(0.01);
    purityTolerance_->setDecimals(3);
    purityTolerance_->setToolTip(
        tr("A class covering at most this fraction of a cell does not force a split"));
    layout->addRow(tr("Purity tolerance"), purityTolerance_);

    blockedThreshold_ = new QDoubleSpinBox(this);
    blockedThreshold_->setObjectName(QStringLiteral("blockedThresholdSpin"));
    blockedThreshold_->setRange(0.0, 1.0);
    blockedThreshold_->setSingleStep(0.05);
    blockedThreshold_->setDecimals(2);
    blockedThreshold_->setToolTip(
        tr("A smallest cell with more obstacle or outside pixels than this fraction is blocked"));
    layout->addRow(tr("Blocked threshold"), blockedThreshold_);

    closedTour_ = new QCheckBox(tr("Return to start (closed tour)"), this);
    closedTour_->setObjectName(QStringLiteral("closedTourCheck"));
    closedTour_->setToolTip(tr("Closed tours end where they start; open paths stop at the last cell"));
    layout->addRow(QString(), closedTour_);

    rebalanceIterations_ = new QSpinBox(this);
    rebalanceIterations_->setObjectName(QStringLiteral("rebalanceSpin"));
    rebalanceIterations_->setRange(0, 1'000'000);
    rebalanceIterations_->setSpecialValueText(tr("automatic"));
    rebalanceIterations_->setToolTip(
        tr("Cap on cell moves that even out the robots' workloads; 0 picks one from the problem size"));
    layout->addRow(tr("Rebalance iterations"), rebalanceIterations_);

    snapStarts_ = new QCheckBox(tr("Move blocked starts to the nearest free cell"), this);
    snapStarts_->setObjectName(QStringLiteral("snapStartsCheck"));
    layout->addRow(QString(), snapStarts_);

    connect(planner_, &QComboBox::currentIndexChanged, this, &PlannerSettingsPanel::emitEdited);
    connect(purityTolerance_, &QDoubleSpinBox::valueChanged, this, &PlannerSettingsPanel::emitEdited);
    connect(blockedThreshold_, &QDoubleSpinBox::valueChanged, this, &PlannerSettingsPanel::emitEdited);
    connect(closedTour_, &QCheckBox::toggled, this, &PlannerSettingsPanel::emitEdited);
    connect(rebalanceIterations_, &QSpinBox::valueChanged, this, &PlannerSettingsPanel::emitEdited);
    connect(snapStarts_, &QCheckBox::toggled, this, &PlannerSettingsPanel::emitEdited);
    setSettings(PlannerSettings{});
}

void PlannerSettingsPanel::setSettings(const PlannerSettings& settings) {
    updating_ = true;
    shown_ = settings;
    const QString name = QString::fromStdString(settings.planner);
    if (planner_->findText(name) < 0)
        planner_->addItem(name); // keep a mission's unknown planner visible
    planner_->setCurrentText(name);
    purityTolerance_->setValue(settings.purityTolerance);
    blockedThreshold_->setValue(settings.blockedThreshold);
    closedTour_->setChecked(settings.closedTour);
    rebalanceIterations_->setValue(settings.rebalanceIterations);
    snapStarts_->setChecked(settings.snapStartsToFreeCells);
    updating_ = false;
}

PlannerSettings PlannerSettingsPanel::settings() const {
    PlannerSettings settings = shown_;
    settings.planner = planner_->currentText().toStdString();
    settings.purityTolerance = purityTolerance_->value();
    settings.blockedThreshold = blockedThreshold_->value();
    settings.closedTour = closedTour_->isChecked();
    settings.rebalanceIterations = rebalanceIterations_->value();
    settings.snapStartsToFreeCells = snapStarts_->isChecked();
    return settings;
}

void PlannerSettingsPanel::emitEdited() {
    if (updating_)
        return;
    shown_ = settings();
    emit settingsEdited(shown_);
}

} // namespace mcpp::ui
