#pragma once

#include "core/model/AreaOutline.hpp"
#include "core/model/ClassGrid.hpp"
#include "core/model/ClassTable.hpp"
#include "core/model/Plan.hpp"
#include "io/ComparisonExport.hpp"

#include <QImage>
#include <QString>
#include <QStringList>
#include <vector>

namespace mcpp::render {

// One planner's place on a comparison sheet: its plan (null when it failed or was skipped) and the lines
// printed under its map.
struct ComparisonPanel {
    QString title;
    QStringList caption;
    const Plan* plan = nullptr;
    QString label; // under its bars in the chart, where the title's note would not fit; empty: the title
};

// A planner's panel: its name, and its key figures or why it has no plan; timed follows the makespan
// (" (1.16 x darp's)").
[[nodiscard]] ComparisonPanel comparisonPanelOf(const io::ComparisonRow& row, const Plan* plan,
                                                const QString& timed = {});

// Every row's panel in reading order (io::rankedRows), each planned one's title led by its rank: the sheet
// reads as the summary and the table do. plans[i] is rows[i]'s plan or null.
[[nodiscard]] std::vector<ComparisonPanel> rankedComparisonPanels(const std::vector<io::ComparisonRow>& rows,
                                                                  const std::vector<const Plan*>& plans);

// The plans as small multiples on one sheet, same extent and scale, each with its name and figures under
// it (as many lines as the longest caption needs), the panels without a plan as a line each of why, and below
// them a bar chart of every robot's time per planner; area: the edges of the area of interest and no-go
// zones the plans were made in, drawn over each. Up to three plans side by side, or mostColumns (one in a
// narrow dock, where three would be scaled down until their captions cannot be read).
[[nodiscard]] QImage renderComparisonSheet(const ClassGrid& grid, const ClassTable& classes,
                                           const std::vector<ComparisonPanel>& panels,
                                           const AreaOutline* area = nullptr, int mostColumns = 3);
// The sheet as a PNG, written atomically; false with a message naming the file on failure.
[[nodiscard]] bool writeComparisonSheet(const ClassGrid& grid, const ClassTable& classes,
                                        const std::vector<ComparisonPanel>& panels, const QString& path,
                                        QString* error, const AreaOutline* area = nullptr);

} // namespace mcpp::render
