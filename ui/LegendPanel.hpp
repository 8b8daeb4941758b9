#pragma once

#include "render/PlanLegend.hpp"

#include <QWidget>

namespace mcpp::ui {

class MissionDocument;

// What the map shows, drawn as the exported sheets draw it: the land-cover classes, the robots with their
// names (and times once planned) and what the overlays mean. Follows the open mission.
class LegendPanel : public QWidget {
    Q_OBJECT

  public:
    explicit LegendPanel(MissionDocument* document, QWidget* parent = nullptr);
    [[nodiscard]] const std::vector<render::LegendSection>& sections() const { return sections_; }
    [[nodiscard]] QSize sizeHint() const override;
    // When each robot (by robot) is done in the field, where later than its path: worked out beside the
    // window with the waypoint files' sizes, for the plan shown. A new plan drops them.
    void showFieldTimes(std::vector<render::FieldTime> times);

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    void rebuild();

    MissionDocument* document_;
    std::vector<render::LegendSection> sections_;
    std::vector<render::FieldTime> fieldTimes_;
};

} // namespace mcpp::ui
