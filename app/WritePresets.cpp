// Build-time tool: writes every built-in class-table preset as a CSV file into a folder, so that the
// installed package carries them under share/mcpp/presets for users to open, copy and edit.
#include "io/ClassTableSources.hpp"

#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: mcpp_write_presets FOLDER\n";
        return 2;
    }
    const std::filesystem::path folder(argv[1]);
    std::error_code code;
    std::filesystem::create_directories(folder, code);
    for (const auto& preset : mcpp::io::classTablePresets()) {
        const auto table = mcpp::io::presetClassTable(preset.name);
        const auto saved =
            table ? mcpp::io::saveClassTableCsv(table.value(), (folder / (preset.name + ".csv")).string())
                  : mcpp::io::Status::failure(table.error());
        if (!saved) {
            std::cerr << "mcpp_write_presets: " << saved.error() << '\n';
            return 1;
        }
    }
    return 0;
}
