#include "core/coverage/TourSplitter.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace mcpp {

TourSplitter::TourSplitter(const std::vector<double>& stepSeconds)
    : reached_(stepSeconds.size() + 1, 0.0), size_(static_cast<int>(stepSeconds.size())) {
    std::partial_sum(stepSeconds.begin(), stepSeconds.end(), reached_.begin() + 1);
}

int TourSplitter::next(int index) const {
    return index + 1 == size_ ? 0 : index + 1;
}

int TourSplitter::previous(int index) const {
    return index == 0 ? size_ - 1 : index - 1;
}

double TourSplitter::forwardSeconds(int from, int to) const {
    const double difference =
        reached_[static_cast<std::size_t>(to)] - reached_[static_cast<std::size_t>(from)];
    return difference >= 0.0 ? difference : difference + reached_.back();
}

std::vector<TourSplitter::Share> TourSplitter::forwardPieces(const std::vector<int>& positions) const {
    const std::vector<int> byPlace = robotsByPlace(positions);
    std::vector<Share> orders(positions.size());
    for (std::size_t k = 0; k < byPlace.size(); ++k) {
        const int robot = byPlace[k];
        const int from = positions[static_cast<std::size_t>(robot)];
        const int following = positions[static_cast<std::size_t>(byPlace[(k + 1) % byPlace.size()])];
        std::vector<int>& order = orders[static_cast<std::size_t>(robot)].order;
        // Alone on the tour, a robot goes all the way round to the point before its own.
        const int to = previous(following);
        walk(order, from, to, true);
    }
    return orders;
}

void TourSplitter::walk(std::vector<int>& order, int from, int to, bool forwards) const {
    for (int index = from;; index = forwards ? next(index) : previous(index)) {
        order.push_back(index);
        if (index == to)
            break;
    }
}

std::vector<int> TourSplitter::robotsByPlace(const std::vector<int>& positions) {
    std::vector<int> byPlace(positions.size());
    std::iota(byPlace.begin(), byPlace.end(), 0);
    std::sort(byPlace.begin(), byPlace.end(), [&](int a, int b) {
        return positions[static_cast<std::size_t>(a)] < positions[static_cast<std::size_t>(b)];
    });
    return byPlace;
}

// Robots in `order` from order[firstRobot] on, pieces from `offset` on: each takes the most points it covers
// within the limit, its way there included. Empty where they do not cover the tour.
std::optional<std::vector<TourSplitter::Piece>> TourSplitter::piecesWithin(double limitSeconds,
                                                                           const std::vector<int>& order,
                                                                           std::size_t firstRobot, int offset,
                                                                           const Approach& approach) const {
    const std::size_t robots = order.size();
    std::vector<Piece> pieces(robots); // by place
    int covered = 0;
    int at = offset;
    for (std::size_t j = 0; j < robots; ++j) {
        const std::size_t place = (firstRobot + j) % robots;
        const int robot = order[place];
        const double toFirst = approach.seconds(robot, at);
        int taken = 0;
        for (int count = 1; covered + count <= size_; ++count) {
            const int last = (at + count - 1) % size_;
            const double piece = forwardSeconds(at, last);
            if (piece > limitSeconds)
                break;
            if (piece + std::min(toFirst, approach.seconds(robot, last)) <= limitSeconds)
                taken = count;
        }
        pieces[place] = {at, (at + std::max(taken, 1) - 1) % size_, taken == 0};
        covered += taken;
        at = (at + taken) % size_;
    }
    if (covered < size_)
        return std::nullopt;
    return pieces;
}

// The cut of the shortest makespan for robots in `order`, any of them first with its piece from its offset
// (offsets by place): a search on the makespan, each try cutting greedily.
TourSplitter::Cut TourSplitter::shortestCut(const std::vector<int>& order, const std::vector<int>& offsets,
                                            const Approach& approach) const {
    const std::size_t robots = order.size();
    const auto within = [&](double limit) -> std::optional<std::vector<Piece>> {
        for (std::size_t first = 0; first < robots; ++first)
            if (auto pieces = piecesWithin(limit, order, first, offsets[first], approach))
                return pieces;
        return std::nullopt;
    };
    // Below twice an even share, most often (doubled until the robots cover the tour); from nothing up, as
    // pieces leave out the steps between them and tiny tours may need no time at all.
    double low = 0.0;
    double high = 2.0 * reached_.back() / static_cast<double>(robots);
    std::optional<std::vector<Piece>> best = within(high);
    for (int doubling = 0; !best && doubling < 64; ++doubling) {
        low = high;
        high *= 2.0;
        best = within(high);
    }
    // To a 32 000th of the range: a makespan that near the best is as good.
    constexpr int halvings = 15;
    for (int halving = 0; halving < halvings && best; ++halving) {
        const double middle = (low + high) / 2.0;
        if (auto found = within(middle)) {
            high = middle;
            best = std::move(found);
        } else {
            low = middle;
        }
    }
    return {order, best.value_or(std::vector<Piece>(robots, Piece{0, 0, true})), high};
}

// The cut again with robots in the order of the pieces that, given each, cost them least to reach in all
// (an assignment of least total way, Hungarian method): robots far along the tour from their place may
// stand right beside another piece.
TourSplitter::Cut TourSplitter::reorderedByNearestPieces(const Cut& cut, const Approach& approach) const {
    const std::size_t robots = cut.order.size();
    const auto cost = [&](std::size_t robot, std::size_t place) {
        const Piece& piece = cut.pieces[place];
        if (piece.empty)
            return 0.0;
        // Robots share the tour's part, so their ways are finite; were one not, it must not stall the search.
        constexpr double unreachable = 1e30;
        return std::min({approach.seconds(static_cast<int>(robot), piece.first),
                         approach.seconds(static_cast<int>(robot), piece.last), unreachable});
    };
    // Potentials u (robots) and v (places), 1-based, place 0 a sentinel; robotAt[p] the robot given place p.
    const double infinite = std::numeric_limits<double>::infinity();
    std::vector<double> u(robots + 1, 0.0);
    std::vector<double> v(robots + 1, 0.0);
    std::vector<std::size_t> robotAt(robots + 1, 0);
    std::vector<std::size_t> way(robots + 1, 0);
    for (std::size_t robot = 1; robot <= robots; ++robot) {
        robotAt[0] = robot;
        std::size_t place = 0;
        std::vector<double> least(robots + 1, infinite);
        std::vector<char> used(robots + 1, 0);
        do {
            used[place] = 1;
            const std::size_t at = robotAt[place];
            double delta = infinite;
            std::size_t next = 0;
            for (std::size_t other = 1; other <= robots; ++other) {
                if (used[other] != 0)
                    continue;
                const double reduced = cost(at - 1, other - 1) - u[at] - v[other];
                if (reduced < least[other]) {
                    least[other] = reduced;
                    way[other] = place;
                }
                if (least[other] < delta) {
                    delta = least[other];
                    next = other;
                }
            }
            for (std::size_t other = 0; other <= robots; ++other) {
                if (used[other] != 0) {
                    u[robotAt[other]] += delta;
                    v[other] -= delta;
                } else {
                    least[other] -= delta;
                }
            }
            place = next;
        } while (robotAt[place] != 0);
        do {
            const std::size_t previousPlace = way[place];
            robotAt[place] = robotAt[previousPlace];
            place = previousPlace;
        } while (place != 0);
    }
    // Places follow the tour from the cut's first piece: the new order takes the robots place by place.
    std::vector<int> order(robots);
    std::vector<int> offsets(robots);
    for (std::size_t place = 1; place <= robots; ++place) {
        order[place - 1] = static_cast<int>(robotAt[place] - 1);
        offsets[place - 1] = cut.pieces[place - 1].first;
    }
    return shortestCut(order, offsets, approach);
}

std::vector<TourSplitter::Share>
TourSplitter::piecesReachedDirectly(const std::vector<int>& positions,
                                    const std::vector<std::vector<float>>& secondsToCell,
                                    const std::vector<int>& cellOfPoint) const {
    const std::size_t robots = positions.size();
    const Approach approach{secondsToCell, cellOfPoint};
    const std::vector<int> byPlace = robotsByPlace(positions);
    std::vector<int> ownPositions;
    for (const int robot : byPlace)
        ownPositions.push_back(positions[static_cast<std::size_t>(robot)]);
    Cut best = shortestCut(byPlace, ownPositions, approach);
    // A few rounds of reassignment while they shorten the makespan.
    constexpr int rounds = 3;
    for (int round = 0; round < rounds; ++round) {
        Cut reordered = reorderedByNearestPieces(best, approach);
        if (!(reordered.limitSeconds < best.limitSeconds))
            break;
        best = std::move(reordered);
    }
    std::vector<Share> shares(robots);
    for (std::size_t place = 0; place < robots; ++place) {
        const auto robot = static_cast<std::size_t>(best.order[place]);
        const Piece& piece = best.pieces[place];
        Share& share = shares[robot];
        if (piece.empty) {
            share.order = {positions[robot]};
            share.approach = 1;
            continue;
        }
        const bool forwards = approach.seconds(static_cast<int>(robot), piece.first) <=
                              approach.seconds(static_cast<int>(robot), piece.last);
        walk(share.order, forwards ? piece.first : piece.last, forwards ? piece.last : piece.first, forwards);
    }
    return shares;
}

} // namespace mcpp
