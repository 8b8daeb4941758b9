#include "core/allocation/AzimuthTrendAllocator.hpp"

#include "core/allocation/CellBlocks.hpp"
#include "core/allocation/CellFigures.hpp"
#include "core/allocation/GrowthFrontier.hpp"
#include "core/allocation/PieceSettlement.hpp"
#include "core/allocation/RegionCosts.hpp"
#include "core/allocation/RegionReconnection.hpp"
#include "core/allocation/StartComponents.hpp"
#include "core/allocation/TreePieces.hpp"
#include "core/coverage/OwnSpeeds.hpp"
#include "core/model/LocalConnectivity.hpp"
#include "core/model/NeighbourSource.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace mcpp {
namespace {

constexpr int unassigned = -1;
constexpr int unreachable = -2;

// When the robots would all finish if the work were shared to that end: costs are each robot's own time (its
// cells' costs times its pace), and a robot of pace p does 1 / p of a cost a second. With every pace 1
// (none given), the mean cost. `robots`: the robots sharing the work.
double fairTime(const std::vector<double>& costs, const std::vector<double>& paces,
                const std::vector<int>& robots) {
    double work = 0.0;
    double rate = 0.0;
    for (const int robot : robots) {
        const double pace = paceOf(paces, static_cast<std::size_t>(robot));
        work += costs[static_cast<std::size_t>(robot)] / pace;
        rate += 1.0 / pace;
    }
    return rate > 0.0 ? work / rate : 0.0;
}

// fairTime for all the robots.
double fairTime(const std::vector<double>& costs, const std::vector<double>& paces) {
    std::vector<int> robots(costs.size());
    std::iota(robots.begin(), robots.end(), 0);
    return fairTime(costs, paces, robots);
}

// The largest of the robots' paces (1 for a robot without one): the slowest robot's seconds for a second
// of cell cost.
double slowestPace(const std::vector<double>& paces, std::size_t robots) {
    double slowest = 0.0;
    for (std::size_t robot = 0; robot < robots; ++robot)
        slowest = std::max(slowest, paceOf(paces, robot));
    return slowest;
}

// Each robot's cost in its own time (costs at pace 1 times its pace).
std::vector<double> pacedCosts(std::vector<double> costs, const std::vector<double>& paces) {
    for (std::size_t robot = 0; robot < costs.size(); ++robot)
        costs[robot] *= paceOf(paces, robot);
    return costs;
}

// Every robot's own time within `slack` of the fair time (the mean at one pace).
bool withinOfTheFairTime(const std::vector<double>& costs, const std::vector<double>& paces, double slack) {
    const double fair = fairTime(costs, paces);
    return std::all_of(costs.begin(), costs.end(),
                       [&](double cost) { return std::abs(cost - fair) <= slack; });
}

struct RobotState {
    double cost = 0.0;
    double sumX = 0.0; // area-weighted, for the region centre Ca
    double sumY = 0.0;
    double area = 0.0;
    int cells = 0;
    int cellsAtLastRekey = 1;
    bool finished = false;
    int startCell = -1;
    // Frontier of unassigned cells keyed by cost_un at push time (lazy: stale entries are skipped).
    GrowthFrontier frontier;
    // Whether a cell was ever taken from the region: until then every frontier entry touches it.
    bool lostCell = false;
    std::vector<int> foreignBorder; // cells of other robots seen next to this region
};

class Allocation {
  public:
    // paces: by robot, its seconds for a second of cell cost (robotPaces); empty: 1 for every robot.
    Allocation(NeighbourSource neighbours, std::vector<CellFigures> figures,
               const std::vector<int>& startCells, const ProgressReporter& progress,
               std::vector<double> paces = {})
        : neighbours_(neighbours), progress_(progress), paces_(std::move(paces)),
          cellCount_(static_cast<int>(figures.size())),
          owner_(static_cast<std::size_t>(cellCount_), unreachable), cells_(std::move(figures)),
          connectivity_(neighbours), robots_(startCells.size()), centreX_(startCells.size()),
          centreY_(startCells.size()) {
        // Cells in no start's component are unreachable from the outset and never considered.
        std::vector<int> queue(startCells.begin(), startCells.end());
        for (int start : startCells)
            owner_[static_cast<std::size_t>(start)] = unassigned;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            for (int neighbour : neighbours.of(queue[head])) {
                if (owner_[static_cast<std::size_t>(neighbour)] == unreachable) {
                    owner_[static_cast<std::size_t>(neighbour)] = unassigned;
                    queue.push_back(neighbour);
                }
            }
        }
        for (int cell = 0; cell < cellCount_; ++cell) {
            if (owner_[static_cast<std::size_t>(cell)] == unassigned) {
                ++unassignedCount_;
                const CellFigures& reachable = cells_[static_cast<std::size_t>(cell)];
                unassignedX_ += reachable.x * reachable.area;
                unassignedY_ += reachable.y * reachable.area;
                unassignedArea_ += reachable.area;
            }
        }
        reachableCount_ = unassignedCount_;
        for (std::size_t robot = 0; robot < robots_.size(); ++robot) {
            robots_[robot].startCell = startCells[robot];
            give(startCells[robot], static_cast<int>(robot));
        }
        for (std::size_t robot = 0; robot < robots_.size(); ++robot)
            pushNeighbours(static_cast<int>(robot), startCells[robot]);
    }

    void grow() {
        const auto robotCount = static_cast<int>(robots_.size());
        int steps = 0;
        std::int64_t stealBudget = 4LL * cellCount_ + 1000;
        const int retryInterval = std::max(64, reachableCount_ / (8 * robotCount));
        if (queueEachCellOnce_ && robots_.size() < 255)
            queuedBy_.assign(static_cast<std::size_t>(cellCount_), 0);
        while (unassignedCount_ > 0) {
            if ((++steps & 4095) == 0) {
                progress_.throwIfCancelled();
                progress_.report("allocation",
                                 0.8 * (1.0 - static_cast<double>(unassignedCount_) / reachableCount_));
            }
            // A robot that found nothing to take may find a richer neighbour later: wake the stuck ones now
            // and then.
            if (steps % retryInterval == 0)
                for (auto& state : robots_)
                    state.finished = false;
            int robot = -1;
            for (int candidate = 0; candidate < robotCount; ++candidate) {
                const RobotState& state = robots_[static_cast<std::size_t>(candidate)];
                if (!state.finished && (robot < 0 || weightedCost(candidate) < weightedCost(robot)))
                    robot = candidate;
            }
            if (robot < 0)
                break;
            RobotState& state = robots_[static_cast<std::size_t>(robot)];
            if (state.cells >= 2 * state.cellsAtLastRekey)
                rekey(robot);
            const int cell = popUnassignedCandidate(robot);
            if (cell >= 0) {
                give(cell, robot);
                pushNeighbours(robot, cell);
                prefetchNextCandidate(state);
                continue;
            }
            if (stealBudget > 0) {
                if (const int stolen = stealFromNeighbour(robot); stolen > 0) {
                    stealBudget -= stolen;
                    continue;
                }
            }
            state.finished = true;
        }
        std::vector<std::uint8_t>().swap(queuedBy_); // the frontiers are spent
    }

    [[nodiscard]] const std::vector<double>& paces() const { return paces_; }

    // Growth takes turns by cost times this weight: a robot weighted below 1 grows ahead of the others.
    void setGrowthWeights(std::vector<double> weights) { growthWeights_ = std::move(weights); }
    // A robot queues a cell once, with its key when first seen, rather than once for each of its cells
    // beside it: on a large map its frontier holds hundreds of thousands of entries, and taking the
    // smallest out is most of the growth.
    void queueEachCellOnce() { queueEachCellOnce_ = true; }

    // Moves cells along chains of adjacent regions from the most loaded robot while the maximum falls.
    int rebalance(int iterationCap) {
        const auto robotCount = static_cast<int>(robots_.size());
        if (robotCount < 2)
            return 0;
        buildBoundaries();
        int moves = 0;
        while (moves < iterationCap) {
            if ((moves & 255) == 0) {
                progress_.throwIfCancelled();
                // On a large map the moves take minutes: the bar goes on with them (up to its cap).
                progress_.report("allocation",
                                 0.8 + 0.15 * static_cast<double>(moves) / static_cast<double>(iterationCap));
            }
            int richest = 0;
            for (int robot = 1; robot < robotCount; ++robot)
                if (robots_[static_cast<std::size_t>(robot)].cost >
                    robots_[static_cast<std::size_t>(richest)].cost)
                    richest = robot;
            // Among regions tied at the maximum, keep draining the one whose chain worked last.
            if (!lastChain_.empty() && robots_[static_cast<std::size_t>(lastChain_.front())].cost >=
                                           robots_[static_cast<std::size_t>(richest)].cost - 1e-9)
                richest = lastChain_.front();
            if (!moveAlongAChain(richest))
                break;
            ++moves;
        }
        return moves;
    }

    // Takes an earlier division's cells as they were; false when it leaves a reachable cell unassigned.
    bool adopt(const RegionAllocation& division) {
        for (int cell = 0; cell < cellCount_; ++cell) {
            const int robot = division.robotOfCell[static_cast<std::size_t>(cell)];
            const int owner = owner_[static_cast<std::size_t>(cell)];
            if (owner == unassigned && robot >= 0 && robot < static_cast<int>(robots_.size()))
                give(cell, robot);
        }
        return unassignedCount_ == 0;
    }

    // About how many single-cell moves would even the regions out: the cost above the fair time (fairTime;
    // the mean at one pace), in cells of average cost (within a few percent of the moves made on the
    // benchmark maps).
    double movesToEvenOut() const {
        std::vector<double> costs;
        for (const RobotState& robot : robots_)
            costs.push_back(robot.cost);
        const double fair = fairTime(costs, paces_);
        double total = 0.0; // in cell costs
        double excess = 0.0;
        for (std::size_t robot = 0; robot < robots_.size(); ++robot) {
            total += robots_[robot].cost / pace(static_cast<int>(robot));
            excess += std::max(0.0, robots_[robot].cost - fair) / pace(static_cast<int>(robot));
        }
        return total > 0.0 ? excess * reachableCount_ / total : 0.0;
    }

    RegionAllocation result() const {
        RegionAllocation allocation;
        allocation.robotOfCell.resize(static_cast<std::size_t>(cellCount_));
        for (int cell = 0; cell < cellCount_; ++cell) {
            const int owner = owner_[static_cast<std::size_t>(cell)];
            allocation.robotOfCell[static_cast<std::size_t>(cell)] = owner >= 0 ? owner : -1;
        }
        for (const auto& robot : robots_) {
            allocation.startCell.push_back(robot.startCell);
            allocation.costSeconds.push_back(robot.cost);
        }
        return allocation;
    }

  private:
    double pace(int robot) const { return paceOf(paces_, static_cast<std::size_t>(robot)); }

    double weightedCost(int robot) const {
        const double cost = robots_[static_cast<std::size_t>(robot)].cost;
        return growthWeights_.empty() ? cost : cost * growthWeights_[static_cast<std::size_t>(robot)];
    }

    double distance(int cell, double x, double y) const {
        const double dx = cells_[static_cast<std::size_t>(cell)].x - x;
        const double dy = cells_[static_cast<std::size_t>(cell)].y - y;
        return std::sqrt(dx * dx +
                         dy * dy); // std::hypot guards overflow we cannot meet, at several times the cost
    }

    double distanceToCentre(int cell, int robot) const {
        return distance(cell, centreX_[static_cast<std::size_t>(robot)],
                        centreY_[static_cast<std::size_t>(robot)]);
    }

    // cost_un: distance to the robot's own centre minus the mean distance to the other centres.
    double growthKey(int robot, int cell) const {
        double key = distanceToCentre(cell, robot);
        const auto robots = static_cast<int>(robots_.size());
        if (robots > 1) {
            double others = 0.0;
            for (int other = 0; other < robots; ++other)
                if (other != robot)
                    others += distanceToCentre(cell, other);
            key -= others / static_cast<double>(robots - 1);
        }
        return key;
    }

    // The region's area-weighted centre Ca, kept beside the sums: growth keys read every robot's centre
    // for every cell they weigh.
    void updateCentre(int robot) {
        const RobotState& state = robots_[static_cast<std::size_t>(robot)];
        centreX_[static_cast<std::size_t>(robot)] = state.sumX / state.area;
        centreY_[static_cast<std::size_t>(robot)] = state.sumY / state.area;
    }

    bool touchesRegion(int cell, int robot) const {
        for (int neighbour : neighbours_.of(cell))
            if (owner_[static_cast<std::size_t>(neighbour)] == robot)
                return true;
        return false;
    }

    void give(int cell, int robot) {
        const int previous = owner_[static_cast<std::size_t>(cell)];
        const CellFigures& figures = cells_[static_cast<std::size_t>(cell)];
        const double area = figures.area;
        const double x = figures.x * area;
        const double y = figures.y * area;
        if (previous == unassigned) {
            --unassignedCount_;
            unassignedX_ -= x;
            unassignedY_ -= y;
            unassignedArea_ -= area;
        } else if (previous >= 0) {
            RobotState& donor = robots_[static_cast<std::size_t>(previous)];
            donor.lostCell = true;
            donor.cost -= figures.cost * pace(previous);
            donor.sumX -= x;
            donor.sumY -= y;
            donor.area -= area;
            --donor.cells;
            updateCentre(previous);
        }
        RobotState& receiver = robots_[static_cast<std::size_t>(robot)];
        receiver.cost += figures.cost * pace(robot);
        receiver.sumX += x;
        receiver.sumY += y;
        receiver.area += area;
        ++receiver.cells;
        updateCentre(robot);
        owner_[static_cast<std::size_t>(cell)] = robot;
        if (!boundaryIndex_.empty()) {
            updateBoundaryAround(cell);
            forgetFacingAround(cell, previous);
            if (previous >= 0)
                regionVersion_[static_cast<std::size_t>(previous)] = ++lastVersion_;
            regionVersion_[static_cast<std::size_t>(robot)] = ++lastVersion_;
        }
    }

    void pushNeighbours(int robot, int cell) {
        RobotState& state = robots_[static_cast<std::size_t>(robot)];
        for (int neighbour : neighbours_.of(cell)) {
            const int owner = owner_[static_cast<std::size_t>(neighbour)];
            if (owner == unassigned) {
                if (!queuedBy_.empty()) {
                    auto& queued = queuedBy_[static_cast<std::size_t>(neighbour)];
                    if (queued == robot + 1)
                        continue;
                    queued = static_cast<std::uint8_t>(robot + 1);
                }
                state.frontier.push(growthKey(robot, neighbour), neighbour);
            } else if (owner >= 0 && owner != robot) {
                state.foreignBorder.push_back(neighbour);
                robots_[static_cast<std::size_t>(owner)].foreignBorder.push_back(cell);
            }
        }
    }

    // Recomputes the frontier's keys once the region has doubled, since its centre has moved.
    void rekey(int robot) {
        RobotState& state = robots_[static_cast<std::size_t>(robot)];
        std::vector<int> cells;
        while (!state.frontier.empty()) {
            cells.push_back(state.frontier.top().second);
            state.frontier.pop();
        }
        std::sort(cells.begin(), cells.end());
        cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
        for (int cell : cells)
            if (owner_[static_cast<std::size_t>(cell)] == unassigned)
                state.frontier.push(growthKey(robot, cell), cell);
        state.cellsAtLastRekey = state.cells;
    }

    // The robot's next candidate is taken a few steps later, when its turn comes again: its data asked for
    // now is in the cache by then. On a large map each step otherwise waits on several cache misses, as
    // the frontier's cells lie far apart in memory.
    void prefetchNextCandidate(const RobotState& state) const {
        if (state.frontier.empty())
            return;
        const auto next = static_cast<std::size_t>(state.frontier.top().second);
        __builtin_prefetch(&owner_[next]);
        __builtin_prefetch(&cells_[next]);
        neighbours_.prefetch(static_cast<int>(next));
    }

    int popUnassignedCandidate(int robot) {
        RobotState& state = robots_[static_cast<std::size_t>(robot)];
        while (!state.frontier.empty()) {
            const int cell = state.frontier.top().second;
            state.frontier.pop();
            const int owner = owner_[static_cast<std::size_t>(cell)];
            if (owner == unassigned) {
                // A cell taken from this robot may have cut it off from an old frontier entry.
                if (!state.lostCell || touchesRegion(cell, robot))
                    return cell;
                if (!queuedBy_.empty() && queuedBy_[static_cast<std::size_t>(cell)] == robot + 1)
                    queuedBy_[static_cast<std::size_t>(cell)] = 0; // may be queued again once it touches
            } else if (owner >= 0 && owner != robot) {
                state.foreignBorder.push_back(cell);
            }
        }
        return -1;
    }

    // True when taking `cell` out of its owner's region surely leaves that region connected: its neighbours
    // in the region must meet again within a small search around it. A region that only reconnects
    // through a long loop is treated as cut, which keeps the check cheap and never breaks a region.
    static constexpr std::size_t localSearch = 24;
    static constexpr std::size_t wideSearch = 256;

    bool removalKeepsConnected(int cell, std::size_t searchLimit = wideSearch) {
        if (regionVersion_.empty())
            return checkRemoval(cell, searchLimit);
        // While regions are evened out, most checks fall on regions no move has changed since they were
        // made. The answer depends on the owner's cells alone, so it holds while the owner's version does.
        const int owner = owner_[static_cast<std::size_t>(cell)];
        const std::uint64_t version = regionVersion_[static_cast<std::size_t>(owner)];
        const std::uint64_t key = static_cast<std::uint64_t>(cell) * 2 + (searchLimit == wideSearch ? 1 : 0);
        const auto [entry, added] = removalKnown_.try_emplace(key, 0);
        if (!added && entry->second >> 1 == version)
            return (entry->second & 1) != 0;
        const bool removable = checkRemoval(cell, searchLimit);
        entry->second = version << 1 | (removable ? 1 : 0);
        return removable;
    }

    bool checkRemoval(int cell, std::size_t searchLimit) {
        if (connectivity_.canRemove(cell, owner_, searchLimit))
            return true;
        // A cell none of its region touches can go as long as it is not the region's last.
        const int owner = owner_[static_cast<std::size_t>(cell)];
        return !touchesRegion(cell, owner) && robots_[static_cast<std::size_t>(owner)].cells > 1;
    }

    // The first of `cells` (at most `maxTries` of them) whose removal surely keeps its region connected:
    // a cheap look around each first, the wide search only when none passes it.
    int firstRemovable(const std::vector<int>& cells, int maxTries) {
        for (std::size_t limit : {localSearch, wideSearch}) {
            int tried = 0;
            for (int cell : cells) {
                if (removalKeepsConnected(cell, limit))
                    return cell;
                if (++tried >= maxTries)
                    break;
            }
        }
        return -1;
    }

    // A stuck robot takes a border cell of a neighbour when that lowers the larger of the two costs:
    // first cells on the side facing the still unassigned area (nu), then the rest (fu), nearest first.
    // Returns how many cells it took.
    int stealFromNeighbour(int robot) {
        RobotState& state = robots_[static_cast<std::size_t>(robot)];
        auto& border = state.foreignBorder;
        const double centreX = centreX_[static_cast<std::size_t>(robot)];
        const double centreY = centreY_[static_cast<std::size_t>(robot)];
        const double towardsX = unassignedArea_ > 0 ? unassignedX_ / unassignedArea_ - centreX : 0.0;
        const double towardsY = unassignedArea_ > 0 ? unassignedY_ / unassignedArea_ - centreY : 0.0;
        struct Candidate {
            bool facingUnassigned;
            double distance;
            int cell;
        };
        std::vector<Candidate> candidates;
        std::size_t kept = 0;
        // A stuck robot steals again and again from a border of thousands of cells: duplicates go by a stamp
        // per call and only the best candidates are ordered, so a steal is linear in the border.
        if (stealSeen_.empty()) // allocated by the first steal, so not at all for plans without one
            stealSeen_.assign(static_cast<std::size_t>(cellCount_), 0);
        ++stealStamp_;
        for (int cell : border) {
            if (stealSeen_[static_cast<std::size_t>(cell)] == stealStamp_ || !isOnForeignBorder(robot, cell))
                continue;
            stealSeen_[static_cast<std::size_t>(cell)] = stealStamp_;
            border[kept++] = cell;
            if (!lowersLargerCost(robot, cell))
                continue;
            const double dx = cells_[static_cast<std::size_t>(cell)].x - centreX;
            const double dy = cells_[static_cast<std::size_t>(cell)].y - centreY;
            candidates.push_back({dx * towardsX + dy * towardsY >= 0.0, std::sqrt(dx * dx + dy * dy), cell});
        }
        border.resize(kept);
        const auto before = [](const Candidate& a, const Candidate& b) {
            if (a.facingUnassigned != b.facingUnassigned)
                return a.facingUnassigned;
            if (a.distance != b.distance)
                return a.distance < b.distance;
            return a.cell < b.cell;
        };
        const auto best = candidates.begin() + std::min<std::ptrdiff_t>(stealTries, std::ssize(candidates));
        std::partial_sort(candidates.begin(), best, candidates.end(), before);
        candidates.erase(best, candidates.end());
        std::vector<int>& ordered = scratchCells_;
        ordered.clear();
        for (const auto& candidate : candidates)
            ordered.push_back(candidate.cell);
        const int chosen = firstRemovable(ordered, stealTries);
        if (chosen < 0)
            return 0;
        int stolen = 1;
        if (!takeStolen(robot, chosen) || kept < batchStealBorder)
            return stolen;
        // The scan above is linear in a border of thousands of cells: while the robot would steal again
        // next, it takes the following candidates of the same order instead of scanning again. Short
        // borders are scanned afresh for each cell, as the order moves with the region's centre.
        const auto after = std::find(ordered.begin(), ordered.end(), chosen) + 1;
        for (auto it = after; it != ordered.end() && isNextToSteal(robot); ++it) {
            if (!stillStealable(robot, *it) || !removalKeepsConnected(*it, localSearch))
                continue;
            ++stolen;
            if (!takeStolen(robot, *it))
                break;
        }
        return stolen;
    }

    // Gives a stolen cell to the robot; false when that opened unassigned cells to it, which it takes next.
    bool takeStolen(int robot, int cell) {
        const int donor = owner_[static_cast<std::size_t>(cell)];
        const std::size_t frontierBefore = robots_[static_cast<std::size_t>(robot)].frontier.size();
        give(cell, robot);
        pushNeighbours(robot, cell);
        robots_[static_cast<std::size_t>(donor)].finished = false;
        // The donor may now reach cells again through its remaining border.
        for (int neighbour : neighbours_.of(cell))
            if (owner_[static_cast<std::size_t>(neighbour)] == donor)
                pushNeighbours(donor, neighbour);
        return robots_[static_cast<std::size_t>(robot)].frontier.size() == frontierBefore;
    }

    // Whether the growth loop would pick this robot again (the cheapest unfinished one, the lowest index
    // among equals), with nothing to rekey first.
    bool isNextToSteal(int robot) const {
        const RobotState& state = robots_[static_cast<std::size_t>(robot)];
        if (state.cells >= 2 * state.cellsAtLastRekey)
            return false;
        for (std::size_t other = 0; other < robots_.size(); ++other) {
            const RobotState& rival = robots_[other];
            if (!rival.finished &&
                (rival.cost < state.cost || (rival.cost == state.cost && static_cast<int>(other) < robot)))
                return false;
        }
        return true;
    }

    // Whether the robot may take the cell from its owner: not the owner's start, and the larger of the two
    // costs falls.
    bool lowersLargerCost(int robot, int cell) const {
        const RobotState& donor = robots_[static_cast<std::size_t>(owner_[static_cast<std::size_t>(cell)])];
        return cell != donor.startCell && robots_[static_cast<std::size_t>(robot)].cost +
                                                  cells_[static_cast<std::size_t>(cell)].cost * pace(robot) <
                                              donor.cost - 1e-9;
    }

    // Whether another robot owns the cell and it touches this robot's region.
    bool isOnForeignBorder(int robot, int cell) const {
        const int owner = owner_[static_cast<std::size_t>(cell)];
        return owner >= 0 && owner != robot && touchesRegion(cell, robot);
    }

    bool stillStealable(int robot, int cell) const {
        return isOnForeignBorder(robot, cell) && lowersLargerCost(robot, cell);
    }

    // Boundary cells of each region (a neighbour belongs to another robot), kept up to date on every move.
    void buildBoundaries() {
        // The facing lists follow the boundary lists' order.
        facingByRegion_.assign(robots_.size(), {});
        facingKnown_.assign(robots_.size(), 0);
        regionVersion_.resize(robots_.size());
        for (std::uint64_t& version : regionVersion_)
            version = ++lastVersion_;
        boundaryIndex_.assign(static_cast<std::size_t>(cellCount_), -1);
        boundaryOwner_.assign(static_cast<std::size_t>(cellCount_), -1);
        boundaries_.assign(robots_.size(), {});
        regionContacts_.assign(robots_.size() * robots_.size(), 0);
        handOverKnown_.assign(robots_.size() * robots_.size(), 0);
        handOverPossible_.assign(robots_.size() * robots_.size(), 0);
        for (int cell = 0; cell < cellCount_; ++cell) {
            const int owner = owner_[static_cast<std::size_t>(cell)];
            if (owner < 0)
                continue;
            for (int neighbour : neighbours_.of(cell)) {
                const int other = owner_[static_cast<std::size_t>(neighbour)];
                if (other >= 0 && other != owner)
                    ++regionContacts_[static_cast<std::size_t>(owner) * robots_.size() +
                                      static_cast<std::size_t>(other)];
            }
            refreshBoundary(cell);
        }
    }

    void refreshBoundary(int cell) {
        const int owner = owner_[static_cast<std::size_t>(cell)];
        bool onBoundary = false;
        if (owner >= 0) {
            for (int neighbour : neighbours_.of(cell)) {
                const int other = owner_[static_cast<std::size_t>(neighbour)];
                if (other >= 0 && other != owner) {
                    onBoundary = true;
                    break;
                }
            }
        }
        int& index = boundaryIndex_[static_cast<std::size_t>(cell)];
        if (index >= 0) {
            // Remove from the list that holds it: its owner may have changed since it was added.
            auto& list =
                boundaries_[static_cast<std::size_t>(boundaryOwner_[static_cast<std::size_t>(cell)])];
            const int last = list.back();
            list[static_cast<std::size_t>(index)] = last;
            boundaryIndex_[static_cast<std::size_t>(last)] = index;
            list.pop_back();
            index = -1;
        }
        if (onBoundary) {
            auto& list = boundaries_[static_cast<std::size_t>(owner)];
            index = static_cast<int>(list.size());
            list.push_back(cell);
            boundaryOwner_[static_cast<std::size_t>(cell)] = owner;
        }
    }

    void updateBoundaryAround(int cell) {
        refreshBoundary(cell);
        for (int neighbour : neighbours_.of(cell))
            refreshBoundary(neighbour);
    }

    // Contact counts between regions change only when a cell changes owner.
    void moveCell(int cell, int to) {
        const int from = owner_[static_cast<std::size_t>(cell)];
        forgetHandOvers(from);
        forgetHandOvers(to);
        const std::size_t n = robots_.size();
        for (int neighbour : neighbours_.of(cell)) {
            const int other = owner_[static_cast<std::size_t>(neighbour)];
            if (other < 0)
                continue;
            if (other != from) {
                --regionContacts_[static_cast<std::size_t>(from) * n + static_cast<std::size_t>(other)];
                --regionContacts_[static_cast<std::size_t>(other) * n + static_cast<std::size_t>(from)];
            }
            if (other != to) {
                ++regionContacts_[static_cast<std::size_t>(to) * n + static_cast<std::size_t>(other)];
                ++regionContacts_[static_cast<std::size_t>(other) * n + static_cast<std::size_t>(to)];
            }
        }
        give(cell, to);
    }

    // The best cell `from` can hand to `to`: on their common border, not the start, keeping `from` connected,
    // and leaving the receiver below `receiverCostLimit`.
    int cellToHandOver(int from, int to, double receiverCostLimit) {
        const RobotState& receiver = robots_[static_cast<std::size_t>(to)];
        std::vector<std::pair<double, int>>& candidates = scratchCandidates_;
        candidates.clear();
        for (int cell : facing(from, to)) {
            if (!(receiver.cost + cells_[static_cast<std::size_t>(cell)].cost * pace(to) < receiverCostLimit))
                continue;
            const double score = distanceToCentre(cell, to) - distanceToCentre(cell, from);
            candidates.emplace_back(score, cell);
        }
        std::sort(candidates.begin(), candidates.end());
        std::vector<int>& ordered = scratchCells_;
        ordered.clear();
        for (const auto& candidate : candidates)
            ordered.push_back(candidate.second);
        return firstRemovable(ordered, 64);
    }

    // Whether `from` has any border cell it could hand to `to`, remembered until either region changes.
    bool canHandOver(int from, int to) {
        const std::size_t key =
            static_cast<std::size_t>(from) * robots_.size() + static_cast<std::size_t>(to);
        if (handOverKnown_[key] == 0) {
            handOverPossible_[key] = searchHandOver(from, to) ? 1 : 0;
            handOverKnown_[key] = 1;
        }
        return handOverPossible_[key] != 0;
    }

    void forgetHandOvers(int region) {
        const std::size_t n = robots_.size();
        for (std::size_t other = 0; other < n; ++other) {
            handOverKnown_[static_cast<std::size_t>(region) * n + other] = 0;
            handOverKnown_[other * n + static_cast<std::size_t>(region)] = 0;
        }
    }

    bool searchHandOver(int from, int to) { return firstRemovable(facing(from, to), 64) >= 0; }

    // The border cells of `from` (not its start) next to `to`, in the order of its boundary list. One look
    // along the border serves the searches towards all its neighbours, and stays until a move changes
    // that border or a region beside it: most moves leave most regions' lists as they were.
    const std::vector<int>& facing(int from, int to) {
        if (facingKnown_[static_cast<std::size_t>(from)] == 0)
            collectFacing(from);
        return facingByRegion_[static_cast<std::size_t>(from)][static_cast<std::size_t>(to)];
    }

    // A cell changed owner: the lists of its old and new regions and of the regions beside it change.
    void forgetFacingAround(int cell, int previous) {
        if (previous >= 0)
            facingKnown_[static_cast<std::size_t>(previous)] = 0;
        facingKnown_[static_cast<std::size_t>(owner_[static_cast<std::size_t>(cell)])] = 0;
        for (int neighbour : neighbours_.of(cell))
            if (const int owner = owner_[static_cast<std::size_t>(neighbour)]; owner >= 0)
                facingKnown_[static_cast<std::size_t>(owner)] = 0;
    }

    void collectFacing(int from) {
        std::vector<std::vector<int>>& lists = facingByRegion_[static_cast<std::size_t>(from)];
        lists.resize(robots_.size());
        for (std::vector<int>& list : lists)
            list.clear();
        const int start = robots_[static_cast<std::size_t>(from)].startCell;
        for (int cell : boundaries_[static_cast<std::size_t>(from)]) {
            if (cell == start)
                continue;
            for (int neighbour : neighbours_.of(cell)) {
                const int other = owner_[static_cast<std::size_t>(neighbour)];
                if (other < 0 || other == from)
                    continue;
                std::vector<int>& list = lists[static_cast<std::size_t>(other)];
                if (list.empty() || list.back() != cell)
                    list.push_back(cell);
            }
        }
        facingKnown_[static_cast<std::size_t>(from)] = 1;
    }

    // Finds regions the richest can pass a cell to, directly or through a chain of regions each able to
    // hand a border cell to the next, and moves one cell along the chain to the poorest such region.
    bool moveAlongAChain(int richest) {
        const std::size_t n = robots_.size();
        const double ceiling = robots_[static_cast<std::size_t>(richest)].cost;
        // The chain that worked last time usually works again: try it before searching.
        if (!lastChain_.empty() && lastChain_.front() == richest &&
            robots_[static_cast<std::size_t>(lastChain_.back())].cost < ceiling - 1e-9 &&
            tryChain(lastChain_))
            return true;
        std::vector<int> parent(n, -2);
        std::vector<int> order{richest};
        parent[static_cast<std::size_t>(richest)] = -1;
        for (std::size_t head = 0; head < order.size(); ++head) {
            const int region = order[head];
            for (std::size_t other = 0; other < n; ++other) {
                if (parent[other] != -2 || regionContacts_[static_cast<std::size_t>(region) * n + other] == 0)
                    continue;
                if (!canHandOver(region, static_cast<int>(other)))
                    continue;
                parent[other] = region;
                order.push_back(static_cast<int>(other));
            }
        }
        std::vector<int> targets(order.begin() + 1, order.end());
        std::stable_sort(targets.begin(), targets.end(), [&](int a, int b) {
            return robots_[static_cast<std::size_t>(a)].cost < robots_[static_cast<std::size_t>(b)].cost;
        });
        int attempts = 0;
        for (int target : targets) {
            if (robots_[static_cast<std::size_t>(target)].cost >= ceiling - 1e-9 || ++attempts > 12)
                break;
            std::vector<int> chain{target};
            while (parent[static_cast<std::size_t>(chain.back())] >= 0)
                chain.push_back(parent[static_cast<std::size_t>(chain.back())]);
            std::reverse(chain.begin(), chain.end()); // richest ... target
            if (tryChain(chain)) {
                lastChain_ = chain;
                return true;
            }
        }
        lastChain_.clear();
        return false;
    }

    // Moves one cell along richest -> ... -> target; keeps the moves only when they help.
    bool tryChain(const std::vector<int>& chain) {
        const int richest = chain.front();
        const double ceiling = robots_[static_cast<std::size_t>(richest)].cost;
        std::vector<double> before;
        for (int region : chain)
            before.push_back(robots_[static_cast<std::size_t>(region)].cost);
        // Hand over from the target's end backwards, so every region keeps cells to give.
        std::vector<std::pair<int, int>> done; // cell, previous owner
        bool ok = true;
        for (std::size_t hop = chain.size() - 1; hop >= 1; --hop) {
            const int from = chain[hop - 1];
            const int to = chain[hop];
            // A region inside the chain may also sit at the maximum: it passes cells on without gaining.
            const double limit =
                hop + 1 < chain.size() ? std::max(ceiling, before[hop]) + 1e-9 : ceiling - 1e-9;
            const int cell = cellToHandOver(from, to, limit);
            if (cell < 0) {
                ok = false;
                break;
            }
            done.emplace_back(cell, from);
            moveCell(cell, to);
        }
        // Accept when the richest falls and no other region rises to the old maximum: the sorted costs
        // then fall lexicographically, so the loop ends.
        bool improves = ok && robots_[static_cast<std::size_t>(richest)].cost < ceiling - 1e-9;
        for (std::size_t i = 1; improves && i < chain.size(); ++i) {
            const double now = robots_[static_cast<std::size_t>(chain[i])].cost;
            improves = now < ceiling - 1e-9 || now <= before[i] + 1e-9;
        }
        if (improves)
            return true;
        for (auto it = done.rbegin(); it != done.rend(); ++it)
            moveCell(it->first, it->second);
        return false;
    }

    NeighbourSource neighbours_;
    const ProgressReporter& progress_;
    std::vector<double> paces_; // by robot; empty: all 1
    int cellCount_;
    std::vector<int> owner_;
    std::vector<CellFigures> cells_;
    LocalConnectivity connectivity_;
    std::vector<RobotState> robots_;
    std::vector<double> centreX_; // by robot: sumX / area, updated with them
    std::vector<double> centreY_;
    int unassignedCount_ = 0;
    int reachableCount_ = 0;
    double unassignedX_ = 0.0;
    double unassignedY_ = 0.0;
    double unassignedArea_ = 0.0;
    std::vector<int> boundaryIndex_;
    std::vector<int> boundaryOwner_;
    std::vector<std::vector<int>> boundaries_;
    std::vector<int> regionContacts_;
    std::vector<int> lastChain_;
    std::vector<double> growthWeights_; // by robot; empty: all 1
    bool queueEachCellOnce_ = false;
    // While growing so, by cell: 1 + the robot whose frontier took it last; empty otherwise and above 254
    // robots.
    std::vector<std::uint8_t> queuedBy_;
    std::vector<std::pair<double, int>> scratchCandidates_;
    std::vector<int> scratchCells_;
    static constexpr int stealTries = 32; // border cells a steal tries, best first
    // Border cells from which one look along the border serves several steals.
    static constexpr std::size_t batchStealBorder = 1024;
    std::vector<std::uint32_t> stealSeen_; // stealStamp_ of the last steal that looked at each cell
    std::uint32_t stealStamp_ = 0;
    // collectFacing's lists, by region and the region they face, and whether each region's are up to date.
    std::vector<std::vector<std::vector<int>>> facingByRegion_;
    std::vector<char> facingKnown_;
    // While evening out: each region's version, new whenever it gains or loses a cell, and the removal
    // checks made, by cell and search width, with the version of the owner they were made for.
    std::vector<std::uint64_t> regionVersion_;
    std::uint64_t lastVersion_ = 0;
    std::unordered_map<std::uint64_t, std::uint64_t> removalKnown_;
    std::vector<char> handOverKnown_;
    std::vector<char> handOverPossible_;
};

// The cap on chain moves: the setting, or one from the problem size.
int moveCap(int rebalanceIterations, std::size_t cells) {
    return rebalanceIterations > 0 ? rebalanceIterations : std::max(1000, static_cast<int>(cells));
}

// The cells moved along chains of adjacent regions while the largest cost falls, then any region left in
// pieces settled. Settling evens out costs at pace 1, which robots of their own paces are not divided by:
// there it would undo the division, and on a large map it took minutes (the Principe crop, 1.35 M cells,
// three drones balanced in the field: over 150 s of border exchanges instead of 24 s for the whole plan).
RegionAllocation evenedOut(Allocation& allocation, const CellGraph& graph, int moves,
                           const ProgressReporter& progress) {
    progress.report("allocation", 0.8);
    (void)allocation.rebalance(moves);
    RegionAllocation result = allocation.result();
    if (allocation.paces().empty())
        settleRegionsWithPieces(graph, result, progress);
    progress.report("allocation", 1.0);
    return result;
}

// The robots of each connected part of the map that holds more than one start: a robot alone in a pocket
// has no one to even out with.
std::vector<std::vector<int>> robotsSharingParts(const CellGraph& graph, const std::vector<int>& startCells) {
    std::vector<std::vector<int>> shared;
    for (StartComponent& part : componentsWithStarts(graph, startCells))
        if (part.robots.size() > 1)
            shared.push_back(std::move(part.robots));
    return shared;
}

// How uneven a division's costs are: the largest over the fair time of the robots sharing its part (fairTime;
// their mean at one pace), at least 1. With `unevenBeyond` (a cost), 1 unless some region also exceeds its
// part's fair time by more than that.
double unevenness(const std::vector<double>& costs, const std::vector<std::vector<int>>& robotsOfParts,
                  const std::vector<double>& paces, double unevenBeyond = 0.0) {
    double largest = 1.0;
    for (const std::vector<int>& robots : robotsOfParts) {
        double most = 0.0;
        for (const int robot : robots)
            most = std::max(most, costs[static_cast<std::size_t>(robot)]);
        const double mean = fairTime(costs, paces, robots);
        if (mean > 0.0 && most - mean > unevenBeyond)
            largest = std::max(largest, most / mean);
    }
    return largest;
}

// Regions grown with these growth weights (none: all 1) and evened out with at most `moves` chain moves.
RegionAllocation grownAndEvenedOut(const CellGraph& graph, std::vector<CellFigures> figures,
                                   const std::vector<int>& startCells, std::vector<double> weights, int moves,
                                   const ProgressReporter& progress, const std::vector<double>& paces,
                                   bool queueEachCellOnce = false) {
    Allocation allocation(graph, std::move(figures), startCells, progress, paces);
    allocation.setGrowthWeights(std::move(weights));
    if (queueEachCellOnce)
        allocation.queueEachCellOnce();
    allocation.grow();
    return evenedOut(allocation, graph, moves, progress);
}

// Regions left further than this from even after evening out (and more than a cell's cost from it, which a
// map of few cells a robot cannot help) are grown again with weights (each try costs about what the first
// growth and evening out cost).
constexpr double unevenAfterEvening = 1.01;
constexpr int weightedGrowths = 6;

// Where the evened-out division stays uneven (starts crowded together, regions walled in by others), the
// regions are grown again, each robot's turn in the growth going by its cost times a weight: a robot left
// with too little weighs less next time and grows ahead, as DARP weighs its regions. The most even division
// is kept, the first one if none beats it.
RegionAllocation regrownWithWeights(const CellGraph& graph, const std::vector<CellFigures>& figures,
                                    const std::vector<int>& startCells, RegionAllocation first,
                                    int rebalanceIterations, const ProgressReporter& progress,
                                    const std::vector<double>& paces) {
    double dearestCell = 0.0; // in the slowest robot's own time
    for (const CellFigures& cell : figures)
        dearestCell = std::max(dearestCell, cell.cost);
    if (!paces.empty())
        dearestCell *= std::max(1.0, *std::max_element(paces.begin(), paces.end()));
    const std::vector<std::vector<int>> robotsOfParts = robotsSharingParts(graph, startCells);
    if (unevenness(first.costSeconds, robotsOfParts, paces, dearestCell) <= unevenAfterEvening)
        return first;
    const int moves = moveCap(rebalanceIterations, graph.size());
    std::vector<double> weights(startCells.size(), 1.0);
    std::vector<double> costs = first.costSeconds;
    RegionAllocation best = std::move(first);
    double bestSpread = unevenness(best.costSeconds, robotsOfParts, paces);
    for (int attempt = 0; attempt < weightedGrowths && bestSpread > unevenAfterEvening; ++attempt) {
        const double mean = fairTime(costs, paces);
        for (std::size_t robot = 0; robot < weights.size(); ++robot)
            if (costs[robot] > 0.0)
                weights[robot] *= std::sqrt(costs[robot] / mean); // half way: whole steps overshoot
        const ProgressReporter tries =
            progress.within("uneven regions grown again", static_cast<double>(attempt) / weightedGrowths,
                            static_cast<double>(attempt + 1) / weightedGrowths);
        RegionAllocation regrown =
            grownAndEvenedOut(graph, figures, startCells, weights, moves, tries, paces);
        costs = regrown.costSeconds;
        if (const double spread = unevenness(regrown.costSeconds, robotsOfParts, paces);
            spread < bestSpread) {
            bestSpread = spread;
            best = std::move(regrown);
        }
    }
    return best;
}

// limits.mostCellsGrownAgain: the largest map grown again with weights where the first division stays
// uneven; above limits.mostCellsQueuedAtEachStep cells a robot queues each cell once as it grows.
RegionAllocation grownCellByCell(const CellGraph& graph, const std::vector<int>& startCells,
                                 int rebalanceIterations, const ProgressReporter& progress,
                                 const AzimuthTrendLimits& limits, const std::vector<double>& paces) {
    const int moves = moveCap(rebalanceIterations, graph.size());
    const bool queueEachCellOnce = graph.size() > limits.mostCellsQueuedAtEachStep;
    if (startCells.size() < 2 || graph.size() > limits.mostCellsGrownAgain) // no copy of the figures kept
        return grownAndEvenedOut(graph, cellFiguresOf(graph), startCells, {}, moves, progress, paces,
                                 queueEachCellOnce);
    const std::vector<CellFigures> figures = cellFiguresOf(graph);
    RegionAllocation division =
        grownAndEvenedOut(graph, figures, startCells, {}, moves, progress, paces, queueEachCellOnce);
    return regrownWithWeights(graph, figures, startCells, std::move(division), rebalanceIterations, progress,
                              paces);
}

// The blocks (or pieces) that hold the start cells.
std::vector<int> startsOn(const std::vector<int>& blockOfCell, const std::vector<int>& startCells) {
    std::vector<int> starts;
    for (int start : startCells)
        starts.push_back(blockOfCell[static_cast<std::size_t>(start)]);
    return starts;
}

// A division of blocks given cell by cell: each cell takes its block's robot; the costs are the blocks'.
RegionAllocation cellsTakeTheirBlocks(const RegionAllocation& blocks, const std::vector<int>& blockOfCell,
                                      const std::vector<int>& startCells) {
    RegionAllocation division;
    division.startCell = startCells;
    division.costSeconds = blocks.costSeconds;
    division.robotOfCell.resize(blockOfCell.size());
    for (std::size_t cell = 0; cell < blockOfCell.size(); ++cell)
        division.robotOfCell[cell] = blocks.robotOfCell[static_cast<std::size_t>(blockOfCell[cell])];
    return division;
}

// Each finer piece takes the robot of the coarser piece it lies in: the cells' owners, which is all
// Allocation::adopt reads.
RegionAllocation finerTakeTheirCoarser(const RegionAllocation& coarser, const CellBlocks& coarserPieces,
                                       const CellBlocks& finerPieces) {
    RegionAllocation division;
    division.robotOfCell.assign(finerPieces.figures.size(), -1);
    for (std::size_t cell = 0; cell < finerPieces.blockOfCell.size(); ++cell)
        division.robotOfCell[static_cast<std::size_t>(finerPieces.blockOfCell[cell])] =
            coarser.robotOfCell[static_cast<std::size_t>(coarserPieces.blockOfCell[cell])];
    return division;
}

// Grown on the coarsest pieces and evened out on each level in turn; the division of the finest pieces.
// Nothing where a finer level cannot adopt a coarser one's division (its pieces lie within the coarser
// ones, so it always can).
std::optional<RegionAllocation> evenedOutOnPieces(const std::vector<CellBlocks>& levels,
                                                  const std::vector<int>& startCells, int rebalanceIterations,
                                                  const ProgressReporter& progress) {
    RegionAllocation division;
    for (std::size_t level = 0; level < levels.size(); ++level) {
        const CellBlocks& pieces = levels[level];
        Allocation allocation(pieces.adjacency, pieces.figures, startsOn(pieces.blockOfCell, startCells),
                              progress);
        if (level == 0)
            allocation.grow();
        else if (!allocation.adopt(finerTakeTheirCoarser(division, levels[level - 1], pieces)))
            return std::nullopt;
        (void)allocation.rebalance(moveCap(rebalanceIterations, pieces.figures.size()));
        division = allocation.result();
    }
    return division;
}

// The regions grown and evened out on blocks, each cell given its block's robot and made whole; robots of
// paces of their own (paces) in their own times. Nothing when two starts share a block, or when a region
// ends further than a block's cost from the fair time (fairTime; the mean at one pace): evening that
// out cell by cell moves thousands of single cells, each leaving a notch a path turns around (on a forest
// with lakes, 7 % more turns than regions grown cell by cell), so such maps are grown cell by cell.
std::optional<RegionAllocation> grownOnBlocks(const CellGraph& graph, const std::vector<int>& startCells,
                                              int rebalanceIterations, const ProgressReporter& progress,
                                              const std::vector<double>& paces) {
    RegionAllocation division;
    double largestBlockCost = 0.0; // in the slowest robot's own time
    bool linked = false;
    {
        const CellBlocks blocks = groupIntoBlocks(graph, AzimuthTrendAllocator::blockSide);
        const std::vector<int> blockStarts = startsOn(blocks.blockOfCell, startCells);
        std::vector<int> distinct = blockStarts;
        std::sort(distinct.begin(), distinct.end());
        if (std::adjacent_find(distinct.begin(), distinct.end()) != distinct.end())
            return std::nullopt;
        for (const CellFigures& block : blocks.figures)
            largestBlockCost = std::max(largestBlockCost, block.cost);
        largestBlockCost *= slowestPace(paces, startCells.size());
        Allocation coarse(blocks.adjacency, blocks.figures, blockStarts, progress, paces);
        coarse.grow();
        (void)coarse.rebalance(moveCap(rebalanceIterations, blocks.figures.size()));
        const RegionAllocation coarseRegions = coarse.result();
        if (!withinOfTheFairTime(coarseRegions.costSeconds, paces, largestBlockCost))
            return std::nullopt;
        division = cellsTakeTheirBlocks(coarseRegions, blocks.blockOfCell, startCells);
        linked = blocks.everyBlockConnected;
    }
    if (!linked) {
        // Obstacles that cut a block may cut a region; the cells it loses or gains move its cost.
        reconnectRegions(graph, startCells, division.robotOfCell);
        division.costSeconds = pacedCosts(regionCosts(graph, division.robotOfCell, startCells.size()), paces);
        if (!withinOfTheFairTime(division.costSeconds, paces, largestBlockCost))
            return std::nullopt;
    }
    progress.report("allocation", 1.0);
    return division;
}

} // namespace

RegionAllocation AzimuthTrendAllocator::rebalance(const CellGraph& graph, const std::vector<int>& startCells,
                                                  const RegionAllocation& division,
                                                  const ProgressReporter& progress) const {
    // Each move walks the borders of the regions along its chain. A few hundred moves take less than growing
    // anew (the multi-cover benchmark map of side 1024 with 16 robots, 667 moves: the turn balance in 0.8 s
    // instead of 1.9 s); far more take longer (17.6 M cells with a fast robot, 13 662 moves: 23 s instead
    // of 16 s).
    constexpr double mostMoves = 4096.0;
    if (division.robotOfCell.size() == graph.size() && division.startCell == startCells) {
        progress.report("allocation", 0.0);
        Allocation allocation(graph, cellFiguresOf(graph), startCells, progress, paces_);
        if (allocation.adopt(division) && allocation.movesToEvenOut() <= mostMoves)
            return evenedOut(allocation, graph, moveCap(rebalanceIterations_, graph.size()), progress);
    } // gone before a new one is grown: on a large map each holds hundreds of megabytes
    return allocate(graph, startCells, progress);
}

ParameterSpec AzimuthTrendAllocator::rebalanceIterationsParameter() {
    return integerParameter(
        "rebalance_iterations", "Rebalance iterations", 0, 0, 100'000'000,
        "Cap on the cell moves that even out the robots' workloads after the regions are grown; 0 "
        "picks one from the problem size");
}

ParameterSpec AzimuthTrendAllocator::treePieceShareParameter() {
    return realParameter("tree_piece_share", "Tree piece size", 0.0, 0.0, 50.0,
                         "Above 0, regions are grown from pieces of one tree over the whole map that turns "
                         "little, each this share of a robot's fair share (3 % works well), so that their "
                         "borders cut few straight runs: fewer turns (0.4-8 % on the maps measured), but "
                         "regions interlock along those runs. 0, the default, grows compact regions cell by "
                         "cell. Maps of at most 50 000 cells a robot",
                         "%");
}

// One robot's region is the whole map however it is grown; above mostCellsGrownOneByOne cells the regions
// grow on blocks.
bool AzimuthTrendAllocator::growsOnTreePieces(const CellGraph& graph, std::size_t robots) const {
    return treePieceShare_ > 0.0 && robots > 1 && graph.size() <= limits_.mostCellsGrownOneByOne &&
           (graph.size() + robots - 1) / robots <= limits_.mostCellsOnTreePiecesPerRobot;
}

// Grown and evened out on two levels of pieces, then evened out cell by cell.
RegionAllocation AzimuthTrendAllocator::grownOnTreePieces(const CellGraph& graph,
                                                          const std::vector<int>& startCells,
                                                          const ProgressReporter& progress) const {
    // The fair share of the parts the robots can reach: a large part no start reaches would make the
    // pieces too large.
    double reachableCost = 0.0;
    for (const StartComponent& component : componentsWithStarts(graph, startCells))
        for (int cell : component.cells)
            reachableCost += graph.cell(cell).coverSeconds();
    const double pieceCost = treePieceShare_ * reachableCost / static_cast<double>(startCells.size());
    // Pieces of an eighth of that within: evened out on them, the division has little left to move cell by
    // cell (one level alone took 18 s of cell moves on a 480 x 480 grid with 8 robots, two 0.26 s).
    std::optional<RegionAllocation> division;
    std::vector<int> finestPieceOfCell;
    {
        std::vector<CellBlocks> levels =
            treePieces(graph, startCells, {pieceCost, pieceCost / 8.0}, &progress);
        division = evenedOutOnPieces(levels, startCells, rebalanceIterations_, progress);
        finestPieceOfCell = std::move(levels.back().blockOfCell);
    } // the pieces' figures and adjacency gone before the cells' allocation is made
    Allocation allocation(graph, cellFiguresOf(graph), startCells, progress);
    if (division && allocation.adopt(cellsTakeTheirBlocks(*division, finestPieceOfCell, startCells)))
        return evenedOut(allocation, graph, moveCap(rebalanceIterations_, graph.size()), progress);
    return grownCellByCell(graph, startCells, rebalanceIterations_, progress, limits_, {});
}

RegionAllocation AzimuthTrendAllocator::allocate(const CellGraph& graph, const std::vector<int>& startCells,
                                                 const ProgressReporter& progress) const {
    progress.report("allocation", 0.0);
    // Robots of their own paces grow cell by cell on maps of tree pieces (the pieces are evened out at one
    // pace); on blocks, each robot's time is its own.
    if (paces_.empty() && growsOnTreePieces(graph, startCells.size()))
        return grownOnTreePieces(graph, startCells, progress);
    if (graph.size() > limits_.mostCellsGrownOneByOne) {
        if (auto grown = grownOnBlocks(graph, startCells, rebalanceIterations_, progress, paces_))
            return std::move(*grown);
    }
    return grownCellByCell(graph, startCells, rebalanceIterations_, progress, limits_, paces_);
}

} // namespace mcpp
