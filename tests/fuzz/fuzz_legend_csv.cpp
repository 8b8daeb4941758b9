// libFuzzer harness: any bytes as a CSV legend beside a raster give entries or an error naming the file.
#include "io/internal/LegendReader.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto legend = mcpp::io::internal::parseLegendCsv(text, "fuzz.csv");
    if (!legend && legend.error().rfind("fuzz.csv", 0) != 0)
        std::abort();
    return 0;
}
