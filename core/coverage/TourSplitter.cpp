#include "core/coverage/TourSplitter.hpp"

#include <algorithm>
#include <cmath>
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
    std::vector<int> byPlace(positions.size());
    std::iota(byPlace.begin(), byPlace.end(), 0);
    std::sort(byPlace.begin(), byPlace.end(), [&](int a, int b) {
        return positions[static_cast<std::size_t>(a)] < positions[static_cast<std::size_t>(b)];
    });
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

std::vector<int> TourSplitter::robotsByPlace(const std::vector<int>& positions) const {
    std::vector<int> byPlace(positions.size());
    std::iota(byPlace.begin(), byPlace.end(), 0);
    std::sort(byPlace.begin(), byPlace.end(), [&](int a, int b) {
        return positions[static_cast<std::size_t>(a)] < positions[static_cast<std::size_t>(b)];
    });
    return byPlace;
}

// Robots in their order along the tour from byPlace[firstRobot], pieces from `offset` on: each takes the
// most points it covers within the limit, its way there included. Empty where they do not cover the tour.
std::optional<std::vector<TourSplitter::Piece>>
TourSplitter::piecesWithin(double limitSeconds, const std::vector<int>& byPlace, std::size_t firstRobot,
                           int offset, const std::vector<std::vector<float>>& secondsToCell,
                           const std::vector<int>& cellOfPoint) const {
    const std::size_t robots = byPlace.size();
    std::vector<Piece> pieces(robots); // by place
    int covered = 0;
    int at = offset;
    for (std::size_t j = 0; j < robots; ++j) {
        const std::size_t place = (firstRobot + j) % robots;
        const std::vector<float>& toCell = secondsToCell[static_cast<std::size_t>(byPlace[place])];
        const auto approach = [&](int point) {
            return static_cast<double>(
                toCell[static_cast<std::size_t>(cellOfPoint[static_cast<std::size_t>(point)])]);
        };
        const double toFirst = approach(at);
        int taken = 0;
        for (int count = 1; covered + count <= size_; ++count) {
            const int last = (at + count - 1) % size_;
            const double piece = forwardSeconds(at, last);
            if (piece > limitSeconds)
                break;
            if (piece + std::min(toFirst, approach(last)) <= limitSeconds)
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

std::vector<TourSplitter::Share>
TourSplitter::piecesReachedDirectly(const std::vector<int>& positions,
                                    const std::vector<std::vector<float>>& secondsToCell,
                                    const std::vector<int>& cellOfPoint) const {
    const std::size_t robots = positions.size();
    const std::vector<int> byPlace = robotsByPlace(positions);
    // The pieces within a limit, the first robot's at its own position, for any robot first.
    const auto within = [&](double limit) -> std::optional<std::pair<std::vector<Piece>, std::size_t>> {
        for (std::size_t first = 0; first < robots; ++first)
            if (auto pieces =
                    piecesWithin(limit, byPlace, first, positions[static_cast<std::size_t>(byPlace[first])],
                                 secondsToCell, cellOfPoint))
                return std::make_pair(std::move(*pieces), first);
        return std::nullopt;
    };
    // Between an even share and twice it, most often: doubled until the robots cover the tour.
    double low = reached_.back() / static_cast<double>(robots);
    double high = 2.0 * low;
    auto best = within(high);
    for (int doubling = 0; !best && doubling < 64; ++doubling) {
        low = high;
        high *= 2.0;
        best = within(high);
    }
    // To a 16 000th of the range: a makespan that near the best is as good.
    constexpr int halvings = 14;
    for (int halving = 0; halving < halvings && best; ++halving) {
        const double middle = (low + high) / 2.0;
        if (auto found = within(middle)) {
            high = middle;
            best = std::move(found);
        } else {
            low = middle;
        }
    }
    std::vector<Share> shares(robots);
    for (std::size_t place = 0; place < robots && best; ++place) {
        const auto robot = static_cast<std::size_t>(byPlace[place]);
        const Piece& piece = best->first[place];
        Share& share = shares[robot];
        if (piece.empty) {
            share.order = {positions[robot]};
            share.approach = 1;
            continue;
        }
        const std::vector<float>& toCell = secondsToCell[robot];
        const auto approach = [&](int point) {
            return toCell[static_cast<std::size_t>(cellOfPoint[static_cast<std::size_t>(point)])];
        };
        const bool forwards = approach(piece.first) <= approach(piece.last);
        walk(share.order, forwards ? piece.first : piece.last, forwards ? piece.last : piece.first, forwards);
    }
    return shares;
}

} // namespace mcpp
