#include "core/model/ParallelFor.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mcpp {

namespace {

std::atomic<int> configuredThreads{0};

} // namespace

int workerThreads() {
    const int configured = configuredThreads.load();
    if (configured > 0)
        return configured;
    return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1U, 64U));
}

void setWorkerThreads(int threads) {
    configuredThreads.store(std::max(threads, 0));
}

void parallelFor(std::size_t count, const std::function<void(std::size_t index, int worker)>& body) {
    const auto threads =
        static_cast<std::size_t>(std::min<std::size_t>(static_cast<std::size_t>(workerThreads()), count));
    if (threads <= 1) {
        for (std::size_t index = 0; index < count; ++index)
            body(index, 0);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr firstError;
    std::mutex errorMutex;
    const auto work = [&](int worker) {
        for (std::size_t index = next++; index < count && !failed.load(); index = next++) {
            try {
                body(index, worker);
            } catch (...) {
                const std::lock_guard lock(errorMutex);
                if (!firstError)
                    firstError = std::current_exception();
                failed.store(true);
            }
        }
    };
    std::vector<std::thread> helpers;
    for (std::size_t worker = 1; worker < threads; ++worker)
        helpers.emplace_back(work, static_cast<int>(worker));
    work(0);
    for (std::thread& helper : helpers)
        helper.join();
    if (firstError)
        std::rethrow_exception(firstError);
}

void parallelForRanges(
    std::size_t count, std::size_t perTask,
    const std::function<void(std::size_t task, std::size_t begin, std::size_t end)>& body) {
    parallelFor((count + perTask - 1) / perTask, [&](std::size_t task, int) {
        body(task, task * perTask, std::min(count, (task + 1) * perTask));
    });
}

} // namespace mcpp
