#pragma once

#include "core/model/CellGraph.hpp"
#include "core/model/NeighbourList.hpp"
#include "core/model/NeighbourTopology.hpp"

namespace mcpp {

// Where a search over cells, or over blocks of them, finds each one's neighbours: a cell graph (which may
// work them out on its grid) or lists of its own. Refers to either; they must outlive it.
class NeighbourSource {
  public:
    // NOLINTNEXTLINE(google-explicit-constructor): either is a source, as it stands
    NeighbourSource(const CellGraph& graph) : graph_(&graph) {}
    // NOLINTNEXTLINE(google-explicit-constructor)
    NeighbourSource(const NeighbourTopology& lists) : lists_(&lists) {}

    [[nodiscard]] NeighbourList of(int id) const {
        return graph_ != nullptr ? graph_->neighbours(id) : NeighbourList(lists_->of(id));
    }
    [[nodiscard]] std::size_t count() const {
        return graph_ != nullptr ? graph_->size() : lists_->cellCount();
    }
    // Asks the cache for what of(id) will read.
    void prefetch(int id) const {
        if (graph_ != nullptr)
            graph_->prefetchNeighbours(id);
        else
            __builtin_prefetch(lists_->offsets().data() + id);
    }

  private:
    const CellGraph* graph_ = nullptr;
    const NeighbourTopology* lists_ = nullptr;
};

} // namespace mcpp
