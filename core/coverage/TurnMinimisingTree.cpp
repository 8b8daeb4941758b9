#include "core/coverage/TurnMinimisingTree.hpp"

#include "core/coverage/StraightRuns.hpp"

#include <bit>
#include <numeric>

namespace mcpp {
namespace {

constexpr unsigned eastWest = 0b0101U;
constexpr unsigned northSouth = 0b1010U;

unsigned bitOf(CellSide side) {
    return 1U << static_cast<unsigned>(side);
}

// Turns a walk makes in a cell joined on the sides in `mask` (an unjoined cell will be a leaf), by mask.
constexpr std::array<int, 16> turnsByMask = [] {
    std::array<int, 16> turns{};
    for (unsigned mask = 0; mask < 16; ++mask) {
        const int sides = std::popcount(mask);
        turns[mask] = sides == 4 ? 4 : (sides == 2 && (mask == eastWest || mask == northSouth) ? 0 : 2);
    }
    return turns;
}();

int turnsInCell(unsigned mask) {
    return turnsByMask[mask];
}

unsigned maskOf(const std::array<std::uint16_t, 4>& counts) {
    unsigned mask = 0;
    for (unsigned side = 0; side < 4; ++side)
        if (counts[side] > 0)
            mask |= 1U << side;
    return mask;
}

class DisjointSets {
  public:
    explicit DisjointSets(std::size_t count) : root_(count) { std::iota(root_.begin(), root_.end(), 0); }
    int find(int x) {
        while (root_[static_cast<std::size_t>(x)] != x) {
            root_[static_cast<std::size_t>(x)] =
                root_[static_cast<std::size_t>(root_[static_cast<std::size_t>(x)])];
            x = root_[static_cast<std::size_t>(x)];
        }
        return x;
    }
    bool unite(int a, int b) {
        a = find(a);
        b = find(b);
        if (a == b)
            return false;
        root_[static_cast<std::size_t>(a)] = b;
        return true;
    }

  private:
    std::vector<int> root_;
};

} // namespace

TurnMinimisingTree::TurnMinimisingTree(const RegionAdjacency& adjacency, Options options,
                                       const SizeChangeConnectors* connectors)
    : adjacency_(adjacency), options_(options), connectors_(connectors),
      sides_(adjacency.nodeCount(), SideCounts{}), inTree_(adjacency.edges().size(), 0) {
    joinRuns(straightRuns(adjacency, options_.progress));
    throwIfCancelled();
    rootTree();
    for (int pass = 0; pass < options_.swapPasses; ++pass) {
        int swaps = 0;
        for (std::size_t edge = 0; edge < inTree_.size(); ++edge) {
            if ((edge & 0xFFFFU) == 0)
                throwIfCancelled();
            if (inTree_[edge] == 0 && trySwap(static_cast<int>(edge)))
                ++swaps;
        }
        if (swaps == 0)
            break;
    }
    if (connectors_ == nullptr && options_.plateauRounds > 0)
        searchPlateaus();
}

void TurnMinimisingTree::searchPlateaus() {
    turns_ = estimatedTurns();
    changedInRound_.assign(adjacency_.nodeCount(), 0);
    const int initial = turns_;
    int fewest = turns_;
    std::vector<char> fewestTree = inTree_;
    std::vector<int> order(inTree_.size());
    std::iota(order.begin(), order.end(), 0);
    const auto changedNow = [&](int node) {
        return changedInRound_[static_cast<std::size_t>(node)] == round_;
    };
    for (round_ = 1; round_ <= options_.plateauRounds; ++round_) {
        throwIfCancelled();
        shuffle(order);
        for (const int edge : order)
            if (inTree_[static_cast<std::size_t>(edge)] == 0)
                trySwap(edge, Accept::FewerOrAsMany);
        // Only a swap near a moved cell can have begun to pay.
        for (const int edge : order) {
            const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
            if (inTree_[static_cast<std::size_t>(edge)] == 0 && (changedNow(e.first) || changedNow(e.second)))
                trySwap(edge);
        }
        if (turns_ < fewest) {
            fewest = turns_;
            fewestTree = inTree_;
        }
    }
    // Sideways swaps after the last gain leave the count but not the tree: back to the tree of the gain, or
    // to the tree built without the search.
    if (inTree_ != fewestTree)
        restore(fewestTree);
    searchLowered_ = fewest < initial;
    changedInRound_ = {};
}

void TurnMinimisingTree::throwIfCancelled() const {
    if (options_.progress != nullptr)
        options_.progress->throwIfCancelled();
}

void TurnMinimisingTree::shuffle(std::vector<int>& order) {
    for (std::size_t i = order.size(); i > 1; --i) {
        shuffleState_ ^= shuffleState_ << 13U;
        shuffleState_ ^= shuffleState_ >> 17U;
        shuffleState_ ^= shuffleState_ << 5U;
        std::swap(order[i - 1], order[shuffleState_ % i]);
    }
}

void TurnMinimisingTree::restore(const std::vector<char>& tree) {
    for (std::size_t edge = 0; edge < inTree_.size(); ++edge) {
        if (inTree_[edge] == tree[edge])
            continue;
        if (tree[edge] != 0)
            link(static_cast<int>(edge));
        else
            unlink(static_cast<int>(edge));
    }
    rootTree(); // the count needs no recount: the search ends here
}

int TurnMinimisingTree::turnChangeAdding(int node, CellSide side) const {
    const SideCounts& counts = sides_[static_cast<std::size_t>(node)];
    if (counts[static_cast<std::size_t>(side)] > 0)
        return 0;
    const unsigned mask = maskOf(counts);
    return turnsInCell(mask | bitOf(side)) - turnsInCell(mask);
}

int TurnMinimisingTree::turnChangeRemoving(int node, CellSide side) const {
    const SideCounts& counts = sides_[static_cast<std::size_t>(node)];
    if (counts[static_cast<std::size_t>(side)] > 1)
        return 0;
    const unsigned mask = maskOf(counts);
    return turnsInCell(mask & ~bitOf(side)) - turnsInCell(mask);
}

int TurnMinimisingTree::joinCost(int edge) const {
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    return turnChangeAdding(e.first, e.sideOfFirst) + turnChangeAdding(e.second, oppositeSide(e.sideOfFirst));
}

// What adding an edge changes, for a swap: turns, or with connectors, seconds (turns at their cells'
// price and the steps between cells of different sizes).
double TurnMinimisingTree::swapCostAdding(int edge) {
    if (connectors_ == nullptr)
        return joinCost(edge);
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    return turnSecondsOf(e.first, turnChangeAdding(e.first, e.sideOfFirst)) +
           turnSecondsOf(e.second, turnChangeAdding(e.second, oppositeSide(e.sideOfFirst))) +
           connectors_->changeOnToggle(edge, inTree_);
}

double TurnMinimisingTree::swapCostRemoving(int edge) {
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const int first = turnChangeRemoving(e.first, e.sideOfFirst);
    const int second = turnChangeRemoving(e.second, oppositeSide(e.sideOfFirst));
    if (connectors_ == nullptr)
        return first + second;
    return turnSecondsOf(e.first, first) + turnSecondsOf(e.second, second) +
           connectors_->changeOnToggle(edge, inTree_);
}

double TurnMinimisingTree::turnSecondsOf(int node, int turns) const {
    return turns == 0 ? 0.0 : turns * connectors_->turnSeconds(node);
}

void TurnMinimisingTree::link(int edge) {
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    inTree_[static_cast<std::size_t>(edge)] = 1;
    ++sides_[static_cast<std::size_t>(e.first)][static_cast<std::size_t>(e.sideOfFirst)];
    ++sides_[static_cast<std::size_t>(e.second)][static_cast<std::size_t>(oppositeSide(e.sideOfFirst))];
}

void TurnMinimisingTree::unlink(int edge) {
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    inTree_[static_cast<std::size_t>(edge)] = 0;
    --sides_[static_cast<std::size_t>(e.first)][static_cast<std::size_t>(e.sideOfFirst)];
    --sides_[static_cast<std::size_t>(e.second)][static_cast<std::size_t>(oppositeSide(e.sideOfFirst))];
}

// Kruskal with costs that change as cells gain sides: a bucket queue by cost (-4..4), each edge re-queued
// when one of its cells changes, and re-checked when it comes out.
void TurnMinimisingTree::joinRuns(const std::vector<char>& inRuns) {
    const auto& edges = adjacency_.edges();
    DisjointSets components(adjacency_.nodeCount());
    for (std::size_t edge = 0; edge < edges.size(); ++edge)
        if (inRuns[edge] != 0 && components.unite(edges[edge].first, edges[edge].second))
            link(static_cast<int>(edge));
    constexpr int lowest = -4;
    std::array<std::vector<int>, 9> buckets;
    std::array<std::size_t, 9> heads{};
    auto queue = [&](int edge) {
        buckets[static_cast<std::size_t>(joinCost(edge) - lowest)].push_back(edge);
    };
    // Buckets sized before they are filled: on a region of millions of cells they would otherwise grow
    // through a dozen copies. Edges queued again as their cells gain sides add up to a third (uniform
    // grids of a million cells).
    std::array<std::size_t, 9> firstCounts{};
    for (std::size_t edge = 0; edge < edges.size(); ++edge)
        if (inTree_[edge] == 0)
            ++firstCounts[static_cast<std::size_t>(joinCost(static_cast<int>(edge)) - lowest)];
    for (std::size_t bucket = 0; bucket < buckets.size(); ++bucket)
        buckets[bucket].reserve(firstCounts[bucket] + firstCounts[bucket] / 2);
    for (std::size_t edge = 0; edge < edges.size(); ++edge)
        if (inTree_[edge] == 0)
            queue(static_cast<int>(edge));
    for (;;) {
        std::size_t bucket = 0;
        while (bucket < buckets.size() && heads[bucket] == buckets[bucket].size())
            ++bucket;
        if (bucket == buckets.size())
            return;
        const int edge = buckets[bucket][heads[bucket]++];
        const auto& e = edges[static_cast<std::size_t>(edge)];
        if (components.find(e.first) == components.find(e.second))
            continue;
        const auto cost = static_cast<std::size_t>(joinCost(edge) - lowest);
        if (cost > bucket) {
            buckets[cost].push_back(edge);
            continue;
        }
        components.unite(e.first, e.second);
        link(edge);
        for (const int node : {e.first, static_cast<int>(e.second)})
            for (const auto& incidence : adjacency_.incident(node))
                if (inTree_[static_cast<std::size_t>(incidence.edge)] == 0 &&
                    components.find(incidence.other) != components.find(node))
                    queue(incidence.edge);
    }
}

void TurnMinimisingTree::rootTree() {
    const std::size_t count = adjacency_.nodeCount();
    parent_.assign(count, -1);
    parentEdge_.assign(count, -1);
    stamp_.assign(count, 0);
    std::vector<char> seen(count, 0);
    std::vector<int> queue;
    queue.reserve(count);
    for (std::size_t root = 0; root < count; ++root) {
        if (seen[root] != 0)
            continue;
        seen[root] = 1;
        queue.assign(1, static_cast<int>(root));
        for (std::size_t head = 0; head < queue.size(); ++head)
            for (const auto& incidence : adjacency_.incident(queue[head])) {
                if (inTree_[static_cast<std::size_t>(incidence.edge)] == 0 ||
                    seen[static_cast<std::size_t>(incidence.other)] != 0)
                    continue;
                seen[static_cast<std::size_t>(incidence.other)] = 1;
                parent_[static_cast<std::size_t>(incidence.other)] = queue[head];
                parentEdge_[static_cast<std::size_t>(incidence.other)] = incidence.edge;
                queue.push_back(incidence.other);
            }
    }
}

// Adds `edge` if dropping some tree edge of the cycle it closes lowers the turn count (or the time).
bool TurnMinimisingTree::trySwap(int edge, Accept accept) {
    // Counted in whole turns, dropping a tree edge saves at most two turns at each of its ends (a walk
    // turns 0, 2 or 4 times in a cell): an edge that adds four can never pay for itself, and its cycle is
    // not looked for. Across a comb's teeth, that is most edges.
    constexpr int mostTurnsSavedByDropping = 4;
    if (connectors_ == nullptr && joinCost(edge) >= mostTurnsSavedByDropping)
        return false;
    const auto& e = adjacency_.edges()[static_cast<std::size_t>(edge)];
    const int u = e.first;
    const int v = e.second;
    // The lowest common ancestor: both walks climb in turn, and the first cell one reaches that the other
    // has passed is it. Each climbs at most cycleLimit cells.
    const int fromFirst = ++stampValue_;
    const int fromSecond = ++stampValue_;
    int meeting = -1;
    int a = u;
    int b = v;
    for (int step = 0; step <= options_.cycleLimit && meeting < 0 && (a >= 0 || b >= 0); ++step) {
        if (a >= 0) {
            if (stamp_[static_cast<std::size_t>(a)] == fromSecond)
                meeting = a;
            stamp_[static_cast<std::size_t>(a)] = fromFirst;
            a = parent_[static_cast<std::size_t>(a)];
        }
        if (b >= 0 && meeting < 0) {
            if (stamp_[static_cast<std::size_t>(b)] == fromFirst)
                meeting = b;
            stamp_[static_cast<std::size_t>(b)] = fromSecond;
            b = parent_[static_cast<std::size_t>(b)];
        }
    }
    if (meeting < 0)
        return false;
    const double adding = swapCostAdding(edge);
    link(edge);
    const auto [bestChild, bestChange] = edgeToDrop(u, v, meeting, adding, accept);
    // Turn counts are whole numbers; seconds need a margin so that rounding never swaps back and forth.
    const double wanted = accept == Accept::Fewer ? -1e-9 : 1e-9;
    if (bestChild < 0 || adding + bestChange >= wanted) {
        unlink(edge);
        return false;
    }
    turns_ += static_cast<int>(adding + bestChange); // searchPlateaus runs on turns only
    if (!changedInRound_.empty())
        for (const int node : {u, v, bestChild, parent_[static_cast<std::size_t>(bestChild)]})
            changedInRound_[static_cast<std::size_t>(node)] = round_;
    // bestChild's subtree holds u or v: re-hang it from that end through the new edge.
    bool onFirstSide = false;
    for (int node = u; node != meeting; node = parent_[static_cast<std::size_t>(node)])
        onFirstSide = onFirstSide || node == bestChild;
    unlink(parentEdge_[static_cast<std::size_t>(bestChild)]);
    if (onFirstSide)
        reverseChain(u, bestChild, v, edge);
    else
        reverseChain(v, bestChild, u, edge);
    return true;
}

// The tree edge of the cycle through u and v (below `meeting`) whose removal changes the count least, as
// the cell it hangs from and the change; for FewerOrAsMany, the first that keeps the count or lowers it.
TurnMinimisingTree::Drop TurnMinimisingTree::edgeToDrop(int u, int v, int meeting, double adding,
                                                        Accept accept) {
    Drop best;
    for (int end : {u, v})
        for (int node = end; node != meeting; node = parent_[static_cast<std::size_t>(node)]) {
            const double change = swapCostRemoving(parentEdge_[static_cast<std::size_t>(node)]);
            if (best.child < 0 || change < best.change)
                best = {node, change};
            if (accept == Accept::FewerOrAsMany && adding + best.change < 1e-9)
                return best;
        }
    return best;
}

// Makes `from` the top of the chain from..to (to's parent edge already dropped) and hangs it from newParent.
void TurnMinimisingTree::reverseChain(int from, int to, int newParent, int viaEdge) {
    std::vector<int>& chain = chain_;
    chain.assign(1, from);
    while (chain.back() != to)
        chain.push_back(parent_[static_cast<std::size_t>(chain.back())]);
    for (std::size_t i = chain.size() - 1; i > 0; --i) {
        parent_[static_cast<std::size_t>(chain[i])] = chain[i - 1];
        parentEdge_[static_cast<std::size_t>(chain[i])] = parentEdge_[static_cast<std::size_t>(chain[i - 1])];
    }
    parent_[static_cast<std::size_t>(from)] = newParent;
    parentEdge_[static_cast<std::size_t>(from)] = viaEdge;
}

std::vector<std::pair<int, int>> TurnMinimisingTree::edges() const {
    std::vector<std::pair<int, int>> result;
    result.reserve(adjacency_.nodeCount()); // a tree, or a forest of fewer edges
    for (std::size_t edge = 0; edge < inTree_.size(); ++edge)
        if (inTree_[edge] != 0)
            result.emplace_back(adjacency_.edges()[edge].first, adjacency_.edges()[edge].second);
    return result;
}

int TurnMinimisingTree::estimatedTurns() const {
    int turns = 0;
    for (const auto& counts : sides_)
        turns += turnsInCell(maskOf(counts));
    return turns;
}

} // namespace mcpp
