#include "core/allocation/RemainingWorkExchange.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>

namespace mcpp {
namespace {

// How far the connectivity check looks around a cell before calling the region cut.
constexpr std::size_t connectivitySearchLimit = 48;
// The fewest cells worth a drive across another region: below this the borders' exchange does better.
constexpr double blockCells = 16.0;

} // namespace

RemainingWorkExchange::RemainingWorkExchange(const CellGraph& graph) : graph_(graph), connectivity_(graph) {
    for (const Cell& cell : graph.cells())
        largestCellSeconds_ = std::max(largestCellSeconds_, cell.coverSeconds());
}

int RemainingWorkExchange::exchange(std::vector<int>& owner, const std::vector<char>& entered,
                                    const std::vector<Robot>& robots, int maxMoves) {
    owner_ = &owner;
    entered_ = &entered;
    robots_ = &robots;
    const std::size_t robotCount = robots.size();
    work_.assign(robotCount, 0.0);
    for (std::size_t r = 0; r < robotCount; ++r)
        work_[r] = robots[r].committedSeconds;
    links_.assign(robotCount * robotCount, {});

    if (lookedAt_.size() != graph_.size())
        lookedAt_.assign(graph_.size(), 0);
    for (int cell = 0; cell < static_cast<int>(graph_.size()); ++cell) {
        const int donor = owner[static_cast<std::size_t>(cell)];
        if (donor < 0 || !isFree(cell))
            continue;
        work_[static_cast<std::size_t>(donor)] += graph_.cell(cell).coverSeconds();
        offerToEveryNeighbour(cell);
    }
    int moved = 0;
    while (moved < maxMoves) {
        const std::vector<int> chain = nextChain();
        if (chain.empty())
            break;
        // From the far end back, so each region on the way gives what it gets.
        for (std::size_t k = chain.size() - 1; k-- > 0;) {
            const int cell = givableCell(chain[k], chain[k + 1]);
            if (cell < 0)
                break; // the link is now empty; the next chain avoids it
            move(cell, chain[k + 1]);
            ++moved;
        }
    }
    for (std::size_t round = 0; round < robotCount && moved < maxMoves; ++round) {
        const int handed = handOverBlock(maxMoves - moved);
        if (handed == 0)
            break;
        moved += handed;
    }
    owner_ = nullptr;
    entered_ = nullptr;
    robots_ = nullptr;
    return moved;
}

double RemainingWorkExchange::timeLeft(int robot) const {
    const double work = work_[static_cast<std::size_t>(robot)];
    const double factor = (*robots_)[static_cast<std::size_t>(robot)].speedFactor;
    if (factor > 0.0)
        return work / factor;
    return work > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

// A chain from the robot with the most time left to the moving robot with the least it can reach over
// links with cells to give; if that one gains nothing, from the next. Empty when no move would shorten the
// longest time.
std::vector<int> RemainingWorkExchange::nextChain() const {
    const int robotCount = static_cast<int>(robots_->size());
    std::vector<int> byTime(static_cast<std::size_t>(robotCount));
    std::iota(byTime.begin(), byTime.end(), 0);
    std::sort(byTime.begin(), byTime.end(), [&](int a, int b) { return timeLeft(a) > timeLeft(b); });
    for (const int from : byTime) {
        std::vector<int> previous(static_cast<std::size_t>(robotCount), -1);
        previous[static_cast<std::size_t>(from)] = from;
        std::vector<int> queue{from};
        int to = -1;
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const int region = queue[head];
            for (int next = 0; next < robotCount; ++next) {
                if (previous[static_cast<std::size_t>(next)] >= 0 || link(region, next).empty())
                    continue;
                previous[static_cast<std::size_t>(next)] = region;
                queue.push_back(next);
                if ((*robots_)[static_cast<std::size_t>(next)].speedFactor > 0.0 &&
                    (to < 0 || timeLeft(next) < timeLeft(to)))
                    to = next;
            }
        }
        if (to < 0)
            continue;
        // The receiver, one cell richer, must still finish before the donor would have.
        const double receiverAfter =
            timeLeft(to) + largestCellSeconds_ / (*robots_)[static_cast<std::size_t>(to)].speedFactor;
        if (receiverAfter >= timeLeft(from))
            continue;
        std::vector<int> chain{to};
        while (chain.back() != from)
            chain.push_back(previous[static_cast<std::size_t>(chain.back())]);
        std::reverse(chain.begin(), chain.end());
        return chain;
    }
    return {};
}

// When borders have nothing left to give (robots cover their region's edge early), the robot with the most
// time left hands a compact block of its free cells, the one nearest the robot with the least, straight to
// it: enough work to bring the two level. The receiver drives over to it. Returns the cells handed over.
int RemainingWorkExchange::handOverBlock(int maxMoves) {
    const int robotCount = static_cast<int>(robots_->size());
    int from = -1;
    int to = -1;
    for (int r = 0; r < robotCount; ++r)
        if (freeWork(r) > 0.0 && (from < 0 || timeLeft(r) > timeLeft(from)))
            from = r;
    if (from < 0)
        return 0;
    // A robot with nothing free left drives over (it would have to leave its region anyway); one with work
    // of its own only to help a robot an event slowed down.
    const bool fromSlowed = (*robots_)[static_cast<std::size_t>(from)].speedFactor < 0.999;
    for (int r = 0; r < robotCount; ++r)
        if (r != from && (*robots_)[static_cast<std::size_t>(r)].speedFactor > 0.0 &&
            (fromSlowed || freeWork(r) <= 0.0) && (to < 0 || timeLeft(r) < timeLeft(to)))
            to = r;
    if (to < 0)
        return 0;
    const double fromFactor = (*robots_)[static_cast<std::size_t>(from)].speedFactor;
    const double toFactor = (*robots_)[static_cast<std::size_t>(to)].speedFactor;
    // The work that leaves both with the same time: (Wa - x) / fa = (Wb + drive + x) / fb. A stopped robot's
    // cells go whatever their number: nobody else will cover them.
    const auto wantedAfter = [&](double drive) {
        return fromFactor > 0.0 ? (work_[static_cast<std::size_t>(from)] * toFactor -
                                   (work_[static_cast<std::size_t>(to)] + drive) * fromFactor) /
                                      (fromFactor + toFactor)
                                : std::max(freeWork(from) / static_cast<double>(robotCount), 1.0);
    };
    const double worthIt = fromFactor > 0.0 ? blockCells * largestCellSeconds_ : 0.0;
    if (wantedAfter(0.0) < worthIt) // not even without the drive: no need to look for a block
        return 0;
    const auto [seed, steps] = nearestFreeCell(from, to);
    if (seed < 0)
        return 0;
    // The drive over, a cell crossed in half the time it takes to cover.
    const double wanted = wantedAfter(steps * largestCellSeconds_ / 2.0);
    if (wanted < worthIt)
        return 0;
    return growBlock(seed, to, std::min(wanted, freeWork(from)), maxMoves);
}

double RemainingWorkExchange::freeWork(int robot) const {
    return work_[static_cast<std::size_t>(robot)] -
           (*robots_)[static_cast<std::size_t>(robot)].committedSeconds;
}

// The free cell of `donor` fewest steps from where `receiver` is, and the steps; -1 when none.
std::pair<int, int> RemainingWorkExchange::nearestFreeCell(int donor, int receiver) {
    const int from = (*robots_)[static_cast<std::size_t>(receiver)].cell;
    if (from < 0)
        return {-1, 0};
    const int stamp = nextStamp();
    steps_[static_cast<std::size_t>(from)] = 0;
    seen_[static_cast<std::size_t>(from)] = stamp;
    std::vector<int> queue{from};
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int at = queue[head];
        for (const int next : graph_.neighbours(at)) {
            if (seen_[static_cast<std::size_t>(next)] == stamp)
                continue;
            seen_[static_cast<std::size_t>(next)] = stamp;
            steps_[static_cast<std::size_t>(next)] = steps_[static_cast<std::size_t>(at)] + 1;
            if ((*owner_)[static_cast<std::size_t>(next)] == donor && isFree(next))
                return {next, steps_[static_cast<std::size_t>(next)]};
            queue.push_back(next);
        }
    }
    return {-1, 0};
}

// A fresh mark for the scratch arrays, so no search clears them.
int RemainingWorkExchange::nextStamp() {
    if (seen_.size() != graph_.size()) {
        seen_.assign(graph_.size(), 0);
        steps_.assign(graph_.size(), 0);
    }
    return ++stamp_;
}

// Hands `seed` and the free cells of its region nearest it to `receiver`, up to `seconds` of cover time.
int RemainingWorkExchange::growBlock(int seed, int receiver, double seconds, int maxMoves) {
    const int donor = (*owner_)[static_cast<std::size_t>(seed)];
    std::vector<int> block{seed};
    const int stamp = nextStamp();
    seen_[static_cast<std::size_t>(seed)] = stamp;
    double total = 0.0;
    for (std::size_t head = 0; head < block.size() && total < seconds && static_cast<int>(head) < maxMoves;
         ++head) {
        total += graph_.cell(block[head]).coverSeconds();
        for (const int next : graph_.neighbours(block[head]))
            if (seen_[static_cast<std::size_t>(next)] != stamp &&
                (*owner_)[static_cast<std::size_t>(next)] == donor && isFree(next)) {
                seen_[static_cast<std::size_t>(next)] = stamp;
                block.push_back(next);
            }
    }
    int handed = 0;
    for (const int cell : block) {
        if (handed >= maxMoves || seconds <= 0.0)
            break;
        seconds -= graph_.cell(cell).coverSeconds();
        move(cell, receiver);
        ++handed;
    }
    return handed;
}

// Whether the receiver's walk will come by: it enters every free cell of its region it reaches and looks at
// each of their sides, so a cell next to one of them needs no detour.
bool RemainingWorkExchange::touchesFreeCellOf(int cell, int region) const {
    for (const int neighbour : graph_.neighbours(cell))
        if ((*owner_)[static_cast<std::size_t>(neighbour)] == region && isFree(neighbour))
            return true;
    return false;
}

int RemainingWorkExchange::countIn(int cell, int region) const {
    int count = 0;
    for (const int neighbour : graph_.neighbours(cell))
        count += (*owner_)[static_cast<std::size_t>(neighbour)] == region ? 1 : 0;
    return count;
}

// Offers `cell` to each other region owning a free cell beside it, at its score there.
void RemainingWorkExchange::offerToEveryNeighbour(int cell) {
    const int donor = (*owner_)[static_cast<std::size_t>(cell)];
    for (const int neighbour : graph_.neighbours(cell)) {
        const int receiver = (*owner_)[static_cast<std::size_t>(neighbour)];
        if (receiver >= 0 && receiver != donor && isFree(neighbour))
            offer(cell, donor, receiver);
    }
}

// Puts `cell` of `donor` on its link to `receiver`, scored by how surrounded by the receiver it is.
void RemainingWorkExchange::offer(int cell, int donor, int receiver) {
    std::vector<Candidate>& candidates = link(donor, receiver);
    candidates.push_back({countIn(cell, receiver) - countIn(cell, donor), cell});
    std::push_heap(candidates.begin(), candidates.end());
}

// The free cell of `donor` next to `receiver` most surrounded by the receiver (smooth borders) that the
// donor can spare without falling apart near it; -1 when there is none. A link's candidates are a heap
// ranked by the score each had when offered, checked as they come up: one that changed hands or no longer
// touches the receiver's free cells is dropped, one whose score fell goes back at its new score (one whose
// score rose since was ranked at the old one and is taken as it is when it comes up), and one the donor
// cannot spare is dropped until a move of a cell beside it to the receiver offers it again. Rescoring the
// whole border for every cell moved took minutes on maps of millions of cells.
int RemainingWorkExchange::givableCell(int donor, int receiver) {
    std::vector<Candidate>& candidates = link(donor, receiver);
    const bool donorStopped = (*robots_)[static_cast<std::size_t>(donor)].speedFactor <= 0.0;
    std::vector<int> cellsLookedAt; // in this call: their other entries are repeats
    int found = -1;
    while (!candidates.empty() && found < 0) {
        std::pop_heap(candidates.begin(), candidates.end());
        const Candidate top = candidates.back();
        candidates.pop_back();
        const auto index = static_cast<std::size_t>(top.cell);
        if (lookedAt_[index] != 0 || (*owner_)[index] != donor || !isFree(top.cell) ||
            !touchesFreeCellOf(top.cell, receiver))
            continue;
        const int score = countIn(top.cell, receiver) - countIn(top.cell, donor);
        if (score < top.score) {
            candidates.push_back({score, top.cell});
            std::push_heap(candidates.begin(), candidates.end());
            continue;
        }
        lookedAt_[index] = 1;
        cellsLookedAt.push_back(top.cell);
        // The connectivity check is the dear part: it runs on the most surrounded cells first.
        if (donorStopped || connectivity_.canRemove(top.cell, *owner_, connectivitySearchLimit))
            found = top.cell;
    }
    for (const int cell : cellsLookedAt)
        lookedAt_[static_cast<std::size_t>(cell)] = 0;
    return found;
}

// Hands `cell` over and offers what the move opened: the donor's free cells beside it to the receiver,
// and the cell itself to the other regions beside it.
void RemainingWorkExchange::move(int cell, int receiver) {
    const int donor = (*owner_)[static_cast<std::size_t>(cell)];
    const double seconds = graph_.cell(cell).coverSeconds();
    work_[static_cast<std::size_t>(donor)] -= seconds;
    work_[static_cast<std::size_t>(receiver)] += seconds;
    (*owner_)[static_cast<std::size_t>(cell)] = receiver;
    for (const int neighbour : graph_.neighbours(cell)) {
        const int other = (*owner_)[static_cast<std::size_t>(neighbour)];
        if (other < 0 || !isFree(neighbour))
            continue;
        if (other == donor)
            offer(neighbour, donor, receiver);
        else if (other != receiver)
            offer(cell, receiver, other);
    }
}

} // namespace mcpp
