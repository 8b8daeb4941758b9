#pragma once

#include <QByteArray>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace mcpp::io::internal {

// Reads what CompressedWriter wrote, inflating one chunk at a time. Any inconsistency (a chunk that does not
// inflate to its size, reading past the end, a count larger than what is left) throws DamagedData.
class CompressedReader {
  public:
    struct DamagedData : std::runtime_error {
        using std::runtime_error::runtime_error;
    };

    explicit CompressedReader(std::string_view compressed);

    template <typename Value> Value get() {
        static_assert(std::is_arithmetic_v<Value>);
        Value value{};
        take(&value, sizeof(Value));
        return value;
    }
    std::string getString();
    template <typename Value> std::vector<Value> getAll() {
        const std::uint64_t count = get<std::uint64_t>();
        if (count > remainingBound() / sizeof(Value))
            throw DamagedData("a list longer than the file");
        std::vector<Value> values(static_cast<std::size_t>(count));
        take(values.data(), values.size() * sizeof(Value));
        return values;
    }
    // A count of items each at least minimumBytes long, checked against what is left.
    std::size_t getCount(std::size_t minimumBytes);
    [[nodiscard]] bool atEnd() const { return position_ == chunkSize() && inputPosition_ == input_.size(); }

  private:
    void take(void* destination, std::size_t bytes);
    void nextChunk();
    [[nodiscard]] std::uint64_t remainingBound() const;
    [[nodiscard]] std::size_t chunkSize() const { return static_cast<std::size_t>(chunk_.size()); }

    std::string_view input_;
    std::size_t inputPosition_ = 0;
    QByteArray chunk_;                // the inflated chunk, read in place
    std::uint64_t rawBytesAhead_ = 0; // in the chunks not yet inflated, as their headers say

    std::size_t position_ = 0;
};

} // namespace mcpp::io::internal
