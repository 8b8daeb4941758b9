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
    [[nodiscard]] double timeLeft(int robot) const;
    [[nodiscard]] std::vector<int> nextChain() const;
    [[nodiscard]] int givableCell(int donor, int receiver);
    [[nodiscard]] int handOverBlock(int maxMoves);
    [[nodiscard]] double freeWork(int robot) const;
    [[nodiscard]] std::pair<int, int> nearestFreeCell(int donor, int receiver);
    [[nodiscard]] int nextStamp();
    int growBlock(int seed, int receiver, double seconds, int maxMoves);
    void move(int cell, int receiver);
    [[nodiscard]] int countIn(int cell, int region) const;
    [[nodiscard]] bool touchesFreeCellOf(int cell, int region) const;
    [[nodiscard]] bool isFree(int cell) const { return (*entered_)[static_cast<std::size_t>(cell)] == 0; }
    [[nodiscard]] std::vector<int>& link(int donor, int receiver) {
        return links_[static_cast<std::size_t>(donor) * robots_->size() + static_cast<std::size_t>(receiver)];
    }
    [[nodiscard]] const std::vector<int>& link(int donor, int receiver) const {
        return links_[static_cast<std::size_t>(donor) * robots_->size() + static_cast<std::size_t>(receiver)];
    }

    const CellGraph& graph_;
    LocalConnectivity connectivity_;
    double largestCellSeconds_ = 0.0;
    std::vector<int>* owner_ = nullptr;
    const std::vector<char>* entered_ = nullptr;
    const std::vector<Robot>* robots_ = nullptr;
    std::vector<double> work_; // by robot: seconds of work left at full speed
    std::vector<int> seen_;    // by cell: the stamp of the last search that reached it
    std::vector<int> steps_;   // by cell: steps from where that search began
    std::vector<char> listed_; // by cell: already kept in the candidate list being cleaned (scratch)
    int stamp_ = 0;
    std::vector<std::vector<int>> links_; // by (donor, receiver): free donor cells next to the receiver
};

} // namespace mcpp
