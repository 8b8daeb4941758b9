// Autopilot missions: speeds as a vehicle is told them, and missions split by the autopilot's item limit.

#include "PlanFixture.hpp"
#include "io/AutopilotMission.hpp"
#include "io/PlanExport.hpp"
#include "io/internal/StraightLine.hpp"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <random>

using namespace mcpp;
using namespace mcpp::io;

namespace {

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
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, true));
        // Rows alternate 2 and 3 m/s: a change at every row; the 5% bumps inside rows are not commanded.
        int changes = 0;
        for (std::size_t i = 0; i < mission.points.size(); ++i) {
            changes += mission.changesSpeedAt(i) ? 1 : 0;
            const double speed = mission.commandedSpeeds[i];
            QVERIFY2(speed == 2.0 || speed == 3.0, qPrintable(QString::number(speed)));
        }
        QCOMPARE(changes, 3);
        // With no tolerance every rounded change is commanded: into and out of each bump too.
        const AutopilotMission exact = autopilotMission(path, vehicle, shaping(0.0, true));
        int exactChanges = 0;
        for (std::size_t i = 0; i < exact.points.size(); ++i)
            exactChanges += exact.changesSpeedAt(i) ? 1 : 0;
        QCOMPARE(exactChanges, 3 + 4 * 2);
        // A cruise speed replaces them all.
        vehicle.cruiseSpeedMetresPerSecond = 5.0;
        const AutopilotMission cruise = autopilotMission(path, vehicle, shaping(0.1, true));
        for (std::size_t i = 0; i < cruise.points.size(); ++i)
            QVERIFY(!cruise.changesSpeedAt(i) && cruise.commandedSpeeds[i] == 5.0);
    }

    void mergedPointsLieOnTheFlownPath() {
        const CoveragePath path = lawnmower(6, 11, 1.0, 1.5);
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, true));
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
        const AutopilotMission anywhere = autopilotMission(path, vehicle, shaping(0.1, true));
        const AutopilotMission atTurns = autopilotMission(path, vehicle, shaping(0.1, true, true));
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
        const AutopilotMission dipped = autopilotMission(dip, vehicle, shaping(0.1, true, true));
        QCOMPARE(dipped.commandedSpeeds[1], 1.9);
        // Speeds are floats: 0.7F is 0.69999998807907, and is flown at 0.7, not rounded down to 0.69.
        const CoveragePath slowRows = lawnmower(2, 5, 0.7, 0.7);
        QCOMPARE(autopilotMission(slowRows, vehicle, shaping(0.1, true, true)).commandedSpeeds[1], 0.7);
        QCOMPARE(roundedDownSpeed(0.3168316831), 0.31);
        QCOMPARE(roundedDownSpeed(0.29), 0.29);
        QCOMPARE(roundedDownSpeed(12.34), 12.0);
        QCOMPARE(roundedDownSpeed(129.0), 120.0);
    }

    void partsJoinUpAndHoldAtMostTheLimit() {
        std::mt19937 random(11);
        for (int trial = 0; trial < 40; ++trial) {
            const int rows = 3 + static_cast<int>(random() % 30);
            const int columns = 2 + static_cast<int>(random() % 12);
            const CoveragePath path = lawnmower(rows, columns, 1.0 + random() % 5, 7.0);
            VehicleSettings vehicle;
            vehicle.maxWaypoints = minimumMaxWaypoints + static_cast<int>(random() % 40);
            const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, random() % 2 == 0));
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
                // Parts are as full as they can be: the next point would not have fitted.
                if (part + 1 < mission.parts.size()) {
                    const int next = mission.changesSpeedAt(piece.last + 1) ? 2 : 1;
                    QVERIFY(piece.items + next > vehicle.maxWaypoints);
                }
            }
            if (mission.items <= vehicle.maxWaypoints)
                QCOMPARE(mission.parts.size(), std::size_t{1});
        }
    }

    void noLimitKeepsOnePart() {
        const CoveragePath path = lawnmower(40, 20, 1.0, 2.0);
        VehicleSettings vehicle;
        vehicle.maxWaypoints = 0;
        const AutopilotMission mission = autopilotMission(path, vehicle, shaping(0.1, false));
        QCOMPARE(mission.parts.size(), std::size_t{1});
        QCOMPARE(mission.points.size(), path.waypoints.size());
        QCOMPARE(mission.items, 2 + 800 + 39); // home, first speed, waypoints, a change per row
    }

    void partFileNames() {
        QCOMPARE(missionPartPath("out/robot_1.plan", 0), std::string("out/robot_1_part_1.plan"));
        QCOMPARE(missionPartPath("robot_12.waypoints", 2), std::string("robot_12_part_3.waypoints"));
    }

    void splitFilesAreWrittenAndJoinUp() {
        Plan plan = test::makeFixturePlan();
        plan.paths[0] = lawnmower(30, 6, 1.0, 2.0);
        const GeoReference reference = GeoReference::fromDefinition("EPSG:26912").value();
        const ClassTable classes;
        ExportSettings settings;
        settings.vehicle.maxWaypoints = 25;
        const ExportContext context{plan, reference, classes, settings};
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
            const QString path = QString::fromStdString(missionPartPath(whole.toStdString(), part));
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
                QCOMPARE(last[4].toDouble(), lonLats[point].latitude);
                QCOMPARE(last[5].toDouble(), lonLats[point].longitude);
                ++point;
            }
            QCOMPARE(point, mission.parts[part].last + 1);
            if (part > 0) {
                QCOMPARE(first[4].toDouble(), previousLast[4].toDouble());
                QCOMPARE(first[5].toDouble(), previousLast[5].toDouble());
            }
            previousLast = last;
        }
        QVERIFY(!QFileInfo::exists(
            QString::fromStdString(missionPartPath(whole.toStdString(), mission.parts.size()))));

        // The waypoint list of the same robot: the same parts, home and first speed rows included in the
        // limit.
        const QString list = folder.filePath(QStringLiteral("robot_1.waypoints"));
        QVERIFY(writeWaypointList(context, 0, list.toStdString()).ok());
        for (std::size_t part = 0; part < mission.parts.size(); ++part) {
            QFile file(QString::fromStdString(missionPartPath(list.toStdString(), part)));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const int rows = static_cast<int>(file.readAll().count('\n')) - 1; // less the header
            QCOMPARE(rows, mission.parts[part].items);
        }
    }
};

QTEST_GUILESS_MAIN(AutopilotMissionTest)
#include "test_autopilot_mission.moc"
