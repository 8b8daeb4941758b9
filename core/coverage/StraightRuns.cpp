#include "core/coverage/StraightRuns.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

namespace mcpp {
namespace {

bool isHorizontal(CellSide side) {
    return side == CellSide::East || side == CellSide::West;
}

// At most four: two ends, each with at most one equal neighbour north and one south.
struct ConflictList {
    std::array<int, 4> ids{};
    std::size_t count = 0;
    [[nodiscard]] const int* begin() const { return ids.data(); }
    [[nodiscard]] const int* end() const { return ids.data() + count; }
    [[nodiscard]] std::size_t size() const { return count; }
    [[nodiscard]] int operator[](std::size_t i) const { return ids[i]; }
};

// A north-south straight adjacency is numbered by its northern cell: a cell has at most one equal
// neighbour south of it, so the numbers are the nodes' and the matching keeps one slot a node, not one an
// adjacency.
int northernEnd(const RegionAdjacency::Edge& edge) {
    return edge.sideOfFirst == CellSide::South ? edge.first : static_cast<int>(edge.second);
}

// The north-south straight adjacencies (by their northern cells) an east-west one conflicts with: those
// of its two ends, in the order the ends' incidences list them. Worked out when asked from 5 bytes a node:
// the cell north of it (the adjacency above it), whether it has one below, and which of the two comes
// first.
class Conflicts {
  public:
    Conflicts(const RegionAdjacency& adjacency, std::vector<int> leftEdges)
        : edges_(adjacency.edges()), leftEdges_(std::move(leftEdges)), north_(adjacency.nodeCount(), -1),
          below_(adjacency.nodeCount(), 0) {
        for (std::size_t node = 0; node < north_.size(); ++node) {
            int found = 0;
            for (const auto& incidence : adjacency.incident(static_cast<int>(node))) {
                if (!edges_[static_cast<std::size_t>(incidence.edge)].straight ||
                    isHorizontal(incidence.side))
                    continue;
                if (found == 2 ||
                    (incidence.side == CellSide::North ? north_[node] >= 0 : (below_[node] & hasBelow) != 0))
                    throw std::logic_error("a cell with more than two straight north-south neighbours");
                if (incidence.side == CellSide::North)
                    north_[node] = incidence.other;
                else
                    below_[node] |= found == 0 ? hasBelow | belowFirst : hasBelow;
                ++found;
            }
        }
    }
    [[nodiscard]] std::size_t leftCount() const { return leftEdges_.size(); }
    [[nodiscard]] int edgeOfLeft(std::size_t left) const { return leftEdges_[left]; }
    // The north-south adjacencies the east-west one `left` conflicts with.
    [[nodiscard]] ConflictList of(int left) const {
        ConflictList list;
        const auto& ends = edges_[static_cast<std::size_t>(leftEdges_[static_cast<std::size_t>(left)])];
        for (const int node : {ends.first, static_cast<int>(ends.second)}) {
            const auto at = static_cast<std::size_t>(node);
            const int above = north_[at];
            const bool hasBelowEdge = (below_[at] & hasBelow) != 0;
            if (hasBelowEdge && (below_[at] & belowFirst) != 0)
                list.ids[list.count++] = node;
            if (above >= 0)
                list.ids[list.count++] = above;
            if (hasBelowEdge && (below_[at] & belowFirst) == 0)
                list.ids[list.count++] = node;
        }
        return list;
    }

  private:
    static constexpr unsigned char hasBelow = 1;
    static constexpr unsigned char belowFirst = 2; // listed before the adjacency above

    const std::vector<RegionAdjacency::Edge>& edges_;
    std::vector<int> leftEdges_;       // the east-west straight adjacencies, by edge number
    std::vector<int> north_;           // the equal cell north of a node in a straight run, or -1
    std::vector<unsigned char> below_; // hasBelow, belowFirst
};

// Hopcroft-Karp between east-west straight adjacencies (left, numbered in order) and north-south ones
// (right, by northern cell) that conflict.
class BipartiteMatching {
  public:
    BipartiteMatching(const Conflicts& conflicts, std::size_t rightCount)
        : conflicts_(conflicts), leftCount_(conflicts.leftCount()), matchOfLeft_(leftCount_, -1),
          matchOfRight_(rightCount, -1), distance_(leftCount_, unreached) {}

    void solve(const ProgressReporter* progress) {
        // A greedy first matching leaves Hopcroft-Karp a few long paths instead of many phases.
        for (std::size_t left = 0; left < leftCount_; ++left)
            for (int right : rightOf(static_cast<int>(left)))
                if (matchOfRight_[static_cast<std::size_t>(right)] < 0) {
                    matchOfRight_[static_cast<std::size_t>(right)] = static_cast<int>(left);
                    matchOfLeft_[left] = right;
                    break;
                }
        // Only free left vertices start a path, and a left vertex is matched only by its own path: each
        // phase works through the free ones of the last, in order, instead of through every left vertex.
        for (std::size_t left = 0; left < leftCount_; ++left)
            if (matchOfLeft_[left] < 0)
                freeLeft_.push_back(static_cast<int>(left));
        if (progress != nullptr)
            progress->throwIfCancelled();
        // Phases past a few add a handful of runs on maps of a million cells but cost seconds: the last
        // ones find paths of hundreds of edges one or two at a time.
        for (int phase = 0; phase < phaseLimit && layer(); ++phase) {
            if (progress != nullptr)
                progress->throwIfCancelled();
            for (const int left : freeLeft_)
                augment(left);
            std::erase_if(freeLeft_,
                          [&](int left) { return matchOfLeft_[static_cast<std::size_t>(left)] >= 0; });
        }
        // Only the matching is read from here on: the search's arrays go before the caller makes its own.
        for (auto* workspace : {&distance_, &freeLeft_, &queue_})
            std::vector<int>().swap(*workspace);
        std::vector<Frame>().swap(stack_);
    }
    [[nodiscard]] const std::vector<int>& matchOfLeft() const { return matchOfLeft_; }
    [[nodiscard]] const std::vector<int>& matchOfRight() const { return matchOfRight_; }
    [[nodiscard]] ConflictList rightOf(int left) const { return conflicts_.of(left); }
    [[nodiscard]] std::size_t leftCount() const { return leftCount_; }

  private:
    static constexpr int unreached = std::numeric_limits<int>::max();
    static constexpr int phaseLimit = 16;

    // Breadth-first layers from the free left vertices; true while an augmenting path exists. Only the
    // last phase's queue holds distances to clear: a vertex gets one only when it is queued.
    bool layer() {
        std::vector<int>& queue = queue_;
        for (const int left : queue)
            distance_[static_cast<std::size_t>(left)] = unreached;
        queue.assign(freeLeft_.begin(), freeLeft_.end());
        for (const int left : queue)
            distance_[static_cast<std::size_t>(left)] = 0;
        int shortest = unreached; // layers beyond the shortest augmenting path are of no use this phase
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const int left = queue[head];
            if (distance_[static_cast<std::size_t>(left)] >= shortest)
                break;
            for (int right : rightOf(left)) {
                const int next = matchOfRight_[static_cast<std::size_t>(right)];
                if (next < 0)
                    shortest = std::min(shortest, distance_[static_cast<std::size_t>(left)] + 1);
                else if (distance_[static_cast<std::size_t>(next)] == unreached) {
                    distance_[static_cast<std::size_t>(next)] = distance_[static_cast<std::size_t>(left)] + 1;
                    queue.push_back(next);
                }
            }
        }
        return shortest != unreached;
    }

    struct Frame {
        int left;
        std::size_t next;
    };

    // Depth-first along the layers, iteratively: the paths of a big region are far deeper than a stack.
    bool augment(int root) {
        std::vector<Frame>& stack = stack_;
        stack.clear();
        stack.push_back({root, 0});
        while (!stack.empty()) {
            Frame& frame = stack.back();
            const auto candidates = rightOf(frame.left);
            if (frame.next == candidates.size()) {
                distance_[static_cast<std::size_t>(frame.left)] = unreached; // a dead end this phase
                stack.pop_back();
                continue;
            }
            const int right = candidates[frame.next++];
            const int next = matchOfRight_[static_cast<std::size_t>(right)];
            if (next < 0) {
                // Flip the path: each left vertex on the stack takes the right vertex it went through.
                int taken = right;
                for (auto it = stack.rbegin(); it != stack.rend(); ++it) {
                    const int previous = matchOfLeft_[static_cast<std::size_t>(it->left)];
                    matchOfLeft_[static_cast<std::size_t>(it->left)] = taken;
                    matchOfRight_[static_cast<std::size_t>(taken)] = it->left;
                    taken = previous;
                }
                return true;
            }
            if (distance_[static_cast<std::size_t>(next)] ==
                distance_[static_cast<std::size_t>(frame.left)] + 1)
                stack.push_back({next, 0});
        }
        return false;
    }

    const Conflicts& conflicts_;
    std::size_t leftCount_;
    std::vector<int> matchOfLeft_;
    std::vector<int> matchOfRight_;
    std::vector<int> distance_;
    std::vector<int> freeLeft_; // ascending
    std::vector<int> queue_;    // layer's, kept for its capacity and to clear its distances
    std::vector<Frame> stack_;
};

} // namespace

std::vector<char> straightRuns(const RegionAdjacency& adjacency, const ProgressReporter* progress) {
    const auto& edges = adjacency.edges();
    // East-west straight adjacencies are the left vertices, in edge order; north-south ones the right
    // vertices, by their northern cells.
    std::vector<int> leftEdges;
    leftEdges.reserve(
        static_cast<std::size_t>(std::count_if(edges.begin(), edges.end(), [](const auto& edge) {
            return edge.straight && isHorizontal(edge.sideOfFirst);
        })));
    for (std::size_t e = 0; e < edges.size(); ++e)
        if (edges[e].straight && isHorizontal(edges[e].sideOfFirst))
            leftEdges.push_back(static_cast<int>(e));
    const Conflicts conflicts(adjacency, std::move(leftEdges));
    BipartiteMatching matching(conflicts, adjacency.nodeCount());
    matching.solve(progress);
    // Konig: left vertices reached from free left vertices by alternating paths, plus right vertices not
    // reached, form the largest independent set.
    std::vector<char> reachedLeft(conflicts.leftCount(), 0);
    std::vector<char> reachedRight(adjacency.nodeCount(), 0);
    std::vector<int> queue;
    for (std::size_t left = 0; left < conflicts.leftCount(); ++left)
        if (matching.matchOfLeft()[left] < 0) {
            reachedLeft[left] = 1;
            queue.push_back(static_cast<int>(left));
        }
    for (std::size_t head = 0; head < queue.size(); ++head)
        for (int right : matching.rightOf(queue[head])) {
            if (reachedRight[static_cast<std::size_t>(right)] != 0)
                continue;
            reachedRight[static_cast<std::size_t>(right)] = 1;
            const int next = matching.matchOfRight()[static_cast<std::size_t>(right)];
            if (next >= 0 && reachedLeft[static_cast<std::size_t>(next)] == 0) {
                reachedLeft[static_cast<std::size_t>(next)] = 1;
                queue.push_back(next);
            }
        }
    std::vector<char> kept(edges.size(), 0);
    for (std::size_t e = 0; e < edges.size(); ++e)
        kept[e] = edges[e].straight && !isHorizontal(edges[e].sideOfFirst) &&
                          reachedRight[static_cast<std::size_t>(northernEnd(edges[e]))] == 0
                      ? 1
                      : 0;
    for (std::size_t left = 0; left < conflicts.leftCount(); ++left)
        kept[static_cast<std::size_t>(conflicts.edgeOfLeft(left))] = reachedLeft[left];
    return kept;
}

} // namespace mcpp
