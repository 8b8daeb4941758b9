#pragma once

#include "io/ExportCatalogue.hpp"

#include <QString>

namespace mcpp::ui {

// The file name an export dialog suggests: batch mode's for a whole-plan file that has one (report.json,
// plan.geojson), plan.<extension> otherwise; after the saved mission's name where there is one
// (survey-report.json). Never the mission file itself: a report exported as survey.json would replace it.
[[nodiscard]] QString suggestedExportFileName(const io::ExportFormat& format, const QString& missionPath);

} // namespace mcpp::ui
