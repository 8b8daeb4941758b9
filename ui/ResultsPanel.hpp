#pragma once

#include "core/model/Plan.hpp"
#include "io/AutopilotMission.hpp"
#include "io/LoadedRaster.hpp"
#include "io/VehicleSettings.hpp"

#include <QStringList>
#include <QWidget>

class QChart;
class QChartView;
class QFormLayout;
class QLabel;
class QScrollArea;
class QSplitter;
class QTableWidget;

namespace mcpp::ui {

// The figures of the last plan: per robot cells, area, length, time and turns; makespan against the lower
// bound; covered and unreachable area; and a bar chart of the robots' times.
class ResultsPanel : public QWidget {
    Q_OBJECT

  public:
    explicit ResultsPanel(QWidget* parent = nullptr);
    // names: robot names by index (may be shorter than the plan's robots); raster: the map planned, whose
    // CRS gives the points the warnings name their degrees.
    void showPlan(const Plan* plan, const QStringList& names, const io::LoadedRaster* raster = nullptr);
    void setStale(bool stale);
    // A note of the window's own beside the plan's (advice on the settings planned with); none if empty.
    void addNote(const QString& note);
    // How big each robot's waypoint files come out with its vehicle's item limit (vehicles: by robot); worked
    // out off the window's thread after each plan, so shown when ready.
    void showWaypointFiles(const std::vector<io::MissionSize>& sizes,
                           const std::vector<io::VehicleSettings>& vehicles, const QStringList& names);

    [[nodiscard]] QTableWidget* robotTable() const { return table_; }
    [[nodiscard]] QString makespanText() const;
    [[nodiscard]] QString ratioText() const;
    [[nodiscard]] QChartView* chartView() const { return chartView_; }

    // "1:02:03" for 3723 s; "4 min 05 s" style is too long for a table column.
    [[nodiscard]] static QString formatDuration(double seconds);
    // Every how many robots the chart numbers a bar: 1, 2, 5, 10, 20, 50... so that at most labelsThatFit
    // numbers stand under the bars.
    [[nodiscard]] static int robotLabelStep(int robots, int labelsThatFit);
    // One line on the robots' waypoint files: "one file per robot, the largest 412 of 700 items", or which
    // robots' missions are split into how many parts.
    [[nodiscard]] static QString waypointFilesText(const std::vector<io::MissionSize>& sizes,
                                                   const std::vector<io::VehicleSettings>& vehicles,
                                                   const QStringList& names);
    // A warning for each robot some of whose flights (or battery runs) take longer than its flight time:
    // missions it cannot fly as planned, said as soon as the plan is made, not only when its waypoint files
    // are written.
    [[nodiscard]] static QStringList flightsTooLongWarnings(const std::vector<io::MissionSize>& sizes,
                                                            const std::vector<io::VehicleSettings>& vehicles,
                                                            const QStringList& names);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void showEvent(QShowEvent* event) override;

  private:
    void describeTimes(bool underEvents);
    void showWarnings(QStringList warnings);
    void describeFieldTimes(const PlanMetrics& metrics);
    void clearChart();
    void showChart(const Plan& plan, const QStringList& names);
    // A bar per robot of chartRobots_, in its colour: seconds by robot of that list.
    void drawBars(const std::vector<double>& seconds, const QString& title);
    void showTimeInTheField(const std::vector<io::MissionSize>& sizes);
    void numberBars();
    void fitSummary();

    QLabel* staleLabel_;
    QScrollArea* summaryArea_; // the figures above the table, scrolled when the dock is too short
    QSplitter* splitter_;      // the figures, the table and the chart
    QTableWidget* table_;
    QLabel* makespan_;
    QLabel* lowerBound_;
    QLabel* ratio_;
    QLabel* covered_;
    QLabel* unreachable_;
    QLabel* planner_;
    QLabel* detection_; // only for plans with a detection layer
    QLabel* timeline_;  // only for plans simulated over time with events
    QFormLayout* summary_;
    QLabel* warnings_;
    QStringList planWarnings_; // the plan's own, before any of its waypoint files' are added
    QLabel* waypointFiles_;    // the size of the robots' waypoint files, once worked out
    QLabel* notes_; // the plan's information issues (a fleet's cruise speed, robots walled in); only if any
    QChartView* chartView_;
    // The robots of the plan charted, their names and path times (or times under the events).
    std::vector<int> chartRobots_;
    QStringList chartNames_;
    std::vector<double> chartPathSeconds_;
    bool chartUnderEvents_ = false;
    QStringList barNumbers_; // robot numbers under the chart's bars, in order
};

} // namespace mcpp::ui
