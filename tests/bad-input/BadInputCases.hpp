#pragma once

#include <QString>
#include <QStringList>
#include <vector>

namespace mcpp::test {

// Where the GUI meets the same broken file: the File menu's open raster, open mission, or the class
// table's Load CSV. None: the input only exists on the command line (flags, starts, output folder).
enum class GuiOpenPath { None, Raster, Mission, ClassTable };

// One row of the bad-input suite: batch arguments (after --batch) with {dir} standing for the fixture
// folder and {out} for an output folder, the exit code expected and text the one stderr line must hold
// ({dir} there too).
struct BadInputCase {
    const char* name;
    QStringList arguments;
    int exitCode;
    QString fragment;
    GuiOpenPath guiPath = GuiOpenPath::None;
    QString guiFile; // under {dir}, for guiPath != None
};

// Every case, in the order of the table in BadInputCases.cpp.
[[nodiscard]] const std::vector<BadInputCase>& badInputCases();

// Writes every file the cases name into `folder` (rasters made with GDAL, class tables, missions).
// Returns an empty string on success, otherwise what failed.
[[nodiscard]] QString writeBadInputFixtures(const QString& folder);

// The case's arguments with {dir} and {out} replaced.
[[nodiscard]] QStringList expandArguments(const BadInputCase& badInput, const QString& folder,
                                          const QString& out);

} // namespace mcpp::test
