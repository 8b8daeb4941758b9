#pragma once

#include <cstddef>
#include <functional>

namespace mcpp {

// How many threads parallelFor uses: the machine's cores unless set (batch mode's --threads). Results never
// depend on it: each index's work is independent and written to its own slot.
[[nodiscard]] int workerThreads();
void setWorkerThreads(int threads); // 0 = the machine's cores

// Runs body(index, worker) for every index in [0, count) on up to workerThreads() threads, the calling
// thread among them; worker in [0, threads) tells which scratch space a call may use. The first exception
// thrown by a body is rethrown here once every thread has stopped taking new indices.
void parallelFor(std::size_t count, const std::function<void(std::size_t index, int worker)>& body);

// parallelFor over [0, count) in tasks of `perTask` consecutive indices: body(task, begin, end) for each.
// Tasks are cut the same way whatever the number of threads, so results kept by task are too.
void parallelForRanges(std::size_t count, std::size_t perTask,
                       const std::function<void(std::size_t task, std::size_t begin, std::size_t end)>& body);

} // namespace mcpp
