// libFuzzer harness: any bytes as a QGIS .qml style give legend entries or an error naming the file.
#include "io/internal/LegendReader.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto legend = mcpp::io::internal::parseQgisStyleLegend(text, "fuzz.qml");
    if (!legend && legend.error().rfind("fuzz.qml", 0) != 0)
        std::abort();
    return 0;
}
