#include "ui/ComparisonPanel.hpp"

#include "core/planners/PlannerRegistry.hpp"
#include "io/ComparisonRanking.hpp"
#include "render/ComparisonSheet.hpp"

#include <QApplication>
#include <QCheckBox>
#include <QDialog>
#include <QEvent>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <optional>

namespace mcpp::ui {

namespace {

// The figures that decide between planners first, so that a narrow dock shows them; comparison.csv and the
// sheet below carry the rest.
enum Column { Name, Covered, Makespan, Home, AgainstFirst, Turns, Ratio, Planning, Outcome, Columns };

constexpr int readingGroupRole = Qt::UserRole + 1;
constexpr int numberRole = Qt::UserRole + 2;

// A figure shown with all its decimals (1.00 beside 1.02, not 1), sorted by its value.
class NumberItem : public QTableWidgetItem {
  public:
    bool operator<(const QTableWidgetItem& other) const override {
        return data(numberRole).toDouble() < other.data(numberRole).toDouble();
    }
};

// A time sorted first by its plan's reading group (io::readingGroup: plans timed unlike the others, then
// those flying flights longer than a battery, then those covering less than the most, after the others; a
// descending sort turns the whole order round): the soonest done among those that do the whole job comes
// first, as batch mode's summary lists them.
class TimeItem : public NumberItem {
  public:
    bool operator<(const QTableWidgetItem& other) const override {
        const int group = data(readingGroupRole).toInt();
        if (group != other.data(readingGroupRole).toInt())
            return group < other.data(readingGroupRole).toInt();
        return NumberItem::operator<(other);
    }
};

template <typename Item = NumberItem> QTableWidgetItem* numberItem(double value, int decimals) {
    auto* item = new Item;
    item->setData(Qt::DisplayRole, QString::number(value, 'f', decimals));
    item->setData(numberRole, value);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    return item;
}

QTableWidgetItem* timeItem(double seconds, double unitSeconds, io::ReadingGroup readingGroup) {
    QTableWidgetItem* item = numberItem<TimeItem>(seconds / unitSeconds, 2);
    item->setData(readingGroupRole, static_cast<int>(readingGroup)); // sorted in the enumeration's order
    return item;
}

// When the team is done (io::doneAfterSeconds), so that sorting by Home reads as batch mode lists the plans:
// for a plan not timed in the field (no flights, or a battery plan's sorties), its makespan, greyed.
QTableWidgetItem* homeItem(const io::ComparisonRow& row, double unitSeconds, io::ReadingGroup readingGroup) {
    QTableWidgetItem* item = timeItem(io::doneAfterSeconds(row), unitSeconds, readingGroup);
    if (!row.metrics.timedInTheField()) {
        item->setForeground(QApplication::palette().brush(QPalette::Disabled, QPalette::Text));
        item->setToolTip(QObject::tr("Not timed in the field: done when its paths end, at its makespan"));
    }
    return item;
}

QString leavesLandNote(const PlannerDescription& planner) {
    if (planner.promises.everyReachableCellCovered)
        return {};
    return QObject::tr(" (leaves the land beyond its robots' reach uncovered: check it to compare it once "
                       "its reach suits the map)");
}

} // namespace

ComparisonPanel::ComparisonPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* choices = new QGridLayout;
    int index = 0;
    for (const PlannerDescription& planner : plannerDescriptions()) {
        auto* box = new QCheckBox(QString::fromStdString(planner.label), this);
        box->setObjectName(QString::fromStdString("compare_" + planner.name));
        box->setToolTip(QString::fromStdString(planner.summary) + leavesLandNote(planner));
        // A planner that leaves land beyond its robots' reach (a battery's) covers a fraction of the map
        // beside the others unless its reach was set for the job: compared when the user asks for it.
        box->setChecked(!planner.singleRobot && planner.promises.everyReachableCellCovered);
        checks_[planner.name] = box;
        choices->addWidget(box, index / 3, index % 3);
        ++index;
    }
    layout->addLayout(choices);
    runButton_ = new QPushButton(tr("Compare the checked planners"), this);
    runButton_->setObjectName(QStringLiteral("runComparisonButton"));
    connect(runButton_, &QPushButton::clicked, this, &ComparisonPanel::compareRequested);
    layout->addWidget(runButton_);

    table_ = new QTableWidget(0, Columns, this);
    table_->setObjectName(QStringLiteral("comparisonTable"));
    // Short headings so the table fits the dock; each says in full what it holds when hovered.
    const std::vector<std::pair<QString, QString>> headings{
        {tr("Planner"), tr("The planner's name")},
        {tr("Covered %"),
         tr("The share of the task area's land the plan covers. Sorted by time, a plan covering over half "
            "a percent less than the most comes after the others")},
        {tr("Hours"), tr("Makespan: the time of the slowest robot, in hours")},
        {tr("Home h"),
         tr("Where flights split the missions: when the last robot is home, its flights and the "
            "turnarounds between them included, in hours (in days where the makespan header says Days); "
            "for a plan not timed in the field, its makespan, greyed")},
        {tr("x 1st"),
         tr("Time done divided by the first plan's (in bold): how much longer the team waits with this one; "
            "none for a plan covering less than the most, one whose waypoint files hold flights longer than "
            "a battery where another plan's all fit, or one timing its robots at the class table's speeds "
            "where the others keep their own (sorted after them)")},
        {tr("Turns"), tr("Turns of all robots together")},
        {tr("Ratio"),
         tr("Makespan divided by the plan's own lower bound, which counts its own cells and turns: near "
            "1.00 the work is shared evenly. It says nothing of which plan is done sooner, and a loose bound "
            "reads high for an even plan (CPPIED's prices every pass at the fastest class's speed)")},
        {tr("Plan s"), tr("Seconds the planner took")},
        {tr("State"), tr("Planned, failed or skipped, and the plan's warnings (hover over the cell)")}};
    for (int column = 0; column < Columns; ++column) {
        auto* heading = new QTableWidgetItem(headings[static_cast<std::size_t>(column)].first);
        heading->setToolTip(headings[static_cast<std::size_t>(column)].second);
        table_->setHorizontalHeaderItem(column, heading);
    }
    table_->setColumnHidden(Home, true); // until some plan's robots are home later than their paths end
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->setVisible(false);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setSortingEnabled(true);
    connect(table_, &QTableWidget::itemSelectionChanged, this, [this] {
        const auto selected = table_->selectedItems();
        if (selected.isEmpty())
            return;
        const QTableWidgetItem* name = table_->item(selected.front()->row(), Name);
        emit planSelected(name->data(Qt::UserRole).toInt());
    });
    layout->addWidget(table_, 1);

    sheet_ = new QLabel(this);
    sheet_->setObjectName(QStringLiteral("comparisonSheet"));
    sheet_->setAlignment(Qt::AlignHCenter | Qt::AlignTop);
    sheet_->setToolTip(tr("Double-click to see the sheet at full size, where its captions can be read"));
    sheet_->installEventFilter(this);
    scroll_ = new QScrollArea(this);
    scroll_->setWidget(sheet_);
    scroll_->setWidgetResizable(true);
    // Fitted to the width, the sheet scrolls down only: a scroll bar appearing would narrow what it fits.
    scroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    scroll_->setMinimumHeight(160);
    layout->addWidget(scroll_, 2);
}

void ComparisonPanel::setRobotCount(int robots) {
    for (const PlannerDescription& planner : plannerDescriptions()) {
        QCheckBox* box = checks_.at(planner.name);
        const bool possible = !planner.singleRobot || robots <= 1;
        box->setEnabled(possible);
        if (!possible)
            box->setChecked(false);
        box->setToolTip(QString::fromStdString(planner.summary) +
                        (possible ? leavesLandNote(planner)
                                  : tr(" (plans for one robot; the mission has %1)").arg(robots)));
    }
}

std::vector<std::string> ComparisonPanel::checkedPlanners() const {
    std::vector<std::string> names;
    for (const PlannerDescription& planner : plannerDescriptions())
        if (checks_.at(planner.name)->isChecked() && checks_.at(planner.name)->isEnabled())
            names.push_back(planner.name);
    return names;
}

void ComparisonPanel::setCheckedPlanners(const std::vector<std::string>& planners) {
    for (auto& [name, box] : checks_)
        box->setChecked(std::find(planners.begin(), planners.end(), name) != planners.end());
}

int ComparisonPanel::widthShowingEveryColumn() const {
    table_->resizeColumnsToContents();
    // Beside the table's viewport the panel holds its margins, the table's frame and any scroll bar.
    return table_->horizontalHeader()->length() + width() - table_->viewport()->width();
}

void ComparisonPanel::setCanCompare(bool can, const QString& whyNot) {
    runButton_->setEnabled(can);
    runButton_->setToolTip(can ? QString() : whyNot);
}

void ComparisonPanel::showOutcome(const ComparisonOutcome& outcome, const ClassGrid& grid,
                                  const ClassTable& classes, const AreaOutline* area,
                                  std::shared_ptr<const void> gridOwner) {
    table_->setSortingEnabled(false);
    table_->clearContents();
    // While the comparison runs, the planners still to come have rows of their own, without figures.
    const std::size_t pending =
        outcome.choices.size() > outcome.rows.size() ? outcome.choices.size() - outcome.rows.size() : 0;
    table_->setRowCount(static_cast<int>(outcome.rows.size() + pending));
    bool inTheField = false; // some plan's robots are home later than their paths end
    // Days where the sheet's chart counts in days (a robot over ten days), so that both read alike.
    double longest = 0.0;
    for (const io::ComparisonRow& row : outcome.rows)
        if (row.outcome == io::ComparisonRow::Outcome::Planned)
            longest = std::max(longest, row.metrics.makespanSeconds);
    const bool inDays = longest > 10.0 * 86400.0;
    const double unitSeconds = inDays ? 86400.0 : 3600.0;
    table_->horizontalHeaderItem(Makespan)->setText(inDays ? tr("Days") : tr("Hours"));
    table_->horizontalHeaderItem(Makespan)->setToolTip(
        inDays ? tr("Makespan: the time of the slowest robot, in days")
               : tr("Makespan: the time of the slowest robot, in hours"));
    table_->horizontalHeaderItem(Home)->setText(inDays ? tr("Home d") : tr("Home h"));
    const std::vector<int> ranks = io::ranksOf(outcome.rows);
    const std::vector<double> againstFirst = io::timesTheFirst(outcome.rows);
    for (std::size_t i = 0; i < outcome.rows.size(); ++i) {
        const io::ComparisonRow& row = outcome.rows[i];
        const auto r = static_cast<int>(i);
        auto* name = new QTableWidgetItem(QString::fromStdString(row.planner));
        name->setData(Qt::UserRole, r);
        if (ranks[i] == 1) {
            // The plan batch mode's summary lists first: said in bold, as the table may be sorted otherwise.
            QFont bold = name->font();
            bold.setBold(true);
            name->setFont(bold);
            name->setToolTip(tr("Soonest done of the plans covering the most land and timed alike"));
        }
        table_->setItem(r, Name, name);
        const io::ReadingGroup group = io::readingGroup(row, outcome.rows);
        // A plan ranked after the first whatever its time says why, where "x 1st" is empty.
        const std::string apart = io::rankedApartReason(group);
        auto* state = new QTableWidgetItem(
            QString::fromStdString(apart.empty() ? io::outcomeName(row.outcome) : apart));
        state->setToolTip(QString::fromStdString(row.message));
        // A plan's warnings (robots timed at the class table's speeds, an uneven plan, land left
        // uncovered, flights longer than a battery) weigh on its figures: flagged on its row, said in full
        // when hovered.
        if (const std::vector<std::string> warnings = outcome.warningsOf(i); !warnings.empty()) {
            state->setText(warnings.size() == 1
                               ? tr("%1, 1 warning").arg(state->text())
                               : tr("%1, %2 warnings").arg(state->text()).arg(warnings.size()));
            // As paragraphs, so that Qt wraps them: a warning is a long sentence.
            QString paragraphs;
            for (const std::string& warning : warnings)
                paragraphs += QStringLiteral("<p>") + QString::fromStdString(warning).toHtmlEscaped() +
                              QStringLiteral("</p>");
            state->setToolTip(paragraphs);
        }
        table_->setItem(r, Outcome, state);
        if (row.outcome != io::ComparisonRow::Outcome::Planned)
            continue;
        const PlanMetrics& metrics = row.metrics;
        table_->setItem(r, Covered, numberItem(metrics.coveredFraction * 100.0, 1));
        QTableWidgetItem* ratio = numberItem(metrics.ratio, 3);
        if (metrics.boundOfDetectionPasses) {
            // Another kind of bound: greyed, so that 8.8 is not read as a plan 8.8 times uneven.
            ratio->setForeground(table_->palette().brush(QPalette::Disabled, QPalette::Text));
            ratio->setToolTip(
                tr("Against a bound of the passes its targets need, each at the fastest class's "
                   "speed: looser than the other plans' bounds, so this ratio reads high for an "
                   "even plan and is not to be set beside theirs"));
        }
        table_->setItem(r, Ratio, ratio);
        table_->setItem(r, Makespan, timeItem(metrics.makespanSeconds, unitSeconds, group));
        table_->setItem(r, Home, homeItem(row, unitSeconds, group));
        inTheField = inTheField || metrics.timedInTheField();
        if (againstFirst[i] > 0.0)
            table_->setItem(r, AgainstFirst, numberItem(againstFirst[i], 3));
        table_->setItem(r, Turns, numberItem(metrics.totalTurns(), 0));
        table_->setItem(r, Planning, numberItem(row.planningMilliseconds / 1000.0, 2));
    }
    for (std::size_t next = 0; next < pending; ++next) {
        const std::size_t index = outcome.rows.size() + next;
        const auto r = static_cast<int>(index);
        auto* name = new QTableWidgetItem(QString::fromStdString(outcome.choices[index].planner));
        name->setData(Qt::UserRole, r);
        // Greyed, in italics: not planned yet, whichever columns the dock has room for.
        QFont italic = name->font();
        italic.setItalic(true);
        name->setFont(italic);
        name->setForeground(table_->palette().brush(QPalette::Disabled, QPalette::Text));
        const QString state = next == 0 ? tr("planning…") : tr("waiting");
        name->setToolTip(state);
        table_->setItem(r, Name, name);
        table_->setItem(r, Outcome, new QTableWidgetItem(state));
    }
    table_->setColumnHidden(Home, !inTheField);
    // Every planner's row in view (up to nine) above the sheet, which scrolls on its own.
    const int shown = std::min(table_->rowCount(), 9);
    table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                             shown * table_->verticalHeader()->defaultSectionSize() +
                             2 * table_->frameWidth() + table_->horizontalScrollBar()->sizeHint().height());
    table_->setSortingEnabled(true);
    // Ratio, planning time and state (which says why a row has no "x 1st") were cut at the dock's usual
    // width, behind a scroll bar few users notice. Asked once every plan is in, not with each one done.
    if (pending == 0)
        emit widthWanted(widthShowingEveryColumn());
    // The soonest done first (of the plans that cover the most): what the user waits for, where a
    // balanced plan may still take longest.
    table_->sortByColumn(inTheField ? Home : Makespan, Qt::AscendingOrder);
    if (pending > 0) {
        // The sheet compares every plan: drawn once they are all made, not from an earlier comparison.
        forgetSheets();
        if (fullSizeSheet_ != nullptr)
            fullSizeSheet_->hide();
        return;
    }
    std::vector<const Plan*> plans;
    for (const auto& plan : outcome.plans)
        plans.push_back(plan.get());
    // One plan under another: the dock is narrow, and scaled to it three side by side had captions 5 px
    // tall. The sheet scrolls down instead.
    sheetImage_ = render::renderComparisonSheet(grid, classes,
                                                render::rankedComparisonPanels(outcome.rows, plans), area, 1);
    // The full-size window's sheet, three side by side, drawn only if asked for. It holds the plans, the
    // class table and what holds the grid.
    wideSheetImage_ = QImage();
    drawWideSheet_ = [grid = &grid, owner = std::move(gridOwner), classes, rows = outcome.rows,
                      kept = outcome.plans,
                      edges = area != nullptr ? std::optional<AreaOutline>(*area) : std::nullopt] {
        std::vector<const Plan*> drawn;
        for (const auto& plan : kept)
            drawn.push_back(plan.get());
        return render::renderComparisonSheet(*grid, classes, render::rankedComparisonPanels(rows, drawn),
                                             edges ? &*edges : nullptr);
    };
    fitSheet();
    if (fullSizeSheet_ != nullptr && fullSizeSheet_->isVisible())
        showFullSizeSheet(); // the new comparison's sheet where the last one's is open
}

void ComparisonPanel::clearOutcome() {
    table_->clearContents();
    table_->setRowCount(0);
    forgetSheets();
    if (fullSizeSheet_ != nullptr)
        fullSizeSheet_->hide();
}

void ComparisonPanel::forgetSheets() {
    sheetImage_ = QImage();
    wideSheetImage_ = QImage();
    drawWideSheet_ = nullptr;
    sheet_->clear();
}

bool ComparisonPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == sheet_ && event->type() == QEvent::MouseButtonDblClick) {
        showFullSizeSheet();
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

QDialog* ComparisonPanel::showFullSizeSheet() {
    if (sheetImage_.isNull())
        return nullptr;
    if (fullSizeSheet_ == nullptr) {
        fullSizeSheet_ = new QDialog(this);
        fullSizeSheet_->setObjectName(QStringLiteral("fullSizeSheet"));
        fullSizeSheet_->setWindowTitle(tr("Planners compared"));
        auto* scroll = new QScrollArea(fullSizeSheet_);
        fullSizeImage_ = new QLabel(scroll);
        scroll->setWidget(fullSizeImage_);
        auto* layout = new QVBoxLayout(fullSizeSheet_);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(scroll);
    }
    if (wideSheetImage_.isNull() && drawWideSheet_) {
        QApplication::setOverrideCursor(Qt::WaitCursor); // a second drawing of every plan
        wideSheetImage_ = drawWideSheet_();
        QApplication::restoreOverrideCursor();
    }
    const QImage& shown = wideSheetImage_.isNull() ? sheetImage_ : wideSheetImage_;
    fullSizeImage_->setPixmap(QPixmap::fromImage(shown));
    fullSizeImage_->adjustSize();
    // As large as the sheet, within most of the panel's screen.
    const QRect screen =
        this->screen() != nullptr ? this->screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    fullSizeSheet_->resize(std::min(shown.width() + 24, screen.width() * 9 / 10),
                           std::min(shown.height() + 24, screen.height() * 9 / 10));
    fullSizeSheet_->show();
    fullSizeSheet_->raise();
    return fullSizeSheet_;
}

void ComparisonPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitSheet();
}

// The sheet as wide as the panel shows it, so the maps and the chart are seen whole.
void ComparisonPanel::fitSheet() {
    if (sheetImage_.isNull())
        return;
    const int width = std::clamp(scroll_->viewport()->width() - 4, 200, sheetImage_.width());
    sheet_->setPixmap(QPixmap::fromImage(sheetImage_.scaledToWidth(width, Qt::SmoothTransformation)));
}

int ComparisonPanel::rowOfPlanner(const std::string& planner) const {
    for (int row = 0; row < table_->rowCount(); ++row)
        if (table_->item(row, Name) != nullptr && table_->item(row, Name)->text().toStdString() == planner)
            return row;
    return -1;
}

} // namespace mcpp::ui
