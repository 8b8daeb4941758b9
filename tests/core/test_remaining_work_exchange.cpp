#include "core/allocation/RemainingWorkExchange.hpp"
#include "tests/support/SyntheticMaps.hpp"

#include <QtTest>
#include <algorithm>
#include <limits>
#include <random>

using namespace mcpp;

namespace {

// A 60 x 60 grid with 15 % obstacles split among four robots grown a ring at a time from random starts;
// the cells within three steps of each start are entered (being covered) and may not change hands.
struct RunningMission {
    CellGraph graph;
    std::vector<int> owner;
    std::vector<char> entered;
    std::vector<RemainingWorkExchange::Robot> robots;

    explicit RunningMission(std::uint32_t seed) {
        const PlanningProblem problem = test::obstacleGridProblem(60, 1, seed);
        graph = test::cellPerPixelGraph(problem);
        owner.assign(graph.size(), -1);
        entered.assign(graph.size(), 0);
        std::mt19937 random(seed);
        std::uniform_int_distribution<int> anyCell(0, static_cast<int>(graph.size()) - 1);
        std::vector<int> queue;
        std::vector<int> steps(graph.size(), 0);
        while (robots.size() < 4) {
            const int start = anyCell(random);
            if (owner[static_cast<std::size_t>(start)] >= 0 || graph.neighbours(start).size() < 2)
                continue;
            owner[static_cast<std::size_t>(start)] = static_cast<int>(robots.size());
            robots.push_back({1.0, 0.0, start});
            queue.push_back(start);
        }
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const auto at = static_cast<std::size_t>(queue[head]);
            entered[at] = steps[at] <= 3 ? 1 : 0;
            for (int next : graph.neighbours(queue[head]))
                if (owner[static_cast<std::size_t>(next)] < 0) {
                    owner[static_cast<std::size_t>(next)] = owner[at];
                    steps[static_cast<std::size_t>(next)] = steps[at] + 1;
                    queue.push_back(next);
                }
        }
    }

    // Cover time of each robot's cells not entered yet.
    [[nodiscard]] std::vector<double> freeWork() const {
        std::vector<double> work(robots.size(), 0.0);
        for (std::size_t cell = 0; cell < graph.size(); ++cell)
            if (owner[cell] >= 0 && entered[cell] == 0)
                work[static_cast<std::size_t>(owner[cell])] +=
                    graph.cell(static_cast<int>(cell)).coverSeconds();
        return work;
    }

    [[nodiscard]] double longestTimeLeft() const {
        const std::vector<double> work = freeWork();
        double longest = 0.0;
        for (std::size_t robot = 0; robot < robots.size(); ++robot)
            longest =
                std::max(longest, robots[robot].speedFactor > 0.0
                                      ? work[robot] / robots[robot].speedFactor
                                      : (work[robot] > 0.0 ? std::numeric_limits<double>::infinity() : 0.0));
        return longest;
    }
};

double sum(const std::vector<double>& values) {
    double total = 0.0;
    for (double value : values)
        total += value;
    return total;
}

} // namespace

class RemainingWorkExchangeTest : public QObject {
    Q_OBJECT

  private slots:
    // A robot slowed to half speed gives free cells to the others: the longest time left falls, no entered
    // cell changes hands, and the work is only moved, never lost.
    void aSlowedRobotGivesWorkAway() {
        for (std::uint32_t seed = 1; seed <= 6; ++seed) {
            RunningMission mission(seed);
            mission.robots[0].speedFactor = 0.5;
            const std::vector<int> before = mission.owner;
            const double longestBefore = mission.longestTimeLeft();
            const double workBefore = sum(mission.freeWork());
            RemainingWorkExchange exchange(mission.graph);
            const int moved = exchange.exchange(mission.owner, mission.entered, mission.robots,
                                                static_cast<int>(mission.graph.size()));
            const QString where = QStringLiteral("seed %1: %2 moved, longest %3 s -> %4 s")
                                      .arg(seed)
                                      .arg(moved)
                                      .arg(longestBefore)
                                      .arg(mission.longestTimeLeft());
            QVERIFY2(moved > 0, qPrintable(where));
            QVERIFY2(mission.longestTimeLeft() < longestBefore, qPrintable(where));
            QVERIFY2(std::abs(sum(mission.freeWork()) - workBefore) <= 1e-9 * workBefore, qPrintable(where));
            int changed = 0;
            for (std::size_t cell = 0; cell < before.size(); ++cell) {
                changed += before[cell] != mission.owner[cell] ? 1 : 0;
                if (mission.entered[cell] != 0)
                    QVERIFY2(before[cell] == mission.owner[cell], qPrintable(where));
                QVERIFY2((before[cell] < 0) == (mission.owner[cell] < 0), qPrintable(where));
            }
            QVERIFY2(changed <= moved, qPrintable(where));
        }
    }

    // A robot that stops gives away every cell it has not entered: nobody else would cover them.
    void aStoppedRobotKeepsNoFreeCell() {
        for (std::uint32_t seed = 1; seed <= 6; ++seed) {
            RunningMission mission(seed);
            mission.robots[1].speedFactor = 0.0;
            QVERIFY(mission.freeWork()[1] > 0.0);
            RemainingWorkExchange exchange(mission.graph);
            // The simulation asks again after each event and while robots drive: a few rounds here.
            for (int round = 0; round < 4; ++round)
                (void)exchange.exchange(mission.owner, mission.entered, mission.robots,
                                        static_cast<int>(mission.graph.size()));
            QVERIFY2(mission.freeWork()[1] == 0.0,
                     qPrintable(QStringLiteral("seed %1: %2 s left").arg(seed).arg(mission.freeWork()[1])));
        }
    }
};

QTEST_APPLESS_MAIN(RemainingWorkExchangeTest)
#include "test_remaining_work_exchange.moc"
