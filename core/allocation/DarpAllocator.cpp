#include "core/allocation/DarpAllocator.hpp"

#include "core/allocation/BorderExchange.hpp"
#include "core/allocation/StartComponents.hpp"
#include "core/coverage/CellIndexScope.hpp"
#include "core/coverage/PathMeasurement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>

namespace mcpp {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// DARP on one component with two or more robots. Cells and robots are numbered locally. Evaluations are
// kept in whole microseconds: with exact sums a tie between two robots is decided the same way all along a
// shortest path (lowest robot index), which is what keeps every region in one piece.
class DarpSolver {
  public:
    using Ticks = std::int64_t;
    static constexpr double ticksPerSecond = 1e6;
    static constexpr int stallRounds = 24; // rounds without a better connected division before settling

    DarpSolver(const CellGraph& graph, const StartComponent& component, const std::vector<int>& startCells,
               const DarpAllocator::Options& options, const ProgressReporter& progress,
               std::vector<int>& scratchIndex)
        : graph_(graph), cells_(component.cells), robots_(component.robots), options_(options),
          progress_(progress), local_(scratchIndex, cells_), cellCount_(cells_.size()),
          robotCount_(robots_.size()) {
        weight_.resize(cellCount_);
        for (std::size_t c = 0; c < cellCount_; ++c)
            weight_[c] = graph.cell(cells_[c]).coverSeconds();
        const double total = std::accumulate(weight_.begin(), weight_.end(), 0.0);
        fairShare_ = total / static_cast<double>(robotCount_);
        const double largestCell = *std::max_element(weight_.begin(), weight_.end());
        toleranceSeconds_ = std::max(options.tolerance * fairShare_, largestCell);
        for (int robot : robots_)
            start_.push_back(local_[startCells[static_cast<std::size_t>(robot)]]);
        initialiseEvaluations(total / static_cast<double>(cellCount_));
        owner_.assign(cellCount_, 0);
        cost_.assign(robotCount_, 0.0);
    }

    void solve(DarpAllocator::Outcome& outcome) {
        std::vector<int> best; // the best division in one piece so far
        double bestError = infinity;
        double stepLength = 1.0;
        int iteration = 0;
        int sinceBest = 0;
        for (; iteration < options_.maxIterations; ++iteration) {
            if ((iteration & 15) == 0) {
                progress_.throwIfCancelled();
                progress_.report("allocation", static_cast<double>(iteration) / options_.maxIterations);
            }
            if (iteration == 0)
                assign();
            const bool connected = pullRegionsTogether();
            const double error = largestError();
            if (connected && error < bestError) {
                bestError = error;
                best = owner_;
                sinceBest = 0;
            }
            if (connected && error <= toleranceSeconds_)
                break;
            // Past this the factors only circle: the border exchange below settles the last cells.
            if (++sinceBest > stallRounds)
                break;
            if (!connected || reclaimLostStarts())
                assign();
            else
                stepLength = correct(stepLength);
        }
        outcome.iterations = std::max(outcome.iterations, iteration + 1);
        if (!best.empty())
            owner_ = std::move(best);
        // Only a robot left with no cell at all can have lost its start: give it back, mend what that splits.
        for (std::size_t r = 0; r < robotCount_; ++r)
            owner_[static_cast<std::size_t>(start_[r])] = static_cast<int>(r);
        joinStrayPieces();
        settleBorders();
        measure();
        const double error = largestError();
        outcome.converged = outcome.converged && error <= toleranceSeconds_;
        outcome.largestShareError = std::max(outcome.largestShareError, error / fairShare_);
    }

    void writeInto(RegionAllocation& regions) const {
        for (std::size_t c = 0; c < cellCount_; ++c)
            regions.robotOfCell[static_cast<std::size_t>(cells_[c])] =
                robots_[static_cast<std::size_t>(owner_[c])];
    }

  private:
    // E_r = exp(T_r / tau), T_r the travel time from robot r's start. Kept as its logarithm, so a correction
    // factor on E_r is an offset on T_r: a cell whose evaluation is lowest for r then lies on a shortest way
    // from r's start through cells that are r's too, and regions come out in one piece.
    void initialiseEvaluations(double typicalCellSeconds) {
        travel_.assign(cellCount_ * robotCount_, 0);
        listSteps();
        offset_.assign(robotCount_, 0);
        pull_.assign(robotCount_, {});
        pullRounds_.assign(robotCount_, 0);
        Ticks largest = 0;
        for (std::size_t r = 0; r < robotCount_; ++r) {
            const std::vector<Ticks> times = travelTimes(start_[r]);
            for (std::size_t c = 0; c < cellCount_; ++c) {
                travel_[c * robotCount_ + r] = times[c];
                largest = std::max(largest, times[c]);
            }
        }
        initialStep_ = std::max(toTicks(typicalCellSeconds), largest / 100);
    }

    [[nodiscard]] static Ticks toTicks(double seconds) { return std::llround(seconds * ticksPerSecond); }

    // The time of one step between neighbouring cells, centre to centre at each cell's speed. On a grid many
    // cells would be exactly as far from two starts, and a boundary through such a band could only move by
    // whole bands; east-west and north-south steps therefore cost a little differently and each step carries
    // a seeded trace of jitter. Times stay a metric, so regions stay in one piece, and few cells tie.
    [[nodiscard]] Ticks stepTime(int fromCell, int toCell) const {
        const Cell& from = graph_.cell(fromCell);
        const Cell& to = graph_.cell(toCell);
        const double distance = std::hypot(to.centreX() - from.centreX(), to.centreY() - from.centreY());
        const double seconds = travelSeconds(distance, from.speedMetresPerSecond, to.speedMetresPerSecond);
        const bool eastWest =
            std::abs(to.centreX() - from.centreX()) > std::abs(to.centreY() - from.centreY());
        const auto low = static_cast<std::uint64_t>(std::min(fromCell, toCell));
        const auto high = static_cast<std::uint64_t>(std::max(fromCell, toCell));
        const double jitter =
            unitHash((low << 32U) ^ high ^ (static_cast<std::uint64_t>(options_.seed) << 17U));
        return std::max<Ticks>(1,
                               toTicks(seconds * (1.0 + (eastWest ? 1e-4 : 1.41421356e-4) + 1e-4 * jitter)));
    }

    // A number in [0, 1) from a 64-bit key (splitmix64).
    [[nodiscard]] static double unitHash(std::uint64_t key) {
        key += 0x9e3779b97f4a7c15ULL;
        key = (key ^ (key >> 30U)) * 0xbf58476d1ce4e5b9ULL;
        key = (key ^ (key >> 27U)) * 0x94d049bb133111ebULL;
        key ^= key >> 31U;
        return static_cast<double>(key >> 11U) * 0x1.0p-53;
    }

    // Dijkstra from one cell.
    std::vector<Ticks> travelTimes(int source) const {
        std::vector<Ticks> time(cellCount_, std::numeric_limits<Ticks>::max());
        using Entry = std::pair<Ticks, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
        time[static_cast<std::size_t>(source)] = 0;
        queue.emplace(0, source);
        while (!queue.empty()) {
            const auto [at, c] = queue.top();
            queue.pop();
            if (at > time[static_cast<std::size_t>(c)])
                continue;
            for (std::size_t k = stepStart_[static_cast<std::size_t>(c)];
                 k < stepStart_[static_cast<std::size_t>(c) + 1]; ++k) {
                const auto [next, ticks] = steps_[k];
                const Ticks arrival = at + ticks;
                if (arrival < time[static_cast<std::size_t>(next)]) {
                    time[static_cast<std::size_t>(next)] = arrival;
                    queue.emplace(arrival, next);
                }
            }
        }
        return time;
    }

    // The steps a robot can take from each cell: to a neighbour, or diagonally to a cell two neighbours
    // share when both are free. Diagonal steps keep travel times closer to straight-line times; with four
    // directions only, whole quadrants are equally far from two starts and change hands at once.
    void listSteps() {
        stepStart_.assign(1, 0);
        for (std::size_t c = 0; c < cellCount_; ++c) {
            const auto around = graph_.neighbours(cells_[c]);
            for (int neighbour : around)
                steps_.emplace_back(local_[neighbour], stepTime(cells_[c], neighbour));
            for (int neighbour : around)
                for (int beyond : graph_.neighbours(neighbour)) {
                    if (beyond == cells_[c] ||
                        std::find(around.begin(), around.end(), beyond) != around.end())
                        continue;
                    const auto beyondAround = graph_.neighbours(beyond);
                    const auto shared = std::count_if(around.begin(), around.end(), [&](int side) {
                        return std::find(beyondAround.begin(), beyondAround.end(), side) !=
                               beyondAround.end();
                    });
                    const bool listed = std::any_of(
                        steps_.begin() + static_cast<std::ptrdiff_t>(stepStart_.back()), steps_.end(),
                        [&](const auto& step) { return step.first == local_[beyond]; });
                    if (shared == 2 && !listed)
                        steps_.emplace_back(local_[beyond], stepTime(cells_[c], beyond));
                }
            stepStart_.push_back(steps_.size());
        }
    }

    // Every cell to the robot with the smallest evaluation; a tie goes to the lower robot index.
    void assign() {
        double lowestSum = 0.0;
        for (std::size_t c = 0; c < cellCount_; ++c) {
            Ticks lowest = std::numeric_limits<Ticks>::max();
            for (std::size_t r = 0; r < robotCount_; ++r) {
                const Ticks value = evaluation(c, r);
                if (value < lowest) {
                    lowest = value;
                    owner_[c] = static_cast<int>(r);
                }
            }
            lowestSum += weight_[c] * static_cast<double>(lowest);
        }
        const double offsetSum =
            static_cast<double>(std::accumulate(offset_.begin(), offset_.end(), Ticks{0}));
        dual_ = (lowestSum - fairShare_ * offsetSum) / ticksPerSecond;
        measure();
    }

    void measure() {
        std::fill(cost_.begin(), cost_.end(), 0.0);
        for (std::size_t c = 0; c < cellCount_; ++c)
            cost_[static_cast<std::size_t>(owner_[c])] += weight_[c];
    }

    [[nodiscard]] double largestError() const {
        double largest = 0.0;
        for (double cost : cost_)
            largest = std::max(largest, std::abs(cost - fairShare_));
        return largest;
    }

    // DARP's correction factors, chosen together. Lowering robot r's factor against a neighbour q's moves
    // their border into q by half the change in travel time, so r gains about the cover time of the cells
    // along that border per cell of travel time. The factors that bring every region to its fair share then
    // solve a small Laplacian system: one Newton step, damped while the error grows.
    double correct(double stepLength) {
        std::vector<double> coupling(robotCount_ * robotCount_, 0.0);
        for (std::size_t c = 0; c < cellCount_; ++c) {
            const auto r = static_cast<std::size_t>(owner_[c]);
            for (int neighbour : graph_.neighbours(cells_[c])) {
                const auto d = static_cast<std::size_t>(local_[neighbour]);
                const auto q = static_cast<std::size_t>(owner_[d]);
                if (q == r || d < c)
                    continue;
                const double seconds = static_cast<double>(stepTime(cells_[c], neighbour)) / ticksPerSecond;
                const double gain = (weight_[c] + weight_[d]) / 2.0 / (2.0 * seconds);
                coupling[r * robotCount_ + q] += gain;
                coupling[q * robotCount_ + r] += gain;
            }
        }
        std::vector<double> excess(robotCount_);
        for (std::size_t r = 0; r < robotCount_; ++r)
            excess[r] = cost_[r] - fairShare_;
        const std::vector<double> change = solveLaplacian(coupling, excess);
        return lineSearch(change, stepLength);
    }

    // The correction factors maximise DARP's dual, sum over cells of weight x lowest evaluation minus fair
    // share x sum of offsets, a concave function whose slope for robot r is r's cost minus its share. A step
    // is kept once the dual rises; the length that worked is where the next search starts.
    double lineSearch(const std::vector<double>& change, double stepLength) {
        const std::vector<Ticks> from = offset_;
        const double fromDual = dual_;
        for (int halving = 0; halving < 12; ++halving, stepLength /= 2.0) {
            for (std::size_t r = 0; r < robotCount_; ++r)
                offset_[r] = from[r] + std::llround(stepLength * change[r] * ticksPerSecond);
            assign();
            if (dual_ > fromDual)
                return std::min(1.0, 2.0 * stepLength);
        }
        return 1.0;
    }

    // A robot whose region has shrunk to nothing gets a factor low enough to win its start cell back.
    bool reclaimLostStarts() {
        bool reclaimed = false;
        for (std::size_t r = 0; r < robotCount_; ++r) {
            const auto start = static_cast<std::size_t>(start_[r]);
            const auto holder = static_cast<std::size_t>(owner_[start]);
            if (holder == r)
                continue;
            offset_[r] = evaluation(start, holder) - evaluation(start, r) + offset_[r] - 1;
            reclaimed = true;
        }
        return reclaimed;
    }

    [[nodiscard]] Ticks evaluation(std::size_t c, std::size_t r) const {
        return travel_[c * robotCount_ + r] + offset_[r] + (pull_[r].empty() ? 0 : pull_[r][c]);
    }

    // Solves L x = b, L the Laplacian of the symmetric coupling matrix and b summing to zero. x is defined up
    // to a constant, which cancels in the evaluations: robot 0's is pinned, then the mean taken out.
    [[nodiscard]] std::vector<double> solveLaplacian(const std::vector<double>& coupling,
                                                     const std::vector<double>& b) const {
        const auto n = static_cast<Eigen::Index>(robotCount_);
        const Eigen::Map<const Eigen::MatrixXd> weights(coupling.data(), n, n);
        Eigen::MatrixXd laplacian = -weights;
        laplacian.diagonal() = weights.rowwise().sum();
        const Eigen::VectorXd rest = laplacian.bottomRightCorner(n - 1, n - 1)
                                         .ldlt()
                                         .solve(Eigen::Map<const Eigen::VectorXd>(b.data() + 1, n - 1));
        Eigen::VectorXd x(n);
        x << 0.0, rest;
        x.array() -= x.mean();
        return {x.data(), x.data() + n};
    }

    // The cells of robot r reached from its start without leaving its region (marks in `reached`).
    std::size_t markStartPiece(std::size_t r, std::vector<char>& reached) const {
        std::fill(reached.begin(), reached.end(), 0);
        if (owner_[static_cast<std::size_t>(start_[r])] != static_cast<int>(r))
            return 0; // a robot without cells has nothing to reach
        std::vector<int> queue{start_[r]};
        reached[static_cast<std::size_t>(start_[r])] = 1;
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (int neighbour : graph_.neighbours(cells_[static_cast<std::size_t>(queue[head])])) {
                const int next = local_[neighbour];
                if (reached[static_cast<std::size_t>(next)] != 0 ||
                    owner_[static_cast<std::size_t>(next)] != static_cast<int>(r))
                    continue;
                reached[static_cast<std::size_t>(next)] = 1;
                queue.push_back(next);
            }
        return queue.size();
    }

    // Hops through the component from the marked cells.
    std::vector<int> hopsFrom(const std::vector<char>& marked) const {
        std::vector<int> hops(cellCount_, -1);
        std::vector<int> queue;
        for (std::size_t c = 0; c < cellCount_; ++c)
            if (marked[c] != 0) {
                hops[c] = 0;
                queue.push_back(static_cast<int>(c));
            }
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (int neighbour : graph_.neighbours(cells_[static_cast<std::size_t>(queue[head])])) {
                const int next = local_[neighbour];
                if (hops[static_cast<std::size_t>(next)] >= 0)
                    continue;
                hops[static_cast<std::size_t>(next)] = hops[static_cast<std::size_t>(queue[head])] + 1;
                queue.push_back(next);
            }
        return hops;
    }

    // DARP's connectivity term for every region in pieces: cells near the piece holding the start become
    // cheaper for the robot, cells near its other pieces dearer. True when every region is in one piece.
    bool pullRegionsTogether() {
        std::vector<std::size_t> size(robotCount_, 0);
        for (int owner : owner_)
            ++size[static_cast<std::size_t>(owner)];
        std::vector<char> reached(cellCount_);
        bool allConnected = true;
        for (std::size_t r = 0; r < robotCount_; ++r) {
            if (markStartPiece(r, reached) == size[r]) {
                pull_[r].clear();
                pullRounds_[r] = 0;
                continue;
            }
            allConnected = false;
            ++pullRounds_[r];
            pull_[r].assign(cellCount_, 0);
            std::vector<char> stray(cellCount_, 0);
            for (std::size_t c = 0; c < cellCount_; ++c)
                stray[c] = owner_[c] == static_cast<int>(r) && reached[c] == 0 ? 1 : 0;
            const std::vector<int> toStart = hopsFrom(reached);
            const std::vector<int> toStray = hopsFrom(stray);
            int lowest = std::numeric_limits<int>::max();
            int highest = std::numeric_limits<int>::min();
            for (std::size_t c = 0; c < cellCount_; ++c) {
                lowest = std::min(lowest, toStart[c] - toStray[c]);
                highest = std::max(highest, toStart[c] - toStray[c]);
            }
            const double span = std::max(1, highest - lowest);
            for (std::size_t c = 0; c < cellCount_; ++c) {
                const double scaled = 2.0 * (toStart[c] - toStray[c] - lowest) / span - 1.0; // -1 .. 1
                // A factor 1 + weight x scaled on E_r, added to its logarithm in units of the travel times.
                pull_[r][c] = pullRounds_[r] * std::llround(std::log1p(options_.connectivityWeight * scaled) *
                                                            static_cast<double>(initialStep_));
            }
        }
        return allConnected;
    }

    // Evaluations that depend on the start alone cannot split an area that every robot reaches through the
    // same cells (behind a narrow passage, or a whole quadrant of a grid where steps go four ways): all of it
    // changes hands at once and the factors swing back and forth. From the best connected division, the last
    // cells are therefore settled one by one across the borders.
    void settleBorders() {
        BorderExchange exchange(graph_, cells_, local_, weight_, start_,
                                [this](int cell, int receiver, int donor) {
                                    const auto c = static_cast<std::size_t>(cell);
                                    return travel_[c * robotCount_ + static_cast<std::size_t>(receiver)] -
                                           travel_[c * robotCount_ + static_cast<std::size_t>(donor)];
                                });
        exchange.balance(owner_, toleranceSeconds_, progress_);
    }

    // When no connected division was found in time: each piece cut off from its robot's start joins a
    // neighbouring region, which stays connected, until every region is in one piece.
    void joinStrayPieces() {
        std::vector<char> reached(cellCount_);
        for (bool changed = true; changed;) {
            changed = false;
            for (std::size_t r = 0; r < robotCount_; ++r) {
                markStartPiece(r, reached);
                for (std::size_t c = 0; c < cellCount_; ++c) {
                    if (owner_[c] != static_cast<int>(r) || reached[c] != 0)
                        continue;
                    for (int neighbour : graph_.neighbours(cells_[c])) {
                        const int other = owner_[static_cast<std::size_t>(local_[neighbour])];
                        if (other != static_cast<int>(r)) {
                            owner_[c] = other;
                            changed = true;
                            break;
                        }
                    }
                }
            }
        }
    }

    const CellGraph& graph_;
    const std::vector<int>& cells_;
    const std::vector<int>& robots_;
    const DarpAllocator::Options& options_;
    const ProgressReporter& progress_;
    CellIndexScope local_;
    std::size_t cellCount_;
    std::size_t robotCount_;
    std::vector<double> weight_;
    double fairShare_ = 0.0;
    double toleranceSeconds_ = 0.0;
    std::vector<int> start_;
    Ticks initialStep_ = 0;                    // first correction step
    std::vector<std::size_t> stepStart_;       // steps_ of local cell c: [stepStart_[c], stepStart_[c + 1])
    std::vector<std::pair<int, Ticks>> steps_; // (next local cell, step time)
    std::vector<Ticks> travel_;                // travel times from the starts, cell-major
    std::vector<Ticks> offset_;                // log of each robot's correction factor, in travel time
    std::vector<std::vector<Ticks>> pull_;     // log of the connectivity term, empty while in one piece
    std::vector<int> pullRounds_;              // rounds each region has been in pieces
    std::vector<int> owner_;
    double dual_ = 0.0; // DARP's dual at the current offsets, see lineSearch
    std::vector<double> cost_;
};

} // namespace

std::vector<ParameterSpec> DarpAllocator::Options::parameters() {
    const Options defaults;
    return {
        integerParameter(
            "max_iterations", "Iteration cap", defaults.maxIterations, 1, 1'000'000,
            "DARP stops after this many rounds even when the regions are not yet within the tolerance"),
        realParameter(
            "convergence_tolerance", "Convergence tolerance", defaults.tolerance, 0.0, 0.5,
            "DARP stops once every region's cover time is within this fraction of the fair share (never "
            "finer than one cell)"),
        realParameter("connectivity_weight", "Connectivity weight", defaults.connectivityWeight, 0.0, 1.0,
                      "Strength of the term that pulls a region in pieces back together"),
        integerParameter(
            "random_seed", "Random seed", static_cast<int>(defaults.seed), 0, 2'000'000'000,
            "Seed of the noise that breaks ties between equal evaluations; the same seed gives the "
            "same plan"),
    };
}

DarpAllocator::Options DarpAllocator::Options::from(const ParameterValues& values) {
    Options options;
    if (values.has("max_iterations"))
        options.maxIterations = values.integer("max_iterations");
    if (values.has("convergence_tolerance"))
        options.tolerance = values.real("convergence_tolerance");
    if (values.has("connectivity_weight"))
        options.connectivityWeight = values.real("connectivity_weight");
    if (values.has("random_seed"))
        options.seed = static_cast<std::uint32_t>(values.integer("random_seed"));
    return options;
}

RegionAllocation DarpAllocator::allocate(const CellGraph& graph, const std::vector<int>& startCells,
                                         const ProgressReporter& progress) const {
    progress.report("allocation", 0.0);
    outcome_ = {};
    RegionAllocation regions;
    regions.robotOfCell.assign(graph.size(), -1);
    regions.startCell = startCells;
    std::vector<int> scratchIndex(graph.size(), -1);
    for (const StartComponent& component : componentsWithStarts(graph, startCells)) {
        if (component.robots.size() == 1) {
            for (int cell : component.cells)
                regions.robotOfCell[static_cast<std::size_t>(cell)] = component.robots.front();
            continue;
        }
        DarpSolver solver(graph, component, startCells, options_, progress, scratchIndex);
        solver.solve(outcome_);
        solver.writeInto(regions);
    }
    progress.report("allocation", 1.0);
    return regions;
}

} // namespace mcpp
