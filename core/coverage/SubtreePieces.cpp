#include "core/coverage/SubtreePieces.hpp"

#include "core/coverage/GridTurnRule.hpp"
#include "core/coverage/TreeCircumnavigation.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace mcpp {

SubtreePieces::SubtreePieces(const CellGraph& graph, const SpanningTree& tree,
                             const std::vector<int>& startCells, const std::vector<MapPoint>& starts,
                             const ProgressReporter& progress, int mostMoves)
    : graph_(graph), tree_(tree), starts_(starts), nodeOfCell_(graph.size(), -1),
      startNode_(startCells.size(), -1), adjacency_(tree.size()), piece_(tree.size(), -1),
      parent_(tree.size(), -1), localOfNode_(tree.size(), -1), subtreeCells_(tree.size(), 0),
      pieceNodes_(startCells.size()), seconds_(startCells.size(), 0.0), turns_(startCells.size(), 0) {
    for (std::size_t node = 0; node < tree.size(); ++node) {
        nodeOfCell_[static_cast<std::size_t>(tree.cellOf(static_cast<int>(node)))] = static_cast<int>(node);
        for (const int next : tree.neighbours(static_cast<int>(node)))
            adjacency_[node].push_back(next);
    }
    for (std::size_t robot = 0; robot < startCells.size(); ++robot)
        startNode_[robot] = nodeOfCell_[static_cast<std::size_t>(startCells[robot])];
    cutFromBestRoot(progress);
    evenOut(progress, mostMoves);
}

// Where no move evens the walks out for real (their turns change too), the estimate's best is made: the
// pieces could then trade branches back and forth, so the search stops once the longest piece has not
// shortened for a while, or the longest lies within a thousandth of the mean, and goes back to the
// division whose longest piece was shortest.
void SubtreePieces::evenOut(const ProgressReporter& progress, int mostMoves) {
    constexpr int patience = 32;
    double longest = longestSeconds();
    std::vector<std::vector<int>> shortestForest = adjacency_; // the division whose longest piece is shortest
    int sinceShortened = 0;
    for (int moves = 0; moves < mostMoves && sinceShortened < patience && !evenEnough(); ++moves) {
        if ((moves & 15) == 0)
            progress.throwIfCancelled();
        const Move move = bestMove();
        if (move.branch < 0)
            break;
        apply(move);
        ++sinceShortened;
        if (const double now = longestSeconds(); now < longest) {
            longest = now;
            shortestForest = adjacency_;
            sinceShortened = 0;
        }
    }
    if (sinceShortened > 0) { // moves made since the shortest division: back to it
        adjacency_ = std::move(shortestForest);
        labelAndMeasureAll();
    }
}

// The cut bottom up depends on where the tree is held from: each start is tried, and
// the cut whose pieces' times have the least sum of squares (what the moves then lower) is kept: fewer
// moves even it out, and each costs turns (100 x 100 cells with 14 robots: 6 153 turns and 1.0044 times the
// lower bound from the tree's root, 6 111 and 1.0018 from the best).
void SubtreePieces::cutFromBestRoot(const ProgressReporter& progress) {
    const std::vector<std::vector<int>> whole = adjacency_;
    // Held from a start, the root's part always has a start; held from elsewhere it might have none.
    std::vector<std::vector<int>> bestCut;
    double leastSquares = std::numeric_limits<double>::infinity();
    for (const int root : startNode_) {
        progress.throwIfCancelled();
        adjacency_ = whole;
        cutBottomUp(root);
        labelAndMeasureAll();
        if (const double squares = sumOfSquares(); bestCut.empty() || squares < leastSquares) {
            leastSquares = squares;
            bestCut = adjacency_;
        }
    }
    adjacency_ = std::move(bestCut);
    labelAndMeasureAll();
}

void SubtreePieces::labelAndMeasureAll() {
    for (std::size_t robot = 0; robot < startNode_.size(); ++robot) {
        label(robot);
        measure(robot);
    }
}

// Bottom up from `root`: a node's open part is itself and its children's parts not yet cut off. Two starts
// never share a part (the larger parts with a start are cut off, the smallest kept), and a part with a
// start is cut off once it reaches a fair share.
void SubtreePieces::cutBottomUp(int root) {
    const std::size_t nodes = tree_.size();
    const double fairShare = static_cast<double>(nodes) / static_cast<double>(startNode_.size());
    std::vector<int> startAt(nodes, -1);
    for (std::size_t robot = 0; robot < startNode_.size(); ++robot)
        startAt[static_cast<std::size_t>(startNode_[robot])] = static_cast<int>(robot);
    std::vector<int> parentOf(nodes, -1);
    std::vector<int> order{root}; // breadth first from the root; walked backwards, children come first
    order.reserve(nodes);
    for (std::size_t head = 0; head < order.size(); ++head)
        for (const int next : tree_.neighbours(order[head]))
            if (next != parentOf[static_cast<std::size_t>(order[head])]) {
                parentOf[static_cast<std::size_t>(next)] = order[head];
                order.push_back(next);
            }
    std::reverse(order.begin(), order.end());
    std::vector<int> openCells(nodes, 0);
    std::vector<int> openStart(nodes, -1);
    std::vector<char> cutOff(nodes, 0);
    for (const int node : order) {
        int cells = 1;
        int start = startAt[static_cast<std::size_t>(node)];
        std::vector<int> withStarts;
        for (const int child : tree_.neighbours(node)) {
            if (child == parentOf[static_cast<std::size_t>(node)] ||
                cutOff[static_cast<std::size_t>(child)] != 0)
                continue;
            if (openStart[static_cast<std::size_t>(child)] >= 0)
                withStarts.push_back(child);
            else
                cells += openCells[static_cast<std::size_t>(child)];
        }
        std::sort(withStarts.begin(), withStarts.end(), [&](int a, int b) {
            return openCells[static_cast<std::size_t>(a)] < openCells[static_cast<std::size_t>(b)];
        });
        for (const int child : withStarts) {
            if (start >= 0) {
                cutOff[static_cast<std::size_t>(child)] = 1;
                continue;
            }
            start = openStart[static_cast<std::size_t>(child)];
            cells += openCells[static_cast<std::size_t>(child)];
        }
        openCells[static_cast<std::size_t>(node)] = cells;
        openStart[static_cast<std::size_t>(node)] = start;
        if (start >= 0 && cells >= fairShare && parentOf[static_cast<std::size_t>(node)] >= 0)
            cutOff[static_cast<std::size_t>(node)] = 1;
    }
    for (std::size_t node = 0; node < nodes; ++node)
        if (cutOff[node] != 0)
            cutEdge(static_cast<int>(node), parentOf[node]);
}

double SubtreePieces::sumOfSquares() const {
    return std::accumulate(seconds_.begin(), seconds_.end(), 0.0,
                           [](double sum, double seconds) { return sum + seconds * seconds; });
}

double SubtreePieces::meanSeconds() const {
    return std::accumulate(seconds_.begin(), seconds_.end(), 0.0) / static_cast<double>(seconds_.size());
}

double SubtreePieces::longestSeconds() const {
    return *std::max_element(seconds_.begin(), seconds_.end());
}

int SubtreePieces::totalTurns() const {
    return std::accumulate(turns_.begin(), turns_.end(), 0);
}

bool SubtreePieces::evenEnough() const {
    return longestSeconds() <= 1.001 * meanSeconds();
}

void SubtreePieces::cutEdge(int a, int b) {
    auto& ofA = adjacency_[static_cast<std::size_t>(a)];
    ofA.erase(std::find(ofA.begin(), ofA.end(), b));
    auto& ofB = adjacency_[static_cast<std::size_t>(b)];
    ofB.erase(std::find(ofB.begin(), ofB.end(), a));
}

// The robot's piece from its start: its nodes in breadth-first order, their parents and subtree sizes.
void SubtreePieces::label(std::size_t robot) {
    std::vector<int>& nodes = pieceNodes_[robot];
    nodes.assign(1, startNode_[robot]);
    parent_[static_cast<std::size_t>(startNode_[robot])] = -1;
    for (std::size_t head = 0; head < nodes.size(); ++head) {
        const int node = nodes[head];
        piece_[static_cast<std::size_t>(node)] = static_cast<int>(robot);
        for (const int next : adjacency_[static_cast<std::size_t>(node)]) {
            if (next == parent_[static_cast<std::size_t>(node)])
                continue;
            parent_[static_cast<std::size_t>(next)] = node;
            nodes.push_back(next);
        }
    }
    for (auto node = nodes.rbegin(); node != nodes.rend(); ++node) {
        int cells = 1;
        for (const int next : adjacency_[static_cast<std::size_t>(*node)])
            if (next != parent_[static_cast<std::size_t>(*node)])
                cells += subtreeCells_[static_cast<std::size_t>(next)];
        subtreeCells_[static_cast<std::size_t>(*node)] = cells;
    }
}

SpanningTree SubtreePieces::pieceTree(std::size_t robot) const {
    const std::vector<int>& nodes = pieceNodes_[robot];
    std::vector<int>& localOf = localOfNode_;
    std::vector<int> cells;
    cells.reserve(nodes.size());
    for (const int node : nodes) {
        localOf[static_cast<std::size_t>(node)] = static_cast<int>(cells.size());
        cells.push_back(tree_.cellOf(node));
    }
    std::vector<std::pair<int, int>> edges;
    edges.reserve(nodes.size());
    for (const int node : nodes)
        if (const int parent = parent_[static_cast<std::size_t>(node)]; parent >= 0)
            edges.emplace_back(localOf[static_cast<std::size_t>(node)],
                               localOf[static_cast<std::size_t>(parent)]);
    for (const int node : nodes)
        localOf[static_cast<std::size_t>(node)] = -1; // left as found: linear in the piece, not the part
    return {std::move(cells), 0, edges};
}

void SubtreePieces::measure(std::size_t robot) {
    TreeCircumnavigation walker(graph_);
    const PathShape shape = walker.walkShape(pieceTree(robot), starts_[robot], false);
    seconds_[robot] = shape.seconds();
    turns_[robot] = shape.turns();
}

// Each node with a grid neighbour in another piece, with that neighbour: visit(node, other), once per pair.
template <typename Visit> void SubtreePieces::forEachBorder(Visit&& visit) const {
    for (std::size_t node = 0; node < tree_.size(); ++node)
        for (const int neighbourCell : graph_.neighbours(tree_.cellOf(static_cast<int>(node)))) {
            const int other = nodeOfCell_[static_cast<std::size_t>(neighbourCell)];
            if (other >= 0 && piece_[static_cast<std::size_t>(other)] != piece_[node])
                visit(static_cast<int>(node), other);
        }
}

// Of all branches that can move to a neighbouring piece of shorter time, the `count` that lower the sum of
// the squares of the pieces' times most, their time taken as their cells at the map's mean time a cell. A
// branch is the subtree below a node on the way from a cell on the piece's border up to its start.
std::vector<SubtreePieces::Move> SubtreePieces::candidateMoves(std::size_t count) const {
    const double cellSeconds = std::accumulate(seconds_.begin(), seconds_.end(), 0.0) /
                               static_cast<double>(std::max<std::size_t>(tree_.size(), 1));
    std::vector<Move> best; // kept sorted, most lowering first
    const auto offer = [&](const Move& move) {
        if (best.size() == count && move.change >= best.back().change)
            return;
        const bool known = std::any_of(best.begin(), best.end(), [&](const Move& other) {
            return other.branch == move.branch && other.to == move.to;
        });
        if (known)
            return;
        best.insert(std::upper_bound(best.begin(), best.end(), move,
                                     [](const Move& a, const Move& b) { return a.change < b.change; }),
                    move);
        if (best.size() > count)
            best.pop_back();
    };
    forEachBorder([&](int node, int other) {
        const auto robot = static_cast<std::size_t>(piece_[static_cast<std::size_t>(node)]);
        const double gap = seconds_[robot] - seconds_[static_cast<std::size_t>(piece_[other])];
        for (int branch = node; branch != startNode_[robot];
             branch = parent_[static_cast<std::size_t>(branch)]) {
            const double moved = subtreeCells_[static_cast<std::size_t>(branch)] * cellSeconds;
            const double change = 2.0 * moved * (moved - gap);
            if (change < 0.0)
                offer({branch, node, other, change});
            if (2.0 * moved >= gap)
                break; // branches only grow on the way up, and past half the gap they gain less
        }
    });
    return best;
}

// The candidates made for real: of those that lower the sum of the squares of the pieces' walk times at
// least half as much as the best of them, the one that adds the fewest turns. Turns are what a move costs
// beyond its time: a branch handed over may leave a U-turn where it was cut off and add one where it joins.
SubtreePieces::Move SubtreePieces::bestMove() {
    // Each trial walks the two pieces: a dozen trials where pieces are small, fewer where each holds
    // thousands of cells (200 x 200 cells with 4 robots took 11 s with a dozen).
    const double meanPieceCells = static_cast<double>(tree_.size()) / static_cast<double>(startNode_.size());
    const auto trials = static_cast<std::size_t>(std::clamp(40000.0 / meanPieceCells, 3.0, 12.0));
    const std::vector<Move> candidates = candidateMoves(trials);
    std::vector<TrialOutcome> tried;
    for (const Move& move : candidates)
        tried.push_back(trial(move));
    double bestChange = 0.0;
    for (const TrialOutcome& outcome : tried)
        bestChange = std::min(bestChange, outcome.squaresChange);
    Move chosen;
    int fewestTurns = std::numeric_limits<int>::max();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const TrialOutcome& outcome = tried[i];
        if (outcome.squaresChange < 0.0 && outcome.squaresChange <= 0.5 * bestChange &&
            outcome.turnsChange < fewestTurns) {
            fewestTurns = outcome.turnsChange;
            chosen = candidates[i];
        }
    }
    if (chosen.branch < 0 && !candidates.empty())
        chosen = candidates.front(); // none evens out for real: the estimate's best, patience stops it
    return chosen;
}

// What a move would do, undone again.
SubtreePieces::TrialOutcome SubtreePieces::trial(const Move& move) {
    const auto from = static_cast<std::size_t>(piece_[static_cast<std::size_t>(move.branch)]);
    const auto to = static_cast<std::size_t>(piece_[static_cast<std::size_t>(move.to)]);
    const double secondsFrom = seconds_[from];
    const double secondsTo = seconds_[to];
    const int turnsFrom = turns_[from];
    const int turnsTo = turns_[to];
    const int parent = parent_[static_cast<std::size_t>(move.branch)];
    apply(move);
    TrialOutcome outcome;
    outcome.squaresChange = seconds_[from] * seconds_[from] + seconds_[to] * seconds_[to] -
                            secondsFrom * secondsFrom - secondsTo * secondsTo;
    outcome.turnsChange = turns_[from] + turns_[to] - turnsFrom - turnsTo;
    outcome.longerSeconds = std::max(seconds_[from], seconds_[to]);
    cutEdge(move.from, move.to);
    adjacency_[static_cast<std::size_t>(move.branch)].push_back(parent);
    adjacency_[static_cast<std::size_t>(parent)].push_back(move.branch);
    label(from);
    label(to);
    seconds_[from] = secondsFrom;
    seconds_[to] = secondsTo;
    turns_[from] = turnsFrom;
    turns_[to] = turnsTo;
    return outcome;
}

void SubtreePieces::apply(const Move& move) {
    const auto from = static_cast<std::size_t>(piece_[static_cast<std::size_t>(move.branch)]);
    const auto to = static_cast<std::size_t>(piece_[static_cast<std::size_t>(move.to)]);
    cutEdge(move.branch, parent_[static_cast<std::size_t>(move.branch)]);
    adjacency_[static_cast<std::size_t>(move.from)].push_back(move.to);
    adjacency_[static_cast<std::size_t>(move.to)].push_back(move.from);
    label(from);
    label(to);
    measure(from);
    measure(to);
}

// Sweeps over the small border branches, making each move that saves turns and leaves both pieces within
// the budget, until a sweep saves none. Branches of a few cells are where a cut leaves its ragged edge
// (100 x 100 cells with 14 robots: branches of up to 4 cells save 58 turns, 8 cells 90, 16 cells 89).
int SubtreePieces::saveTurns(double mostSeconds, const ProgressReporter& progress, double mostWalkedNodes) {
    const double budget = std::max(longestSeconds(), mostSeconds);
    const int turnsBefore = totalTurns();
    const double meanPieceCells = static_cast<double>(tree_.size()) / static_cast<double>(startNode_.size());
    const auto mostTrials = static_cast<long>(mostWalkedNodes / (2.0 * meanPieceCells)); // two pieces a trial
    long trials = 0;
    for (bool saved = true; saved && trials < mostTrials;) {
        saved = false;
        for (const Move& move : smallBorderMoves()) {
            if (trials >= mostTrials)
                break;
            // An earlier move of the sweep may have changed its branch or taken its neighbour; and only
            // moves that save turns where they are made are worth a trial.
            if (!stillPossible(move) || turnChangeOnGrid(move) >= 0)
                continue;
            if (++trials % 64 == 0)
                progress.throwIfCancelled();
            const TrialOutcome outcome = trial(move);
            if (outcome.turnsChange < 0 && outcome.longerSeconds <= budget) {
                apply(move);
                saved = true;
            }
        }
    }
    return turnsBefore - totalTurns();
}

// Every branch of at most mostBranchCells cells with a cell next to another piece, as a move to that piece.
std::vector<SubtreePieces::Move> SubtreePieces::smallBorderMoves() const {
    std::vector<Move> moves;
    forEachBorder([&](int node, int other) {
        const int start = startNode_[static_cast<std::size_t>(piece_[static_cast<std::size_t>(node)])];
        for (int branch = node;
             branch != start && subtreeCells_[static_cast<std::size_t>(branch)] <= mostBranchCells;
             branch = parent_[static_cast<std::size_t>(branch)])
            moves.push_back({branch, node, other, 0.0});
    });
    return moves;
}

// Whether a listed move can still be made: its branch still small, below its piece's start and above its
// joining node, and the node it joins still in another piece.
bool SubtreePieces::stillPossible(const Move& move) const {
    const int robot = piece_[static_cast<std::size_t>(move.branch)];
    if (subtreeCells_[static_cast<std::size_t>(move.branch)] > mostBranchCells ||
        piece_[static_cast<std::size_t>(move.from)] != robot ||
        piece_[static_cast<std::size_t>(move.to)] == robot ||
        move.branch == startNode_[static_cast<std::size_t>(robot)])
        return false;
    // The way up from the joining node to the branch is shorter than the branch holds cells.
    int node = move.from;
    for (int step = 0;
         node != move.branch && node >= 0 && step < subtreeCells_[static_cast<std::size_t>(move.branch)];
         ++step)
        node = parent_[static_cast<std::size_t>(node)];
    return node == move.branch;
}

// The quarter a neighbouring node's cell lies in, seen from `node`'s: 0 east, 1 north, 2 west, 3 south.
int SubtreePieces::sideOf(int node, int other) const {
    const Cell& here = graph_.cell(tree_.cellOf(node));
    const Cell& there = graph_.cell(tree_.cellOf(other));
    if (there.column >= here.column + here.span)
        return 0;
    if (there.row + there.span <= here.row)
        return 1;
    if (there.column + there.span <= here.column)
        return 2;
    return 3;
}

// Bit s set where the node has a forest edge on side s.
unsigned SubtreePieces::sidesWithEdges(int node) const {
    unsigned sides = 0;
    for (const int next : adjacency_[static_cast<std::size_t>(node)])
        sides |= 1U << sideOf(node, next);
    return sides;
}

// The change of the walks' turns a move makes where its edges change, as on a grid of like cells with
// every sub-cell free: a sieve before the trial, which walks both pieces. Near a start (where an open walk
// begins and ends), by cells of other sizes or blocked sub-cells it may be wrong, and a move it sieves out
// there is lost (on the benchmark grids, at most one a run).
int SubtreePieces::turnChangeOnGrid(const Move& move) const {
    std::array<std::pair<int, unsigned>, 4> sidesOfNode{};
    std::size_t known = 0;
    const auto sidesOf = [&](int node) -> unsigned& {
        for (std::size_t i = 0; i < known; ++i)
            if (sidesOfNode[i].first == node)
                return sidesOfNode[i].second;
        sidesOfNode[known] = {node, sidesWithEdges(node)};
        return sidesOfNode[known++].second;
    };
    const int parent = parent_[static_cast<std::size_t>(move.branch)];
    int change = GridTurnRule::toggle(sidesOf(move.branch), sideOf(move.branch, parent));
    change += GridTurnRule::toggle(sidesOf(parent), sideOf(parent, move.branch));
    change += GridTurnRule::toggle(sidesOf(move.from), sideOf(move.from, move.to));
    change += GridTurnRule::toggle(sidesOf(move.to), sideOf(move.to, move.from));
    return change;
}

} // namespace mcpp
