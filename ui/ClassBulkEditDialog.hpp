#pragma once

#include "ui/ClassTableModel.hpp"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace mcpp::ui {

// Asks what to change in the selected classes: a speed, a FOV, passability, and a factor for the FOVs.
class ClassBulkEditDialog : public QDialog {
    Q_OBJECT

  public:
    ClassBulkEditDialog(int selectedClasses, QWidget* parent = nullptr);
    [[nodiscard]] ClassBulkEdit edit() const;

    QCheckBox* speedCheck;
    QDoubleSpinBox* speed;
    QCheckBox* fieldOfViewCheck;
    QDoubleSpinBox* fieldOfView;
    QCheckBox* passableCheck;
    QComboBox* passable;
    QDoubleSpinBox* fieldOfViewFactor;
};

} // namespace mcpp::ui
