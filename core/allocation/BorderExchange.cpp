#include "core/allocation/BorderExchange.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

namespace mcpp {

bool BorderExchange::Candidate::operator>(const Candidate& other) const {
    return std::tie(spareNeighbours, preference, cell) >
           std::tie(other.spareNeighbours, other.preference, other.cell);
}

BorderExchange::BorderExchange(const CellGraph& graph, const std::vector<int>& cells,
                               const CellIndexScope& local, std::vector<double> weights,
                               std::vector<int> startCells, Preference preference)
    : weight_(std::move(weights)), start_(std::move(startCells)), preference_(std::move(preference)),
      regionCount_(start_.size()) {
    adjacencyStart_.reserve(cells.size() + 1);
    adjacencyStart_.push_back(0);
    for (int cell : cells) {
        for (int neighbour : graph.neighbours(cell))
            adjacency_.push_back(local[neighbour]);
        adjacencyStart_.push_back(static_cast<int>(adjacency_.size()));
    }
    fairShare_ = std::accumulate(weight_.begin(), weight_.end(), 0.0) / static_cast<double>(regionCount_);
    largestCell_ = weight_.empty() ? 0.0 : *std::max_element(weight_.begin(), weight_.end());
    visitStamp_.assign(cells.size(), 0);
}

double BorderExchange::balance(std::vector<int>& owner, double toleranceSeconds,
                               const ProgressReporter& progress) {
    owner_ = &owner;
    cost_.assign(regionCount_, 0.0);
    cellCount_.assign(regionCount_, 0);
    for (std::size_t c = 0; c < owner.size(); ++c) {
        cost_[static_cast<std::size_t>(owner[c])] += weight_[c];
        ++cellCount_[static_cast<std::size_t>(owner[c])];
    }
    regionVersion_.resize(regionCount_);
    for (std::uint64_t& version : regionVersion_)
        version = ++lastVersion_;
    keptAtVersion_.assign(owner.size(), 0);
    queues_.assign(regionCount_ * regionCount_, {});
    closed_.assign(regionCount_ * regionCount_, 0);
    for (int c = 0; c < static_cast<int>(owner.size()); ++c)
        offerNeighboursOf(c);
    Spread best = spread();
    errorWhenStopped_ = best.largest;
    movesSinceBest_.clear();
    // Near balance, chains can pass the same cells round in a cycle without getting closer: the exchange
    // stops after this many exchanges that moved cells without a new best, and keeps the best.
    const std::size_t stallExchanges = std::max<std::size_t>(64, 8 * regionCount_);
    std::size_t exchangesSinceBest = 0;
    exchanges_ = 0;
    // The cap counts each exchange as at least one move, so exchanges that only close a link are bounded
    // too; a cell should not need to cross more than a few borders.
    bool reopen = false;
    for (std::size_t moves = 0; moves < 8 * owner.size() && best.largest > toleranceSeconds &&
                                exchangesSinceBest < stallExchanges;) {
        if ((exchanges_ & 63) == 0) // on a map of a million cells, thousands of exchanges take minutes
            progress.throwIfCancelled();
        if (reopen) // borders have moved: a link closed before may have cells to give now
            std::fill(closed_.begin(), closed_.end(), 0);
        const std::vector<int> chain = nextChain();
        if (chain.empty())
            break;
        // Far from balance, several cells cross each border at once.
        const double gap =
            cost_[static_cast<std::size_t>(chain.front())] - cost_[static_cast<std::size_t>(chain.back())];
        const int cellsPerLink = std::clamp(static_cast<int>(gap / (8.0 * largestCell_)), 1, 64);
        const Passage passage = passAlong(chain, cellsPerLink, gap / 2.0);
        moves += static_cast<std::size_t>(std::max(passage.moved, 1));
        reopen = passage.complete;
        ++exchanges_;
        if (passage.moved == 0)
            continue; // it only closed a link
        ++exchangesSinceBest;
        if (const Spread now = spread(); isCloser(now, best)) {
            best = now;
            movesSinceBest_.clear();
            exchangesSinceBest = 0;
        }
    }
    errorWhenStopped_ = spread().largest;
    returnToBest();
    const double error = spread().largest;
    owner_ = nullptr;
    return error;
}

// Whether `a` is nearer balance than `b`: a smaller largest error, or the same with the others nearer
// their share (one region that cannot move would otherwise hide what the rest gained). The margins keep
// the rounding of running sums from counting a division met before as a new one.
bool BorderExchange::isCloser(const Spread& a, const Spread& b) const {
    const double margin = 1e-9 * fairShare_;
    if (a.largest < b.largest - margin)
        return true;
    return a.largest <= b.largest + margin && a.squares < b.squares - margin * fairShare_;
}

BorderExchange::Spread BorderExchange::spread() const {
    Spread result;
    for (double cost : cost_) {
        const double error = cost - fairShare_;
        result.largest = std::max(result.largest, std::abs(error));
        result.squares += error * error;
    }
    return result;
}

// Undoes the moves made since the division nearest balance (isCloser), latest first.
void BorderExchange::returnToBest() {
    for (auto entry = movesSinceBest_.rbegin(); entry != movesSinceBest_.rend(); ++entry) {
        const auto index = static_cast<std::size_t>(entry->cell);
        cost_[static_cast<std::size_t>((*owner_)[index])] -= weight_[index];
        cost_[static_cast<std::size_t>(entry->previousOwner)] += weight_[index];
        --cellCount_[static_cast<std::size_t>((*owner_)[index])];
        ++cellCount_[static_cast<std::size_t>(entry->previousOwner)];
        changed((*owner_)[index]);
        changed(entry->previousOwner);
        (*owner_)[index] = entry->previousOwner;
    }
    movesSinceBest_.clear();
}

std::size_t BorderExchange::pair(int donor, int receiver) const {
    return static_cast<std::size_t>(donor) * regionCount_ + static_cast<std::size_t>(receiver);
}

int BorderExchange::countIn(int cell, int region) const {
    int count = 0;
    for (int k = adjacencyStart_[static_cast<std::size_t>(cell)];
         k < adjacencyStart_[static_cast<std::size_t>(cell) + 1]; ++k)
        count +=
            (*owner_)[static_cast<std::size_t>(adjacency_[static_cast<std::size_t>(k)])] == region ? 1 : 0;
    return count;
}

BorderExchange::Candidate BorderExchange::candidate(int cell, int donor, int receiver) const {
    return {countIn(cell, donor) - countIn(cell, receiver), preference_(cell, receiver, donor), cell};
}

// Offers `cell` to every other region it touches.
void BorderExchange::offerNeighboursOf(int cell) {
    const int donor = (*owner_)[static_cast<std::size_t>(cell)];
    for (int k = adjacencyStart_[static_cast<std::size_t>(cell)];
         k < adjacencyStart_[static_cast<std::size_t>(cell) + 1]; ++k) {
        const int receiver = (*owner_)[static_cast<std::size_t>(adjacency_[static_cast<std::size_t>(k)])];
        if (receiver != donor)
            queues_[pair(donor, receiver)].push(candidate(cell, donor, receiver));
    }
}

// A chain from the region with the most time to the one with the least it can reach over links not closed;
// if that gains nothing, from the region with the next most. Empty when no chain would even out more than
// one cell.
std::vector<int> BorderExchange::nextChain() const {
    std::vector<int> byCost(regionCount_);
    std::iota(byCost.begin(), byCost.end(), 0);
    std::sort(byCost.begin(), byCost.end(), [&](int a, int b) {
        return cost_[static_cast<std::size_t>(a)] > cost_[static_cast<std::size_t>(b)];
    });
    for (int from : byCost) {
        const std::vector<int> previous = reachedFrom(from);
        int to = -1;
        for (int r = 0; r < static_cast<int>(regionCount_); ++r)
            if (r != from && previous[static_cast<std::size_t>(r)] >= 0 &&
                (to < 0 || cost_[static_cast<std::size_t>(r)] < cost_[static_cast<std::size_t>(to)]))
                to = r;
        if (to < 0 ||
            cost_[static_cast<std::size_t>(from)] - cost_[static_cast<std::size_t>(to)] <= largestCell_)
            continue;
        std::vector<int> chain{to};
        while (chain.back() != from)
            chain.push_back(previous[static_cast<std::size_t>(chain.back())]);
        std::reverse(chain.begin(), chain.end());
        return chain;
    }
    return {};
}

// For each region reached from `from` over links not closed, the region before it on a shortest chain.
std::vector<int> BorderExchange::reachedFrom(int from) const {
    std::vector<int> previous(regionCount_, -1);
    previous[static_cast<std::size_t>(from)] = from;
    std::vector<int> queue{from};
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int r = queue[head];
        for (int q = 0; q < static_cast<int>(regionCount_); ++q)
            if (previous[static_cast<std::size_t>(q)] < 0 && !queues_[pair(r, q)].empty() &&
                closed_[pair(r, q)] == 0) {
                previous[static_cast<std::size_t>(q)] = r;
                queue.push_back(q);
            }
    }
    return previous;
}

// Moves up to `cellsPerLink` cells across each link, from the far end back, so every region on the way gives
// about what it gets. A donor that can spare no single cell may give a cell together with the part of it
// that cell holds on (at most `pieceSeconds` of cover time). A link that has nothing to give is closed and
// the chain stops short of it.
BorderExchange::Passage BorderExchange::passAlong(const std::vector<int>& chain, int cellsPerLink,
                                                  double pieceSeconds) {
    int moved = 0;
    int wanted = cellsPerLink;
    for (std::size_t link = chain.size() - 1; link-- > 0;) {
        const int donor = chain[link];
        const int receiver = chain[link + 1];
        int given = 0;
        for (; given < wanted; ++given) {
            const int cell = givableCell(donor, receiver);
            if (cell < 0)
                break;
            move(cell, receiver);
        }
        if (given == 0) {
            const std::vector<int> piece = givablePiece(donor, receiver, pieceSeconds);
            for (int cell : piece)
                move(cell, receiver);
            given = static_cast<int>(piece.size());
        }
        if (given == 0) {
            closed_[pair(donor, receiver)] = 1;
            return {moved, false};
        }
        moved += given;
        wanted = given;
    }
    return {moved, true};
}

void BorderExchange::move(int cell, int receiver) {
    const auto index = static_cast<std::size_t>(cell);
    movesSinceBest_.push_back({cell, (*owner_)[index]});
    cost_[static_cast<std::size_t>((*owner_)[index])] -= weight_[index];
    cost_[static_cast<std::size_t>(receiver)] += weight_[index];
    --cellCount_[static_cast<std::size_t>((*owner_)[index])];
    ++cellCount_[static_cast<std::size_t>(receiver)];
    changed((*owner_)[index]);
    changed(receiver);
    (*owner_)[index] = receiver;
    offerNeighboursOf(cell);
    for (int k = adjacencyStart_[index]; k < adjacencyStart_[index + 1]; ++k)
        offerNeighboursOf(adjacency_[static_cast<std::size_t>(k)]);
}

// The best cell `donor` can give `receiver`, or -1. Entries are checked when they come up: a cell that
// changed hands or no longer touches the receiver is dropped, one whose neighbourhood changed is queued
// again, one the donor cannot spare now waits for later.
int BorderExchange::givableCell(int donor, int receiver) {
    CandidateQueue& queue = queues_[pair(donor, receiver)];
    std::vector<Candidate> waiting;
    int found = -1;
    while (!queue.empty() && found < 0) {
        const Candidate top = queue.top();
        queue.pop();
        const auto index = static_cast<std::size_t>(top.cell);
        if ((*owner_)[index] != donor || countIn(top.cell, receiver) == 0)
            continue;
        const Candidate now = candidate(top.cell, donor, receiver);
        if (now.spareNeighbours != top.spareNeighbours) {
            queue.push(now);
            continue;
        }
        const std::uint64_t version = regionVersion_[static_cast<std::size_t>(donor)];
        if (top.cell == start_[static_cast<std::size_t>(donor)] || keptAtVersion_[index] == version) {
            waiting.push_back(top);
        } else if (!isRemovable(top.cell, donor)) {
            keptAtVersion_[index] = version;
            waiting.push_back(top);
        } else {
            found = top.cell;
        }
    }
    for (const Candidate& entry : waiting)
        queue.push(entry);
    return found;
}

// A cell of `donor` next to `receiver` with the part of the donor that would hang on it alone (cut off
// from the donor's start without it), whose cover time is at most `limitSeconds`; empty if there is none.
// Tries the donor's first few border cells only: each try searches the whole donor.
std::vector<int> BorderExchange::givablePiece(int donor, int receiver, double limitSeconds) {
    constexpr std::size_t triesAtMost = 16;
    CandidateQueue& queue = queues_[pair(donor, receiver)];
    std::vector<Candidate> looked;
    std::vector<int> piece;
    while (!queue.empty() && looked.size() < triesAtMost && piece.empty()) {
        const Candidate top = queue.top();
        queue.pop();
        if ((*owner_)[static_cast<std::size_t>(top.cell)] != donor || countIn(top.cell, receiver) == 0)
            continue;
        looked.push_back(top);
        if (top.cell != start_[static_cast<std::size_t>(donor)])
            piece = hangingOn(top.cell, donor, limitSeconds);
    }
    for (const Candidate& entry : looked)
        queue.push(entry);
    return piece;
}

// `cell` and the cells of `region` reached from its start only through it, if their cover time is at most
// `limitSeconds`; otherwise empty. The cells left unreached are looked for over the whole map only when
// there are some and the region's cost leaves room for them: most tries find none, or far too many.
std::vector<int> BorderExchange::hangingOn(int cell, int region, double limitSeconds) {
    const int start = start_[static_cast<std::size_t>(region)];
    // The count of unreached cells below takes the start as the region's and the cell as another.
    if (cell == start || (*owner_)[static_cast<std::size_t>(start)] != region)
        return {};
    ++stamp_;
    visitStamp_[static_cast<std::size_t>(cell)] = stamp_;
    visitStamp_[static_cast<std::size_t>(start)] = stamp_;
    std::vector<int> queue{start};
    double reachedSeconds = weight_[static_cast<std::size_t>(start)];
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const auto at = static_cast<std::size_t>(queue[head]);
        for (int k = adjacencyStart_[at]; k < adjacencyStart_[at + 1]; ++k) {
            const auto next = static_cast<std::size_t>(adjacency_[static_cast<std::size_t>(k)]);
            if (visitStamp_[next] == stamp_ || (*owner_)[next] != region)
                continue;
            visitStamp_[next] = stamp_;
            queue.push_back(static_cast<int>(next));
            reachedSeconds += weight_[next];
        }
    }
    const std::size_t unreached = cellCount_[static_cast<std::size_t>(region)] - queue.size() - 1;
    const double regionSeconds = cost_[static_cast<std::size_t>(region)];
    // The running cost may be off by rounding: only a clear excess is trusted without the scan.
    if (regionSeconds - reachedSeconds > limitSeconds + 1e-6 * regionSeconds)
        return {};
    std::vector<int> piece{cell};
    double seconds = weight_[static_cast<std::size_t>(cell)];
    for (std::size_t c = 0; c < owner_->size() && piece.size() <= unreached && seconds <= limitSeconds; ++c)
        if ((*owner_)[c] == region && visitStamp_[c] != stamp_) {
            piece.push_back(static_cast<int>(c));
            seconds += weight_[c];
        }
    return seconds <= limitSeconds ? piece : std::vector<int>{};
}

void BorderExchange::changed(int region) {
    regionVersion_[static_cast<std::size_t>(region)] = ++lastVersion_;
}

// True when `region` stays in one piece without `cell`: its neighbours in the region still reach one another.
bool BorderExchange::isRemovable(int cell, int region) {
    std::vector<int>& inRegion = inRegion_;
    inRegion.clear();
    for (int k = adjacencyStart_[static_cast<std::size_t>(cell)];
         k < adjacencyStart_[static_cast<std::size_t>(cell) + 1]; ++k)
        if ((*owner_)[static_cast<std::size_t>(adjacency_[static_cast<std::size_t>(k)])] == region)
            inRegion.push_back(adjacency_[static_cast<std::size_t>(k)]);
    if (inRegion.size() <= 1)
        return true;
    ++stamp_;
    visitStamp_[static_cast<std::size_t>(cell)] = stamp_;
    visitStamp_[static_cast<std::size_t>(inRegion.front())] = stamp_;
    std::size_t found = 1;
    std::vector<int>& queue = searchQueue_;
    queue.assign(1, inRegion.front());
    // Around a cell that can go, its neighbours meet again within a few steps; a longer way round is
    // not looked for, so some cells that could go are kept, and the search stays short.
    constexpr std::size_t searchLimit = 64;
    for (std::size_t head = 0; head < queue.size() && head < searchLimit && found < inRegion.size(); ++head) {
        const auto at = static_cast<std::size_t>(queue[head]);
        for (int k = adjacencyStart_[at]; k < adjacencyStart_[at + 1]; ++k) {
            const int next = adjacency_[static_cast<std::size_t>(k)];
            const auto index = static_cast<std::size_t>(next);
            if (visitStamp_[index] == stamp_ || (*owner_)[index] != region)
                continue;
            visitStamp_[index] = stamp_;
            if (std::find(inRegion.begin(), inRegion.end(), next) != inRegion.end())
                ++found;
            queue.push_back(next);
        }
    }
    return found == inRegion.size();
}

} // namespace mcpp
