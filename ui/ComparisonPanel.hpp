#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "ui/ComparisonRunner.hpp"

#include <QImage>
#include <QWidget>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

class QCheckBox;
class QDialog;
class QLabel;
class QPushButton;
class QScrollArea;
class QTableWidget;

namespace mcpp::ui {

// The comparison dock: which planners to run (checkboxes), then a sortable table of their figures and the
// plans side by side with a chart of every robot's time. Selecting a row asks for that plan to be shown.
class ComparisonPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ComparisonPanel(QWidget* parent = nullptr);

    // One-robot planners cannot take part with several robots: their boxes are disabled and say why.
    void setRobotCount(int robots);
    [[nodiscard]] std::vector<std::string> checkedPlanners() const;
    void setCheckedPlanners(const std::vector<std::string>& planners);
    // Whether the panel's button runs a comparison (not while planning or exporting, nor without a map and
    // robots); why not, in its tooltip.
    void setCanCompare(bool can, const QString& whyNot);
    // area: the area of interest's and no-go zones' edges, drawn on the sheet's maps. An outcome with fewer
    // rows than choices is one still running: the rest are listed as to come, and the sheet waits for them.
    // gridOwner: what holds the grid, kept while the full-size sheet may still be drawn from it (none: the
    // caller keeps the grid until the next outcome or clearOutcome).
    void showOutcome(const ComparisonOutcome& outcome, const ClassGrid& grid, const ClassTable& classes,
                     const AreaOutline* area = nullptr, std::shared_ptr<const void> gridOwner = {});

    // No rows and no sheet: a comparison dropped because another map was opened while it ran.
    void clearOutcome();

    [[nodiscard]] QTableWidget* table() const { return table_; }
    [[nodiscard]] QLabel* sheet() const { return sheet_; }
    // The table row (in its current order) of a planner, or -1.
    [[nodiscard]] int rowOfPlanner(const std::string& planner) const;
    // The sheet at full size in a window of its own, up to three plans side by side, where its captions can
    // be read (the dock shows one plan under another, scaled to its width); what double-clicking the sheet
    // does. Null before any comparison.
    QDialog* showFullSizeSheet();

  signals:
    void compareRequested();
    void planSelected(int outcomeRow); // index into the outcome's rows
    // The panel's width at which every column of the table shows without scrolling sideways.
    void widthWanted(int pixels);

  protected:
    void resizeEvent(QResizeEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void fitSheet();
    // The panel's width that shows every column of the table side by side.
    [[nodiscard]] int widthShowingEveryColumn() const;
    // No sheet shown and none to draw: the comparison is still running or was dropped.
    void forgetSheets();

    std::map<std::string, QCheckBox*> checks_;
    QPushButton* runButton_ = nullptr;
    QTableWidget* table_ = nullptr;
    QLabel* sheet_ = nullptr;
    QScrollArea* scroll_ = nullptr;
    QImage sheetImage_; // full size; shown scaled to the panel
    // The sheet of up to three plans side by side, drawn when the full-size window first shows it.
    std::function<QImage()> drawWideSheet_;
    QImage wideSheetImage_;
    QDialog* fullSizeSheet_ = nullptr;
    QLabel* fullSizeImage_ = nullptr;
};

} // namespace mcpp::ui
