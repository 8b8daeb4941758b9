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

// The first point at or after a time along the tour (times wrap round).
int TourSplitter::indexAtTime(double seconds) const {
    const double total = reached_.back();
    double wrapped = std::fmod(seconds, total);
    if (wrapped < 0.0)
        wrapped += total;
    const auto found = std::lower_bound(reached_.begin(), reached_.end() - 1, wrapped);
    const auto index = static_cast<int>(found - reached_.begin());
    return index >= size_ ? 0 : index;
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

std::vector<TourSplitter::Piece> TourSplitter::equalPieces(double offsetSeconds, std::size_t count) const {
    const double length = reached_.back() / static_cast<double>(count);
    std::vector<int> cuts;
    for (std::size_t k = 0; k < count; ++k)
        cuts.push_back(indexAtTime(offsetSeconds + static_cast<double>(k) * length));
    std::vector<Piece> pieces;
    for (std::size_t k = 0; k < count; ++k) {
        const int first = cuts[k];
        const int end = cuts[(k + 1) % count];
        const bool empty = count > 1 && first == end;
        pieces.push_back({first, previous(end), empty});
    }
    return pieces;
}

void TourSplitter::walk(std::vector<int>& order, int from, int to, bool forwards) const {
    for (int index = from;; index = forwards ? next(index) : previous(index)) {
        order.push_back(index);
        if (index == to)
            break;
    }
}

// The quickest way for a robot at `position` to cover `piece`: from inside it, back to one end first; from
// outside, along the tour to the nearer end, forwards or backwards.
TourSplitter::Route TourSplitter::route(int position, const Piece& piece, bool withOrder) const {
    Route best{std::numeric_limits<double>::infinity(), {}};
    if (piece.empty) {
        best.seconds = 0.0;
        if (withOrder) {
            best.share.order = {position};
            best.share.approach = 1; // it stays where it is, in another robot's piece
        }
        return best;
    }
    const double length = forwardSeconds(piece.first, piece.last);
    const bool inside = forwardSeconds(piece.first, position) <= length;
    struct Option {
        double seconds;
        int approachEnd; // the end reached first
        bool approachForwards;
    };
    std::vector<Option> options;
    if (inside) {
        options.push_back({forwardSeconds(piece.first, position) + length, piece.first, false});
        options.push_back({forwardSeconds(position, piece.last) + length, piece.last, true});
    } else {
        options.push_back({forwardSeconds(position, piece.first) + length, piece.first, true});
        options.push_back({forwardSeconds(piece.last, position) + length, piece.last, false});
    }
    const Option chosen =
        *std::min_element(options.begin(), options.end(),
                          [](const Option& a, const Option& b) { return a.seconds < b.seconds; });
    best.seconds = chosen.seconds;
    if (!withOrder)
        return best;
    walk(best.share.order, position, chosen.approachEnd, chosen.approachForwards);
    best.share.order.pop_back(); // the end is where the piece begins
    best.share.approach = best.share.order.size();
    const bool pieceForwards = chosen.approachEnd == piece.first;
    walk(best.share.order, chosen.approachEnd, pieceForwards ? piece.last : piece.first, pieceForwards);
    return best;
}

std::vector<TourSplitter::Share> TourSplitter::balancedPieces(const std::vector<int>& positions) const {
    const std::size_t robots = positions.size();
    std::vector<int> byPlace(robots);
    std::iota(byPlace.begin(), byPlace.end(), 0);
    std::sort(byPlace.begin(), byPlace.end(), [&](int a, int b) {
        return positions[static_cast<std::size_t>(a)] < positions[static_cast<std::size_t>(b)];
    });
    // Cuts at a robot's position, or half a piece after it; robots keep their order along the tour.
    const double half = reached_.back() / static_cast<double>(robots) / 2.0;
    double bestMakespan = std::numeric_limits<double>::infinity();
    std::vector<Piece> bestPieces;
    std::size_t bestShift = 0;
    for (int position : positions)
        for (double offset : {reached_[static_cast<std::size_t>(position)],
                              reached_[static_cast<std::size_t>(position)] + half}) {
            const std::vector<Piece> pieces = equalPieces(offset, robots);
            for (std::size_t shift = 0; shift < robots; ++shift) {
                double makespan = 0.0;
                for (std::size_t k = 0; k < robots && makespan < bestMakespan; ++k) {
                    const int robot = byPlace[k];
                    makespan = std::max(makespan, route(positions[static_cast<std::size_t>(robot)],
                                                        pieces[(k + shift) % robots], false)
                                                      .seconds);
                }
                if (makespan < bestMakespan) {
                    bestMakespan = makespan;
                    bestPieces = pieces;
                    bestShift = shift;
                }
            }
        }
    std::vector<Share> orders(robots);
    for (std::size_t k = 0; k < robots; ++k) {
        const auto robot = static_cast<std::size_t>(byPlace[k]);
        orders[robot] = route(positions[robot], bestPieces[(k + bestShift) % robots], true).share;
    }
    return orders;
}

} // namespace mcpp
