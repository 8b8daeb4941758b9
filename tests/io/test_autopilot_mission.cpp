// Autopilot missions: speeds as a vehicle is told them, and missions split by the autopilot's item limit.

#include "PlanFixture.hpp"
#include "core/coverage/PathMeasurement.hpp"
#include "core/model/HumanUnits.hpp"
#include "io/AutopilotMission.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/StraightLine.hpp"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <filesystem>
#include <random>

using namespace mcpp;
using namespace mcpp::io;

namespace {

// Mission files hold degrees to eight decimals: a point read back lies within half of the last (and a hair
// more, for the rounding's own arithmetic).
constexpr double writtenDegrees = 6e-9;

// A scratch folder of empty files, listed by name.
class FileFolder {
  public:
    [[nodiscard]] std::string path(const std::string& name) const {
        return folder_.filePath(QString::fromStdString(name)).toStdString();
    }
    void touch(const std::string& name) const {
        QFile file(QString::fromStdString(path(name)));
        QVERIFY(file.open(QIODevice::WriteOnly));
    }
    // The files' names, sorted, space-separated.
    [[nodiscard]] QString names() const {
        QStringList names = QDir(folder_.path()).entryList(QDir::Files);
        names.sort();
        return names.join(QLatin1Char(' '));
    }
    [[nodiscard]] std::string root() const { return folder_.path().toStdString(); }

  private:
    QTemporaryDir folder_;
};

// Hand-made paths lie in no cell, so their turns cost nothing.
const CellGraph noTurnPrice;

// A lawnmower path of `rows` rows of `columns` points 10 m apart, each row a land cover of its own speed
// (rows alternate between two speeds) and one point in the middle of every row faster than its row.
CoveragePath lawnmower(int rows, int columns, double slow, double fast) {
    CoveragePath path;
    for (int row = 0; row < rows; ++row) {
        for (int step = 0; step < columns; ++step) {
            const int column = row % 2 == 0 ? step : columns - 1 - step;
            Waypoint waypoint;
            waypoint.x = 301900.0 + 10.0 * column;
            waypoint.y = 4154080.0 + 10.0 * row;
            waypoint.speedMetresPerSecond = row % 2 == 0 ? slow : fast;
            if (step == columns / 2)
                waypoint.speedMetresPerSecond *= 1.05; // inside the default tolerance
            path.waypoints.push_back(waypoint);
        }
    }
    return path;
}

// A waypoint x metres east and y north of the lawnmower's corner, on land crossed at 5 m/s.
void addAtFiveMetresASecond(CoveragePath& path, double x, double y) {
    Waypoint point;
    point.x = 301900.0 + x;
    point.y = 4154080.0 + y;
    point.speedMetresPerSecond = 5.0F;
    path.waypoints.push_back(point);
}

// A multirotor at 5 m/s on 10-minute flights, without an item limit.
VehicleSettings tenMinuteDrone() {
    VehicleSettings drone;
    drone.type = VehicleType::Multirotor;
    drone.cruiseSpeedMetresPerSecond = 5.0;
    drone.maxWaypoints = 0;
    drone.flightTimeSeconds = 600.0;
    return drone;
}

// Whether point p lies on the segment from a to b (within a micrometre).
bool onSegment(const Waypoint& a, const Waypoint& b, const Waypoint& p) {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    const double along = (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
    return std::abs(cross) <= 1e-6 * std::max(length, 1.0) && along >= -1e-9 &&
           along <= length * length + 1e-9;
}

ExportSettings shaping(double speedTolerance, bool mergeCollinear, bool atTurnsOnly = false) {
    ExportSettings settings;
    settings.speedTolerance = speedTolerance;
    settings.mergeCollinear = mergeCollinear;
    settings.speedChangesAtTurnsOnly = atTurnsOnly;
    return settings;
}

// How many parts a mission takes when each is filled to the vehicle's limit before the next begins.
std::size_t partsFilledToTheLimit(const AutopilotMission& mission, const VehicleSettings& vehicle) {
    std::size_t parts = 1;
    int items = itemsBesideWaypoints(vehicle) + 1;
    for (std::size_t point = 1; point < mission.points.size(); ++point) {
        const int added = mission.changesSpeedAt(point) ? 2 : 1;
        if (items + added > vehicle.maxWaypoints) {
            ++parts;
            items = itemsBesideWaypoints(vehicle) + 1;
        }
        items += added;
    }
    return parts;
}

// The fixture plan with its first robot on a 30-row lawnmower in UTM zone 12, to export with `settings`.
struct LawnmowerExport {
    Plan plan = withLawnmower();
    GeoReference reference = GeoReference::fromDefinition("EPSG:26912").value();
    ClassTable classes;
    ExportSettings settings;

    [[nodiscard]] ExportContext context() const { return {plan, reference, classes, settings}; }

    static Plan withLawnmower() {
        Plan plan = test::makeFixturePlan();
        plan.paths[0] = lawnmower(30, 6, 1.0, 2.0);
        return plan;
    }
};

QJsonObject readJson(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

} // namespace

class AutopilotMissionTest : public QObject {
    Q_OBJECT

  private slots:
    // Points on a line of the grid take a shortcut past std::hypot; it must answer as the test for any three
    // points does, ends, repeated points and spacings that are not whole numbers (US survey feet) included.
    void gridLinePointsAreTestedAsAnyOthers() {
        std::mt19937 random(20261126);
        std::uniform_int_distribution<int> step(-3, 3);
        int compared = 0;
        int between = 0;
        for (const double spacing : {10.0, 1.25, 0.3048006096 * 7.0, 0.1}) {
            for (int trial = 0; trial < 20000; ++trial) {
                const bool alongColumn = trial % 2 == 0;
                const double fixed = (alongColumn ? 431215.0 : 5399615.0) + spacing * step(random);
                const double start = (alongColumn ? 5399615.0 : 431215.0) + spacing * step(random);
                Waypoint points[3];
                for (Waypoint& point : points) {
                    const double moving = start + spacing * step(random);
                    point.x = alongColumn ? fixed : moving;
                    point.y = alongColumn ? moving : fixed;
                }
                const bool expected = internal::collinearAndBetweenAnywhere(points[0], points[1], points[2]);
                QCOMPARE(internal::collinearAndBetween(points[0], points[1], points[2]), expected);
                between += expected ? 1 : 0;
                ++compared;
            }
        }
        // Both answers were given many times over.
        QVERIFY(between > compared / 10);
        QVERIFY(between < compared - compared / 10);
    }

    void speedsAreRoundedToTwoSignificantDigits() {
        QCOMPARE(roundedSpeed(0.3168316831), 0.32);
        QCOMPARE(roundedSpeed(12.34), 12.0);
        QCOMPARE(roundedSpeed(8.0), 8.0);
        QCOMPARE(roundedSpeed(0.0549), 0.055);
        QCOMPARE(roundedSpeed(123.4), 120.0);
        QCOMPARE(roundedSpeed(9.96), 10.0);
        QCOMPARE(roundedSpeed(0.0), 0.0);
        QCOMPARE(roundedSpeed(-3.0), 0.0);
    }

    void smallSpeedChangesAreNotCommanded() {
        const CoveragePath path = lawnmower(4, 9, 2.0, 3.0);
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, true), noTurnPrice);
        // Rows alternate 2 and 3 m/s: a change at every row; the 5% bumps inside rows are not commanded.
        int changes = 0;
        for (std::size_t i = 0; i < mission.points.size(); ++i) {
            changes += mission.changesSpeedAt(i) ? 1 : 0;
            const double speed = mission.commandedSpeeds[i];
            QVERIFY2(speed == 2.0 || speed == 3.0, qPrintable(QString::number(speed)));
        }
        QCOMPARE(changes, 3);
        // With no tolerance every rounded change is commanded: into and out of each bump too.
        const AutopilotMission exact = autopilotMission(path, vehicle, shaping(0.0, true), noTurnPrice);
        int exactChanges = 0;
        for (std::size_t i = 0; i < exact.points.size(); ++i)
            exactChanges += exact.changesSpeedAt(i) ? 1 : 0;
        QCOMPARE(exactChanges, 3 + 4 * 2);
        // A cruise speed replaces them all.
        vehicle.cruiseSpeedMetresPerSecond = 5.0;
        const AutopilotMission cruise = autopilotMission(path, vehicle, shaping(0.1, true), noTurnPrice);
        for (std::size_t i = 0; i < cruise.points.size(); ++i)
            QVERIFY(!cruise.changesSpeedAt(i) && cruise.commandedSpeeds[i] == 5.0);
    }

    void mergedPointsLieOnTheFlownPath() {
        const CoveragePath path = lawnmower(6, 11, 1.0, 1.5);
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, true), noTurnPrice);
        QVERIFY(mission.points.size() < path.waypoints.size());
        // Each row keeps its two ends: 12 points.
        QCOMPARE(mission.points.size(), std::size_t{12});
        std::size_t segment = 0;
        for (const Waypoint& original : path.waypoints) {
            while (segment + 1 < mission.points.size() &&
                   !onSegment(mission.points[segment], mission.points[segment + 1], original))
                ++segment;
            QVERIFY2(segment + 1 < mission.points.size(), "an original point is off the mission's path");
        }
    }

    void speedsChangeOnlyAtTurnsWhenAsked() {
        CoveragePath path = lawnmower(6, 11, 2.0, 3.0);
        for (std::size_t i = 0; i < path.waypoints.size(); i += 11)
            path.waypoints[i + 3].speedMetresPerSecond = 0.5; // a patch of mud in every row
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission anywhere = autopilotMission(path, vehicle, shaping(0.1, true), noTurnPrice);
        const AutopilotMission atTurns =
            autopilotMission(path, vehicle, shaping(0.1, true, true), noTurnPrice);
        QVERIFY(anywhere.points.size() > 12);             // the mud's points stay in the middle of rows
        QCOMPARE(atTurns.points.size(), std::size_t{12}); // each row's two ends
        QVERIFY(atTurns.items < anywhere.items);
        // Every leg goes no faster than the slowest land cover along it.
        std::size_t point = 1;
        for (std::size_t i = 1; i < path.waypoints.size(); ++i) {
            if (!onSegment(atTurns.points[point - 1], atTurns.points[point], path.waypoints[i]))
                ++point;
            QVERIFY(point < atTurns.points.size());
            QVERIFY(atTurns.commandedSpeeds[point] <= path.waypoints[i].speedMetresPerSecond);
            QVERIFY(atTurns.commandedSpeeds[point] <= path.waypoints[i - 1].speedMetresPerSecond);
        }
        QCOMPARE(atTurns.commandedSpeeds[1], 0.5);
        // Flown at the slowest speed of every row: six rows of 100 m at 0.5 m/s, five 10 m steps between a
        // 2 and a 3 m/s row at 2 m/s.
        const double expected = 6 * 100.0 / 0.5 + 5 * 10.0 / 2.0;
        QVERIFY2(std::abs(atTurns.seconds - expected) < 1e-9,
                 qPrintable(QStringLiteral("%1 s, expected %2 s").arg(atTurns.seconds).arg(expected)));
        QVERIFY(anywhere.seconds < atTurns.seconds);

        // A dip within the tolerance still sets the leg's speed, rounded down: 1.96 m/s in a 2 m/s row is
        // flown at 1.9, never at 2.
        CoveragePath dip = lawnmower(2, 5, 2.0, 2.0);
        dip.waypoints[2].speedMetresPerSecond = 1.96;
        const AutopilotMission dipped = autopilotMission(dip, vehicle, shaping(0.1, true, true), noTurnPrice);
        QCOMPARE(dipped.commandedSpeeds[1], 1.9);
        // Speeds are floats: 0.7F is 0.69999998807907, and is flown at 0.7, not rounded down to 0.69.
        const CoveragePath slowRows = lawnmower(2, 5, 0.7, 0.7);
        QCOMPARE(
            autopilotMission(slowRows, vehicle, shaping(0.1, true, true), noTurnPrice).commandedSpeeds[1],
            0.7);
        QCOMPARE(roundedDownSpeed(0.3168316831), 0.31);
        QCOMPARE(roundedDownSpeed(0.29), 0.29);
        QCOMPARE(roundedDownSpeed(12.34), 12.0);
        QCOMPARE(roundedDownSpeed(129.0), 120.0);
    }

    void partsJoinUpAndHoldAtMostTheLimit() {
        std::mt19937 random(11);
        for (int trial = 0; trial < 60; ++trial) {
            const int rows = 3 + static_cast<int>(random() % 30);
            const int columns = 2 + static_cast<int>(random() % 12);
            const CoveragePath path = lawnmower(rows, columns, 1.0 + random() % 5, 7.0);
            VehicleSettings vehicle;
            vehicle.type = trial % 3 == 0 ? VehicleType::Multirotor : VehicleType::Rover;
            vehicle.maxWaypoints = minimumMaxWaypoints + static_cast<int>(random() % 40);
            const ExportSettings settings = shaping(0.1, random() % 2 == 0);
            const AutopilotMission mission = autopilotMission(path, vehicle, settings, noTurnPrice);
            QVERIFY(!mission.parts.empty());
            QCOMPARE(mission.parts.front().first, std::size_t{0});
            QCOMPARE(mission.parts.back().last, mission.points.size() - 1);
            for (std::size_t part = 0; part < mission.parts.size(); ++part) {
                const MissionPart& piece = mission.parts[part];
                QVERIFY(piece.last > piece.first);
                QVERIFY2(
                    piece.items <= vehicle.maxWaypoints,
                    qPrintable(
                        QStringLiteral("%1 items, limit %2").arg(piece.items).arg(vehicle.maxWaypoints)));
                if (part > 0)
                    QCOMPARE(piece.first, mission.parts[part - 1].last); // begins where the last one ended
                // Items: what every part holds besides its waypoints, its first point, and each later point
                // with its speed change.
                int items = itemsBesideWaypoints(vehicle) + 1;
                for (std::size_t point = piece.first + 1; point <= piece.last; ++point)
                    items += mission.changesSpeedAt(point) ? 2 : 1;
                QCOMPARE(piece.items, items);
            }
            // As few parts as filling each to the limit gives.
            QCOMPARE(mission.parts.size(), partsFilledToTheLimit(mission, vehicle));
            // As even as they can be: a limit one item below the fullest part needs more parts.
            int fullest = 0;
            for (const MissionPart& piece : mission.parts)
                fullest = std::max(fullest, piece.items);
            if (mission.parts.size() > 1 && fullest - 1 >= minimumMaxWaypoints) {
                VehicleSettings tighter = vehicle;
                tighter.maxWaypoints = fullest - 1;
                QVERIFY(autopilotMission(path, tighter, settings, noTurnPrice).parts.size() >
                        mission.parts.size());
            }
            if (mission.items <= vehicle.maxWaypoints)
                QCOMPARE(mission.parts.size(), std::size_t{1});
        }
    }

    // A robot that flies sorties from its start: each sortie is a part of its own, the very mission it would
    // make alone, or more parts under a tight item limit, none across two sorties; with sorties ending at no
    // one charger, or one sortie, its path is split as any other.
    void sortiesAreTheMissionsParts() {
        CoveragePath path;
        const std::vector<std::pair<double, double>> corners{
            {0, 0},    {200, 0}, {200, 10}, {0, 10},   {0, 0},    {0, 20}, {200, 20},
            {200, 30}, {0, 30},  {0, 40},   {200, 40}, {200, 50}, {0, 50}, {0, 0}};
        for (const auto& [x, y] : corners)
            addAtFiveMetresASecond(path, x, y);
        RobotSorties sorties;
        sorties.sorties = {{0, 4}, {4, 13}};
        QVERIFY(fliesSortiesFromACharger(path, &sorties));
        VehicleSettings drone = tenMinuteDrone();
        const ExportSettings settings = shaping(0.1, true);
        const AutopilotMission mission = sortieMission(path, sorties.sorties, drone, settings, noTurnPrice);
        QCOMPARE(mission.parts.size(), std::size_t{2});
        QCOMPARE(mission.sorties, std::size_t{2});
        QVERIFY(!mission.takeOff);
        int items = 0;
        double seconds = 0.0;
        for (std::size_t sortie = 0; sortie < 2; ++sortie) {
            const AutopilotMission alone =
                autopilotMission(sortiePath(path, sorties.sorties[sortie]), drone, settings, noTurnPrice);
            QCOMPARE(alone.sorties, std::size_t{0}); // one flight, as any path's mission
            const MissionPart& part = mission.parts[sortie];
            QCOMPARE(part.last - part.first + 1, alone.points.size());
            for (std::size_t point = 0; point < alone.points.size(); ++point) {
                QCOMPARE(mission.points[part.first + point].x, alone.points[point].x);
                QCOMPARE(mission.points[part.first + point].y, alone.points[point].y);
            }
            QCOMPARE(part.items, alone.parts.front().items);
            QCOMPARE(part.seconds, alone.parts.front().seconds);
            items += alone.items;
            seconds += alone.seconds;
        }
        QCOMPARE(mission.parts[1].first, mission.parts[0].last + 1); // its own first point, at the charger
        QCOMPARE(mission.items, items);
        QVERIFY(std::abs(mission.seconds - seconds) < 1e-9);

        drone.maxWaypoints = minimumMaxWaypoints;
        const AutopilotMission tight = sortieMission(path, sorties.sorties, drone, settings, noTurnPrice);
        QVERIFY(tight.parts.size() > 2);
        QCOMPARE(tight.sorties, std::size_t{2}); // more parts than sorties
        const std::size_t firstSortieEnds = sortiePath(path, sorties.sorties[0]).waypoints.size();
        for (const MissionPart& part : tight.parts) {
            QVERIFY(part.items <= minimumMaxWaypoints);
            QVERIFY(part.last < firstSortieEnds || part.first >= firstSortieEnds);
        }

        RobotSorties away = sorties;
        away.sorties = {{0, 3}, {3, 12}}; // the second ends away from where the first did: no charger
        QVERIFY(!fliesSortiesFromACharger(path, &away));
        RobotSorties one = sorties;
        one.sorties = {{0, 13}};
        QVERIFY(!fliesSortiesFromACharger(path, &one));
        QVERIFY(!fliesSortiesFromACharger(path, nullptr));
    }

    // A charger away from the start: the first sortie takes off at the start and lands at the charger, with
    // no flight back; the next takes off from the charger and returns to it, and is timed and measured from
    // there.
    void aFirstSortieFromTheStartLandsAtTheCharger() {
        CoveragePath path;
        const std::vector<std::pair<double, double>> corners{
            {0, 0}, {200, 0}, {200, 10}, {0, 10}, {0, 20}, {200, 20}, {200, 30}, {0, 30}, {0, 20}};
        for (const auto& [x, y] : corners)
            addAtFiveMetresASecond(path, x, y);
        RobotSorties sorties;
        sorties.sorties = {{0, 4}, {4, 8}};
        QVERIFY(fliesSortiesFromACharger(path, &sorties));
        VehicleSettings drone = tenMinuteDrone();
        drone.altitudeMetres = 30.0;
        const AutopilotMission mission =
            sortieMission(path, sorties.sorties, drone, shaping(0.1, true), noTurnPrice);
        QVERIFY(mission.firstSortieFromStart);
        QCOMPARE(mission.parts.size(), std::size_t{2});
        const MissionPart& out = mission.parts[0];
        const MissionPart& back = mission.parts[1];
        QCOMPARE(out.home, std::size_t{0});
        QVERIFY(out.landsAtLast);
        QCOMPARE(back.home, back.first);
        QVERIFY(!back.landsAtLast);
        // Both fly 420 m at 5 m/s, climb and descent on top; neither flies to or from anywhere else.
        const double flown = climbAndDescentSeconds(drone) + 420.0 / 5.0;
        QVERIFY2(std::abs(out.seconds - flown) < 1e-9, qPrintable(QString::number(out.seconds)));
        QVERIFY2(std::abs(back.seconds - flown) < 1e-9, qPrintable(QString::number(back.seconds)));
        // Returning to the start instead would add the 20 m back from the charger.
        MissionPart returning = out;
        returning.landsAtLast = false;
        QVERIFY(std::abs(partSeconds(mission, returning, drone, noTurnPrice) - (flown + 20.0 / 5.0)) < 1e-9);
        // The second sortie's farthest point, (200, 30), lies 200 m east and 10 m north of its charger.
        QVERIFY(std::abs(farthestFromHome(mission, back) - std::hypot(200.0, 10.0)) < 1e-9);
        QCOMPARE(mission.homeOf(back).y, path.waypoints[4].y);

        // Under a tight item limit the first sortie takes several parts: those before its last return to
        // the start, and only its last lands at the charger; the second's parts take off from the charger.
        CoveragePath zigzag; // eight rows out to the charger at (0, 80), then a loop from it
        for (int row = 0; row < 8; ++row) {
            addAtFiveMetresASecond(zigzag, row % 2 == 0 ? 0 : 200, 10.0 * row);
            addAtFiveMetresASecond(zigzag, row % 2 == 0 ? 200 : 0, 10.0 * row);
        }
        addAtFiveMetresASecond(zigzag, 0, 80);
        const std::size_t charger = zigzag.waypoints.size() - 1;
        for (const auto& [x, y] :
             std::vector<std::pair<double, double>>{{200, 80}, {200, 90}, {0, 90}, {0, 80}})
            addAtFiveMetresASecond(zigzag, x, y);
        RobotSorties zigzagSorties;
        zigzagSorties.sorties = {{0, charger}, {charger, zigzag.waypoints.size() - 1}};
        QVERIFY(fliesSortiesFromACharger(zigzag, &zigzagSorties));
        drone.maxWaypoints = minimumMaxWaypoints;
        const AutopilotMission tight =
            sortieMission(zigzag, zigzagSorties.sorties, drone, shaping(0.1, true), noTurnPrice);
        const std::size_t secondSortie = charger + 1;
        std::size_t landings = 0;
        for (const MissionPart& part : tight.parts) {
            const bool inFirst = part.last < secondSortie;
            QCOMPARE(part.home, inFirst ? std::size_t{0} : secondSortie);
            QCOMPARE(part.landsAtLast, inFirst && part.last + 1 == secondSortie);
            landings += part.landsAtLast ? 1 : 0;
        }
        QVERIFY(tight.parts.size() > 2);
        QCOMPARE(landings, std::size_t{1});

        RobotSorties elsewhere = sorties;
        elsewhere.sorties = {{0, 4}, {4, 7}}; // the second ends away from the charger
        QVERIFY(!fliesSortiesFromACharger(path, &elsewhere));
    }

    // A robot is done in the field after its flights and a turnaround between each two, a charge between
    // two sorties; with a part's time unknown, so is that.
    void fieldTimeAddsTurnaroundsBetweenParts() {
        AutopilotMission mission;
        mission.parts = {{0, 4, 10, 600.0}, {4, 9, 10, 1300.0}, {9, 12, 8, 450.0}};
        VehicleSettings drone;
        drone.flightTimeSeconds = 1200.0;
        drone.turnaroundSeconds = 240.0;
        const MissionFlights flights = missionFlights(mission, drone);
        QCOMPARE(flights.totalSeconds, 2350.0);
        QCOMPARE(flights.longestSeconds, 1300.0);
        QCOMPARE(flights.overFlightTime, std::size_t{1});
        QCOMPARE(flights.fieldSeconds, 2350.0 + 2 * 240.0);
        drone.flightTimeSeconds = 0.0; // no limit: nothing is over it
        QCOMPARE(missionFlights(mission, drone).overFlightTime, std::size_t{0});
        mission.parts[1].seconds = 0.0; // a speed unknown
        QCOMPARE(missionFlights(mission, drone).fieldSeconds, 0.0);

        // Sorties: the time at the charger before each sortie after the first, the turnaround before a part
        // the item limit cut from its sortie (it does not take off from the sortie's first point).
        AutopilotMission sorties;
        sorties.sorties = 2;
        sorties.rechargeSeconds = 900.0;
        sorties.parts = {{0, 4, 10, 600.0}, {4, 7, 10, 500.0}, {8, 12, 8, 450.0}};
        sorties.parts[1].home = 0;
        sorties.parts[2].home = 8;
        QCOMPARE(missionFlights(sorties, drone).fieldSeconds, 1550.0 + 240.0 + 900.0);
    }

    // Each part fits one flight, trips included, and the parts are as few as filling each flight in turn
    // gives (counted here point by point with partSeconds) and as even as they can be.
    void partsFitTheFlightTime() {
        std::mt19937 random(23);
        for (int trial = 0; trial < 40; ++trial) {
            const CoveragePath path =
                lawnmower(4 + static_cast<int>(random() % 20), 3 + static_cast<int>(random() % 20), 1.0, 1.0);
            VehicleSettings vehicle;
            vehicle.type = trial % 2 == 0 ? VehicleType::Multirotor : VehicleType::Rover;
            vehicle.cruiseSpeedMetresPerSecond = 0.5;
            vehicle.maxWaypoints = 0;
            const ExportSettings settings = shaping(0.1, true);
            const double whole = autopilotMission(path, vehicle, settings, noTurnPrice).seconds;
            // Within reach: a flight three times the longest trip from the start and back.
            double farthest = 0.0;
            for (const Waypoint& point : path.waypoints)
                farthest = std::max(farthest,
                                    std::hypot(point.x - path.waypoints[0].x, point.y - path.waypoints[0].y));
            const double trip =
                isAircraft(vehicle.type) ? 2.0 * farthest / vehicle.cruiseSpeedMetresPerSecond : 0.0;
            vehicle.flightTimeSeconds =
                std::max({minimumFlightTimeSeconds, whole / (2.0 + random() % 5), 3.0 * trip});
            const AutopilotMission mission = autopilotMission(path, vehicle, settings, noTurnPrice);
            QCOMPARE(mission.parts.front().first, std::size_t{0});
            QCOMPARE(mission.parts.back().last, mission.points.size() - 1);
            for (std::size_t part = 0; part < mission.parts.size(); ++part) {
                const MissionPart& piece = mission.parts[part];
                if (part > 0)
                    QCOMPARE(piece.first, mission.parts[part - 1].last);
                QCOMPARE(piece.seconds, partSeconds(mission, piece, vehicle, noTurnPrice));
                QVERIFY2(piece.seconds <= vehicle.flightTimeSeconds,
                         qPrintable(QStringLiteral("%1 s in a %2 s flight")
                                        .arg(piece.seconds)
                                        .arg(vehicle.flightTimeSeconds)));
            }
            // Parts filled one after the other, point by point, to a flight of `limit`.
            const auto filledUpTo = [&](double limit) {
                std::size_t parts = 1;
                for (std::size_t first = 0, last = 1; last < mission.points.size(); ++last) {
                    if (partSeconds(mission, {first, last}, vehicle, noTurnPrice) > limit) {
                        ++parts;
                        first = last - 1;
                    }
                }
                return parts;
            };
            QCOMPARE(mission.parts.size(), filledUpTo(vehicle.flightTimeSeconds));
            // Even: the same points in flights a little shorter than the longest part need more parts.
            double longest = 0.0;
            for (const MissionPart& piece : mission.parts)
                longest = std::max(longest, piece.seconds);
            QVERIFY(filledUpTo(longest * 0.99) > mission.parts.size());
        }
    }

    // A leg longer than a flight is cut along the way: the parts of one straight 10 km leg each fit a
    // 5 min flight and together fly the leg, with no speed change added.
    void longLegsAreCutAlongTheWay() {
        CoveragePath path;
        Waypoint from;
        from.speedMetresPerSecond = 10.0F;
        Waypoint to = from;
        to.x = 10000.0;
        path.waypoints = {from, to};
        VehicleSettings rover;
        rover.flightTimeSeconds = 300.0;
        const AutopilotMission mission = autopilotMission(path, rover, shaping(0.1, true), noTurnPrice);
        QCOMPARE(mission.parts.size(), std::size_t{4}); // 1000 s of flight
        double flown = 0.0;
        for (const MissionPart& part : mission.parts) {
            QVERIFY(part.seconds <= 300.0);
            flown += part.seconds;
        }
        QVERIFY(std::abs(flown - 1000.0) < 1e-6);
        // Pieces of at most a fortieth of a flight (7.5 s, 75 m): a flight at the edge of its working reach,
        // a twentieth of its time left, holds one and the turns at its ends.
        for (std::size_t point = 1; point < mission.points.size(); ++point) {
            QVERIFY(!mission.changesSpeedAt(point));
            QCOMPARE(mission.points[point].y, 0.0);
            QVERIFY(mission.points[point].x - mission.points[point - 1].x <= 75.0 + 1e-6);
        }
        // A flight long enough for the whole leg keeps it whole: no waypoint along it.
        rover.flightTimeSeconds = 1200.0;
        const AutopilotMission whole = autopilotMission(path, rover, shaping(0.1, true), noTurnPrice);
        QCOMPARE(whole.parts.size(), std::size_t{1});
        QCOMPARE(whole.points.size(), std::size_t{2});
    }

    // Ground out of one flight's reach: its parts take longer than the flight (the warning's case), but each
    // holds a flight's work, not two points.
    void groundOutOfReachTakesAFlightOfWorkAPart() {
        CoveragePath path = lawnmower(20, 30, 5.0, 5.0); // 10 m steps at 5 m/s: 2 s a step
        Waypoint home = path.waypoints.front();
        home.x -= 20000.0; // 4000 s away at 5 m/s
        path.waypoints.insert(path.waypoints.begin(), home);
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.maxWaypoints = 0;
        drone.flightTimeSeconds = 600.0;
        const AutopilotMission mission = autopilotMission(path, drone, shaping(0.1, true), noTurnPrice);
        // 4000 s out to the lawnmower and 1198 s over it (599 steps): at least 9 flights of 600 s of work.
        QVERIFY2(mission.parts.size() >= 9 && mission.parts.size() <= 11,
                 qPrintable(QStringLiteral("%1 parts").arg(mission.parts.size())));
        // The first flies out 300 s and back; the others cannot come back in time.
        QVERIFY(mission.parts.front().seconds <= drone.flightTimeSeconds);
        for (std::size_t part = 1; part < mission.parts.size(); ++part)
            QVERIFY(mission.parts[part].seconds > drone.flightTimeSeconds);
    }

    // Ground out of reach, then ground near the start: the parts out of reach end where ground within
    // reach begins again, so that every flight over the near ground fits.
    void partsOutOfReachEndWhereFlightsFitAgain() {
        CoveragePath path;
        const auto add = [&path](double x, double y) { addAtFiveMetresASecond(path, x, y); };
        add(0.0, 0.0); // the start
        for (int row = 0; row < 2;
             ++row) { // 1.7 km out, beyond the 1.42 km a flight reaches and returns from
            add(row % 2 == 0 ? 0.0 : 100.0, 1700.0 + 10.0 * row);
            add(row % 2 == 0 ? 100.0 : 0.0, 1700.0 + 10.0 * row);
        }
        for (int row = 0; row < 20; ++row) { // 100 to 290 m out
            add(row % 2 == 0 ? 0.0 : 400.0, 100.0 + 10.0 * row);
            add(row % 2 == 0 ? 400.0 : 0.0, 100.0 + 10.0 * row);
        }
        const VehicleSettings drone = tenMinuteDrone();
        const AutopilotMission mission = autopilotMission(path, drone, shaping(0.1, true), noTurnPrice);
        int tooLong = 0;
        int nearFlights = 0;
        for (const MissionPart& part : mission.parts) {
            tooLong += part.seconds > drone.flightTimeSeconds ? 1 : 0;
            bool near = false;
            for (std::size_t point = part.first + 1; point <= part.last; ++point)
                near = near || mission.points[point].y - mission.points[0].y < 500.0;
            if (!near)
                continue;
            ++nearFlights;
            QVERIFY2(part.seconds <= drone.flightTimeSeconds,
                     qPrintable(QStringLiteral("a part over the near ground takes %1 s").arg(part.seconds)));
        }
        QVERIFY(tooLong > 0);      // the far ground is out of reach
        QVERIFY(nearFlights >= 3); // 8 km of near ground: several flights
    }

    // Ground near the edge of the reach fits a flight only a little at a time: evening the parts out must not
    // merge those flights into a few out of reach, as many short parts out of reach are already.
    void partsNearTheEdgeOfTheReachStayFlights() {
        CoveragePath path;
        const auto add = [&path](double x, double y) { addAtFiveMetresASecond(path, x, y); };
        // Lines north and south, 1.1 to 1.55 km north of the take-off: each crosses the 1.42 km a flight
        // reaches, so the ground out of reach comes in many short stretches between flights that fit.
        for (int column = 0; column < 30; ++column) {
            add(10.0 * column, column % 2 == 0 ? 1100.0 : 1550.0);
            add(10.0 * column, column % 2 == 0 ? 1550.0 : 1100.0);
        }
        path.takeOff = MapPoint{301900.0, 4154080.0};
        const VehicleSettings drone = tenMinuteDrone();
        const AutopilotMission mission = autopilotMission(path, drone, shaping(0.1, true), noTurnPrice);
        int tooLong = 0;
        for (const MissionPart& part : mission.parts) {
            if (part.seconds <= drone.flightTimeSeconds)
                continue;
            ++tooLong;
            // Over the flight time only where a flight of its first leg alone would be: out of reach.
            const double firstLeg = partSeconds(mission, {part.first, part.first + 1, 0}, drone, noTurnPrice);
            QVERIFY2(
                firstLeg > drone.flightTimeSeconds,
                qPrintable(QStringLiteral("a part of %1 s from point %2, whose first leg alone is a flight "
                                          "of %3 s")
                               .arg(part.seconds)
                               .arg(part.first)
                               .arg(firstLeg)));
        }
        QVERIFY2(tooLong >= 10, qPrintable(QString::number(tooLong))); // each line's far end is out of reach
        QVERIFY(mission.parts.size() > static_cast<std::size_t>(tooLong) + 10); // and flights between them
    }

    void partsAreEvenNotFilledOneAfterTheOther() {
        // 800 waypoints, no speed change: 2 + 800 items at a 700 limit fill one part of 700 and leave one
        // of about 100; even parts hold about 400 each.
        CoveragePath path = lawnmower(40, 20, 1.0, 1.0);
        VehicleSettings vehicle;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, false), noTurnPrice);
        QCOMPARE(mission.parts.size(), std::size_t{2});
        QVERIFY2(
            std::abs(mission.parts[0].items - mission.parts[1].items) <= 1,
            qPrintable(
                QStringLiteral("%1 and %2 items").arg(mission.parts[0].items).arg(mission.parts[1].items)));
    }

    void noLimitKeepsOnePart() {
        const CoveragePath path = lawnmower(40, 20, 1.0, 2.0);
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, false), noTurnPrice);
        QCOMPARE(mission.parts.size(), std::size_t{1});
        QCOMPARE(mission.points.size(), path.waypoints.size());
        QCOMPARE(mission.items, 2 + 800 + 39); // home, first speed, waypoints, a change per row
    }

    void partFileNames() {
        QCOMPARE(missionPartPath("out/robot_1.plan", 0, 3), std::string("out/robot_1_part_1.plan"));
        QCOMPARE(missionPartPath("robot_12.waypoints", 2, 9), std::string("robot_12_part_3.waypoints"));
        // Padded to the width of the last part's number, so that a file list sorts parts as they are flown.
        QCOMPARE(missionPartPath("robot_1.plan", 2, 12), std::string("robot_1_part_03.plan"));
        QCOMPARE(missionPartPath("robot_1.plan", 11, 12), std::string("robot_1_part_12.plan"));
        QCOMPARE(missionPartPath("robot_1.plan", 6, 100), std::string("robot_1_part_007.plan"));
        QCOMPARE(missionSortiePath("out/robot_2.plan", 0, 10), std::string("out/robot_2_sortie_01.plan"));
        QCOMPARE(missionSortiePath("out/robot_2.plan", 1, 2), std::string("out/robot_2_sortie_2.plan"));
    }

    // An export in 12 parts after one in 3, then in 3 again, then whole: each time only its own files stay,
    // whatever the padding of the earlier ones; other robots' and other formats' files are left alone.
    void staleFilesOfAnotherPaddingGo() {
        const FileFolder folder;
        const std::string whole = folder.path("robot_1.plan");
        const auto touch = [&](const std::string& name) { folder.touch(name); };
        const auto left = [&] { return folder.names(); };
        for (const char* other :
             {"robot_11_part_1.plan", "robot_1_part_1.waypoints", "robot_1.csv", "notes.txt"})
            touch(other);
        const QString others =
            QStringLiteral("notes.txt robot_11_part_1.plan robot_1.csv robot_1_part_1.waypoints");
        const auto write = [&](std::size_t parts) {
            for (std::size_t part = 0; part < parts; ++part)
                touch(std::filesystem::path(missionPartPath(whole, part, parts)).filename().string());
        };
        write(3);
        touch("robot_1.plan");
        QVERIFY(removeStaleMissionFiles(whole, 3)); // the whole file of an earlier export
        write(12);
        QVERIFY(removeStaleMissionFiles(whole, 12));
        QVERIFY2(!left().contains(QStringLiteral("robot_1_part_1.plan")), qPrintable(left()));
        QVERIFY2(left().contains(QStringLiteral("robot_1_part_01.plan")), qPrintable(left()));
        QCOMPARE(left().count(QStringLiteral(".plan")), 12 + 1);
        write(3);
        QVERIFY(removeStaleMissionFiles(whole, 3));
        const auto sorted = [](QStringList names) {
            names.sort();
            return names.join(QLatin1Char(' '));
        };
        QStringList expected = others.split(QLatin1Char(' '));
        QCOMPARE(left(), sorted(expected + QStringList{QStringLiteral("robot_1_part_1.plan"),
                                                       QStringLiteral("robot_1_part_2.plan"),
                                                       QStringLiteral("robot_1_part_3.plan")}));
        touch("robot_1.plan");
        QVERIFY(removeStaleMissionFiles(whole, 1));
        QVERIFY(!removeStaleMissionFiles(whole, 1)); // nothing more to remove
        expected << QStringLiteral("robot_1.plan");
        QCOMPARE(left(), sorted(expected));

        // Sorties: a sortie written in parts only, in another padding, goes with its parts.
        for (const char* sortie : {"robot_1_sortie_1.plan", "robot_1_sortie_2_part_1.plan",
                                   "robot_1_sortie_2_part_2.plan", "robot_1_sortie_01.plan"})
            touch(sortie);
        removeStaleSortieFiles(whole, 0);
        QCOMPARE(left(), sorted(expected));
    }

    // Robots' files are numbered to the width of the last robot's number; a run of 3 robots after one of 12
    // in the same folder leaves its own files only, those of other robots and paddings going with their
    // parts and sorties; other formats' files and other files are left alone.
    void robotFilesArePaddedAndStaleOnesGo() {
        QCOMPARE(robotFileStem(0, 1), std::string("robot_1"));
        QCOMPARE(robotFileStem(8, 9), std::string("robot_9"));
        QCOMPARE(robotFileStem(1, 12), std::string("robot_02"));
        QCOMPARE(robotFileStem(11, 12), std::string("robot_12"));
        QCOMPARE(robotFileStem(4, 100), std::string("robot_005"));
        QCOMPARE(robotFileStem(12, 12), std::string("robot_13")); // past the count: its own width
        const FileFolder folder;
        const auto touch = [&](const std::string& name) { folder.touch(name); };
        const auto left = [&] { return folder.names(); };
        for (int robot = 0; robot < 12; ++robot)
            touch(robotFileStem(robot, 12) + ".plan");
        for (const char* other : {"robot_05_part_1.plan", "robot_05_part_2.plan", "robot_11_sortie_1.plan",
                                  "robot_12_sortie_2_part_1.plan", "robot_1.csv", "robot_one.plan",
                                  "robot_2_notes.plan", "notes.txt"})
            touch(other);
        removeStaleRobotFiles(folder.root(), "plan", 12);
        QCOMPARE(left().count(QStringLiteral(".plan")), 12 + 6);
        for (int robot = 0; robot < 3; ++robot)
            touch(robotFileStem(robot, 3) + ".plan");
        removeStaleRobotFiles(folder.root(), "plan", 3);
        QCOMPARE(left(), QStringLiteral("notes.txt robot_1.csv robot_1.plan robot_2.plan robot_2_notes.plan "
                                        "robot_3.plan robot_one.plan"));
    }

    void splitFilesAreWrittenAndJoinUp() {
        LawnmowerExport lawnmowerExport;
        lawnmowerExport.settings.vehicle.maxWaypoints = 25;
        const ExportContext context = lawnmowerExport.context();
        const GeoReference& reference = lawnmowerExport.reference;
        QTemporaryDir folder;
        const QString whole = folder.filePath(QStringLiteral("robot_1.plan"));
        const Status written = writeQGroundControlPlan(context, 0, whole.toStdString());
        QVERIFY2(written.ok(), written.error().c_str());
        QVERIFY(!QFileInfo::exists(whole)); // a mission the autopilot cannot hold is not written whole
        const AutopilotMission mission = autopilotMissionOf(context, 0);
        QVERIFY(mission.parts.size() > 2);
        // The mission's points are placed on WGS84 once for all its files: each part holds its own slice.
        std::vector<MapPoint> missionPoints;
        for (const Waypoint& point : mission.points)
            missionPoints.push_back({point.x, point.y});
        const std::vector<LonLat> lonLats = reference.toWgs84(missionPoints).value();
        QJsonArray previousLast;
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            const QString path =
                QString::fromStdString(missionPartPath(whole.toStdString(), part, mission.parts.size()));
            const QJsonObject file = readJson(path);
            const QJsonArray items = file["mission"].toObject()["items"].toArray();
            QVERIFY2(!items.isEmpty(), qPrintable(path));
            QCOMPARE(static_cast<int>(items.size()) + 1, mission.parts[part].items); // + home
            QCOMPARE(items[0].toObject()["command"].toInt(), 178);                   // its starting speed
            QJsonArray first, last;
            std::size_t point = mission.parts[part].first;
            for (const QJsonValue& item : items) {
                if (item.toObject()["command"].toInt() != 16)
                    continue;
                if (first.isEmpty())
                    first = item.toObject()["params"].toArray();
                last = item.toObject()["params"].toArray();
                QVERIFY(std::abs(last[4].toDouble() - lonLats[point].latitude) <= writtenDegrees);
                QVERIFY(std::abs(last[5].toDouble() - lonLats[point].longitude) <= writtenDegrees);
                ++point;
            }
            QCOMPARE(point, mission.parts[part].last + 1);
            if (part > 0) {
                QCOMPARE(first[4].toDouble(), previousLast[4].toDouble());
                QCOMPARE(first[5].toDouble(), previousLast[5].toDouble());
            }
            previousLast = last;
        }
        QVERIFY(!QFileInfo::exists(QString::fromStdString(
            missionPartPath(whole.toStdString(), mission.parts.size(), mission.parts.size()))));

        // The waypoint list of the same robot: the same parts, home and first speed rows included in the
        // limit.
        const QString list = folder.filePath(QStringLiteral("robot_1.waypoints"));
        QVERIFY(writeWaypointList(context, 0, list.toStdString()).ok());
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            QFile file(
                QString::fromStdString(missionPartPath(list.toStdString(), part, mission.parts.size())));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const int rows = static_cast<int>(file.readAll().count('\n')) - 1; // less the header
            QCOMPARE(rows, mission.parts[part].items);
        }

        // The report says so among its issues, for scripts that read it rather than what the run printed.
        const QString report = folder.filePath(QStringLiteral("report.json"));
        QVERIFY(writeReportJson(context, report.toStdString()).ok());
        QStringList splitMessages;
        for (const QJsonValue& issue : readJson(report)["issues"].toArray())
            if (issue.toObject()["code"].toString() == QStringLiteral("mission-split"))
                splitMessages << issue.toObject()["message"].toString();
        QCOMPARE(splitMessages.size(), 1);
        QVERIFY2(splitMessages[0].contains(
                     QStringLiteral("robot_1_part_1.plan to robot_1_part_%1.plan").arg(mission.parts.size())),
                 qPrintable(splitMessages[0]));
        QVERIFY(splitMessages[0].contains(QStringLiteral(".waypoints")));
        // The parts' times in all: a rover's ("take", it does not fly), with no trips and no turns, the
        // mission's time.
        QVERIFY2(splitMessages[0].contains(QStringLiteral("the parts take %1 in all, the longest")
                                               .arg(QString::fromStdString(formatDuration(mission.seconds)))),
                 qPrintable(splitMessages[0]));
        // Each part's own flight time, for a battery.
        const QJsonArray partTimes =
            readJson(report)["robots"].toArray()[0].toObject()["mission_part_seconds"].toArray();
        QCOMPARE(static_cast<std::size_t>(partTimes.size()), mission.parts.size());
        double total = 0.0;
        for (const QJsonValue& seconds : partTimes) {
            QVERIFY(seconds.toDouble() > 0.0);
            total += seconds.toDouble();
        }
        QVERIFY(std::abs(total - mission.seconds) < 1e-6 * mission.seconds); // a rover: no trips, no turns
        // Each part's items, as its waypoint list holds them (home and first speed rows included).
        const QJsonArray partItems =
            readJson(report)["robots"].toArray()[0].toObject()["mission_part_items"].toArray();
        QCOMPARE(static_cast<std::size_t>(partItems.size()), mission.parts.size());
        for (std::size_t part = 0; part < mission.parts.size(); ++part)
            QCOMPARE(partItems[static_cast<qsizetype>(part)].toInt(), mission.parts[part].items);
        QCOMPARE(readJson(report)["robots"].toArray()[0].toObject()["mission_flights_s"].toDouble(), total);
    }

    // A part's flight: its legs at their commanded speeds; an aircraft's also its climb, the trips from home
    // and back, and its descent.
    void partSecondsCountTheTripsToAndFromHome() {
        AutopilotMission mission;
        const auto at = [](double x, double y) {
            Waypoint point;
            point.x = x;
            point.y = y;
            return point;
        };
        mission.points = {at(0, 0), at(100, 0), at(100, 100), at(0, 100)};
        mission.commandedSpeeds = {10.0, 10.0, 5.0, 5.0};
        const MissionPart second{1, 2, 0};
        VehicleSettings rover;
        QCOMPARE(partSeconds(mission, second, rover, noTurnPrice), 20.0); // 100 m at 5 m/s
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.altitudeMetres = 60.0;
        // Up to 60 m at 2.5 m/s, out to (100, 0) at 10 m/s, on at 5 m/s, back from (100, 100) at 5 m/s, and
        // down at 1.5 m/s.
        const double expected = 24.0 + 10.0 + 20.0 + std::hypot(100.0, 100.0) / 5.0 + 40.0;
        QVERIFY(std::abs(partSeconds(mission, second, drone, noTurnPrice) - expected) < 1e-9);
        // Taking off 50 m west of the first point (outside the task area): out from there, back to there.
        mission.takeOff = MapPoint{-50.0, 0.0};
        const double fromAfar = 24.0 + 15.0 + 20.0 + std::hypot(150.0, 100.0) / 5.0 + 40.0;
        QVERIFY(std::abs(partSeconds(mission, second, drone, noTurnPrice) - fromAfar) < 1e-9);
        // The first part too flies out to its first point: 50 m at 10 m/s.
        const MissionPart first{0, 1, 0};
        const double firstFromAfar = 24.0 + 5.0 + 10.0 + 15.0 + 40.0;
        QVERIFY(std::abs(partSeconds(mission, first, drone, noTurnPrice) - firstFromAfar) < 1e-9);
        mission.takeOff.reset();
        mission.commandedSpeeds[2] = 0.0;
        QCOMPARE(partSeconds(mission, second, drone, noTurnPrice), 0.0); // a speed unknown
    }

    // Turns are priced as the plan prices them: one part of a whole mission takes the mission's time.
    void partSecondsPriceTurnsAsThePlanDoes() {
        Plan plan = test::makeFixturePlan();
        TurnTimeModel turns;
        turns.fixedSecondsPer90Degrees = 2.0;
        plan.cells.applyTurnTime(turns);
        CoveragePath path = plan.paths[0];
        measurePath(path, plan.cells);
        QVERIFY(path.turnSeconds > 0.0);
        VehicleSettings rover;
        rover.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, rover, shaping(0.0, true), plan.cells);
        QCOMPARE(mission.parts.size(), std::size_t{1});
        const double seconds = partSeconds(mission, mission.parts[0], rover, plan.cells);
        QVERIFY2(std::abs(seconds - mission.seconds) < 1e-9 * mission.seconds,
                 qPrintable(QStringLiteral("%1 s, the mission %2 s").arg(seconds).arg(mission.seconds)));
    }

    // Flights that cannot fit are named with the distance that makes them too long and one flight's reach.
    void flightsOutOfReachAreNamed() {
        LawnmowerExport lawnmowerExport;
        VehicleSettings& drone = lawnmowerExport.settings.vehicle;
        drone.type = VehicleType::Multirotor;
        drone.cruiseSpeedMetresPerSecond = 1.0;
        drone.maxWaypoints = 0;
        drone.flightTimeSeconds = 60.0; // 12 s up to 30 m, 20 s down: 14 m out and 14 m back
        QCOMPARE(flightReachMetres(drone), 14.0);
        const ExportContext context = lawnmowerExport.context();
        const AutopilotMission& mission = autopilotMissionOf(context, 0);
        double farthest = 0.0;
        for (const Waypoint& point : mission.points)
            farthest =
                std::max(farthest, std::hypot(point.x - mission.points[0].x, point.y - mission.points[0].y));
        const std::string warning = flightTimeWarning(context, 0, "robot_1.plan");
        // The parts too long are named by file, the first three of them, in order.
        std::vector<std::string> over;
        for (std::size_t part = 0; part < mission.parts.size(); ++part)
            if (exceedsFlightTime(mission.parts[part], drone))
                over.push_back(missionPartPath("robot_1.plan", part, mission.parts.size()));
        QVERIFY(over.size() > 3);
        const std::string named = " (" + over[0] + ", " + over[1] + ", " + over[2] + " and " +
                                  std::to_string(over.size() - 3) + " more; fits_flight 0";
        QVERIFY2(warning.find(named) != std::string::npos, (warning + "\nwanted: " + named).c_str());
        const std::string lead =
            flightsTooLongLead(context.robotName(0), drone, mission.parts.size(), over.size(),
                               missionFlights(mission, drone).longestSeconds);
        QVERIFY2(warning.rfind(lead + ": ", 0) == 0, (warning + "\nwanted first: " + lead).c_str());
        QVERIFY2(warning.find(
                     "its farthest waypoint lies " + formatDistance(farthest) +
                     " from its start, and one flight at 1 m/s goes at most 14 m from its start and back") !=
                     std::string::npos,
                 warning.c_str());
        // Flights long enough for the whole mission: nothing to say.
        lawnmowerExport.settings.vehicle.flightTimeSeconds = 3600.0 * 10.0;
        QVERIFY(flightTimeWarning(lawnmowerExport.context(), 0, "robot_1.plan").empty());
        drone.type = VehicleType::Rover;
        QCOMPARE(flightReachMetres(drone), 0.0);
    }

    // The window and the exports say it in one sentence: flights for an aircraft, mission parts for a rover,
    // one verb for one part, and what to do that suits the vehicle.
    void flightsTooLongAreSaidAlike() {
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.flightTimeSeconds = 20.0 * 60.0;
        QCOMPARE(
            flightsTooLongLead("Robot 1", drone, 883, 305, 4140.0),
            std::string("Robot 1: 305 of its 883 flights take up to 1 h 9 min with the flights to and from "
                        "its start, longer than its 20 min flight time"));
        QCOMPARE(flightsTooLongLead("Robot 1", drone, 4, 1, 1500.0).substr(0, 44),
                 std::string("Robot 1: 1 of its 4 flights takes up to 25 m"));
        QCOMPARE(flightsTooLongLead("Robot 1", drone, 1, 1, 1500.0).substr(0, 39),
                 std::string("Robot 1: its mission takes 25 min with "));
        VehicleSettings rover = drone;
        rover.type = VehicleType::Rover;
        QCOMPARE(
            flightsTooLongLead("north", rover, 4, 2, 1500.0),
            std::string("north: 2 of its 4 mission parts take up to 25 min, longer than its 20 min battery "
                        "time"));
        QVERIFY(flightsTooLongAdvice(drone).find("start them nearer") != std::string::npos);
        QVERIFY(flightsTooLongAdvice(rover).find("start them nearer") == std::string::npos);
        QVERIFY(flightsTooLongCause(drone) != flightsTooLongCause(rover));
    }

    void flightsTooShortForTheClimbAreRefused() {
        VehicleSettings drone;
        drone.type = VehicleType::Multirotor;
        drone.altitudeMetres = 120.0;
        drone.flightTimeSeconds = 60.0;
        QCOMPARE(climbAndDescentSeconds(drone), 120.0 / 2.5 + 120.0 / 1.5); // 48 s up, 80 s down
        const auto problem = flightTooShortProblem(drone);
        QVERIFY(problem.has_value());
        QVERIFY2(
            problem->find("a flight of 1 min leaves no time to survey: climbing to 120 m and coming back "
                          "down take 2 min 8 s") != std::string::npos,
            problem->c_str());
        drone.flightTimeSeconds = 129.0; // a second of survey left: short, but a flight
        QVERIFY(!flightTooShortProblem(drone));
        drone.flightTimeSeconds = 0.0; // no limit
        QVERIFY(!flightTooShortProblem(drone));
        VehicleSettings rover = drone;
        rover.type = VehicleType::Rover;
        rover.flightTimeSeconds = 60.0;
        QCOMPARE(climbAndDescentSeconds(rover), 0.0);
        QVERIFY(!flightTooShortProblem(rover));
    }

    void aircraftTakeOffAtTheStartAndReturnToItInEveryPart() {
        LawnmowerExport lawnmowerExport;
        lawnmowerExport.settings.vehicle.type = VehicleType::Multirotor;
        lawnmowerExport.settings.vehicle.altitudeMetres = 45.0;
        lawnmowerExport.settings.vehicle.maxWaypoints = 40;
        const ExportContext context = lawnmowerExport.context();
        const GeoReference& reference = lawnmowerExport.reference;
        QTemporaryDir folder;
        const QString whole = folder.filePath(QStringLiteral("robot_1.plan"));
        QVERIFY(writeQGroundControlPlan(context, 0, whole.toStdString()).ok());
        const AutopilotMission mission = autopilotMissionOf(context, 0);
        QVERIFY(mission.parts.size() > 2);
        const LonLat start = reference.toWgs84({{mission.points[0].x, mission.points[0].y}}).value().front();
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            const QString path =
                QString::fromStdString(missionPartPath(whole.toStdString(), part, mission.parts.size()));
            const QJsonObject plannedMission = readJson(path)["mission"].toObject();
            QCOMPARE(plannedMission["vehicleType"].toInt(), 2); // a quadrotor
            const QJsonArray home = plannedMission["plannedHomePosition"].toArray();
            QVERIFY(std::abs(home[0].toDouble() - start.latitude) <=
                    writtenDegrees); // every part's home is the robot's start
            QVERIFY(std::abs(home[1].toDouble() - start.longitude) <= writtenDegrees);
            const QJsonArray items = plannedMission["items"].toArray();
            QCOMPARE(static_cast<int>(items.size()) + 1, mission.parts[part].items);
            const QJsonObject takeoff = items.first().toObject();
            QCOMPARE(takeoff["command"].toInt(), 22);
            QVERIFY(std::abs(takeoff["params"].toArray()[4].toDouble() - start.latitude) <= writtenDegrees);
            QCOMPARE(takeoff["params"].toArray()[6].toDouble(), 45.0);
            QCOMPARE(items[2].toObject()["command"].toInt(), 16); // waypoints at the aircraft's altitude
            QCOMPARE(items[2].toObject()["Altitude"].toDouble(), 45.0);
            QCOMPARE(items[1].toObject()["command"].toInt(), 178);    // then the speed the part starts at
            QCOMPARE(items.last().toObject()["command"].toInt(), 20); // and back to launch at the end
            QCOMPARE(items.last().toObject()["frame"].toInt(), 2);
        }
        const QString list = folder.filePath(QStringLiteral("robot_1.waypoints"));
        QVERIFY(writeWaypointList(context, 0, list.toStdString()).ok());
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            QFile file(
                QString::fromStdString(missionPartPath(list.toStdString(), part, mission.parts.size())));
            QVERIFY(file.open(QIODevice::ReadOnly));
            QList<QByteArrayList> rows;
            for (const QByteArray& line : file.readAll().split('\n').mid(1))
                if (!line.isEmpty())
                    rows.push_back(line.split('\t'));
            QCOMPARE(static_cast<int>(rows.size()), mission.parts[part].items);
            QVERIFY(std::abs(rows[0][8].toDouble() - start.latitude) < 1e-8); // home, to 8 decimals
            QCOMPARE(rows[1][3], QByteArray("22"));
            QCOMPARE(rows[3][3], QByteArray("16"));
            QCOMPARE(rows[3][10].toDouble(), 45.0);
            QCOMPARE(rows.last()[3], QByteArray("20"));
            for (const QByteArrayList& row : rows)
                if (row[3] == "178")
                    QCOMPARE(row[2], QByteArray("2")); // a command, not a place: the mission frame
        }
    }

    // An aircraft taking off outside the task area (a road beside it): every part's home and take-off are
    // there, and its waypoints are the path's as before.
    void anAircraftTakingOffElsewhereFliesFromThere() {
        LawnmowerExport lawnmowerExport;
        lawnmowerExport.settings.vehicle.type = VehicleType::Multirotor;
        lawnmowerExport.settings.vehicle.altitudeMetres = 45.0;
        lawnmowerExport.settings.vehicle.maxWaypoints = 40;
        const Waypoint& first = lawnmowerExport.plan.paths[0].waypoints.front();
        const MapPoint road{first.x - 30.0, first.y + 5.0};
        lawnmowerExport.plan.paths[0].takeOff = road;
        const ExportContext context = lawnmowerExport.context();
        QTemporaryDir folder;
        const QString whole = folder.filePath(QStringLiteral("robot_1.plan"));
        QVERIFY(writeQGroundControlPlan(context, 0, whole.toStdString()).ok());
        const AutopilotMission mission = autopilotMissionOf(context, 0);
        QVERIFY(mission.parts.size() > 2);
        QVERIFY(mission.points[0].x == first.x && mission.points[0].y == first.y);
        const LonLat takeOff = lawnmowerExport.reference.toWgs84({{road}}).value().front();
        const LonLat pathStart = lawnmowerExport.reference.toWgs84({{{first.x, first.y}}}).value().front();
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            const QString path =
                QString::fromStdString(missionPartPath(whole.toStdString(), part, mission.parts.size()));
            const QJsonObject plannedMission = readJson(path)["mission"].toObject();
            const QJsonArray home = plannedMission["plannedHomePosition"].toArray();
            QVERIFY(std::abs(home[0].toDouble() - takeOff.latitude) <= writtenDegrees);
            QVERIFY(std::abs(home[1].toDouble() - takeOff.longitude) <= writtenDegrees);
            const QJsonArray items = plannedMission["items"].toArray();
            QVERIFY(std::abs(items.first().toObject()["params"].toArray()[4].toDouble() - takeOff.latitude) <=
                    writtenDegrees);
            if (part == 0) // then to where the path begins
                QVERIFY(std::abs(items[2].toObject()["params"].toArray()[4].toDouble() -
                                 pathStart.latitude) <= writtenDegrees);
        }
        // Each flight's trips from the road and back are in its time: more than from the path's first point.
        AutopilotMission fromThePath = mission;
        fromThePath.takeOff.reset();
        const VehicleSettings& drone = lawnmowerExport.settings.vehicle;
        QVERIFY(partSeconds(mission, mission.parts[0], drone, noTurnPrice) >
                partSeconds(fromThePath, mission.parts[0], drone, noTurnPrice) + 2.0 * 30.0 / 10.0);
    }
};

QTEST_GUILESS_MAIN(AutopilotMissionTest)
#include "test_autopilot_mission.moc"
