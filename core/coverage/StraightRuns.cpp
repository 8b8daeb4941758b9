#include "core/coverage/StraightRuns.hpp"

#include <algorithm>
#include <limits>
#include <span>

namespace mcpp {
namespace {

bool isHorizontal(CellSide side) {
    return side == CellSide::East || side == CellSide::West;
}

// Hopcroft-Karp over a bipartite graph given as left-vertex adjacency lists (compressed).
class BipartiteMatching {
  public:
    BipartiteMatching(std::vector<int> offsets, std::vector<int> targets, std::size_t rightCount)
        : offsets_(std::move(offsets)), targets_(std::move(targets)), leftCount_(offsets_.size() - 1),
          matchOfLeft_(leftCount_, -1), matchOfRight_(rightCount, -1), distance_(leftCount_, unreached) {}

    void solve() {
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
        // Phases past a few add a handful of runs on maps of a million cells but cost seconds: the last
        // ones find paths of hundreds of edges one or two at a time.
        for (int phase = 0; phase < phaseLimit && layer(); ++phase) {
            for (const int left : freeLeft_)
                augment(left);
            std::erase_if(freeLeft_,
                          [&](int left) { return matchOfLeft_[static_cast<std::size_t>(left)] >= 0; });
        }
    }
    [[nodiscard]] const std::vector<int>& matchOfLeft() const { return matchOfLeft_; }
    [[nodiscard]] const std::vector<int>& matchOfRight() const { return matchOfRight_; }
    [[nodiscard]] std::span<const int> rightOf(int left) const {
        const auto begin = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(left)]);
        const auto end = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(left) + 1]);
        return {targets_.data() + begin, end - begin};
    }
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

    std::vector<int> offsets_;
    std::vector<int> targets_;
    std::size_t leftCount_;
    std::vector<int> matchOfLeft_;
    std::vector<int> matchOfRight_;
    std::vector<int> distance_;
    std::vector<int> freeLeft_; // ascending
    std::vector<int> queue_;    // layer's, kept for its capacity and to clear its distances
    std::vector<Frame> stack_;
};

} // namespace

std::vector<char> straightRuns(const RegionAdjacency& adjacency) {
    const auto& edges = adjacency.edges();
    // Straight adjacencies become vertices: east-west ones on the left, north-south ones on the right.
    std::vector<int> vertexOfEdge(edges.size(), -1);
    std::vector<int> leftEdges;
    std::vector<int> rightEdges;
    const auto horizontal =
        static_cast<std::size_t>(std::count_if(edges.begin(), edges.end(), [](const auto& edge) {
            return edge.straight && isHorizontal(edge.sideOfFirst);
        }));
    leftEdges.reserve(horizontal);
    rightEdges.reserve(static_cast<std::size_t>(std::count_if(
                           edges.begin(), edges.end(), [](const auto& edge) { return edge.straight; })) -
                       horizontal);
    for (std::size_t e = 0; e < edges.size(); ++e) {
        if (!edges[e].straight)
            continue;
        auto& side = isHorizontal(edges[e].sideOfFirst) ? leftEdges : rightEdges;
        vertexOfEdge[e] = static_cast<int>(side.size());
        side.push_back(static_cast<int>(e));
    }
    // A conflict for every east-west and north-south straight adjacency sharing a cell.
    std::vector<int> offsets(leftEdges.size() + 1, 0);
    std::vector<int> targets;
    // A cell has at most one equal neighbour in its column on either side, so an east-west adjacency
    // conflicts with at most four north-south ones.
    targets.reserve(4 * leftEdges.size());
    auto conflictsOf = [&](int edge, auto&& visit) {
        const auto& ends = edges[static_cast<std::size_t>(edge)];
        for (const int node : {ends.first, static_cast<int>(ends.second)})
            for (const auto& incidence : adjacency.incident(node))
                if (edges[static_cast<std::size_t>(incidence.edge)].straight && !isHorizontal(incidence.side))
                    visit(vertexOfEdge[static_cast<std::size_t>(incidence.edge)]);
    };
    for (std::size_t left = 0; left < leftEdges.size(); ++left) {
        conflictsOf(leftEdges[left], [&](int right) { targets.push_back(right); });
        offsets[left + 1] = static_cast<int>(targets.size());
    }
    BipartiteMatching matching(std::move(offsets), std::move(targets), rightEdges.size());
    matching.solve();
    // Konig: left vertices reached from free left vertices by alternating paths, plus right vertices not
    // reached, form the largest independent set.
    std::vector<char> reachedLeft(leftEdges.size(), 0);
    std::vector<char> reachedRight(rightEdges.size(), 0);
    std::vector<int> queue;
    for (std::size_t left = 0; left < leftEdges.size(); ++left)
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
    for (std::size_t left = 0; left < leftEdges.size(); ++left)
        kept[static_cast<std::size_t>(leftEdges[left])] = reachedLeft[left];
    for (std::size_t right = 0; right < rightEdges.size(); ++right)
        kept[static_cast<std::size_t>(rightEdges[right])] = reachedRight[right] == 0 ? 1 : 0;
    return kept;
}

} // namespace mcpp
