#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace mcpp::io::internal {

// Little-endian values appended to a buffer that is deflated in chunks as it fills, so a large plan never
// exists uncompressed in memory whole. Chunks: 8-byte raw size, 8-byte compressed size, zlib bytes.
class CompressedWriter {
  public:
    template <typename Value> void put(Value value) {
        static_assert(std::is_arithmetic_v<Value>);
        const auto* bytes = reinterpret_cast<const char*>(&value);
        buffer_.append(bytes, sizeof(Value));
        flushIfFull();
    }
    void put(const std::string& text);
    template <typename Value> void putAll(const std::vector<Value>& values) {
        put(static_cast<std::uint64_t>(values.size()));
        buffer_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(Value));
        flushIfFull();
    }
    // The compressed bytes, after the last chunk is deflated.
    [[nodiscard]] std::string finish();

  private:
    void flushIfFull();
    void flush();

    std::string buffer_;
    std::string output_;
};

} // namespace mcpp::io::internal
