#include "ui/MainWindow.hpp"

#include "core/decomposition/FieldOfViewRounding.hpp"
#include "core/decomposition/LandCoverSamples.hpp"
#include "core/model/HumanUnits.hpp"
#include "core/model/SortieLayer.hpp"
#include "core/model/TimelineLayer.hpp"
#include "core/planners/PlannerRegistry.hpp"
#include "io/AreaOfInterest.hpp"
#include "io/AutopilotMission.hpp"
#include "io/ClassTableSources.hpp"
#include "io/ExportCatalogue.hpp"
#include "io/LongPlanCauses.hpp"
#include "io/MissionInputs.hpp"
#include "io/MissionScale.hpp"
#include "io/PlanExport.hpp"
#include "io/PlanFile.hpp"
#include "io/PointsInDegrees.hpp"
#include "render/PlanImageWriter.hpp"
#include "render/PlanLegend.hpp"
#include "ui/ApplicationResources.hpp"
#include "ui/ClassBulkEditDialog.hpp"
#include "ui/ClassTableBanner.hpp"
#include "ui/ClassTableEditCommand.hpp"
#include "ui/ClassTableModel.hpp"
#include "ui/ComparedWarnings.hpp"
#include "ui/ComparisonPanel.hpp"
#include "ui/ComparisonRunner.hpp"
#include "ui/EventTableModel.hpp"
#include "ui/ExportFileName.hpp"
#include "ui/ExportRunner.hpp"
#include "ui/LayersPanel.hpp"
#include "ui/LegendPanel.hpp"
#include "ui/MapCanvas.hpp"
#include "ui/MessageLog.hpp"
#include "ui/PlannerSettingsPanel.hpp"
#include "ui/PlanningRunner.hpp"
#include "ui/RecentFiles.hpp"
#include "ui/ResultsPanel.hpp"
#include "ui/RobotTableModel.hpp"
#include "ui/SampleMission.hpp"
#include "ui/TimelineBar.hpp"
#include "ui/VehicleSettingsDialog.hpp"
#include "ui/VehicleSettingsEditCommand.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardItemModel>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableView>
#include <QTimer>
#include <QToolBar>
#include <QToolTip>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace mcpp::ui {

namespace {

// A refusal of the mission's classes or starts, with the warning of a preset of another product, which may
// be why: its obstacles are that product's classes.
QString refusalText(const std::string& error, const io::Mission& mission, const io::LoadedRaster& raster) {
    QString text = QString::fromStdString(error);
    if (const auto otherProduct = io::presetOfAnotherProductWarning(mission, raster))
        text += QStringLiteral("\n\n") + QString::fromStdString(*otherProduct);
    return text;
}

// The files an export wrote, for the status bar: each where few, else how many, where, and the first and
// last (a drone's mission split into hundreds of parts named them all, cut off at the window's edge).
QString exportedFilesText(const QStringList& written) {
    constexpr int mostNamed = 3;
    if (written.size() <= mostNamed)
        return written.join(QStringLiteral(", "));
    return QObject::tr("%1 files in %2 (%3 to %4)")
        .arg(written.size())
        .arg(QDir::toNativeSeparators(QFileInfo(written.front()).absolutePath()),
             QFileInfo(written.front()).fileName(), QFileInfo(written.back()).fileName());
}

// A speed as batch mode gives it: "0.3", "1.5" (three significant digits).
QString speedText(double metresPerSecond) {
    return QString::fromStdString(formatQuantity(metresPerSecond, 3));
}

// What the legend says of when each robot is done in the field, from its waypoint files' sizes (by path,
// as the plan holds them), where that comes later than its path.
std::vector<render::FieldTime> fieldTimesOf(const Plan& plan, const std::vector<io::MissionSize>& sizes,
                                            const std::vector<io::VehicleSettings>& vehicles) {
    std::vector<render::FieldTime> times(plan.metrics.robots.size());
    for (std::size_t i = 0; i < sizes.size() && i < plan.paths.size(); ++i) {
        const auto robot = static_cast<std::size_t>(plan.paths[i].robot);
        if (robot >= times.size())
            continue;
        const bool flights = robot < vehicles.size() && io::isAircraft(vehicles[robot].type);
        times[robot] = render::fieldTimeBeyondPath(plan.metrics.robots[robot].timeSeconds,
                                                   sizes[i].fieldSeconds, sizes[i].parts, flights);
    }
    return times;
}

// The size warning: what the map needs against what the machine allows, and what fits.
// The planner is named: planners need different memory per cell.
QString tooFineText(const QString& planner, const CellBudgetEstimate& estimate, double fovMin, int levels,
                    double fitFactor) {
    const QString need =
        QObject::tr("Too fine to plan with %1 on this machine: the smallest FOV, %2 m, makes "
                    "%3 million cells, which need %4 GB of memory; %5 GB are available.")
            .arg(planner)
            .arg(fovMin)
            .arg(static_cast<double>(estimate.bottomCells) / 1e6, 0, 'f', 1)
            .arg(static_cast<double>(estimate.neededBytes) / 1e9, 0, 'f', 1)
            .arg(static_cast<double>(estimate.allowedBytes) / 1e9, 0, 'f', 1);
    if (fitFactor > 0.0)
        return need + QStringLiteral(" ") +
               QObject::tr("Scaling every FOV by %1 (smallest %2 m) fits.")
                   .arg(fitFactor)
                   .arg(fovMin * fitFactor);
    if (levels > 1)
        return need + QStringLiteral(" ") +
               QObject::tr("No scaling fits while the FOVs need %1 quadtree levels: bring them closer.")
                   .arg(levels);
    return need;
}

const QString kRasterFolderKey = QStringLiteral("folders/raster");
const QString kMissionFolderKey = QStringLiteral("folders/mission");
const QString kExportFolderKey = QStringLiteral("folders/export");
const QString kOwnTableData = QStringLiteral("<own table>"); // preset box: neither a preset nor the legend
const QString kSampleShownKey = QStringLiteral("sampleShown");
const QString kRasterFilter =
    QObject::tr("Land-cover rasters (*.tif *.tiff *.img *.vrt *.asc *.gpkg *.nc);;All files (*)");
const QString kMissionFilter = QObject::tr("mcpp missions (*.json);;All files (*)");

// Whether every class has the same field of view, as one given over the whole table makes it.
bool hasOneFieldOfView(const ClassTable& classes) {
    return std::all_of(classes.classes().begin(), classes.classes().end(),
                       [&](const LandCoverClass& landCover) {
                           return landCover.fieldOfViewMetres == classes.classes().front().fieldOfViewMetres;
                       });
}

// Exported PNGs are for print: larger than batch mode's plan.png.
constexpr int exportImageSide = 3000;

// "zion-plan.plan" -> "zion-plan-robot2.plan" when several robots share one chosen name, the number padded
// with zeros to the width of the last ("zion-plan-robot02.plan" of 12) so that file lists sort them in order.
QString perRobotPath(const QString& path, int robot, int robots) {
    if (robots <= 1)
        return path;
    const QFileInfo info(path);
    const QString suffix = info.suffix().isEmpty() ? QString() : QStringLiteral(".") + info.suffix();
    const auto width = static_cast<int>(QString::number(robots).size());
    return info.dir().filePath(QStringLiteral("%1-robot%2%3")
                                   .arg(info.completeBaseName())
                                   .arg(robot + 1, width, 10, QLatin1Char('0'))
                                   .arg(suffix));
}

// No thousands separators: "228,269.3, 12,469.5" cannot be read back; pairs are labelled X and Y instead.
QString formatCoordinate(double value) {
    QLocale locale = QLocale::system();
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale.toString(value, 'f', 1);
}

QString formatDegrees(double value, QChar positive, QChar negative) {
    return QStringLiteral("%1° %2").arg(std::abs(value), 0, 'f', 5).arg(value >= 0.0 ? positive : negative);
}

// Warnings come from io as clauses ("no CRS: ..."); in the window they follow other sentences.
// A plan's message as the messages panel keeps it: a sentence, a robot's name as written, the robots it
// numbers named and the map points it names with their degrees (on a map of a CRS).
QString loggedText(const std::string& message, const std::vector<std::string>& robotNames,
                   const io::LoadedRaster* raster) {
    QString text = QString::fromStdString(io::messageForPeople(message, raster, robotNames));
    if (!text.endsWith(QLatin1Char('.')))
        text += QLatin1Char('.');
    return text;
}

QString asSentence(const std::string& clause) {
    QString text = QString::fromStdString(clause).trimmed();
    if (text.isEmpty())
        return text;
    text[0] = text[0].toUpper();
    if (!text.endsWith(QLatin1Char('.')))
        text += QLatin1Char('.');
    return text;
}

// The toolbar's Undo or Redo: a short label that keeps the buttons after it in place, the step it takes
// ("Undo Move centre") in its tooltip; it does what the Edit menu's action does, when that one can.
QAction* toolbarStep(QAction* menuAction, const QString& label, QObject* parent) {
    auto* step = new QAction(menuAction->icon(), label, parent);
    step->setToolTip(menuAction->text().remove(QLatin1Char('&')));
    step->setEnabled(menuAction->isEnabled());
    QObject::connect(step, &QAction::triggered, menuAction, &QAction::trigger);
    QObject::connect(menuAction, &QAction::changed, step, [step, menuAction] {
        step->setEnabled(menuAction->isEnabled());
        step->setToolTip(menuAction->text().remove(QLatin1Char('&')));
    });
    return step;
}

// A vehicle setting no robot can fly, with where the window changes it. It begins with a robot's name as
// the user wrote it, or "every robot".
QString vehiclesProblemText(const std::string& problem) {
    QString text = QString::fromStdString(problem);
    if (text.startsWith(QStringLiteral("every robot")))
        text[0] = text[0].toUpper();
    return QObject::tr("%1. Change it in the Robot vehicles dialog (Plan menu).").arg(text);
}

// A planner setting as the Planner panel labels it; advice to switch a checkbox on says to tick it.
std::string plannerSettingName(const std::string& planner, const io::MissionField& field) {
    const auto description = findPlannerDescription(planner);
    const ParameterSpec* spec = nullptr;
    if (description)
        for (const ParameterSpec& candidate : description->parameters)
            if (candidate.key == field.key)
                spec = &candidate;
    const std::string label = spec ? "\"" + spec->label + "\"" : field.key;
    if (spec && spec->type == ParameterType::Boolean && field.value == "true")
        return "tick " + label + " in the Planner panel";
    return "the Planner panel's " + label + (field.value.empty() ? std::string() : " set to " + field.value);
}

QDockWidget* makeDock(const QString& objectName, const QString& title, QWidget* content, QWidget* parent) {
    auto* dock = new QDockWidget(title, parent);
    dock->setObjectName(objectName);
    dock->setWidget(content);
    return dock;
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), document_(new MissionDocument(this)), undoStack_(new QUndoStack(this)),
      canvas_(new MapCanvas(document_, this)), classModel_(new ClassTableModel(document_, undoStack_, this)),
      robotModel_(new RobotTableModel(document_, undoStack_, this)),
      eventModel_(new EventTableModel(document_, undoStack_, this)), runner_(new PlanningRunner(this)),
      exportRunner_(new ExportRunner(this)), comparisonRunner_(new ComparisonRunner(this)) {
    setObjectName(QStringLiteral("mainWindow"));
    setWindowIcon(actionIcon("mcpp"));
    classTableBanner_ = new ClassTableBanner(this);
    auto* centre = new QWidget(this);
    auto* centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(classTableBanner_);
    centreLayout->addWidget(canvas_, 1);
    timelineBar_ = new TimelineBar(centre);
    timelineBar_->hide();
    centreLayout->addWidget(timelineBar_);
    setCentralWidget(centre);
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    createDocks();
    createActions();
    createStatusBar();
    connectDocument();
    restoreSettings();
    updateTitle();
    updateActions();
    updateResults();

    // Deferred so that app/main.cpp (or a test) can open a file or opt out before the event loop runs.
    QTimer::singleShot(0, this, [this] {
        if (!openSampleOnFirstStart_ || document_->hasMap())
            return;
        QSettings settings;
        if (settings.value(kSampleShownKey, false).toBool())
            return;
        settings.setValue(kSampleShownKey, true);
        openSampleMission(true);
    });
}

MainWindow::~MainWindow() {
    // A run that ends now must not call back into a window being torn down.
    disconnect(runner_, nullptr, this, nullptr);
    disconnect(exportRunner_, nullptr, this, nullptr);
    disconnect(comparisonRunner_, nullptr, this, nullptr);
    if (comparisonRunner_->isRunning()) {
        comparisonRunner_->cancel();
        comparisonRunner_->waitForFinished();
        QGuiApplication::restoreOverrideCursor();
    }
    if (exportRunner_->isRunning()) {
        exportRunner_->cancel();
        exportRunner_->waitForFinished();
        QGuiApplication::restoreOverrideCursor();
    }
    disconnect(undoStack_, nullptr, this,
               nullptr); // clearing the stack on destruction signals an index change
    disconnect(document_, nullptr, this, nullptr);
    runner_->cancel();
    runner_->waitForFinished();
}

void MainWindow::createDocks() {
    layersPanel_ = new LayersPanel(this);
    connect(layersPanel_, &LayersPanel::layersChanged, canvas_, &MapCanvas::setLayers);

    // Land-cover classes: a preset chooser above the table.
    auto* classesWidget = new QWidget(this);
    auto* classesLayout = new QVBoxLayout(classesWidget);
    classesLayout->setContentsMargins(4, 4, 4, 4);
    auto* presetRow = new QHBoxLayout;
    presetRow->addWidget(new QLabel(tr("Preset:"), classesWidget));
    presetCombo_ = new QComboBox(classesWidget);
    presetCombo_->setObjectName(QStringLiteral("presetCombo"));
    presetCombo_->addItem(tr("From the raster's legend"), QString());
    for (const auto& preset : io::classTablePresets()) {
        presetCombo_->addItem(QString::fromStdString(preset.name), QString::fromStdString(preset.name));
        presetCombo_->setItemData(presetCombo_->count() - 1, QString::fromStdString(preset.description),
                                  Qt::ToolTipRole);
    }
    // Shown, never chosen: the table was loaded from a CSV or edited away from the raster's legend.
    presetCombo_->addItem(tr("Own table (loaded or edited)"), kOwnTableData);
    if (auto* items = qobject_cast<QStandardItemModel*>(presetCombo_->model()))
        items->item(presetCombo_->count() - 1)->setEnabled(false);
    presetCombo_->setToolTip(tr("Replace speeds, FOVs and passability with a preset's (one undoable step)"));
    presetRow->addWidget(presetCombo_, 1);
    auto* loadCsv = new QPushButton(tr("Load CSV…"), classesWidget);
    loadCsv->setObjectName(QStringLiteral("loadClassCsvButton"));
    auto* saveCsv = new QPushButton(tr("Save CSV…"), classesWidget);
    saveCsv->setObjectName(QStringLiteral("saveClassCsvButton"));
    auto* editSelected = new QPushButton(tr("Edit selected…"), classesWidget);
    editSelected->setObjectName(QStringLiteral("editSelectedClassesButton"));
    editSelected->setToolTip(tr("Set speed, FOV or passability of every selected class at once, or scale "
                                "their FOVs (select rows with Ctrl or Shift; Ctrl+A for all)"));
    presetRow->addWidget(editSelected);
    presetRow->addWidget(loadCsv);
    presetRow->addWidget(saveCsv);
    classesLayout->addLayout(presetRow);
    classView_ = new QTableView(classesWidget);
    classView_->setObjectName(QStringLiteral("classTableView"));
    classView_->setModel(classModel_);
    classView_->verticalHeader()->hide();
    classView_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    classView_->horizontalHeader()->setSectionResizeMode(ClassTableModel::Name, QHeaderView::Stretch);
    classView_->setSelectionBehavior(QAbstractItemView::SelectRows);
    classView_->setSelectionMode(QAbstractItemView::ExtendedSelection);
    classView_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                QAbstractItemView::AnyKeyPressed);
    classesLayout->addWidget(classView_, 1);
    connect(presetCombo_, &QComboBox::activated, this,
            [this](int index) { applyPreset(presetCombo_->itemData(index).toString()); });
    connect(classModel_, &ClassTableModel::editRefused, this, [this](const QString& reason) {
        showStatus(reason);
        QToolTip::showText(QCursor::pos(), reason, classView_);
    });
    connect(editSelected, &QPushButton::clicked, this, [this] {
        QList<int> rows;
        for (const QModelIndex& index : classView_->selectionModel()->selectedRows())
            rows << index.row();
        if (rows.isEmpty()) {
            showStatus(
                tr("Select the classes to change first (click rows with Ctrl or Shift; Ctrl+A for all)."));
            return;
        }
        ClassBulkEditDialog dialog(static_cast<int>(rows.size()), this);
        if (dialog.exec() == QDialog::Accepted && !classModel_->editRows(rows, dialog.edit()))
            reportError(tr("Cannot edit classes"), classModel_->lastRefusal());
    });
    connect(loadCsv, &QPushButton::clicked, this, [this] {
        if (!document_->hasMap())
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Load class table"),
                                                          dialogFolder(kMissionFolderKey), tr("CSV (*.csv)"));
        if (path.isEmpty())
            return;
        loadClassTable(path);
    });
    connect(saveCsv, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save class table"),
                                                          dialogFolder(kMissionFolderKey), tr("CSV (*.csv)"));
        if (path.isEmpty())
            return;
        const auto status = io::saveClassTableCsv(document_->classes(), path.toStdString());
        if (!status.ok())
            reportError(tr("Cannot save class table"), QString::fromStdString(status.error()));
        else
            showStatus(tr("Saved class table to %1").arg(path));
    });

    // Robots: table plus add/remove.
    auto* robotsWidget = new QWidget(this);
    auto* robotsLayout = new QVBoxLayout(robotsWidget);
    robotsLayout->setContentsMargins(4, 4, 4, 4);
    robotView_ = new QTableView(robotsWidget);
    robotView_->setObjectName(QStringLiteral("robotTableView"));
    robotView_->setModel(robotModel_);
    robotView_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    robotView_->horizontalHeader()->setStretchLastSection(true);
    // The colour shows beside the name: the table fits the dock without scrolling sideways.
    robotView_->hideColumn(RobotTableModel::Colour);
    showBatteryColumnForBatteryPlanners();
    robotView_->setSelectionBehavior(QAbstractItemView::SelectRows);
    robotView_->setSelectionMode(QAbstractItemView::SingleSelection);
    // Room for two robots at least (one looked like the only one), still fitting a 1000-pixel screen.
    robotView_->setMinimumHeight(robotView_->horizontalHeader()->sizeHint().height() +
                                 2 * robotView_->verticalHeader()->defaultSectionSize() +
                                 2 * robotView_->frameWidth());
    robotsLayout->addWidget(robotView_, 1);
    auto* robotButtons = new QHBoxLayout;
    auto* addRobot = new QPushButton(tr("Add on map"), robotsWidget);
    addRobot->setObjectName(QStringLiteral("addRobotButton"));
    addRobot->setToolTip(tr("Switch to the Place start tool: each click on the map adds a robot"));
    auto* removeRobot = new QPushButton(tr("Remove"), robotsWidget);
    removeRobot->setObjectName(QStringLiteral("removeRobotButton"));
    robotButtons->addWidget(addRobot);
    robotButtons->addWidget(removeRobot);
    robotButtons->addStretch(1);
    robotsLayout->addLayout(robotButtons);
    connect(addRobot, &QPushButton::clicked, this, [this] {
        placeToolAction_->setChecked(true);
        canvas_->setFocus();
    });
    connect(removeRobot, &QPushButton::clicked, this, &MainWindow::removeSelectedRobot);
    connect(robotModel_, &RobotTableModel::editRefused, this,
            [this](const QString& reason) { showStatus(reason); });
    connect(robotView_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                canvas_->setSelectedStart(current.isValid() ? current.row() : -1);
            });
    connect(canvas_, &MapCanvas::selectedStartChanged, this, [this](int robot) {
        if (robot < 0)
            robotView_->clearSelection();
        else if (robotView_->currentIndex().row() != robot)
            robotView_->selectRow(robot);
    });

    auto* eventsWidget = createEventsWidget();

    settingsPanel_ = new PlannerSettingsPanel(this);
    connect(settingsPanel_, &PlannerSettingsPanel::choiceEdited, this, [this](const PlannerChoice& choice) {
        document_->setPlannerChoice(choice);
        settingsModified_ = true;
        updateTitle();
    });

    resultsPanel_ = new ResultsPanel(this);

    // Layers and planner settings scroll rather than take the height the robots' table needs: at 1600 x
    // 1000 their full heights left that table two rows.
    const auto scrolled = [this](QWidget* panel) {
        auto* scroll = new QScrollArea(this);
        scroll->setWidget(panel);
        scroll->setWidgetResizable(true);
        scroll->setFrameShape(QFrame::NoFrame);
        // Only up and down: the dock stays as wide as the panel needs.
        scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        scroll->setMinimumWidth(panel->minimumSizeHint().width() +
                                scroll->verticalScrollBar()->sizeHint().width());
        return scroll;
    };
    QScrollArea* layersScroll = scrolled(layersPanel_);
    // Its three rows of toggles in full, taken from the robots' table below it.
    layersScroll->setMinimumHeight(layersPanel_->sizeHint().height());
    auto* layersDock = makeDock(QStringLiteral("layersDock"), tr("Layers"), layersScroll, this);
    auto* classesDock =
        makeDock(QStringLiteral("classesDock"), tr("Land-cover classes"), classesWidget, this);
    auto* robotsDock = makeDock(QStringLiteral("robotsDock"), tr("Robots"), robotsWidget, this);
    auto* eventsDock = makeDock(QStringLiteral("eventsDock"), tr("Events"), eventsWidget, this);
    auto* settingsDock =
        makeDock(QStringLiteral("plannerDock"), tr("Planner"), scrolled(settingsPanel_), this);
    auto* resultsDock = makeDock(QStringLiteral("resultsDock"), tr("Results"), resultsPanel_, this);
    comparisonPanel_ = new ComparisonPanel(this);
    connect(comparisonPanel_, &ComparisonPanel::compareRequested, this,
            [this] { startComparison(comparisonPanel_->checkedPlanners()); });
    connect(comparisonPanel_, &ComparisonPanel::planSelected, this, &MainWindow::showComparedPlan);
    comparisonDock_ =
        makeDock(QStringLiteral("comparisonDock"), tr("Compare planners"), comparisonPanel_, this);
    connect(comparisonPanel_, &ComparisonPanel::widthWanted, this, [this](int pixels) {
        // Wider, never narrower, and the map keeps at least half the window; a floating dock is the
        // user's to size.
        const int frame = comparisonDock_->width() - comparisonPanel_->width();
        const int wanted = std::min(pixels + frame, width() / 2);
        if (comparisonDock_->isVisible() && !comparisonDock_->isFloating() &&
            wanted > comparisonDock_->width())
            resizeDocks({comparisonDock_}, {wanted}, Qt::Horizontal);
    });
    addDockWidget(Qt::LeftDockWidgetArea, layersDock);
    legendPanel_ = new LegendPanel(document_, this);
    // The legend scrolls both ways: long class names must not widen the dock.
    auto* legendScroll = new QScrollArea(this);
    legendScroll->setWidget(legendPanel_);
    legendScroll->setWidgetResizable(true);
    legendScroll->setFrameShape(QFrame::NoFrame);
    auto* legendDock = makeDock(QStringLiteral("legendDock"), tr("Legend"), legendScroll, this);
    addDockWidget(Qt::LeftDockWidgetArea, legendDock);
    tabifyDockWidget(layersDock, legendDock);
    layersDock->raise();
    addDockWidget(Qt::LeftDockWidgetArea, robotsDock);
    addDockWidget(Qt::LeftDockWidgetArea, eventsDock);
    tabifyDockWidget(robotsDock, eventsDock);
    robotsDock->raise();
    addDockWidget(Qt::LeftDockWidgetArea, settingsDock);
    addDockWidget(Qt::RightDockWidgetArea, resultsDock);
    addDockWidget(Qt::RightDockWidgetArea, comparisonDock_);
    tabifyDockWidget(resultsDock, comparisonDock_);
    resultsDock->raise();
    addDockWidget(Qt::BottomDockWidgetArea, classesDock);
    messageLog_ = new MessageLog(this);
    auto* messagesDock = makeDock(QStringLiteral("messagesDock"), tr("Messages"), messageLog_, this);
    addDockWidget(Qt::BottomDockWidgetArea, messagesDock);
    tabifyDockWidget(classesDock, messagesDock);
    classesDock->raise();
    resizeDocks({layersDock, robotsDock, settingsDock}, {120, 240, 260}, Qt::Vertical);
    resizeDocks({layersDock, resultsDock}, {360, 420}, Qt::Horizontal);
    resizeDocks({classesDock}, {250}, Qt::Vertical);
}

void MainWindow::createActions() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    auto* openRasterAction =
        fileMenu->addAction(actionIcon("open-raster"), tr("Open &raster…"), this, [this] {
            if (!maybeSave())
                return;
            const QString path = QFileDialog::getOpenFileName(this, tr("Open land-cover raster"),
                                                              dialogFolder(kRasterFolderKey), kRasterFilter);
            if (!path.isEmpty())
                openRaster(path);
        });
    openRasterAction->setObjectName(QStringLiteral("openRasterAction"));
    openRasterAction->setShortcut(QKeySequence::Open);
    auto* openMissionAction =
        fileMenu->addAction(actionIcon("open-mission"), tr("Open &mission…"), this, [this] {
            if (!maybeSave())
                return;
            const QString path = QFileDialog::getOpenFileName(
                this, tr("Open mission"), dialogFolder(kMissionFolderKey), kMissionFilter);
            if (!path.isEmpty())
                openMission(path);
        });
    openMissionAction->setObjectName(QStringLiteral("openMissionAction"));
    openMissionAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O));
    recentMenu_ = fileMenu->addMenu(tr("Open r&ecent"));
    fileMenu->addSeparator();
    saveAction_ = fileMenu->addAction(actionIcon("save"), tr("&Save mission"), this, [this] {
        if (document_->missionPath().isEmpty()) {
            const QString path = askMissionPath(tr("Save mission"));
            if (!path.isEmpty())
                saveMission(path);
        } else {
            saveMission(document_->missionPath());
        }
    });
    saveAction_->setObjectName(QStringLiteral("saveMissionAction"));
    saveAction_->setShortcut(QKeySequence::Save);
    auto* saveAsAction = fileMenu->addAction(tr("Save mission &as…"), this, [this] {
        const QString path = askMissionPath(tr("Save mission as"));
        if (!path.isEmpty())
            saveMission(path);
    });
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    fileMenu->addSeparator();
    QMenu* exportMenu = fileMenu->addMenu(actionIcon("export"), tr("&Export plan"));
    for (const io::ExportFormat& format : io::exportFormats()) {
        const std::string key = format.key;
        auto* action = exportMenu->addAction(QString::fromStdString(format.label) + QStringLiteral("…"), this,
                                             [this, key] { chooseExport(key); });
        action->setObjectName(QString::fromStdString("export_" + key));
        action->setData(QString::fromStdString(key));
        exportActions_ << action;
    }
    fileMenu->addSeparator();
    auto* quitAction = fileMenu->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setShortcut(QKeySequence::Quit);

    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    QAction* undoAction = undoStack_->createUndoAction(this, tr("&Undo"));
    undoAction->setShortcut(QKeySequence::Undo);
    undoAction->setIcon(actionIcon("undo"));
    QAction* redoAction = undoStack_->createRedoAction(this, tr("&Redo"));
    redoAction->setObjectName(QStringLiteral("redoAction"));
    redoAction->setShortcut(QKeySequence::Redo);
    redoAction->setIcon(actionIcon("redo"));
    editMenu->addAction(undoAction);
    editMenu->addAction(redoAction);
    editMenu->addSeparator();
    removeRobotAction_ =
        editMenu->addAction(tr("Remove selected robot"), this, &MainWindow::removeSelectedRobot);
    removeRobotAction_->setShortcut(QKeySequence::Delete);
    removeRobotAction_->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    robotView_->addAction(removeRobotAction_);

    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    auto* zoomIn = viewMenu->addAction(actionIcon("zoom-in"), tr("Zoom &in"), canvas_, &MapCanvas::zoomIn);
    zoomIn->setShortcut(QKeySequence::ZoomIn);
    auto* zoomOut =
        viewMenu->addAction(actionIcon("zoom-out"), tr("Zoom &out"), canvas_, &MapCanvas::zoomOut);
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    auto* zoomFit =
        viewMenu->addAction(actionIcon("zoom-fit"), tr("Zoom to &fit"), canvas_, &MapCanvas::zoomToFit);
    zoomFit->setObjectName(QStringLiteral("zoomToFitAction"));
    zoomFit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    viewMenu->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        viewMenu->addAction(dock->toggleViewAction());

    QMenu* planMenu = menuBar()->addMenu(tr("&Plan"));
    auto* tools = new QActionGroup(this);
    panToolAction_ = planMenu->addAction(actionIcon("pan"), tr("&Pan tool"));
    panToolAction_->setObjectName(QStringLiteral("panToolAction"));
    panToolAction_->setCheckable(true);
    panToolAction_->setChecked(true);
    panToolAction_->setShortcut(QKeySequence(Qt::Key_P));
    panToolAction_->setToolTip(tr("Drag to pan, wheel to zoom, drag a start marker to move it (P)"));
    placeToolAction_ = planMenu->addAction(actionIcon("place-start"), tr("Place &start tool"));
    placeToolAction_->setObjectName(QStringLiteral("placeStartToolAction"));
    placeToolAction_->setCheckable(true);
    placeToolAction_->setShortcut(QKeySequence(Qt::Key_S));
    placeToolAction_->setToolTip(tr("Click on the map to add a robot start there (S)"));
    drawAreaAction_ = planMenu->addAction(tr("&Draw area of interest"));
    drawAreaAction_->setObjectName(QStringLiteral("drawAreaAction"));
    drawAreaAction_->setCheckable(true);
    drawAreaAction_->setToolTip(tr(
        "Click the corners of the area to plan on the map and double-click to finish, or drag a rectangle"));
    drawNoGoAction_ = planMenu->addAction(tr("Draw &no-go zone"));
    drawNoGoAction_->setObjectName(QStringLiteral("drawNoGoAction"));
    drawNoGoAction_->setCheckable(true);
    drawNoGoAction_->setToolTip(
        tr("Click the corners of a zone to leave out and double-click to finish, or drag a rectangle"));
    tools->addAction(panToolAction_);
    tools->addAction(placeToolAction_);
    tools->addAction(drawAreaAction_);
    tools->addAction(drawNoGoAction_);
    for (QAction* draw : {drawAreaAction_, drawNoGoAction_}) {
        connect(draw, &QAction::toggled, this, [this](bool on) {
            if (!on)
                return;
            canvas_->setTool(MapCanvas::Tool::DrawArea);
            showStatus(
                tr("Click the corners on the map, then double-click or press Enter to finish; or drag a "
                   "rectangle. Backspace takes back a corner, Esc starts again."),
                0);
        });
    }
    connect(canvas_, &MapCanvas::areaDrawn, this, &MainWindow::useDrawnArea);
    connect(panToolAction_, &QAction::toggled, this, [this](bool on) {
        if (on)
            canvas_->setTool(MapCanvas::Tool::Pan);
    });
    connect(placeToolAction_, &QAction::toggled, this, [this](bool on) {
        if (on)
            canvas_->setTool(MapCanvas::Tool::PlaceStart);
    });
    planMenu->addSeparator();
    const QString vectorFilter =
        tr("Vector files (*.gpkg *.geojson *.json *.shp *.kml *.gml *.fgb);;All files (*)");
    auto* areaAction = planMenu->addAction(tr("&Area of interest from file…"), this, [this, vectorFilter] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Area of interest"),
                                                          dialogFolder(kMissionFolderKey), vectorFilter);
        if (!path.isEmpty())
            setAreaFiles(path, QString::fromStdString(document_->mission().area.excludePath));
    });
    areaAction->setObjectName(QStringLiteral("areaOfInterestAction"));
    areaAction->setToolTip(tr("Plan only inside the polygons of a vector file"));
    auto* noGoAction = planMenu->addAction(tr("&No-go zones from file…"), this, [this, vectorFilter] {
        const QString path = QFileDialog::getOpenFileName(this, tr("No-go zones"),
                                                          dialogFolder(kMissionFolderKey), vectorFilter);
        if (!path.isEmpty())
            setAreaFiles(QString::fromStdString(document_->mission().area.includePath), path);
    });
    noGoAction->setObjectName(QStringLiteral("noGoZonesAction"));
    auto* clearAreaAction =
        planMenu->addAction(tr("C&lear area and no-go zones"), this, [this] { setAreaFiles({}, {}); });
    clearAreaAction->setObjectName(QStringLiteral("clearAreaAction"));
    planMenu->addSeparator();
    planAction_ = planMenu->addAction(actionIcon("plan"), tr("&Plan"), this, &MainWindow::startPlanning);
    planAction_->setObjectName(QStringLiteral("planAction"));
    planAction_->setShortcuts({QKeySequence(Qt::Key_F5), QKeySequence(Qt::CTRL | Qt::Key_Return)});
    planAction_->setToolTip(tr("Plan coverage paths for all robots (F5)"));
    cancelAction_ =
        planMenu->addAction(actionIcon("cancel"), tr("&Cancel planning"), this, &MainWindow::cancelPlanning);
    cancelAction_->setObjectName(QStringLiteral("cancelPlanningAction"));
    compareAction_ =
        planMenu->addAction(actionIcon("compare"), tr("C&ompare checked planners"), this, [this] {
            comparisonDock_->show();
            comparisonDock_->raise();
            startComparison(comparisonPanel_->checkedPlanners());
        });
    compareAction_->setObjectName(QStringLiteral("compareAction"));
    compareAction_->setToolTip(tr("Run the planners checked in the Compare planners panel on this mission, "
                                  "one after another, and compare their plans"));
    planMenu->addSeparator();
    vehiclesAction_ = planMenu->addAction(tr("Robot &vehicles…"), this, &MainWindow::editVehicles);
    vehiclesAction_->setObjectName(QStringLiteral("vehiclesAction"));
    vehiclesAction_->setToolTip(tr("Vehicle type, altitude, cruise speed and autopilot item limit of each "
                                   "robot's waypoint files"));

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    auto* sampleAction = helpMenu->addAction(tr("Open &sample mission"), this, [this] {
        if (maybeSave())
            openSampleMission(true);
    });
    sampleAction->setObjectName(QStringLiteral("openSampleAction"));
    helpMenu->addAction(tr("&About mcpp"), this, [this] {
        QMessageBox about(QMessageBox::NoIcon, tr("About mcpp"), aboutText(), QMessageBox::Close, this);
        about.setObjectName(QStringLiteral("aboutBox"));
        about.setIconPixmap(actionIcon("mcpp").pixmap(64, 64));
        about.exec();
    });

    auto* toolbar = addToolBar(tr("Main"));
    toolbar->setObjectName(QStringLiteral("mainToolBar"));
    toolbar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolbar->addAction(openRasterAction);
    toolbar->addAction(openMissionAction);
    toolbar->addAction(saveAction_);
    toolbar->addSeparator();
    toolbar->addAction(toolbarStep(undoAction, tr("Undo"), toolbar));
    toolbar->addAction(toolbarStep(redoAction, tr("Redo"), toolbar));
    toolbar->addSeparator();
    toolbar->addAction(panToolAction_);
    toolbar->addAction(placeToolAction_);
    toolbar->addAction(zoomFit);
    toolbar->addSeparator();
    toolbar->addAction(planAction_);
    toolbar->addAction(cancelAction_);
    toolbar->addAction(compareAction_);

    rebuildRecentMenu();
}

void MainWindow::createStatusBar() {
    cursorLabel_ = new QLabel(this);
    cursorLabel_->setObjectName(QStringLiteral("cursorLabel"));
    cursorLabel_->setMinimumWidth(360);
    stageLabel_ = new QLabel(this);
    stageLabel_->setObjectName(QStringLiteral("stageLabel"));
    progressBar_ = new QProgressBar(this);
    progressBar_->setObjectName(QStringLiteral("planningProgress"));
    progressBar_->setRange(0, 1000);
    progressBar_->setMaximumWidth(200);
    progressBar_->setTextVisible(false);
    cancelButton_ = new QPushButton(tr("Cancel"), this);
    cancelButton_->setObjectName(QStringLiteral("cancelPlanningButton"));
    connect(cancelButton_, &QPushButton::clicked, this, [this] {
        if (comparisonRunner_->isRunning()) {
            comparisonRunner_->cancel();
            cancelButton_->setEnabled(false);
            stageLabel_->setText(tr("Cancelling…"));
        } else if (exportRunner_->isRunning())
            cancelExport();
        else
            cancelPlanning();
    });
    statusBar()->addPermanentWidget(stageLabel_);
    statusBar()->addPermanentWidget(progressBar_);
    statusBar()->addPermanentWidget(cancelButton_);
    statusBar()->addPermanentWidget(cursorLabel_);
    stageLabel_->hide();
    progressBar_->hide();
    cancelButton_->hide();

    connect(canvas_, &MapCanvas::cursorMoved, this, &MainWindow::showCursor);
    connect(canvas_, &MapCanvas::cursorLeft, cursorLabel_, &QLabel::clear);
    connect(canvas_, &MapCanvas::placeStartRequested, this, &MainWindow::placeStart);
    connect(canvas_, &MapCanvas::moveStartRequested, this, [this](int robot, MapPoint point) {
        if (robotModel_->moveRobot(robot, point))
            showStatus(
                tr("Moved %1.")
                    .arg(QString::fromStdString(document_->robots()[static_cast<std::size_t>(robot)].name)));
    });
    connect(canvas_, &MapCanvas::removeStartRequested, this, [this](int robot) {
        const QString name =
            QString::fromStdString(document_->robots()[static_cast<std::size_t>(robot)].name);
        if (robotModel_->removeRobot(robot)) {
            canvas_->setSelectedStart(-1);
            showStatus(tr("Removed %1.").arg(name));
        }
    });

    connect(runner_, &PlanningRunner::progressed, this, [this](const QString& stage, double fraction) {
        stageLabel_->setText(stage);
        progressBar_->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000.0));
    });
    connect(runner_, &PlanningRunner::finished, this, &MainWindow::handlePlanningFinished);
    connect(exportRunner_, &ExportRunner::progressed, this, [this](int done, int files) {
        if (files > 1)
            progressBar_->setValue(done);
    });
    connect(exportRunner_, &ExportRunner::finished, this, &MainWindow::handleExportFinished);
    connect(comparisonRunner_, &ComparisonRunner::progressed, this,
            [this](int planner, int planners, const QString& name, const QString& stage, double fraction) {
                stageLabel_->setText(
                    tr("%1 (%2 of %3): %4").arg(name).arg(planner + 1).arg(planners).arg(stage));
                progressBar_->setValue(
                    static_cast<int>((planner + std::clamp(fraction, 0.0, 1.0)) / planners * 1000.0));
            });
    connect(comparisonRunner_, &ComparisonRunner::plannerFinished, this, &MainWindow::handleComparedPlanner);
    connect(comparisonRunner_, &ComparisonRunner::finished, this, &MainWindow::handleComparisonFinished);
}

void MainWindow::connectDocument() {
    connect(undoStack_, &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(undoStack_, &QUndoStack::indexChanged, this, &MainWindow::updateTitle);
    connect(document_, &MissionDocument::missionPathChanged, this, &MainWindow::updateTitle);
    connect(document_, &MissionDocument::mapChanged, this, [this] {
        crsName_.clear();
        if (const auto* raster = document_->raster()) {
            crsName_ = QString::fromStdString(raster->georeference.authorityCode());
            if (crsName_.isEmpty())
                crsName_ = QString::fromStdString(raster->georeference.name());
        }
        rememberInputFiles();
        updateActions();
    });
    connect(document_, &MissionDocument::settingsChanged, this, [this] {
        settingsPanel_->setChoice(document_->plannerChoice());
        showBatteryColumnForBatteryPlanners();
        updateSizeWarning(); // planners need different memory per cell
    });
    connect(document_, &MissionDocument::classesChanged, this, &MainWindow::syncPresetCombo);
    connect(document_, &MissionDocument::classesChanged, this, &MainWindow::updateSizeWarning);
    connect(classTableBanner_, &ClassTableBanner::fitRequested, this, &MainWindow::scaleFieldsOfViewToFit);
    connect(document_, &MissionDocument::planChanged, this, [this] {
        updateResults();
        updateActions();
        updateTimeline();
    });
    connect(timelineBar_, &TimelineBar::secondsChanged, canvas_,
            [this](double seconds) { canvas_->setTimelineSeconds(seconds); });
    connect(document_, &MissionDocument::robotsChanged, this, [this] {
        updateResults();
        updateActions();
    });
    connect(document_, &MissionDocument::staleChanged, resultsPanel_, &ResultsPanel::setStale);
}

// Batteries, events and chargers, as batch mode adds them; the window keeps chargers in the planning frame.
void MainWindow::addRobotSettings(PlanningProblem& problem) const {
    io::applyRobotSettings(document_->mission(), *document_->raster(), problem);
    problem.chargers = document_->chargers();
}

// A robot's own battery and charger matter only to planners that fly on batteries: the others keep the
// table narrow.
void MainWindow::showBatteryColumnForBatteryPlanners() {
    const auto description = findPlannerDescription(document_->plannerChoice().planner);
    const bool batteries = description && description->fliesOnBatteries();
    for (const int column :
         {RobotTableModel::Battery, RobotTableModel::ChargerEasting, RobotTableModel::ChargerNorthing})
        robotView_->setColumnHidden(column, !batteries);
}

void MainWindow::restoreSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) {
        // First start: most of the screen, since the map is what people came for.
        const QRect available = screen() != nullptr ? screen()->availableGeometry() : QRect(0, 0, 1480, 920);
        resize(std::max(900, available.width() * 19 / 20), std::max(650, available.height() * 19 / 20));
    }
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

QString MainWindow::dialogFolder(const QString& key) const {
    // Missions, class tables and exports go beside the saved mission; rasters come from where the last did.
    if (key != kRasterFolderKey && !document_->missionPath().isEmpty())
        return QFileInfo(document_->missionPath()).absolutePath();
    return QSettings().value(key, QDir::homePath()).toString();
}

void MainWindow::rememberFolder(const QString& key, const QString& path) {
    QSettings().setValue(key, QFileInfo(path).absolutePath());
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = RecentFiles::list();
    for (int i = 0; i < files.size(); ++i) {
        const QString path = files[i];
        auto* action = recentMenu_->addAction(
            QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()), this, [this, path] {
                if (maybeSave())
                    openFile(path);
            });
        action->setToolTip(path);
        action->setStatusTip(path);
    }
    if (files.isEmpty())
        recentMenu_->addAction(tr("(none)"))->setEnabled(false);
    recentMenu_->addSeparator();
    recentMenu_->addAction(tr("Clear list"), this, [this] {
        QSettings().remove(QStringLiteral("recentFiles"));
        rebuildRecentMenu();
    });
}

bool MainWindow::isMissionModified() const {
    return !undoStack_->isClean() || settingsModified_ || planUnsaved_;
}

void MainWindow::updateTitle() {
    QString name = tr("Untitled mission");
    if (!document_->missionPath().isEmpty())
        name = QFileInfo(document_->missionPath()).fileName();
    else if (const auto* raster = document_->raster())
        name = tr("%1 (unsaved mission)").arg(QFileInfo(QString::fromStdString(raster->path)).fileName());
    setWindowTitle(QStringLiteral("%1[*] — mcpp").arg(name));
    setWindowModified(isMissionModified());
}

void MainWindow::updateActions() {
    const bool planning = runner_->isRunning() || comparisonRunner_->isRunning();
    const bool exporting = exportRunner_->isRunning();
    const bool hasMap = document_->hasMap();
    planAction_->setEnabled(hasMap && !planning && !exporting && !document_->robots().empty());
    cancelAction_->setEnabled(planning);
    saveAction_->setEnabled(hasMap);
    const bool hasCrs = hasMap && document_->raster()->georeference.hasCrs();
    for (QAction* action : exportActions_) {
        const io::ExportFormat* format = io::findExportFormat(action->data().toString().toStdString());
        const bool placeable = hasCrs || format == nullptr || !format->needsLongitudeLatitude;
        const Plan* plan = document_->plan();
        const bool applies = plan == nullptr || format == nullptr || io::formatApplies(*format, *plan);
        action->setEnabled(plan != nullptr && !planning && !exporting && placeable && applies);
        action->setToolTip(!placeable ? tr("The map has no CRS: this format needs longitude and latitude")
                           : !applies
                               ? tr("Only plans that model what the sensor sees (CPPIED) have this layer")
                               : QString());
    }
    compareAction_->setEnabled(hasMap && !planning && !exporting && !document_->robots().empty());
    comparisonPanel_->setCanCompare(compareAction_->isEnabled(),
                                    !hasMap                       ? tr("Open a land-cover raster first")
                                    : document_->robots().empty() ? tr("Place robot starts first (S)")
                                    : planning                    ? tr("Planning is under way")
                                    : exporting                   ? tr("An export is under way")
                                                                  : QString());
    comparisonPanel_->setRobotCount(static_cast<int>(document_->robots().size()));
}

// The timeline shows under the map for plans simulated over time, at the end of the mission at first.
void MainWindow::updateTimeline() {
    const Plan* plan = document_->plan();
    const TimelineLayer* timeline = plan != nullptr ? timelineLayerOf(*plan) : nullptr;
    if (timeline == nullptr) {
        timelineBar_->stop();
        timelineBar_->hide();
        canvas_->setTimelineSeconds(std::nullopt);
        return;
    }
    std::vector<double> eventSeconds;
    for (const SpeedEvent& event : timeline->summary().events)
        eventSeconds.push_back(event.timeSeconds);
    timelineBar_->setTimeline(timeline->summary().makespanSeconds, eventSeconds);
    canvas_->setTimelineSeconds(timelineBar_->seconds());
    timelineBar_->show();
}

// Events: a table of when which robot slows down or stops, plus add/remove.
QWidget* MainWindow::createEventsWidget() {
    auto* widget = new QWidget(this);
    auto* layout = new QVBoxLayout(widget);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* view = new QTableView(widget);
    view->setObjectName(QStringLiteral("eventTableView"));
    view->setModel(eventModel_);
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view->horizontalHeader()->setStretchLastSection(true);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setSelectionMode(QAbstractItemView::SingleSelection);
    view->setToolTip(tr("From its time on, the robot drives at its speed factor times its land-cover speeds "
                        "(0.5 half speed, 0 stopped). Robots count from 0. Played by MDSTC"));
    layout->addWidget(view, 1);
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add"), widget);
    add->setObjectName(QStringLiteral("addEventButton"));
    auto* remove = new QPushButton(tr("Remove"), widget);
    remove->setObjectName(QStringLiteral("removeEventButton"));
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    connect(add, &QPushButton::clicked, eventModel_, [this] { static_cast<void>(eventModel_->addEvent()); });
    connect(remove, &QPushButton::clicked, eventModel_,
            [this, view] { static_cast<void>(eventModel_->removeEvent(view->currentIndex().row())); });
    connect(eventModel_, &EventTableModel::editRefused, this,
            [this](const QString& reason) { showStatus(reason); });
    return widget;
}

void MainWindow::updateResults() {
    QStringList names;
    for (const auto& robot : document_->robots())
        names << QString::fromStdString(robot.name);
    resultsPanel_->showPlan(document_->plan(), names, document_->raster());
    // Where the user looks, for the plan it was worked out for (not once the settings change under it).
    if (const auto shown = document_->sharedPlan(); shown && advisedPlan_.lock() == shown)
        resultsPanel_->addNote(planAdvice_);
    resultsPanel_->setStale(document_->planStale());
    sizeWaypointFiles();
}

void MainWindow::sizeWaypointFiles() {
    const int asked =
        ++waypointFileSizesAsked_; // an earlier plan's sizes, still being worked out, are dropped
    const std::shared_ptr<const Plan> plan = document_->sharedPlan();
    if (!plan)
        return;
    if (waypointFileSizes_ == nullptr)
        waypointFileSizes_ = new QFutureWatcher<std::vector<io::MissionSize>>(this);
    waypointFileSizes_->disconnect(this);
    const std::vector<io::VehicleSettings> vehicles = io::robotVehicles(document_->mission());
    const io::ExportSettings settings = document_->mission().exports;
    connect(waypointFileSizes_, &QFutureWatcherBase::finished, this, [this, asked, vehicles, plan] {
        if (asked != waypointFileSizesAsked_ || document_->sharedPlan() != plan)
            return;
        QStringList names;
        for (const auto& robot : document_->robots())
            names << QString::fromStdString(robot.name);
        const std::vector<io::MissionSize> sizes = waypointFileSizes_->result();
        resultsPanel_->showWaypointFiles(sizes, vehicles, names);
        legendPanel_->showFieldTimes(fieldTimesOf(*plan, sizes, vehicles));
        // Flights a battery cannot fly, said where every message is kept, once a plan (the results are
        // shown again whenever a robot is renamed; a compared plan's were said with the comparison's).
        if (!flightsSaidOf(plan)) {
            const QStringList tooLong = ResultsPanel::flightsTooLongWarnings(sizes, vehicles, names);
            for (const QString& warning : tooLong)
                messageLog_->add(tr("Warning: %1").arg(warning));
            if (!tooLong.isEmpty())
                flightsSaid_.push_back(plan);
        }
    });
    // A large map's paths hold tens of millions of points: measured beside the window, not in it.
    waypointFileSizes_->setFuture(QtConcurrent::run([plan, vehicles, settings] {
        std::vector<io::MissionSize> sizes;
        for (const CoveragePath& path : plan->paths) {
            const auto robot = static_cast<std::size_t>(path.robot);
            const io::VehicleSettings vehicle = robot < vehicles.size() ? vehicles[robot] : settings.vehicle;
            sizes.push_back(io::missionSize(*plan, path, vehicle, settings));
        }
        return sizes;
    }));
}

// What each compared plan's waypoint files would warn of, as the results panel says it of the plan shown:
// flights longer than a battery lasts. None where no robot has a flight time.
FileWarnings MainWindow::waypointFileWarnings() const {
    const std::vector<io::VehicleSettings> vehicles = io::robotVehicles(document_->mission());
    if (std::none_of(vehicles.begin(), vehicles.end(),
                     [](const io::VehicleSettings& vehicle) { return vehicle.flightTimeSeconds > 0.0; }))
        return {};
    QStringList names;
    for (const auto& robot : document_->robots())
        names << QString::fromStdString(robot.name);
    return [vehicles, names, settings = document_->mission().exports](const Plan& plan) {
        std::vector<io::MissionSize> sizes(vehicles.size());
        for (const CoveragePath& path : plan.paths) {
            const auto robot = static_cast<std::size_t>(path.robot);
            if (robot < sizes.size())
                sizes[robot] = io::missionSize(plan, path, vehicles[robot], settings);
        }
        WaypointFileFindings findings;
        for (const QString& warning : ResultsPanel::flightsTooLongWarnings(sizes, vehicles, names))
            findings.warnings.push_back(warning.toStdString());
        std::size_t over = 0;
        for (std::size_t robot = 0; robot < sizes.size(); ++robot)
            if (vehicles[robot].flightTimeSeconds > 0.0)
                over += sizes[robot].partsOverFlightTime;
        findings.flightsOverBattery = over;
        return findings;
    };
}

bool MainWindow::loadClassTable(const QString& path) {
    if (!document_->hasMap())
        return false;
    io::ClassesWithoutColour withoutColour;
    auto table = io::loadClassTableCsv(path.toStdString(), &withoutColour);
    if (!table.ok()) {
        reportError(tr("Cannot load class table"), QString::fromStdString(table.error()));
        return false;
    }
    // Rows without a colour keep the one the map shows for their class (the preset's off the map).
    const ClassTable loaded = io::withColoursFrom(
        table.value(), withoutColour, io::colourReference(document_->classes(), document_->mission().preset));
    undoStack_->push(new ClassTableEditCommand(
        document_, document_->classes(), QString::fromStdString(document_->mission().preset), loaded,
        QString(), tr("Load class table %1").arg(QFileInfo(path).fileName())));
    classTableBanner_->clearExplanation();
    // Said, so that an earlier file's error does not stay in the status bar as if about this one.
    showStatus(tr("Loaded the class table %1 (%2 classes).")
                   .arg(QDir::toNativeSeparators(path))
                   .arg(static_cast<qulonglong>(loaded.size())));
    return true;
}

void MainWindow::syncPresetCombo() {
    const QSignalBlocker blocker(presetCombo_);
    const QString preset = QString::fromStdString(document_->mission().preset);
    int index = presetCombo_->findData(preset);
    // The preset's or the legend's table edited (FOVs scaled, a speed changed) is the user's own now; one
    // field of view over every class (a mission's classes.fov_m, a drone's footprint) keeps it the preset's.
    if (document_->hasMap()) {
        ClassTable presetTable = io::classTableForRaster(*document_->raster(), preset.toStdString());
        const ClassTable& classes = document_->classes();
        if (!classes.empty() && hasOneFieldOfView(classes))
            presetTable.setEveryFieldOfView(classes.classes().front().fieldOfViewMetres);
        if (!(classes == presetTable))
            index = presetCombo_->findData(kOwnTableData);
    }
    presetCombo_->setCurrentIndex(std::max(index, 0));
}

void MainWindow::explainClassTable(const io::OpeningClassTable& opening) {
    const QString text = QString::fromStdString(opening.explanation);
    classTableBanner_->showExplanation(text, !opening.preset.empty());
    updateSizeWarning();
    messageLog_->add(text);
}

bool MainWindow::setAreaFiles(const QString& includePath, const QString& excludePath) {
    const io::AreaOfInterest before = document_->mission().area;
    if (!useAreaFiles(includePath, excludePath))
        return false;
    const bool cleared = includePath.isEmpty() && excludePath.isEmpty();
    if (!(document_->mission().area == before)) // the same files again change nothing
        pushAreaEdit(before, cleared ? tr("Clear area and no-go zones") : tr("Area from file"));
    return true;
}

void MainWindow::pushAreaEdit(io::AreaOfInterest before, const QString& text) {
    const auto useArea = [this](const io::AreaOfInterest& area, bool undoing) {
        if (useAreaFiles(QString::fromStdString(area.includePath), QString::fromStdString(area.excludePath)))
            return true;
        // The step leaves the stack and the map stays as it is. A failed undo leaves the stack one step back
        // over the same map: where that index is the saved one, the map is not (the index test holds inside
        // undo(), before the stack moves; no view sets the index here). QUndoStack::redo() drops an obsolete
        // step without sending canRedoChanged or redoTextChanged: they are sent here, queued.
        if (undoing && undoStack_->cleanIndex() == undoStack_->index() - 1)
            undoStack_->resetClean();
        if (!undoing)
            QMetaObject::invokeMethod(
                undoStack_,
                [stack = undoStack_] {
                    emit stack->canRedoChanged(stack->canRedo());
                    emit stack->redoTextChanged(stack->redoText());
                },
                Qt::QueuedConnection);
        return false;
    };
    undoStack_->push(new AreaEditCommand(std::move(before), document_->mission().area, useArea, text));
}

bool MainWindow::useAreaFiles(const QString& includePath, const QString& excludePath) {
    if (!document_->hasMap())
        return false;
    io::Mission mission = document_->mission();
    // Read again from the file, so that clearing or changing the area starts from the whole map.
    mission.rasterPath = document_->raster()->path;
    const auto absolute = [](const QString& path) {
        return path.isEmpty() ? std::string() : QFileInfo(path).absoluteFilePath().toStdString();
    };
    mission.area.includePath = absolute(includePath);
    mission.area.excludePath = absolute(excludePath);
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto raster = io::loadMissionRaster(mission, std::string());
    QApplication::restoreOverrideCursor();
    if (!raster.ok()) {
        reportError(tr("Cannot use the area"), QString::fromStdString(raster.error()));
        return false;
    }
    runner_->cancel();
    comparisonRunner_->cancel(); // its plans would be of the map before
    mission.rasterPath = document_->mission().rasterPath;
    const bool wholeMap = mission.area.empty();
    // What the area leaves to plan on, and how much of it lies off the raster (the raster's own warnings
    // were said when it was opened).
    QStringList areaNotes;
    for (const std::string& note : raster.value().notes)
        areaNotes << asSentence(note);
    for (const std::string& warning : raster.value().warnings)
        if (warning.starts_with("area of interest") || warning.starts_with("no-go zones"))
            areaNotes << asSentence(warning);
    document_->reset(std::make_shared<io::LoadedRaster>(std::move(raster.value())), std::move(mission),
                     document_->missionPath());
    updateTitle();
    updateActions();
    QString message = wholeMap ? tr("Planning on the whole map again.") : areaNotes.join(QLatin1Char(' '));
    // Starts the new area leaves out are kept, to be moved: say so now rather than at Plan.
    QStringList outside;
    const std::vector<bool> flying = io::flyingRobots(document_->mission());
    for (std::size_t robot = 0; robot < document_->robots().size(); ++robot)
        if (document_->startProblem(document_->robots()[robot].start, static_cast<int>(robot), {},
                                    flying[robot]))
            outside << QString::fromStdString(document_->robots()[robot].name);
    if (outside.size() == 1)
        message +=
            QStringLiteral(" ") +
            tr("%1's start is now outside the task area: move it inside before planning.").arg(outside[0]);
    else if (outside.size() > 1)
        message += QStringLiteral(" ") + tr("%1 starts are now outside the task area (%2): move them inside "
                                            "before planning.")
                                             .arg(outside.size())
                                             .arg(outside.join(QStringLiteral(", ")));
    showStatus(message, 15000);
    return true;
}

void MainWindow::updateSizeWarning() {
    fitFactor_ = 0.0;
    const io::LoadedRaster* raster = document_->raster();
    if (raster == nullptr) {
        classTableBanner_->clearSizeWarning();
        return;
    }
    const PlannerChoice& choice = document_->plannerChoice();
    const auto memory = io::planningMemory(*raster, document_->classes(), choice);
    if (!memory) {
        classTableBanner_->clearSizeWarning();
        return;
    }
    const CellBudgetEstimate& estimate = memory->estimate;
    const double fovMin = memory->smallestFieldOfViewMetres;
    const int levels = memory->levels;
    const auto planner = findPlannerDescription(choice.planner);
    if (estimate.fits()) {
        classTableBanner_->clearSizeWarning();
        return;
    }
    // The rounding margin keeps 1.7000000000000002 at 1.70.
    fitFactor_ = std::ceil(estimate.fittingFieldOfView / fovMin * 100.0 - 1e-9) / 100.0;
    const QString text = tooFineText(planner ? QString::fromStdString(planner->label) : tr("this planner"),
                                     estimate, fovMin, levels, fitFactor_);
    if (!classTableBanner_->hasSizeWarning())
        messageLog_->add(text);
    classTableBanner_->showSizeWarning(text,
                                       fitFactor_ > 0.0 ? tr("Scale FOVs ×%1").arg(fitFactor_) : QString());
}

void MainWindow::scaleFieldsOfViewToFit() {
    if (!(fitFactor_ > 0.0))
        return;
    QList<int> rows;
    for (int row = 0; row < classModel_->rowCount(); ++row)
        rows << row;
    ClassBulkEdit edit;
    edit.fieldOfViewFactor = fitFactor_;
    if (classModel_->editRows(rows, edit))
        showStatus(
            tr("Scaled every FOV by %1 to fit this machine's memory (Ctrl+Z undoes it).").arg(fitFactor_));
    else
        reportError(tr("Cannot scale FOVs"), classModel_->lastRefusal());
}

void MainWindow::showStatus(const QString& message, int timeoutMilliseconds) {
    lastStatus_ = message;
    if (messageLog_ != nullptr && timeoutMilliseconds != 0)
        messageLog_->add(message); // messages shown until replaced are progress, not news
    statusBar()->showMessage(message, timeoutMilliseconds);
}

void MainWindow::reportError(const QString& title, const QString& message) {
    lastError_ = message;
    showStatus(message, 15000);
    if (dialogsEnabled_)
        QMessageBox::warning(this, title, message);
}

// Where to save the mission; a name typed without an extension gets .json (asked about before it replaces a
// file), so that Open mission lists it.
QString MainWindow::askMissionPath(const QString& title) {
    QFileDialog dialog(this, title, dialogFolder(kMissionFolderKey), kMissionFilter);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setDefaultSuffix(QStringLiteral("json"));
    if (dialog.exec() != QDialog::Accepted)
        return {};
    return dialog.selectedFiles().value(0);
}

bool MainWindow::maybeSave() {
    if (!isMissionModified() || !dialogsEnabled_)
        return true;
    // Only a new plan of a saved mission: say so, since the mission itself reads as the user left it.
    const bool onlyThePlan = undoStack_->isClean() && !settingsModified_;
    const auto answer = QMessageBox::question(
        this, tr("Unsaved changes"),
        onlyThePlan ? tr("The plan made since the mission was saved is not saved with it. Save it first?")
                    : tr("The mission has unsaved changes. Save them first?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel)
        return false;
    if (answer == QMessageBox::Discard)
        return true;
    QString path = document_->missionPath();
    if (path.isEmpty())
        path = askMissionPath(tr("Save mission"));
    return !path.isEmpty() && saveMission(path);
}

void MainWindow::openFile(const QString& path) {
    if (path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive))
        openMission(path);
    else
        openRaster(path);
}

void MainWindow::openSampleMission(bool plan) {
    const QString sample = findSampleMission();
    if (sample.isEmpty()) {
        showStatus(tr("The sample mission samples/zion-nlcd/mission.json was not found beside the program."));
        return;
    }
    // An untitled copy: Save asks where, so the bundled file is never overwritten or remembered as a folder.
    openingSample_ = true;
    const bool opened = openMission(sample);
    openingSample_ = false;
    if (!opened)
        return;
    document_->setMissionPath(QString());
    updateTitle();
    if (plan && !document_->robots().empty())
        startPlanning();
}

bool MainWindow::openRaster(const QString& path, const QString& preset) {
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto loaded = io::loadLandCoverRaster(path.toStdString());
    QApplication::restoreOverrideCursor();
    if (!loaded.ok()) {
        reportError(tr("Cannot open raster"),
                    tr("Cannot open raster %1: %2").arg(path, QString::fromStdString(loaded.error())));
        return false;
    }
    runner_->cancel();
    comparisonRunner_->cancel(); // its plans would be of the map before
    auto raster = std::make_shared<io::LoadedRaster>(std::move(loaded.value()));
    io::Mission mission;
    mission.rasterPath = QFileInfo(path).absoluteFilePath().toStdString();
    mission.band = raster->band;
    io::OpeningClassTable opening;
    if (preset.isEmpty()) {
        opening = io::openingClassTable(*raster);
    } else {
        opening.preset = preset.toStdString();
        opening.table = io::classTableForRaster(*raster, opening.preset);
    }
    mission.preset = opening.preset;
    mission.classes = opening.table;
    // The planner the user works with stays; its settings start from the defaults on a new map (a purity
    // tolerance tuned for another map is not a choice made for this one).
    mission.planner =
        defaultPlannerChoice(document_->hasMap() ? document_->plannerChoice().planner : std::string());
    std::vector<std::string> warnings = raster->notes; // said alike in the status bar
    warnings.insert(warnings.end(), raster->warnings.begin(), raster->warnings.end());
    document_->reset(std::move(raster), std::move(mission), QString());
    undoStack_->clear();
    settingsModified_ = false;
    planUnsaved_ = false;
    RecentFiles::add(path);
    rememberFolder(kRasterFolderKey, path);
    rebuildRecentMenu();
    updateTitle();
    QString message = tr("Opened %1: %2 classes. Place robot starts with the Place start tool (S).")
                          .arg(QFileInfo(path).fileName())
                          .arg(document_->classes().size());
    for (const auto& warning : warnings)
        message += QStringLiteral(" ") + asSentence(warning);
    showStatus(message, 15000);
    if (!opening.explanation.empty())
        explainClassTable(opening);
    else
        classTableBanner_->clearExplanation();
    return true;
}

bool MainWindow::openMission(const QString& path) {
    auto loaded = io::loadMission(path.toStdString());
    if (!loaded.ok()) {
        // The reader's errors name the file already: said once.
        const QString error = QString::fromStdString(loaded.error());
        reportError(tr("Cannot open mission"),
                    tr("Cannot open mission %1")
                        .arg(error.startsWith(path) ? error : path + QStringLiteral(": ") + error));
        return false;
    }
    io::Mission mission = std::move(loaded.value());
    const std::string missionPath = path.toStdString();
    const std::string savedInputs = io::planInputsFingerprint(mission, missionPath);
    const QString rasterPath = QString::fromStdString(io::resolveRasterPath(mission, missionPath));
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto raster = io::loadMissionRaster(mission, missionPath);
    QApplication::restoreOverrideCursor();
    if (!raster.ok()) {
        reportError(tr("Cannot open mission"),
                    tr("Mission %1 uses raster %2, which cannot be opened: %3")
                        .arg(path, rasterPath, QString::fromStdString(raster.error())));
        return false;
    }
    // The same reading of classes and starts as batch mode, so both plan the same mission.
    const io::FieldNamer names = io::missionFileFields(missionPath, io::robotNames(mission));
    std::optional<io::OpeningClassTable> opening;
    if (mission.classes.empty() && mission.preset.empty()) {
        opening = io::openingClassTable(raster.value());
        mission.preset = opening->preset; // the preset box then names what was applied
        mission.classes = opening->table; // read once: missionClasses below takes these rows
    }
    auto classes = io::missionClasses(mission, raster.value(), names);
    auto starts = classes ? io::missionStarts(mission, raster.value(), io::StartUnits::PlanningCrs, names)
                          : io::Result<std::vector<MapPoint>>::failure(classes.error());
    auto chargers = starts ? io::missionChargers(mission, raster.value(), io::StartUnits::PlanningCrs, names)
                           : io::Result<std::vector<std::optional<MapPoint>>>::failure(starts.error());
    if (!chargers.ok()) {
        reportError(tr("Cannot open mission"), QString::fromStdString(chargers.error()));
        return false;
    }
    mission.classes = std::move(classes.value());
    mission.classesWithoutColour.clear(); // coloured now, from the preset or the raster
    mission.fieldOfViewMetres.reset();    // in the rows now, where an edit to one class's is kept
    // The window holds the area files by absolute path; saving writes them relative again.
    mission.area.includePath = io::resolveMissionPath(mission.area.includePath, missionPath);
    mission.area.excludePath = io::resolveMissionPath(mission.area.excludePath, missionPath);
    // The window keeps every start in the planning frame; saving writes them back in the CRS they were given
    // in (start_crs, kept), else in the planning CRS's units (io::robotAsWritten).
    for (std::size_t robot = 0; robot < mission.robots.size(); ++robot) {
        mission.robots[robot].start = starts.value()[robot];
        mission.robots[robot].charger = chargers.value()[robot];
    }
    runner_->cancel();
    comparisonRunner_->cancel(); // its plans would be of the map before
    std::vector<std::string> warnings = raster.value().notes;
    warnings.insert(warnings.end(), raster.value().warnings.begin(), raster.value().warnings.end());
    document_->reset(std::make_shared<io::LoadedRaster>(std::move(raster.value())), std::move(mission),
                     QFileInfo(path).absoluteFilePath());
    undoStack_->clear();
    settingsModified_ = false;
    if (!openingSample_) {
        RecentFiles::add(path);
        rememberFolder(kMissionFolderKey, path);
        rebuildRecentMenu();
    }
    planUnsaved_ = false;
    updateTitle();
    QString message = tr("Opened mission %1 with %2 robots.")
                          .arg(QFileInfo(path).fileName())
                          .arg(document_->robots().size());
    message += restorePlanBeside(QFileInfo(path).absoluteFilePath(), savedInputs);
    for (const auto& warning : warnings)
        message += QStringLiteral(" ") + asSentence(warning);
    showStatus(message, 15000);
    if (opening)
        explainClassTable(*opening);
    else
        classTableBanner_->clearExplanation();
    return true;
}

bool MainWindow::saveMission(const QString& path) {
    if (!document_->hasMap()) {
        reportError(tr("Cannot save mission"), tr("Open a raster before saving a mission."));
        return false;
    }
    if (!keepDrawnAreasBeside(path))
        return false;
    io::Mission mission = document_->mission();
    // Relative to the mission's folder so the pair can be moved together.
    const QString rasterAbsolute =
        QFileInfo(QString::fromStdString(document_->raster()->path)).absoluteFilePath();
    mission.rasterPath = QFileInfo(path).absoluteDir().relativeFilePath(rasterAbsolute).toStdString();
    for (std::string* areaPath : {&mission.area.includePath, &mission.area.excludePath})
        if (!areaPath->empty())
            *areaPath = QFileInfo(path)
                            .absoluteDir()
                            .relativeFilePath(QString::fromStdString(*areaPath))
                            .toStdString();
    for (io::RobotSpec& robot : mission.robots)
        robot = io::robotAsWritten(robot, document_->raster()->georeference);
    const auto status = io::saveMission(mission, path.toStdString());
    if (!status.ok()) {
        reportError(tr("Cannot save mission"),
                    tr("Cannot save mission to %1: %2").arg(path, QString::fromStdString(status.error())));
        return false;
    }
    document_->setMissionPath(QFileInfo(path).absoluteFilePath());
    const QString planNote = savePlanBeside(QFileInfo(path).absoluteFilePath(),
                                            io::planInputsFingerprint(mission, path.toStdString()));
    undoStack_->setClean();
    settingsModified_ = false;
    planUnsaved_ = false;
    RecentFiles::add(path);
    rememberFolder(kMissionFolderKey, path);
    rebuildRecentMenu();
    updateTitle();
    showStatus(tr("Saved mission to %1.").arg(path) + planNote);
    return true;
}

QString MainWindow::savePlanBeside(const QString& missionPath, const std::string& fingerprint) {
    const std::string planPath = io::planFilePath(missionPath.toStdString());
    const Plan* plan = document_->plan();
    // A plan file already there is left alone: one made from other inputs is refused on the next open, and
    // one this mcpp cannot read may be another version's.
    if (plan == nullptr || document_->planStale() || fingerprint.empty())
        return {};
    if (sortieLayerOf(*plan) != nullptr)
        return tr(" Its plan is not saved with it: plan files do not hold sorties, so opening the mission "
                  "plans again.");
    if (inputFilesAtLoad_.empty() || currentInputFiles() != inputFilesAtLoad_) {
        messageLog_->add(tr("The raster or area files have changed on disk since they were read, so the plan "
                            "was not saved with the mission: open the mission again and plan."));
        return tr(" The plan was not saved with it: its input files have changed on disk (see Messages).");
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    const io::Status saved = io::savePlanFile(*plan, fingerprint, planPath);
    QApplication::restoreOverrideCursor();
    if (!saved.ok()) {
        messageLog_->add(
            tr("The plan was not saved with the mission: %1").arg(QString::fromStdString(saved.error())));
        return tr(" The plan could not be saved beside it (see Messages).");
    }
    return tr(" The plan is saved beside it in %1.")
        .arg(QFileInfo(QString::fromStdString(planPath)).fileName());
}

QString MainWindow::restorePlanBeside(const QString& missionPath, const std::string& fingerprint) {
    const std::string planPath = io::planFilePath(missionPath.toStdString());
    if (!QFileInfo::exists(QString::fromStdString(planPath)))
        return {};
    if (fingerprint.empty())
        return tr(" Its saved plan is not shown: the raster's or an area file's size and time cannot be read "
                  "to check it is the one planned. Press Plan to plan again.");
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto loaded = io::loadPlanFile(planPath, fingerprint);
    QApplication::restoreOverrideCursor();
    if (!loaded.ok()) {
        messageLog_->add(asSentence(loaded.error()));
        return tr(" Its saved plan cannot be read (see Messages): press Plan to plan again.");
    }
    if (!loaded.value()) {
        return tr(" Its saved plan was made from other inputs (the raster, area, classes, starts or planner "
                  "have changed since): press Plan to plan again.");
    }
    auto plan = std::make_shared<const Plan>(std::move(*loaded.value()));
    // The time the results lead with: the last robot home where flights split the missions.
    const PlanMetrics& metrics = plan->metrics;
    const QString done =
        metrics.timedInTheField()
            ? tr("last robot home after %1").arg(ResultsPanel::formatDuration(metrics.fieldMakespanSeconds))
            : tr("makespan %1").arg(ResultsPanel::formatDuration(metrics.makespanSeconds));
    document_->setPlan(std::move(plan), document_->currentInputs());
    return tr(" Restored its saved plan (%1).").arg(done);
}

namespace {

// Where areas drawn for an untitled mission wait until it is saved.
QString drawnAreasFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/drawn-areas");
}

// folder/base-kind.geojson, or base-kind-2.geojson, ... : the first name no file has.
QString freeAreaFileName(const QString& folder, const QString& base, const QString& kind) {
    QString path = QDir(folder).filePath(QStringLiteral("%1-%2.geojson").arg(base, kind));
    for (int number = 2; QFileInfo::exists(path); ++number)
        path = QDir(folder).filePath(QStringLiteral("%1-%2-%3.geojson").arg(base, kind).arg(number));
    return path;
}

} // namespace

QString MainWindow::drawnAreaPath(bool exclude) const {
    const QString kind = exclude ? QStringLiteral("no-go") : QStringLiteral("area");
    QString folder;
    QString base;
    if (!document_->missionPath().isEmpty()) {
        folder = QFileInfo(document_->missionPath()).absolutePath();
        base = QFileInfo(document_->missionPath()).completeBaseName();
    } else {
        folder = drawnAreasFolder();
        QDir().mkpath(folder);
        base = QFileInfo(QString::fromStdString(document_->raster()->path)).completeBaseName();
    }
    // Always a name no file has: no file is written twice, so undo only switches files, and a file a saved
    // mission names is never changed.
    return freeAreaFileName(folder, base, kind);
}

void MainWindow::useDrawnArea(const std::vector<MapPoint>& ring) {
    const bool exclude = drawNoGoAction_->isChecked();
    panToolAction_->setChecked(true);
    if (!document_->hasMap())
        return;
    const io::AreaOfInterest area = document_->mission().area;
    const QString path = drawnAreaPath(exclude);
    // Written beside its final name and tried first: an area the map refuses changes no file in use.
    const QString trial = path + QStringLiteral(".trial");
    // No-go zones add up (the polygons of the file in use come first); an area of interest replaces the last.
    const io::Status written = io::writeAreaPolygons(trial.toStdString(), {ring}, *document_->raster(),
                                                     exclude ? area.excludePath : std::string());
    if (!written.ok()) {
        reportError(tr("Cannot use the area"), QString::fromStdString(written.error()));
        return;
    }
    const bool used = exclude ? useAreaFiles(QString::fromStdString(area.includePath), trial)
                              : useAreaFiles(trial, QString::fromStdString(area.excludePath));
    if (!used) {
        QFile::remove(trial);
        return;
    }
    if (!QFile::rename(trial, path)) {
        reportError(tr("Cannot use the area"), tr("Cannot move %1 to %2.").arg(trial, path));
        return;
    }
    io::AreaOfInterest placed = document_->mission().area;
    (exclude ? placed.excludePath : placed.includePath) = path.toStdString();
    document_->setAreaPaths(placed);
    rememberInputFiles();
    pushAreaEdit(area, exclude ? tr("Draw no-go zone") : tr("Draw area of interest"));
}

bool MainWindow::keepDrawnAreasBeside(const QString& missionPath) {
    const QString drawnFolder = drawnAreasFolder() + QStringLiteral("/");
    io::AreaOfInterest area = document_->mission().area;
    const QString folder = QFileInfo(missionPath).absolutePath();
    const QString base = QFileInfo(missionPath).completeBaseName();
    for (auto [path, kind] : {std::pair{&area.includePath, QStringLiteral("area")},
                              std::pair{&area.excludePath, QStringLiteral("no-go")}}) {
        const QString current = QString::fromStdString(*path);
        if (current.isEmpty() || !QFileInfo(current).absoluteFilePath().startsWith(drawnFolder))
            continue;
        const QString target = freeAreaFileName(folder, base, kind);
        if (!QFile::copy(current, target)) {
            reportError(tr("Cannot save mission"),
                        tr("Cannot copy the drawn area %1 to %2.").arg(current, target));
            return false;
        }
        *path = target.toStdString();
    }
    document_->setAreaPaths(area);
    rememberInputFiles(); // the same polygons, in their copies
    return true;
}

std::string MainWindow::currentInputFiles() const {
    if (!document_->hasMap())
        return {};
    const io::AreaOfInterest& area = document_->mission().area;
    return io::inputFilesIdentity({document_->raster()->path, area.includePath, area.excludePath});
}

void MainWindow::rememberInputFiles() {
    inputFilesAtLoad_ = currentInputFiles();
}

void MainWindow::notePlanToSave() {
    // An untitled mission's plan is saved with it anyway; only a saved mission becomes modified.
    if (document_->missionPath().isEmpty())
        return;
    planUnsaved_ = true;
    updateTitle();
}

void MainWindow::chooseExport(const std::string& formatKey) {
    const io::ExportFormat* format = io::findExportFormat(formatKey);
    if (format == nullptr)
        return;
    const QString suggested = suggestedExportFileName(*format, document_->missionPath());
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export plan"), QDir(dialogFolder(kExportFolderKey)).filePath(suggested),
        QString::fromStdString(format->filter));
    if (path.isEmpty())
        return;
    rememberFolder(kExportFolderKey, path);
    exportPlan(formatKey, path);
}

bool MainWindow::exportPlan(const std::string& formatKey, const QString& path) {
    if (document_->plan() == nullptr || !document_->hasMap()) {
        reportError(tr("Cannot export"), tr("There is no plan to export yet; press Plan first."));
        return false;
    }
    const io::ExportFormat* format = io::findExportFormat(formatKey);
    if (format == nullptr) {
        reportError(tr("Cannot export"),
                    tr("Unknown export format %1.").arg(QString::fromStdString(formatKey)));
        return false;
    }
    if (exportRunner_->isRunning() || runner_->isRunning()) {
        reportError(tr("Cannot export"), tr("Wait until the running plan or export has finished."));
        return false;
    }
    ExportJob job;
    job.formatKey = formatKey;
    job.plan = document_->sharedPlan();
    job.raster = document_->sharedRaster();
    job.classes = document_->classes();
    job.settings = document_->mission().exports;
    job.robotNames = io::robotNames(document_->mission());
    job.vehicles = io::robotVehicles(document_->mission());
    job.imageSide = exportImageSide;
    const int robots = static_cast<int>(job.plan->paths.size());
    const int files = format->perRobot ? robots : 1;
    for (int file = 0; file < files; ++file)
        job.files.emplace_back(file, format->perRobot ? perRobotPath(path, file, robots) : path);
    exportStale_ = document_->planStale();
    if (!exportRunner_->start(std::move(job)))
        return false;
    showBusy(tr("Exporting %1…").arg(QString::fromStdString(format->label)), true);
    // Files are counted as they are written; one file alone (a GeoPackage of millions of cells) shows a
    // busy bar rather than one stuck at none of one.
    progressBar_->setRange(0, files > 1 ? files : 0);
    progressBar_->setValue(0);
    updateActions();
    return true;
}

void MainWindow::cancelExport() {
    if (!exportRunner_->isRunning())
        return;
    exportRunner_->cancel();
    cancelButton_->setEnabled(false);
    stageLabel_->setText(tr("Cancelling…"));
}

void MainWindow::editVehicles() {
    VehicleSettingsDialog dialog(document_->mission(), this);
    dialog.setObjectName(QStringLiteral("vehicleSettingsDialog"));
    if (dialog.exec() != QDialog::Accepted)
        return;
    const io::ExportSettings exports = dialog.exports();
    std::vector<io::VehicleOverrides> vehicles = dialog.vehicles();
    std::vector<io::VehicleOverrides> current;
    for (const io::RobotSpec& robot : document_->robots())
        current.push_back(robot.vehicle);
    if (exports == document_->mission().exports && vehicles == current)
        return;
    undoStack_->push(new VehicleSettingsEditCommand(document_, exports, std::move(vehicles)));
}

bool MainWindow::isExporting() const {
    return exportRunner_->isRunning();
}

void MainWindow::handleExportFinished(const ExportOutcome& outcome) {
    showBusy({}, false);
    progressBar_->setRange(0, 1000);
    updateActions();
    if (outcome.cancelled) {
        showStatus(tr("Export cancelled; no unfinished file was left behind."));
    } else if (!outcome.error.isEmpty()) {
        reportError(tr("Export failed"), outcome.error);
    } else {
        QString message = tr("Exported %1").arg(exportedFilesText(outcome.written));
        if (exportStale_)
            message += tr(" (note: the plan is out of date)");
        showStatus(message);
        for (const QString& note : outcome.notes)
            messageLog_->add(note);
    }
    emit exportFinished(!outcome.cancelled && outcome.error.isEmpty());
}

// The status bar's stage, progress and Cancel, and a busy cursor, while a background job runs.
void MainWindow::showBusy(const QString& stage, bool busy) {
    stageLabel_->setText(stage);
    stageLabel_->setVisible(busy);
    progressBar_->setVisible(busy);
    cancelButton_->setVisible(busy);
    cancelButton_->setEnabled(busy);
    if (busy)
        QGuiApplication::setOverrideCursor(Qt::BusyCursor);
    else
        QGuiApplication::restoreOverrideCursor();
}

io::FieldNamer MainWindow::fieldNamer(const std::string& planner) const {
    return [this, planner](const io::MissionField& field) -> std::string {
        using Part = io::MissionField::Part;
        const auto& robots = document_->robots();
        switch (field.part) {
        case Part::Raster:
            return "the raster";
        case Part::Classes:
            return "the class table";
        case Part::MissingClassesOption:
            return "the mission's classes.missing_as_obstacles";
        case Part::Start:
        case Part::StartCrs:
            if (field.robot >= 0 && static_cast<std::size_t>(field.robot) < robots.size())
                return robots[static_cast<std::size_t>(field.robot)].name + "'s start";
            return "robot " + std::to_string(field.robot + 1) + "'s start";
        case Part::Charger:
            if (field.robot >= 0 && static_cast<std::size_t>(field.robot) < robots.size())
                return robots[static_cast<std::size_t>(field.robot)].name + "'s charger";
            return "robot " + std::to_string(field.robot + 1) + "'s charger";
        case Part::Planner:
            return "the planner";
        case Part::Parameter:
            break;
        }
        return plannerSettingName(planner.empty() ? document_->plannerChoice().planner : planner, field);
    };
}

QString MainWindow::planningErrorText(const PlanningOutcome& outcome) const {
    if (!outcome.planningError)
        return outcome.error;
    // As "Cannot plan" gives the starts it checks first: the robots the planner numbers by their names, the
    // points with their degrees.
    const auto named = io::planningErrorText(*outcome.planningError, fieldNamer(), robotNames());
    return named ? QString::fromStdString(withDegrees(*named)) : outcome.error;
}

// The message's map points with their longitude and latitude, where the map has a CRS.
std::string MainWindow::withDegrees(const std::string& message) const {
    return io::messageForPeople(message, document_->raster(), {});
}

std::vector<std::string> MainWindow::robotNames() const {
    std::vector<std::string> names;
    for (const io::RobotSpec& robot : document_->robots())
        names.push_back(robot.name);
    return names;
}

bool MainWindow::isPlanning() const {
    return runner_->isRunning();
}

bool MainWindow::startComparison(const std::vector<std::string>& planners) {
    if (runner_->isRunning() || comparisonRunner_->isRunning() || exportRunner_->isRunning())
        return false;
    if (!document_->hasMap() || document_->robots().empty()) {
        reportError(tr("Cannot compare"),
                    !document_->hasMap() ? tr("Open a land-cover raster first.")
                                         : tr("Place robot starts first, with the Place start tool (S)."));
        return false;
    }
    if (planners.empty()) {
        reportError(tr("Cannot compare"), tr("Check at least one planner in the Compare planners panel."));
        return false;
    }
    if (const auto flight = io::fleetFlightProblem(document_->mission())) {
        reportError(tr("Cannot compare"), vehiclesProblemText(*flight));
        return false;
    }
    // The same checks as for one plan, with the mission's own planner.
    auto prepared =
        io::planningProblem(*document_->raster(), document_->classes(),
                            document_->mission().missingClassesAsObstacles, document_->starts(),
                            document_->plannerChoice(), fieldNamer(), io::flyingRobots(document_->mission()));
    if (!prepared.ok()) {
        reportError(tr("Cannot compare"),
                    refusalText(prepared.error(), document_->mission(), *document_->raster()));
        return false;
    }
    std::vector<PlannerChoice> choices;
    for (const std::string& name : planners)
        choices.push_back(switchPlanner(document_->plannerChoice(), name));
    comparisonInputs_.clear();
    for (const PlannerChoice& choice : choices)
        comparisonInputs_.push_back(document_->inputsFor(choice));
    comparisonRaster_ = document_->sharedRaster();
    addRobotSettings(prepared.value().problem);
    if (!comparisonRunner_->start(std::move(prepared.value().problem), choices, waypointFileWarnings()))
        return false;
    // The planners listed at once, each row filled in as its planner is done.
    comparison_ = ComparisonOutcome{};
    comparison_.choices = choices;
    showComparison();
    logLargeMission(choices);
    showBusy(tr("Comparing…"), true);
    comparisonUnderway_ = true;
    showWorkUnderway();
    progressBar_->setValue(0);
    updateActions();
    showStatus(planners.size() == 1
                   ? tr("Comparing the one planner checked in the Compare planners panel (check more there)…")
                   : tr("Comparing the %1 planners checked in the Compare planners panel (uncheck any not "
                        "wanted there)…")
                         .arg(planners.size()),
               0);
    return true;
}

// Said as the work starts, which the user may cancel: how large a mission is (io::largeMissionWarning), with
// the factor the class table's Scale FOVs would take.
void MainWindow::logLargeMission(const std::vector<PlannerChoice>& planners) {
    const auto remedy = [](double factor) {
        return "Scaling every FOV by " + formatQuantity(factor, 2) + " (Edit selected… > Scale FOVs)";
    };
    if (const auto warning = io::largeMissionWarning(document_->mission(), *document_->raster(),
                                                     document_->classes(), planners, remedy)) {
        QString text = QString::fromStdString(*warning);
        messageLog_->add(text.left(1).toUpper() + text.mid(1));
    }
}

bool MainWindow::isComparing() const {
    return comparisonRunner_->isRunning();
}

void MainWindow::handleComparisonFinished(const ComparisonOutcome& outcome) {
    showBusy({}, false);
    comparisonUnderway_ = false;
    showWorkUnderway();
    if (!document_->hasMap() || document_->sharedRaster() != comparisonRaster_) {
        // Another map was opened meanwhile: these plans belong to the one before, and so do its rows.
        comparisonRaster_.reset();
        comparison_ = ComparisonOutcome{};
        comparisonPanel_->clearOutcome();
        showStatus(tr("Comparison dropped: another map was opened while it ran."));
        updateActions();
        emit comparisonFinished(false);
        return;
    }
    comparison_ = outcome;
    nameRefusals(comparison_);
    showComparison();
    logComparedWarnings();
    const auto planned = std::count_if(outcome.plans.begin(), outcome.plans.end(),
                                       [](const auto& plan) { return plan != nullptr; });
    canvas_->setComparedPlansWaiting(planned > 0);
    showStatus(outcome.cancelled
                   ? tr("Comparison cancelled after %1 plans.").arg(planned)
                   : tr("Compared %1 planners: select a row to show its plan.").arg(outcome.rows.size()));
    updateActions();
    emit comparisonFinished(!outcome.cancelled && planned > 0);
}

// The rows so far, where the user can select a plan made while the others are still planned.
void MainWindow::handleComparedPlanner(const ComparisonOutcome& outcomeSoFar) {
    // Late news of a run already over, or of one made on a map since closed, is not shown.
    if (outcomeSoFar.rows.size() <= comparison_.rows.size() || !document_->hasMap() ||
        document_->sharedRaster() != comparisonRaster_)
        return;
    comparison_ = outcomeSoFar;
    nameRefusals(comparison_);
    showComparison(false);
    emit comparisonProgressed(static_cast<int>(comparison_.rows.size()));
}

// A planner's refusal named as the window names Plan's: the field in the window's terms, the robots by name,
// the points with their degrees.
void MainWindow::nameRefusals(ComparisonOutcome& outcome) const {
    for (std::size_t row = 0; row < outcome.rows.size() && row < outcome.errors.size(); ++row)
        if (const auto& error = outcome.errors[row])
            if (const auto named =
                    io::planningErrorText(*error, fieldNamer(outcome.choices[row].planner), robotNames()))
                outcome.rows[row].message = withDegrees(*named);
}

// raise: brings the dock forward (as the comparison starts and ends, not over a tab opened meanwhile).
void MainWindow::showComparison(bool raise) {
    // Shown first, so that the panel can be widened to its table as it fills.
    if (raise) {
        comparisonDock_->show();
        comparisonDock_->raise();
    }
    comparisonPanel_->showOutcome(comparison_, *document_->grid(), document_->classes(),
                                  document_->raster() != nullptr ? &document_->raster()->area : nullptr,
                                  document_->sharedRaster());
}

// What the banner says while the window works out a plan or a comparison for this map.
void MainWindow::showWorkUnderway() {
    // Flags of their own: a runner's future may be done before its finished signal is handled.
    if (comparisonUnderway_)
        canvas_->setWorkUnderway(tr("Comparing planners… select a row under Compare planners to show a plan "
                                    "once its planner is done."));
    else if (planningUnderway_)
        canvas_->setWorkUnderway(tr("Planning… the plan is shown here when it is done (Cancel, beside the "
                                    "progress bar, stops it)."));
    else
        canvas_->setWorkUnderway({});
}

// A plan of weeks: what to change, where the window changes it; empty for a plan of less.
QString MainWindow::longPlanAdvice(double makespanSeconds, std::size_t robots) const {
    const auto causes = io::longPlanCauses(makespanSeconds, document_->mission(), document_->classes());
    if (!causes)
        return {};
    QString advice = (robots == 1 ? tr("The robot needs %1") : tr("The robots need %1"))
                         .arg(ResultsPanel::formatDuration(makespanSeconds));
    if (causes->wholeRaster)
        advice +=
            tr(" for all the raster's land: to plan part of it, draw it (Plan ▸ Draw area of interest) or "
               "open its polygons (Plan ▸ Area of interest from file…); for a wider sensor footprint, raise "
               "the classes' field of view");
    if (causes->groundSpeeds) {
        const QString speeds = causes->fastestSpeedMetresPerSecond > causes->slowestSpeedMetresPerSecond
                                   ? tr("%1 to %2 m/s")
                                         .arg(speedText(causes->slowestSpeedMetresPerSecond),
                                              speedText(causes->fastestSpeedMetresPerSecond))
                                   : tr("%1 m/s").arg(speedText(causes->slowestSpeedMetresPerSecond));
        advice +=
            (causes->wholeRaster ? tr("; if") : tr(": if")) +
            tr(" the robots fly, set their vehicle and cruise speed in Plan ▸ Robot vehicles… (the class "
               "table's speeds, %1, are a ground robot's)")
                .arg(speeds);
    }
    return advice + QLatin1Char('.');
}

bool MainWindow::flightsSaidOf(const std::shared_ptr<const Plan>& plan) {
    std::erase_if(flightsSaid_, [](const std::weak_ptr<const Plan>& said) { return said.expired(); });
    return std::any_of(flightsSaid_.begin(), flightsSaid_.end(),
                       [&plan](const std::weak_ptr<const Plan>& said) { return said.lock() == plan; });
}

// A plan's warnings and notes, whole, in the messages panel, where every message is kept.
void MainWindow::logPlanIssues(const Plan& plan) {
    const std::vector<std::string> names = robotNames();
    for (const PlanIssue& issue : plan.issues)
        messageLog_->add((issue.severity == IssueSeverity::Information ? tr("Note: %1") : tr("Warning: %1"))
                             .arg(loggedText(issue.message, names, document_->raster())));
}

// The compared plans' warnings, each once (comparedWarnings), under the planners that carry it.
void MainWindow::logComparedWarnings() {
    std::vector<PlannerWarnings> plans;
    for (std::size_t row = 0; row < comparison_.plans.size() && row < comparison_.rows.size(); ++row) {
        if (!comparison_.plans[row])
            continue;
        flightsSaid_.push_back(comparison_.plans[row]); // its file warnings are among these
        plans.push_back({comparison_.rows[row].planner, comparison_.warningsOf(row)});
    }
    const std::vector<std::string> names = robotNames();
    for (const ComparedWarning& warning : comparedWarnings(plans)) {
        const QString text = loggedText(warning.text, names, document_->raster());
        messageLog_->add(tr("Warning: %1")
                             .arg(warning.planners.empty() ? text
                                                           : QString::fromStdString(warning.planners) +
                                                                 QStringLiteral(": ") + text));
    }
}

void MainWindow::showComparedPlan(int row) {
    if (row >= static_cast<int>(comparison_.plans.size()) &&
        row < static_cast<int>(comparison_.choices.size())) {
        showStatus(
            tr("%1 is not planned yet: its row fills in when it is done.")
                .arg(QString::fromStdString(comparison_.choices[static_cast<std::size_t>(row)].planner)));
        return;
    }
    if (row < 0 || static_cast<std::size_t>(row) >= comparison_.plans.size() ||
        !comparison_.plans[static_cast<std::size_t>(row)])
        return;
    if (document_->sharedRaster() != comparisonRaster_) {
        showStatus(tr("That comparison was made on another map: compare again to show its plans here."));
        return;
    }
    // The shown plan is the mission's plan: its planner becomes the mission's, so exports and the results
    // panel are about it, and it is not out of date.
    const PlannerChoice& choice = comparison_.choices[static_cast<std::size_t>(row)];
    if (!(choice == document_->plannerChoice())) {
        document_->setPlannerChoice(choice);
        settingsModified_ = true;
        updateTitle();
    }
    // What the plan was made from, with its own planner chosen (a battery planner's batteries among them).
    const auto made = std::find_if(comparisonInputs_.begin(), comparisonInputs_.end(),
                                   [&](const PlanInputs& inputs) { return inputs.planner == choice; });
    document_->setPlan(comparison_.plans[static_cast<std::size_t>(row)],
                       made != comparisonInputs_.end() ? *made : document_->inputsFor(choice));
    notePlanToSave();
    showStatus(tr("Showing the plan of %1.").arg(QString::fromStdString(choice.planner)));
}

bool MainWindow::startPlanning() {
    if (runner_->isRunning())
        return false;
    if (!document_->hasMap()) {
        reportError(tr("Cannot plan"), tr("Open a land-cover raster first."));
        return false;
    }
    if (document_->robots().empty()) {
        showStatus(tr(
            "Place at least one robot start first: choose the Place start tool (S) and click on the map."));
        return false;
    }
    if (const auto problem = document_->classes().validate()) {
        reportError(tr("Cannot plan"),
                    tr("The class table has a problem: %1").arg(QString::fromStdString(*problem)));
        return false;
    }
    if (const auto flight = io::fleetFlightProblem(document_->mission())) {
        reportError(tr("Cannot plan"), vehiclesProblemText(*flight));
        return false;
    }
    // The same checks batch mode makes, named in the window's terms.
    auto prepared =
        io::planningProblem(*document_->raster(), document_->classes(),
                            document_->mission().missingClassesAsObstacles, document_->starts(),
                            document_->plannerChoice(), fieldNamer(), io::flyingRobots(document_->mission()));
    if (!prepared.ok()) {
        reportError(tr("Cannot plan"),
                    refusalText(prepared.error(), document_->mission(), *document_->raster()));
        return false;
    }
    planningInputs_ = document_->currentInputs();
    addRobotSettings(prepared.value().problem);
    if (!runner_->start(std::move(prepared.value().problem)))
        return false;
    logLargeMission({document_->plannerChoice()});
    planningStartedAt_ = QDateTime::currentMSecsSinceEpoch();
    planningUnderway_ = true;
    showWorkUnderway();
    stageLabel_->setText(tr("Starting…"));
    progressBar_->setValue(0);
    stageLabel_->show();
    progressBar_->show();
    cancelButton_->show();
    cancelButton_->setEnabled(true);
    updateActions();
    const auto robots = static_cast<int>(document_->robots().size());
    const QString planner = QString::fromStdString(document_->plannerChoice().planner);
    showStatus(robots == 1 ? tr("Planning 1 robot with %1…").arg(planner)
                           : tr("Planning %1 robots with %2…").arg(robots).arg(planner),
               0);
    return true;
}

void MainWindow::cancelPlanning() {
    if (!runner_->isRunning())
        return;
    runner_->cancel();
    cancelButton_->setEnabled(false);
    stageLabel_->setText(tr("Cancelling…"));
}

void MainWindow::handlePlanningFinished(const PlanningOutcome& outcome) {
    planningUnderway_ = false;
    showWorkUnderway();
    stageLabel_->hide();
    progressBar_->hide();
    cancelButton_->hide();
    const double seconds =
        static_cast<double>(QDateTime::currentMSecsSinceEpoch() - planningStartedAt_) / 1000.0;
    if (outcome.plan) {
        // Worked out from the settings it was planned with, before showing it shows the advice.
        advisedPlan_ = outcome.plan;
        planAdvice_ = longPlanAdvice(outcome.plan->metrics.makespanSeconds, outcome.plan->paths.size());
        document_->setPlan(outcome.plan, planningInputs_);
        notePlanToSave();
        const auto& metrics = outcome.plan->metrics;
        // A small map plans in milliseconds, which "0.0 s" would hide.
        const QString took =
            seconds < 1.0 ? tr("%1 ms").arg(qRound(seconds * 1000.0)) : tr("%1 s").arg(seconds, 0, 'f', 1);
        // Where flights split the missions, when the last robot is home, as the results panel gives it.
        const bool inTheField = metrics.timedInTheField();
        showStatus(inTheField ? tr("Planned in %1: the last robot home after %2.")
                                    .arg(took)
                                    .arg(ResultsPanel::formatDuration(metrics.fieldMakespanSeconds))
                              : tr("Planned in %1: makespan %2, %3 × the lower bound.")
                                    .arg(took)
                                    .arg(ResultsPanel::formatDuration(metrics.makespanSeconds))
                                    .arg(metrics.ratio, 0, 'f', 3), // as plan.png gives it
                   15000);
        logPlanIssues(*outcome.plan); // whole, where every message is kept
        if (!planAdvice_.isEmpty())
            messageLog_->add(tr("Note: %1").arg(planAdvice_));
    } else if (outcome.cancelled) {
        showStatus(tr("Planning cancelled; the previous plan, if any, is kept."));
    }
    updateActions(); // before any dialog: Cancel must not stay enabled behind it
    if (!outcome.plan && !outcome.cancelled)
        reportError(tr("Planning failed"), planningErrorText(outcome));
    emit planningFinished(outcome.plan != nullptr);
}

void MainWindow::placeStart(MapPoint point) {
    if (robotModel_->addRobot(point)) {
        const int robot = static_cast<int>(document_->robots().size()) - 1;
        canvas_->setSelectedStart(robot);
        showStatus(tr("Added %1 at X %2  Y %3%4.")
                       .arg(QString::fromStdString(document_->robots().back().name),
                            formatCoordinate(point.x), formatCoordinate(point.y), degreesOf(point)));
    }
}

void MainWindow::removeSelectedRobot() {
    int robot = canvas_->selectedStart();
    if (robot < 0 && robotView_->currentIndex().isValid())
        robot = robotView_->currentIndex().row();
    if (robot < 0) {
        showStatus(tr("Select a robot (click its marker or its row) to remove it."));
        return;
    }
    const QString name = QString::fromStdString(document_->robots()[static_cast<std::size_t>(robot)].name);
    if (robotModel_->removeRobot(robot)) {
        canvas_->setSelectedStart(-1);
        showStatus(tr("Removed %1.").arg(name));
    }
}

bool MainWindow::applyPreset(const QString& preset) {
    if (!document_->hasMap())
        return false;
    const ClassTable table = io::classTableForRaster(*document_->raster(), preset.toStdString());
    const QString presetBefore = QString::fromStdString(document_->mission().preset);
    if (table == document_->classes() && preset == presetBefore)
        return true;
    const QString label = preset.isEmpty() ? tr("the raster's legend") : preset;
    undoStack_->push(new ClassTableEditCommand(document_, document_->classes(), presetBefore, table, preset,
                                               tr("Apply preset %1").arg(label)));
    showStatus(tr("Applied %1 to the class table.").arg(label));
    classTableBanner_->clearExplanation();
    return true;
}

// What the status line adds to a point: its degrees where the map has a CRS.
QString MainWindow::degreesOf(MapPoint point) const {
    const auto* raster = document_->raster();
    if (raster == nullptr || !raster->georeference.hasCrs())
        return {};
    const auto lonLat = raster->georeference.toWgs84(point);
    if (!lonLat.ok())
        return {};
    return QStringLiteral("  ·  %1, %2")
        .arg(formatDegrees(lonLat.value().latitude, QLatin1Char('N'), QLatin1Char('S')),
             formatDegrees(lonLat.value().longitude, QLatin1Char('E'), QLatin1Char('W')));
}

void MainWindow::showCursor(MapPoint point) {
    QString text = QStringLiteral("X %1  Y %2 m").arg(formatCoordinate(point.x), formatCoordinate(point.y));
    if (!crsName_.isEmpty())
        text += QStringLiteral(" (%1)").arg(crsName_);
    text += degreesOf(point);
    if (const auto value = document_->classValueAt(point)) {
        const LandCoverClass* landCoverClass = document_->classes().find(*value);
        const QString name =
            landCoverClass != nullptr ? QString::fromStdString(landCoverClass->name) : tr("unknown class");
        text += QStringLiteral("  ·  %1 (%2)").arg(name).arg(*value);
    } else {
        // On the raster but left out (nodata, outside the area of interest, a no-go zone) is not off the map.
        const auto* raster = document_->raster();
        const bool onTheRaster = raster != nullptr && raster->grid.pixelAt(point).has_value();
        text += onTheRaster ? tr("  ·  outside the task area") : tr("  ·  outside the map");
    }
    cursorLabel_->setText(text);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    runner_->cancel();
    runner_->waitForFinished();
    exportRunner_->cancel();
    exportRunner_->waitForFinished();
    comparisonRunner_->cancel();
    comparisonRunner_->waitForFinished();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls() && !event->mimeData()->urls().isEmpty() &&
        event->mimeData()->urls().front().isLocalFile())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile())
        return;
    event->acceptProposedAction();
    const QString path = urls.front().toLocalFile();
    // Opened after the drop returns so a message box does not block the drag source.
    QTimer::singleShot(0, this, [this, path] {
        if (maybeSave())
            openFile(path);
    });
}

} // namespace mcpp::ui
