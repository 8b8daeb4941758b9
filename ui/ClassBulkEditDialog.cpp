#include "ui/ClassBulkEditDialog.hpp"

#include "core/model/LandCoverClass.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace mcpp::ui {

namespace {

QDoubleSpinBox* numberBox(double maximum, double value, const QString& suffix, QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(0.0, maximum);
    box->setDecimals(2);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setEnabled(false);
    return box;
}

} // namespace

ClassBulkEditDialog::ClassBulkEditDialog(int selectedClasses, QWidget* parent)
    : QDialog(parent), speedCheck(new QCheckBox(tr("Speed"), this)),
      speed(numberBox(kMaximumSpeedMetresPerSecond, 1.0, tr(" m/s"), this)),
      fieldOfViewCheck(new QCheckBox(tr("FOV"), this)),
      fieldOfView(numberBox(kMaximumFieldOfViewMetres, 10.0, tr(" m"), this)),
      passableCheck(new QCheckBox(tr("Passable"), this)), passable(new QComboBox(this)),
      fieldOfViewFactor(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("classBulkEditDialog"));
    setWindowTitle(tr("Edit %n classes", nullptr, selectedClasses));
    passable->addItem(tr("yes"), true);
    passable->addItem(tr("no (obstacle)"), false);
    passable->setEnabled(false);
    fieldOfViewFactor->setRange(0.01, 100.0);
    fieldOfViewFactor->setDecimals(2);
    fieldOfViewFactor->setValue(1.0);
    fieldOfViewFactor->setPrefix(QStringLiteral("× "));
    fieldOfViewFactor->setToolTip(tr("Multiplies every selected class's FOV (after a new FOV above, if set): "
                                     "2 doubles the swath and quarters the number of cells"));
    connect(speedCheck, &QCheckBox::toggled, speed, &QWidget::setEnabled);
    connect(fieldOfViewCheck, &QCheckBox::toggled, fieldOfView, &QWidget::setEnabled);
    connect(passableCheck, &QCheckBox::toggled, passable, &QWidget::setEnabled);

    auto* form = new QFormLayout;
    form->addRow(speedCheck, speed);
    form->addRow(fieldOfViewCheck, fieldOfView);
    form->addRow(passableCheck, passable);
    form->addRow(tr("Scale FOVs"), fieldOfViewFactor);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Tick what to set in all %n selected classes; the rest stays as it is. "
                                    "One step to undo.",
                                    nullptr, selectedClasses),
                                 this));
    layout->addLayout(form);
    layout->addWidget(buttons);
}

ClassBulkEdit ClassBulkEditDialog::edit() const {
    ClassBulkEdit result;
    if (speedCheck->isChecked())
        result.speed = speed->value();
    if (fieldOfViewCheck->isChecked())
        result.fieldOfView = fieldOfView->value();
    if (passableCheck->isChecked())
        result.passable = passable->currentData().toBool();
    result.fieldOfViewFactor = fieldOfViewFactor->value();
    return result;
}

} // namespace mcpp::ui
