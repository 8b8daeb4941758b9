#pragma once

#include <cstddef>
#include <vector>

namespace mcpp {

// Cuts one closed tour into one piece per robot (MSTC, Hazon & Kaminka). The tour is a cycle of points;
// stepSeconds[i] is the time from point i to point i + 1 (the last step closes the cycle). A robot's
// visit order is a list of tour indices: the way to its piece first, if any, then the piece.
class TourSplitter {
  public:
    // One robot's share: the tour indices it passes in order; the first `approach` of them only lead to
    // its piece (they lie in other robots' pieces).
    struct Share {
        std::vector<int> order;
        std::size_t approach = 0;
    };

    explicit TourSplitter(const std::vector<double>& stepSeconds);

    // Without backtracking: each robot goes forward from its own position to the next robot's.
    [[nodiscard]] std::vector<Share> forwardPieces(const std::vector<int>& positions) const;

    // Balanced: pieces of equal time, each robot walking along the tour, forwards or backwards, to one end
    // of its own; the cuts and the order of robots along the tour are chosen for the shortest makespan.
    [[nodiscard]] std::vector<Share> balancedPieces(const std::vector<int>& positions) const;

  private:
    struct Piece {
        int first; // tour index
        int last;  // tour index; the piece runs forward from first to last
        bool empty;
    };
    struct Route {
        double seconds;
        Share share;
    };

    [[nodiscard]] double forwardSeconds(int from, int to) const;
    [[nodiscard]] int next(int index) const;
    [[nodiscard]] int previous(int index) const;
    [[nodiscard]] int indexAtTime(double seconds) const;
    [[nodiscard]] Route route(int position, const Piece& piece, bool withOrder) const;
    void walk(std::vector<int>& order, int from, int to, bool forwards) const;
    [[nodiscard]] std::vector<Piece> equalPieces(double offsetSeconds, std::size_t count) const;

    std::vector<double> reached_; // time from point 0 to each point, going forward; the tour's time last
    int size_;
};

} // namespace mcpp
