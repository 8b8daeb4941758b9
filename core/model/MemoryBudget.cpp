#include "core/model/MemoryBudget.hpp"

#include <atomic>

namespace mcpp {

namespace {

std::atomic<std::int64_t> budget{std::int64_t{8} << 30};

} // namespace

std::int64_t memoryBudgetBytes() {
    return budget.load();
}

void setMemoryBudgetBytes(std::int64_t bytes) {
    if (bytes > 0)
        budget.store(bytes);
}

} // namespace mcpp
