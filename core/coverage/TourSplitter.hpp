#pragma once

#include <cstddef>
#include <optional>
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

    // Balanced: each robot goes to its piece by a way of its own, not along the tour:
    // secondsToCell[k][cellOfPoint[i]] is robot k's time from its start to tour point i. Pieces are cut
    // for the shortest makespan, way there included, robots first in their order along the tour, then in
    // the order of the pieces that cost them least to reach in all; each enters its piece at the end it
    // reaches sooner. A Share holds its piece only, from that end (approach 0); a robot
    // left no piece stays at its position (approach 1).
    [[nodiscard]] std::vector<Share>
    piecesReachedDirectly(const std::vector<int>& positions,
                          const std::vector<std::vector<float>>& secondsToCell,
                          const std::vector<int>& cellOfPoint) const;

  private:
    struct Piece {
        int first; // tour index
        int last;  // tour index; the piece runs forward from first to last
        bool empty;
    };
    // Robots' times to the tour's points.
    struct Approach {
        const std::vector<std::vector<float>>& secondsToCell;
        const std::vector<int>& cellOfPoint;
        [[nodiscard]] double seconds(int robot, int point) const {
            return secondsToCell[static_cast<std::size_t>(robot)]
                                [static_cast<std::size_t>(cellOfPoint[static_cast<std::size_t>(point)])];
        }
    };
    // Robots in a cyclic order, the piece of each (by place in it) and the makespan they keep within.
    struct Cut {
        std::vector<int> order;
        std::vector<Piece> pieces;
        double limitSeconds = 0.0;
    };

    [[nodiscard]] double forwardSeconds(int from, int to) const;
    [[nodiscard]] int next(int index) const;
    [[nodiscard]] int previous(int index) const;
    void walk(std::vector<int>& order, int from, int to, bool forwards) const;
    [[nodiscard]] std::optional<std::vector<Piece>> piecesWithin(double limitSeconds,
                                                                 const std::vector<int>& order,
                                                                 std::size_t firstRobot, int offset,
                                                                 const Approach& approach) const;
    [[nodiscard]] Cut shortestCut(const std::vector<int>& order, const std::vector<int>& offsets,
                                  const Approach& approach) const;
    [[nodiscard]] Cut reorderedByNearestPieces(const Cut& cut, const Approach& approach) const;
    [[nodiscard]] static std::vector<int> robotsByPlace(const std::vector<int>& positions);

    std::vector<double> reached_; // time from point 0 to each point, going forward; the tour's time last
    int size_;
};

} // namespace mcpp
