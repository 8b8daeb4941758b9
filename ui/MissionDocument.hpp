#pragma once

#include "core/model/ClassTable.hpp"
#include "core/model/MapPoint.hpp"
#include "core/model/Plan.hpp"
#include "core/parameters/PlannerChoice.hpp"
#include "io/LoadedRaster.hpp"
#include "io/Mission.hpp"

#include <QObject>
#include <QString>
#include <memory>
#include <optional>
#include <vector>

namespace mcpp::ui {

// The inputs a plan was computed from; a plan is stale once the current inputs differ.
struct PlanInputs {
    ClassTable classes;
    std::vector<MapPoint> starts;
    PlannerChoice planner;
    std::vector<SpeedEvent> events = {};
    std::vector<double> batteries = {}; // each robot's own, 0 where it has none
    std::vector<double> recharges = {}; // each robot's time at its charger (a battery planner's), 0: none
    std::vector<std::optional<MapPoint>> chargers = {};
    // Each robot's cruise speed, which the plan uses over every passable class; 0: the classes'.
    std::vector<double> cruiseSpeeds = {};
    // Where time in the field is measured, what it depends on (the plan's figures there, MCPP-MLCT's
    // division).
    io::FieldTimeInputs fieldTime = {};
    // Which robots fly: an aircraft may take off beside its path.
    std::vector<bool> flyingRobots = {};

    friend bool operator==(const PlanInputs&, const PlanInputs&) = default;
};

// The open mission: raster, class table, robots, planner settings and the last plan. Widgets read it and
// change it only through its setters (undo commands call them), so every view hears about every change.
class MissionDocument : public QObject {
    Q_OBJECT

  public:
    explicit MissionDocument(QObject* parent = nullptr);

    // Replaces everything. The mission supplies band, preset, exports and settings; its robots must already
    // be in the raster's CRS.
    void reset(std::shared_ptr<const io::LoadedRaster> raster, io::Mission mission, QString missionPath);
    void clear();

    [[nodiscard]] bool hasMap() const { return raster_ != nullptr; }
    [[nodiscard]] const io::LoadedRaster* raster() const { return raster_.get(); }
    [[nodiscard]] std::shared_ptr<const io::LoadedRaster> sharedRaster() const { return raster_; }
    [[nodiscard]] const ClassGrid* grid() const { return raster_ ? &raster_->grid : nullptr; }
    [[nodiscard]] const io::Mission& mission() const { return mission_; }
    [[nodiscard]] const ClassTable& classes() const { return mission_.classes; }
    [[nodiscard]] const std::vector<io::RobotSpec>& robots() const { return mission_.robots; }
    [[nodiscard]] const std::vector<SpeedEvent>& events() const { return mission_.events; }
    [[nodiscard]] std::vector<MapPoint> starts() const;
    // Each robot's charger in the planning frame, none where it charges at its start.
    [[nodiscard]] std::vector<std::optional<MapPoint>> chargers() const;
    [[nodiscard]] const PlannerChoice& plannerChoice() const { return mission_.planner; }
    [[nodiscard]] const QString& missionPath() const { return missionPath_; }
    [[nodiscard]] const Plan* plan() const { return plan_.get(); }
    [[nodiscard]] std::shared_ptr<const Plan> sharedPlan() const { return plan_; }
    [[nodiscard]] bool planStale() const;
    [[nodiscard]] PlanInputs currentInputs() const;
    // The inputs as they would be with another planner chosen: what its plan depends on (a battery planner's
    // batteries among them).
    [[nodiscard]] PlanInputs inputsFor(const PlannerChoice& planner) const;

    void setClasses(const ClassTable& classes, const QString& preset);
    void setRobots(std::vector<io::RobotSpec> robots);
    void setEvents(std::vector<SpeedEvent> events);
    void setPlannerChoice(const PlannerChoice& choice);
    void setMissionPath(const QString& path);
    // The waypoint files' settings: the mission's exports and each robot's vehicle (robots otherwise as
    // they are). They shape the exported files, not the plan.
    void setVehicles(const io::ExportSettings& exports, const std::vector<io::VehicleOverrides>& vehicles);
    // The area files' paths only (the same polygons, moved or copied elsewhere): nothing to redraw.
    void setAreaPaths(const io::AreaOfInterest& area) { mission_.area = area; }
    void setPlan(std::shared_ptr<const Plan> plan, PlanInputs inputs);

    // Why a robot cannot start at this point (outside the map, nodata, obstacle class, on another start's
    // pixel), or nothing when it can. ignoreRobot skips one robot when moving it.
    // `what` names the point in the message ("Start" when empty; a charger is checked by the same rule).
    // With takesOff (the robot flies), a point on the raster where a rover cannot start is where it takes
    // off: no problem.
    [[nodiscard]] std::optional<QString> startProblem(MapPoint point, int ignoreRobot = -1,
                                                      const QString& what = {}, bool takesOff = false) const;
    // Whether a robot flies (its vehicle is an aircraft); robot -1: a robot added now, of the mission's
    // vehicle.
    [[nodiscard]] bool robotFlies(int robot) const;
    // The raster value under a point, or nothing outside the map or on nodata.
    [[nodiscard]] std::optional<std::int32_t> classValueAt(MapPoint point) const;
    // "Robot N" with the smallest N not in use.
    [[nodiscard]] QString nextRobotName() const;

  signals:
    void mapChanged();
    void classesChanged();
    void robotsChanged();
    void eventsChanged();
    void settingsChanged();
    void planChanged();
    void staleChanged(bool stale);
    void missionPathChanged(const QString& path);

  private:
    // The advice to a ground robot refused where an aircraft would take off, naming the window's control.
    [[nodiscard]] static QString aircraftHint();
    void emitStaleIfChanged();
    [[nodiscard]] PlanInputs inputsOf(const io::Mission& mission) const;

    std::shared_ptr<const io::LoadedRaster> raster_;
    io::Mission mission_;
    QString missionPath_;
    std::shared_ptr<const Plan> plan_;
    PlanInputs planInputs_;
    bool lastStale_ = false;
};

} // namespace mcpp::ui
