#pragma once

#include "app/CommandLineOptions.hpp"
#include "app/ProgressPrinter.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "core/model/PlanningProblem.hpp"
#include "io/ComparisonExport.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"
#include "io/MissionInputs.hpp"
#include "io/PlanExport.hpp"

#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace mcpp::app {

// Runs one headless planning job: mission in (file or flags), outputs out, and the batch contract's
// exit code. Needs a QGuiApplication (plan.png is painted with QPainter).
class BatchRunner {
  public:
    BatchRunner(CommandLineOptions options, std::ostream& output, std::ostream& diagnostics);

    // 0 on success, 2 on bad input, 1 on an internal error; the reason is one line on diagnostics.
    [[nodiscard]] int run();

  private:
    void execute();
    // --compare: every named planner on the same mission, one after another.
    void executeComparison();
    // The mission's planner switched to `name`, with the --param values that planner declares.
    [[nodiscard]] PlannerChoice comparedPlanner(const std::string& name) const;
    void assembleMission();
    void applyOverrides();
    // Refuses vehicle settings that cannot fly together (a flight too short for its climb and descent).
    void checkVehicles() const;
    // The robots' names that messages numbering robots add; none for robots given by --start flags.
    [[nodiscard]] std::vector<std::string> robotNamesForMessages() const;
    // A plan's message as batch mode says it: its map points with their degrees, its robots named.
    [[nodiscard]] std::string planMessage(const std::string& message) const;
    void addEventFlags();
    void loadRaster();
    // The mission's part of the problem, the same whatever the planner: classes_, starts_ and chargers_.
    void prepareMission();
    // The problem for mission_.planner, from the mission's part.
    PlanningProblem prepareProblem();
    // Whether any planner of --compare moves starts off obstacles itself (snap_starts_to_free_cells).
    [[nodiscard]] bool someComparedPlannerSnapsStarts() const;
    void checkOutputFolder() const;
    Plan runPlanner(const PlanningProblem& problem);
    // Frees the raster's pixels while the problem holds the same (returns whether it did); they are moved
    // back from the problem after planning.
    bool lendPixelsTo(const PlanningProblem& problem);
    // Every batch output on workerThreads() threads (set from --threads), report.json last.
    void writeOutputs(const Plan& plan, const std::string& folder);
    // partsWritten: the parts of each robot's autopilot files this run wrote, by robot and format key.
    void removeStaleRobotFiles(int robots,
                               const std::map<std::pair<int, std::string>, std::size_t>& partsWritten,
                               const std::string& folder) const;
    // Says when a robot's mission, as written, is above its autopilot's item limit, and when it is also
    // written sortie by sortie.
    void applyVehicleFlags();
    void scaleFieldsOfView(double factor);
    void setFieldsOfView(double metres);
    void warnIfLarge();
    void noteMissionFiles(const io::ExportContext& context, int robot);
    void printSummary(const Plan& plan) const;
    // comparison.csv, comparison.json and comparison.png in the output folder, and the table on stdout.
    void writeComparison(const std::vector<io::ComparisonRow>& rows,
                         const std::vector<std::optional<Plan>>& plans);
    void printComparisonRows(const std::vector<io::ComparisonRow>& rows) const;
    // The notes and warnings held back until the input is known to be good.
    void flushPending();
    void note(const std::string& message);
    void warn(const std::string& message);
    // Refuses the mission's classes or starts, after the warning of a preset of another product, which may
    // be why: its obstacles are that product's classes.
    [[noreturn]] void refuseMission(const std::string& error);
    // saidOnce: in a comparison, the notes of the mission said already (said once, under no planner).
    void sayMissionNotes(const Plan& plan, const PlanningProblem& problem,
                         std::set<std::string>* saidOnce = nullptr);
    void sayComparedPlanWarnings(const Plan& plan, const PlanningProblem& problem,
                                 std::set<std::string>& saidOnce);
    [[nodiscard]] std::string areaGivenIn(const std::string& message) const;
    [[nodiscard]] bool namesNoGoFile(const std::string& message) const;

    // Where a value came from, so errors name the flag or the mission file and field.
    [[nodiscard]] std::string fieldName(const io::MissionField& field) const;
    [[nodiscard]] io::FieldNamer fieldNamer() const;

    CommandLineOptions options_;
    std::ostream& output_;
    std::ostream& diagnostics_;
    ProgressPrinter progress_;
    io::Mission mission_;
    io::LoadedRaster raster_;
    ClassTable classes_;
    std::vector<MapPoint> starts_; // planning frame
    std::vector<std::optional<MapPoint>> chargers_;
    std::vector<std::string> pendingWarnings_;      // printed once the input is known to be good
    std::vector<std::string> pendingNotes_;         // likewise
    std::vector<std::string> inputWarnings_;        // said before planning, for report.json
    std::vector<std::string> plannerWarnings_;      // likewise, of the planner --compare runs
    std::string fieldTimeNote_;                     // with the summary, when missions are written in parts
    std::string fieldBoundNote_;                    // the least time in the field, said after fieldTimeNote_
    std::optional<std::size_t> flightsOverBattery_; // of the plan written last, for its comparison row
    std::string plannerPrefix_; // "darp: " before notes and warnings while --compare runs it
    std::vector<std::pair<std::string, double>> processMilliseconds_; // read_raster, plan
    int exitCode_ = 0;
};

} // namespace mcpp::app
