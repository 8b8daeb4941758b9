// libFuzzer harness: any bytes as a class-table CSV give a valid table or an error naming the file.
#include "io/ClassTableSources.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const auto table = mcpp::io::parseClassTableCsv(text, "fuzz.csv");
    if (!table && table.error().rfind("fuzz.csv", 0) != 0)
        std::abort();
    if (table && table.value().validate().has_value())
        std::abort(); // an accepted table is a valid one
    return 0;
}
