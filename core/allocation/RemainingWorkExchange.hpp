#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/LocalConnectivity.hpp"

#include <utility>
#include <vector>

namespace mcpp {

// MDSTC's exchange (seed 003): while robots drive, cells nobody has entered yet move across region borders
// from the robot with the most time of work left to the one with the least, along a chain of neighbouring
// regions when the two do not touch. A robot's time left is the cover time of its free cells, plus the work
// it has committed to, over its speed factor; a stopped robot (factor 0) gives away all it has left.
class RemainingWorkExchange {
  public:
    struct Robot {
        double speedFactor = 1.0;
        double committedSeconds = 0.0; // work on cells it has entered and not finished, at full speed
        int cell = -1;                 // where it is now
    };

    explicit RemainingWorkExchange(const CellGraph& graph);

    // Moves free cells (entered[cell] == 0) between the regions of `owner`, at most `maxMoves` of them;
    // returns how many moved.
    int exchange(std::vector<int>& owner, const std::vector<char>& entered, const std::vector<Robot>& robots,
                 int maxMoves);

  private:
    struct Candidate {
        int score; // the receiver's cells beside it, less the donor's
        int cell;
        friend bool operator<(const Candidate& a, const Candidate& b) {
            return a.score != b.score ? a.score < b.score : a.cell < b.cell;
        }
    };

    [[nodiscard]] double timeLeft(int robot) const;
    [[nodiscard]] std::vector<int> nextChain() const;
    [[nodiscard]] int givableCell(int donor, int receiver);
    [[nodiscard]] int handOverBlock(int maxMoves);
    [[nodiscard]] double freeWork(int robot) const;
    [[nodiscard]] std::pair<int, int> nearestFreeCell(int donor, int receiver);
    [[nodiscard]] int nextStamp();
    int growBlock(int seed, int receiver, double seconds, int maxMoves);
    void move(int cell, int receiver);
    void offer(int cell, int donor, int receiver);
    void offerToEveryNeighbour(int cell);
    [[nodiscard]] int countIn(int cell, int region) const;
    [[nodiscard]] bool touchesFreeCellOf(int cell, int region) const;
    [[nodiscard]] bool isFree(int cell) const { return (*entered_)[static_cast<std::size_t>(cell)] == 0; }
    [[nodiscard]] std::vector<Candidate>& link(int donor, int receiver) {
        return links_[static_cast<std::size_t>(donor) * robots_->size() + static_cast<std::size_t>(receiver)];
    }
    [[nodiscard]] const std::vector<Candidate>& link(int donor, int receiver) const {
        return links_[static_cast<std::size_t>(donor) * robots_->size() + static_cast<std::size_t>(receiver)];
    }

    const CellGraph& graph_;
    LocalConnectivity connectivity_;
    double largestCellSeconds_ = 0.0;
    std::vector<int>* owner_ = nullptr;
    const std::vector<char>* entered_ = nullptr;
    const std::vector<Robot>* robots_ = nullptr;
    std::vector<double> work_;   // by robot: seconds of work left at full speed
    std::vector<int> seen_;      // by cell: the stamp of the last search that reached it
    std::vector<int> steps_;     // by cell: steps from where that search began
    std::vector<char> lookedAt_; // by cell: already looked at by the givableCell under way (scratch)
    int stamp_ = 0;
    // By (donor, receiver): a heap of free donor cells offered to the receiver, best first; entries may be
    // stale (givableCell checks them).
    std::vector<std::vector<Candidate>> links_;
};

} // namespace mcpp
