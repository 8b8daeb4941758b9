#pragma once

#include "core/model/MapPoint.hpp"
#include "io/AutopilotMission.hpp"
#include "io/MissionInputs.hpp"
#include "ui/AreaEditCommand.hpp"
#include "ui/ComparisonRunner.hpp"
#include "ui/MissionDocument.hpp"

#include <QFutureWatcher>
#include <QMainWindow>
#include <QString>
#include <string>
#include <vector>

class QAction;
class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTableView;
class QUndoStack;

namespace mcpp::io {
struct OpeningClassTable;
} // namespace mcpp::io

namespace mcpp::ui {

class ClassTableBanner;
class ClassTableModel;
class ComparisonPanel;
class ComparisonRunner;
class EventTableModel;
class ExportRunner;
class LayersPanel;
class LegendPanel;
class MapCanvas;
class MessageLog;
class PlannerSettingsPanel;
class PlanningRunner;
class ResultsPanel;
class RobotTableModel;
class TimelineBar;
struct ExportOutcome;
struct PlanningOutcome;

// The desktop application: map canvas in the middle; layers, classes, robots, planner and results in docks.
// Every file operation is also a public method so app/main.cpp and the tests can drive it without dialogs.
class MainWindow : public QMainWindow {
    Q_OBJECT

  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Each returns false after reporting what went wrong; the open mission is kept on failure.
    bool openMission(const QString& path);
    bool openRaster(const QString& path, const QString& preset = {});
    bool saveMission(const QString& path);
    // Replaces the class table with a CSV file's, as one undoable step; false (and a message) on error.
    bool loadClassTable(const QString& path);
    // Per-robot formats (QGC .plan, WPL, CSV waypoints) write one file per robot: path's stem plus the robot
    // number, unless there is a single robot.
    // formatKey: a key of io::exportFormats(), e.g. "geojson". The files are written in the background
    // (exportFinished says how it went); false when no export could start.
    bool exportPlan(const std::string& formatKey, const QString& path);
    void cancelExport();
    // The robots' autopilot settings in a dialog; one undo step.
    void editVehicles();
    [[nodiscard]] bool isExporting() const;
    bool startPlanning();
    // Runs these planners on the mission one after another in the background; the comparison panel then
    // lists them, and selecting one shows its plan (comparisonFinished says how it went).
    bool startComparison(const std::vector<std::string>& planners);
    [[nodiscard]] bool isComparing() const;
    [[nodiscard]] ComparisonPanel* comparisonPanel() const { return comparisonPanel_; }
    void cancelPlanning();
    [[nodiscard]] bool isPlanning() const;

    // Off: errors and prompts go to the status bar and lastError() instead of message boxes (tests).
    void setDialogsEnabled(bool enabled) { dialogsEnabled_ = enabled; }
    // On (the default): on a first start with nothing open, show and plan the bundled sample mission.
    void setOpenSampleOnFirstStart(bool enabled) { openSampleOnFirstStart_ = enabled; }

    [[nodiscard]] MissionDocument* document() const { return document_; }
    [[nodiscard]] MapCanvas* canvas() const { return canvas_; }
    [[nodiscard]] QUndoStack* undoStack() const { return undoStack_; }
    [[nodiscard]] ClassTableModel* classTableModel() const { return classModel_; }
    [[nodiscard]] RobotTableModel* robotTableModel() const { return robotModel_; }
    [[nodiscard]] QTableView* classTableView() const { return classView_; }
    [[nodiscard]] QTableView* robotTableView() const { return robotView_; }
    [[nodiscard]] ResultsPanel* resultsPanel() const { return resultsPanel_; }
    [[nodiscard]] LayersPanel* layersPanel() const { return layersPanel_; }
    [[nodiscard]] LegendPanel* legendPanel() const { return legendPanel_; }
    [[nodiscard]] PlannerSettingsPanel* plannerSettingsPanel() const { return settingsPanel_; }
    [[nodiscard]] QComboBox* presetCombo() const { return presetCombo_; }
    [[nodiscard]] const QString& lastError() const { return lastError_; }
    [[nodiscard]] const QString& lastStatusMessage() const { return lastStatus_; }
    [[nodiscard]] MessageLog* messageLog() const { return messageLog_; }
    [[nodiscard]] ClassTableBanner* classTableBanner() const { return classTableBanner_; }
    [[nodiscard]] bool isMissionModified() const;
    // Plans only inside the polygons of includePath and outside those of excludePath (vector files; empty
    // for none): the raster is read again with the area, the robots and classes kept, the plan dropped.
    // One undoable edit.
    bool setAreaFiles(const QString& includePath, const QString& excludePath);
    // Applies a class-table preset to the open raster as one undoable edit.
    bool applyPreset(const QString& preset);

  signals:
    void planningFinished(bool success);
    void exportFinished(bool success);
    // A planner of a running comparison is done: its row is in the table, the others' still to come.
    void comparisonProgressed(int plannersDone);
    void comparisonFinished(bool success);

  protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

  private:
    void createDocks();
    void createActions();
    void createStatusBar();
    void connectDocument();
    void addRobotSettings(PlanningProblem& problem) const;
    void showBatteryColumnForBatteryPlanners();
    void restoreSettings();
    void rebuildRecentMenu();
    void updateTitle();
    void updateActions();
    void updateResults();
    // Works out the size of each robot's waypoint files for the results panel, off this thread.
    void sizeWaypointFiles();
    void updateTimeline();
    [[nodiscard]] QWidget* createEventsWidget();
    void syncPresetCombo();
    // Says where the class table of a newly opened raster came from: banner, status bar and message log.
    void explainClassTable(const io::OpeningClassTable& opening);
    // Warns in the banner when the table's smallest FOV makes more cells than this machine can plan, and
    // offers the factor that fits; scaleFieldsOfViewToFit applies it as one undoable edit.
    void updateSizeWarning();
    void logLargeMission(const std::vector<PlannerChoice>& planners);
    void scaleFieldsOfViewToFit();
    void showStatus(const QString& message, int timeoutMilliseconds = 8000);
    void reportError(const QString& title, const QString& message);
    // Save/Discard/Cancel on unsaved changes; true when it is fine to replace the mission.
    bool maybeSave();
    void openFile(const QString& path);
    void openSampleMission(bool plan);
    // The plan beside a mission file (io/PlanFile): written on save when it is up to date, restored on open
    // when the mission's inputs are those it was planned from. Returns a sentence for the status bar.
    // The fingerprint is of the mission as its file holds it (io::planInputsFingerprint).
    QString savePlanBeside(const QString& missionPath, const std::string& fingerprint);
    QString restorePlanBeside(const QString& missionPath, const std::string& fingerprint);
    // A new plan of a saved mission makes the mission modified, so that it is saved with the mission.
    void notePlanToSave();
    // The raster and area files as they were when read (io::inputFilesIdentity), to tell whether they have
    // been rewritten on disk since.
    [[nodiscard]] std::string currentInputFiles() const;
    void rememberInputFiles();
    // Areas drawn on the map (Plan > Draw area of interest / Draw no-go zone) become GeoJSON files: beside
    // a saved mission, else in the application's data folder until the mission is saved.
    void useDrawnArea(const std::vector<MapPoint>& ring);
    // setAreaFiles without the undo step: what the undo steps themselves use.
    bool useAreaFiles(const QString& includePath, const QString& excludePath);
    void pushAreaEdit(io::AreaOfInterest before, const QString& text);
    [[nodiscard]] QString drawnAreaPath(bool exclude) const;
    // Saving a mission copies area files drawn before it had a folder beside it; returns false on failure.
    bool keepDrawnAreasBeside(const QString& missionPath);
    // "  ·  1.55616° N, 7.40209° E" for a point of a map with a CRS, empty otherwise: for the status line.
    [[nodiscard]] QString degreesOf(MapPoint point) const;
    [[nodiscard]] std::string withDegrees(const std::string& message) const;
    void showCursor(MapPoint point);
    void handlePlanningFinished(const PlanningOutcome& outcome);
    void handleExportFinished(const ExportOutcome& outcome);
    void handleComparedPlanner(const ComparisonOutcome& outcomeSoFar);
    void handleComparisonFinished(const ComparisonOutcome& outcome);
    void nameRefusals(ComparisonOutcome& outcome) const;
    [[nodiscard]] FileWarnings waypointFileWarnings() const;
    [[nodiscard]] QString askMissionPath(const QString& title);
    void showComparison(bool raise = true);
    void showWorkUnderway();
    void showComparedPlan(int row);
    void logPlanIssues(const Plan& plan);
    [[nodiscard]] QString longPlanAdvice(double makespanSeconds, std::size_t robots) const;
    void logComparedWarnings();
    // Whether Messages said the plan's too long flights (those of plans gone are forgotten).
    bool flightsSaidOf(const std::shared_ptr<const Plan>& plan);
    void showBusy(const QString& stage, bool busy);
    void placeStart(MapPoint point);
    void removeSelectedRobot();
    void chooseExport(const std::string& formatKey);
    // How messages of the shared mission layer name a field here: robots by name, settings by key.
    // Fields in the window's terms; a parameter as `planner`'s setting (empty: the mission's planner).
    [[nodiscard]] io::FieldNamer fieldNamer(const std::string& planner = {}) const;
    // Why planning failed, a robot's start or a setting named as the window names them, with advice.
    [[nodiscard]] QString planningErrorText(const PlanningOutcome& outcome) const;
    // The robots' names as the robot table holds them, in order.
    [[nodiscard]] std::vector<std::string> robotNames() const;
    [[nodiscard]] QString dialogFolder(const QString& key) const;
    void rememberFolder(const QString& key, const QString& path);

    MissionDocument* document_;
    QUndoStack* undoStack_;
    MapCanvas* canvas_;
    ClassTableModel* classModel_;
    RobotTableModel* robotModel_;
    EventTableModel* eventModel_ = nullptr;
    TimelineBar* timelineBar_ = nullptr;
    PlanningRunner* runner_;
    ExportRunner* exportRunner_;
    ComparisonRunner* comparisonRunner_;
    ComparisonPanel* comparisonPanel_ = nullptr;
    QDockWidget* comparisonDock_ = nullptr;
    QAction* compareAction_ = nullptr;
    QAction* vehiclesAction_ = nullptr;
    QTableView* classView_ = nullptr;
    QTableView* robotView_ = nullptr;
    QComboBox* presetCombo_ = nullptr;
    LayersPanel* layersPanel_ = nullptr;
    LegendPanel* legendPanel_ = nullptr;
    PlannerSettingsPanel* settingsPanel_ = nullptr;
    ResultsPanel* resultsPanel_ = nullptr;
    MessageLog* messageLog_ = nullptr;
    ClassTableBanner* classTableBanner_ = nullptr;
    QLabel* cursorLabel_ = nullptr;
    QLabel* stageLabel_ = nullptr;
    QProgressBar* progressBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QAction* saveAction_ = nullptr;
    QAction* planAction_ = nullptr;
    QAction* cancelAction_ = nullptr;
    QAction* panToolAction_ = nullptr;
    QAction* placeToolAction_ = nullptr;
    QAction* drawAreaAction_ = nullptr;
    QAction* drawNoGoAction_ = nullptr;
    QAction* removeRobotAction_ = nullptr;
    QList<QAction*> exportActions_;
    QString crsName_;
    QString lastError_;
    QString lastStatus_;
    PlanInputs planningInputs_;
    bool exportStale_ = false; // the exported plan was out of date
    ComparisonOutcome comparison_;
    std::vector<PlanInputs> comparisonInputs_; // by compared planner, as it was chosen
    QFutureWatcher<std::vector<io::MissionSize>>* waypointFileSizes_ = nullptr;
    int waypointFileSizesAsked_ = 0; // the last request: an older one's answer is dropped
    std::shared_ptr<const io::LoadedRaster> comparisonRaster_; // the map the comparison ran on
    qint64 planningStartedAt_ = 0;
    bool planningUnderway_ = false;         // from starting a plan to handling its outcome
    bool comparisonUnderway_ = false;       // the same for a comparison
    std::weak_ptr<const Plan> advisedPlan_; // the last plan made here, and what to change for a better one
    std::vector<std::weak_ptr<const Plan>> flightsSaid_; // plans whose too long flights Messages said
    QString planAdvice_;
    bool settingsModified_ = false;
    bool planUnsaved_ = false;
    std::string inputFilesAtLoad_; // a saved mission's new plan, written beside it on the next save
    double fitFactor_ = 0.0;       // FOV factor the banner offers; 0 when the table fits
    bool openingSample_ = false;   // the bundled sample opens as an untitled copy
    bool dialogsEnabled_ = true;
    bool openSampleOnFirstStart_ = true;
};

} // namespace mcpp::ui
