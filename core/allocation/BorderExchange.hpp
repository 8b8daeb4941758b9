#pragma once

#include "core/coverage/CellIndexScope.hpp"
#include "core/model/CellGraph.hpp"
#include "core/model/ProgressReporter.hpp"

#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

namespace mcpp {

// Brings connected regions to equal cover time by passing single border cells from the region with the most
// time to the one with the least, along a chain of neighbouring regions. A donor only gives a cell it can
// spare without falling apart and never its start; when it has none, it may give a cell together with the
// part of it that hangs on that cell. The receiver touches what it gets, so it stays in one piece. Among
// the cells a donor could give, the one most surrounded by the receiver goes first, then the one the caller
// prefers, which keeps borders smooth. Cells and regions are numbered locally, 0..n-1.
class BorderExchange {
  public:
    // Lower is more willing: how readily `receiver` takes `cell` from `donor`.
    using Preference = std::function<std::int64_t(int cell, int receiver, int donor)>;

    BorderExchange(const CellGraph& graph, const std::vector<int>& cells, const CellIndexScope& local,
                   std::vector<double> weights, std::vector<int> startCells, Preference preference);

    // Exchanges cells until every region is within `toleranceSeconds` of the fair share, no chain can pass
    // a cell, the moves run out or the exchanges stop getting closer; then keeps the closest division seen.
    // `owner` holds each cell's region; returns the largest error left.
    double balance(std::vector<int>& owner, double toleranceSeconds,
                   const ProgressReporter& progress = ProgressReporter{});

    // Chains passed along in the last balance, those that moved no cell included.
    [[nodiscard]] std::size_t exchangesMade() const { return exchanges_; }
    // The largest error of the division the last balance stopped at, before it went back to the best.
    [[nodiscard]] double errorWhenStopped() const { return errorWhenStopped_; }

  private:
    struct Candidate {
        int spareNeighbours; // the donor's cells next to it, less the receiver's
        std::int64_t preference;
        int cell;
        bool operator>(const Candidate& other) const;
    };
    struct Passage {
        int moved;     // cells that changed hands
        bool complete; // every link passed at least one
    };
    struct Spread {
        double largest = 0.0; // the largest distance of a region's cost from the fair share
        double squares = 0.0; // the sum of the squared distances
    };
    struct Move {
        int cell;
        int previousOwner;
    };
    using CandidateQueue = std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>>;

    [[nodiscard]] std::size_t pair(int donor, int receiver) const;
    [[nodiscard]] Candidate candidate(int cell, int donor, int receiver) const;
    void offerNeighboursOf(int cell);
    [[nodiscard]] std::vector<int> nextChain() const;
    [[nodiscard]] std::vector<int> reachedFrom(int from) const;
    Passage passAlong(const std::vector<int>& chain, int cellsPerLink, double pieceSeconds);
    void move(int cell, int receiver);
    void returnToBest();
    [[nodiscard]] int givableCell(int donor, int receiver);
    [[nodiscard]] std::vector<int> givablePiece(int donor, int receiver, double limitSeconds);
    [[nodiscard]] std::vector<int> hangingOn(int cell, int region, double limitSeconds);
    [[nodiscard]] bool isRemovable(int cell, int region);
    void changed(int region); // a cell moved in or out: its version is new
    [[nodiscard]] int countIn(int cell, int region) const;
    [[nodiscard]] Spread spread() const;
    [[nodiscard]] bool isCloser(const Spread& a, const Spread& b) const;

    std::vector<int> adjacencyStart_; // local adjacency, compressed rows
    std::vector<int> adjacency_;
    std::vector<double> weight_;
    std::vector<int> start_;
    Preference preference_;
    std::size_t regionCount_;
    double fairShare_ = 0.0;
    double largestCell_ = 0.0;
    std::vector<int>* owner_ = nullptr;
    std::vector<double> cost_;
    std::vector<std::size_t> cellCount_; // by region
    std::vector<CandidateQueue> queues_; // per (donor, receiver)
    std::vector<char> closed_;           // per (donor, receiver): no cell to give since the last exchange
    std::size_t exchanges_ = 0;
    double errorWhenStopped_ = 0.0;
    std::vector<Move> movesSinceBest_; // undone at the end when a later exchange did not improve on them
    std::vector<int> visitStamp_;
    int stamp_ = 0;
    // Whether a cell can leave its region depends on that region's cells alone: each region carries a
    // version, new at every move in or out, and a cell found unable to leave is not searched again until
    // its region's version changes (corridor regions keep dozens of such cells on their borders).
    std::vector<std::uint64_t> regionVersion_;
    std::vector<std::uint64_t> keptAtVersion_; // per cell: its region's version when it could not leave
    std::uint64_t lastVersion_ = 0;
    std::vector<int> inRegion_; // isRemovable's buffers
    std::vector<int> searchQueue_;
};

} // namespace mcpp
