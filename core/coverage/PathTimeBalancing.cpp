#include "core/coverage/PathTimeBalancing.hpp"

#include "core/coverage/OwnSpeeds.hpp"
#include "core/model/LocalConnectivity.hpp"
#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <cassert>

namespace mcpp {
namespace {

// Moves tried for one longest path before giving up: when the likeliest fail, the rest seldom help.
constexpr int trialsPerStep = 32;
// Cells a connectivity check may visit: a giver's cell whose neighbours do not meet again nearby is kept.
constexpr std::size_t searchLimit = 256;

// Within 0.2 % of the mean time in the field: what is left would cost more planning than it saves.
bool balanced(const std::vector<CoveragePath>& paths, const std::vector<double>& fieldPaces) {
    double longest = 0.0;
    double total = 0.0;
    for (const CoveragePath& path : paths) {
        longest = std::max(longest, fieldSeconds(path, fieldPaces));
        total += fieldSeconds(path, fieldPaces);
    }
    return paths.empty() || longest <= 1.002 * total / static_cast<double>(paths.size());
}

// One balancing run: regions, their cells, which regions touch, and paths, kept in step.
class Balancer {
  public:
    Balancer(const CellGraph& graph, const SpanningTreeCoverage& coverage, RegionAllocation& regions,
             std::vector<CoveragePath>& paths, const std::vector<MapPoint>& starts,
             const std::vector<double>& fieldPaces, const PathTimeBalancing::MayTake& mayTake)
        : graph_(graph), coverage_(coverage), regions_(regions), paths_(paths), starts_(starts),
          fieldPaces_(fieldPaces), mayTake_(mayTake), cells_(cellsByRobot(regions)), connectivity_(graph),
          touches_(paths.size(), std::vector<char>(paths.size(), 0)) {
        // Costs in the units of the cells as they are now (a turn calibration may have changed them).
        regions_.costSeconds.assign(paths.size(), 0.0);
        for (std::size_t robot = 0; robot < cells_.size(); ++robot) {
            for (int cell : cells_[robot])
                regions_.costSeconds[robot] += graph.cell(cell).coverSeconds();
            findContacts(robot);
        }
    }

    // A robot's path's time in the field.
    [[nodiscard]] double seconds(std::size_t robot) const { return fieldSeconds(paths_[robot], fieldPaces_); }

    [[nodiscard]] std::size_t longest() const {
        std::size_t longest = 0;
        for (std::size_t robot = 1; robot < paths_.size(); ++robot)
            if (seconds(robot) > seconds(longest))
                longest = robot;
        return longest;
    }

    // Regions reachable from `from` through neighbouring regions, each with the chain leading to it, the
    // shortest paths first.
    [[nodiscard]] std::vector<std::vector<int>> chainsFrom(int from) const {
        const std::size_t robots = paths_.size();
        std::vector<int> previous(robots, -2);
        std::vector<int> queue{from};
        previous[static_cast<std::size_t>(from)] = -1;
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (std::size_t next = 0; next < robots; ++next)
                if (touches_[static_cast<std::size_t>(queue[head])][next] != 0 && previous[next] == -2) {
                    previous[next] = queue[head];
                    queue.push_back(static_cast<int>(next));
                }
        std::vector<int> targets(queue.begin() + 1, queue.end());
        std::stable_sort(targets.begin(), targets.end(), [&](int a, int b) {
            return seconds(static_cast<std::size_t>(a)) < seconds(static_cast<std::size_t>(b));
        });
        std::vector<std::vector<int>> chains;
        for (int target : targets) {
            std::vector<int> chain;
            for (int at = target; at >= 0; at = previous[static_cast<std::size_t>(at)])
                chain.push_back(at);
            std::reverse(chain.begin(), chain.end());
            chains.push_back(std::move(chain));
        }
        return chains;
    }

    [[nodiscard]] std::size_t cellsIn(const std::vector<int>& chain) const {
        std::size_t count = 0;
        for (int robot : chain)
            count += cells_[static_cast<std::size_t>(robot)].size();
        return count;
    }

    // Passes one cell along each link of the chain and replans its regions; keeps the change when every
    // new path is shorter than `makespan`. Returns the cells planned.
    std::size_t tryChain(const std::vector<int>& chain, double makespan, bool& accepted) {
        std::vector<std::pair<int, int>> passed; // cell, giver
        accepted = false;
        for (std::size_t link = 0; link + 1 < chain.size(); ++link) {
            const int cell = cellToPass(chain[link], chain[link + 1]);
            if (cell < 0)
                break;
            moveCell(cell, chain[link], chain[link + 1]);
            passed.emplace_back(cell, chain[link]);
        }
        if (passed.size() + 1 != chain.size()) {
            undo(passed);
            return 0;
        }
        // The chain's regions are replanned side by side, each into its own slot: the same paths whatever the
        // thread count.
        std::vector<CoveragePath> replanned(chain.size());
        scratchByWorker_.resize(std::max(scratchByWorker_.size(), static_cast<std::size_t>(workerThreads())));
        parallelFor(chain.size(), [&](std::size_t link, int worker) {
            std::vector<int>& scratch = scratchByWorker_[static_cast<std::size_t>(worker)];
            if (scratch.size() != graph_.size())
                scratch.assign(graph_.size(), -1);
            const auto r = static_cast<std::size_t>(chain[link]);
            replanned[link] = coverage_.regionPath(graph_, cells_[r], regions_.startCell[r], chain[link],
                                                   starts_[r], scratch);
        });
        std::size_t planned = 0;
        bool shorter = true;
        for (std::size_t link = 0; link < chain.size(); ++link) {
            planned += cells_[static_cast<std::size_t>(chain[link])].size();
            shorter = shorter && fieldSeconds(replanned[link], fieldPaces_) < makespan - 1e-9;
        }
        if (!shorter) {
            undo(passed);
            return planned;
        }
        for (std::size_t i = 0; i < chain.size(); ++i)
            paths_[static_cast<std::size_t>(chain[i])] = std::move(replanned[i]);
        for (int robot : chain)
            findContacts(static_cast<std::size_t>(robot));
        accepted = true;
        return planned;
    }

  private:
    // The regions this one touches, both ways round (contact is mutual).
    void findContacts(std::size_t robot) {
        for (std::size_t other = 0; other < touches_.size(); ++other) {
            touches_[robot][other] = 0;
            touches_[other][robot] = 0;
        }
        for (int cell : cells_[robot])
            for (int neighbour : graph_.neighbours(cell)) {
                const int other = regions_.robotOfCell[static_cast<std::size_t>(neighbour)];
                if (other >= 0 && static_cast<std::size_t>(other) != robot) {
                    touches_[robot][static_cast<std::size_t>(other)] = 1;
                    touches_[static_cast<std::size_t>(other)][robot] = 1;
                }
            }
    }

    // The giver's border cell next to the receiver that it can spare, most surrounded by the receiver.
    [[nodiscard]] int cellToPass(int giver, int receiver) {
        const auto& owner = regions_.robotOfCell;
        int best = -1;
        int bestContacts = 0;
        for (int cell : cells_[static_cast<std::size_t>(giver)]) {
            if (cell == regions_.startCell[static_cast<std::size_t>(giver)])
                continue;
            int contacts = 0;
            for (int neighbour : graph_.neighbours(cell))
                contacts += owner[static_cast<std::size_t>(neighbour)] == receiver ? 1 : 0;
            if (contacts > bestContacts &&
                (!mayTake_ || mayTake_(static_cast<std::size_t>(receiver), cell)) &&
                connectivity_.canRemove(cell, owner, searchLimit)) {
                best = cell;
                bestContacts = contacts;
            }
        }
        return best;
    }

    void moveCell(int cell, int from, int to) {
        auto& giverCells = cells_[static_cast<std::size_t>(from)];
        auto& takerCells = cells_[static_cast<std::size_t>(to)];
        const auto at = std::lower_bound(giverCells.begin(), giverCells.end(), cell);
        assert(at != giverCells.end() && *at == cell); // cells_ stays sorted and in step with the owners
        giverCells.erase(at);
        takerCells.insert(std::lower_bound(takerCells.begin(), takerCells.end(), cell), cell);
        regions_.robotOfCell[static_cast<std::size_t>(cell)] = to;
        const double cost = graph_.cell(cell).coverSeconds();
        regions_.costSeconds[static_cast<std::size_t>(from)] -= cost;
        regions_.costSeconds[static_cast<std::size_t>(to)] += cost;
    }

    void undo(const std::vector<std::pair<int, int>>& passed) {
        for (auto it = passed.rbegin(); it != passed.rend(); ++it)
            moveCell(it->first, regions_.robotOfCell[static_cast<std::size_t>(it->first)], it->second);
    }

    const CellGraph& graph_;
    const SpanningTreeCoverage& coverage_;
    RegionAllocation& regions_;
    std::vector<CoveragePath>& paths_;
    const std::vector<MapPoint>& starts_;
    const std::vector<double>& fieldPaces_;
    const PathTimeBalancing::MayTake& mayTake_;
    std::vector<std::vector<int>> cells_;
    std::vector<std::vector<int>> scratchByWorker_; // regionPath's index, one per thread, made on first use
    LocalConnectivity connectivity_;
    std::vector<std::vector<char>> touches_;
};

} // namespace

int PathTimeBalancing::balance(const CellGraph& graph, RegionAllocation& regions,
                               std::vector<CoveragePath>& paths, const std::vector<MapPoint>& starts,
                               const ProgressReporter& progress) const {
    if (paths.size() < 2 || balanced(paths, fieldPaces_))
        return 0;
    Balancer balancer(graph, coverage_, regions, paths, starts, fieldPaces_, mayTake_);
    std::size_t spent = 0;
    int moved = 0;
    while (spent < cellBudget_ && !balanced(paths, fieldPaces_)) {
        progress.throwIfCancelled();
        const std::size_t longest = balancer.longest();
        const double makespan = balancer.seconds(longest);
        bool accepted = false;
        int trials = 0;
        for (const auto& chain : balancer.chainsFrom(static_cast<int>(longest))) {
            if (trials++ == trialsPerStep ||
                balancer.seconds(static_cast<std::size_t>(chain.back())) >= makespan)
                break;
            if (spent + balancer.cellsIn(chain) > cellBudget_)
                continue;
            spent += balancer.tryChain(chain, makespan, accepted);
            if (accepted) {
                moved += static_cast<int>(chain.size()) - 1;
                break;
            }
        }
        if (!accepted)
            break;
    }
    return moved;
}

} // namespace mcpp
