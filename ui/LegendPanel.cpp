#include "ui/LegendPanel.hpp"

#include "io/AutopilotMission.hpp"
#include "io/Mission.hpp"
#include "ui/MissionDocument.hpp"

#include <QPainter>
#include <utility>

namespace mcpp::ui {

namespace {
constexpr int kPadding = 8;
} // namespace

LegendPanel::LegendPanel(MissionDocument* document, QWidget* parent) : QWidget(parent), document_(document) {
    setObjectName(QStringLiteral("legendPanel"));
    for (const auto signal :
         {&MissionDocument::mapChanged, &MissionDocument::classesChanged, &MissionDocument::robotsChanged})
        connect(document_, signal, this, &LegendPanel::rebuild);
    connect(document_, &MissionDocument::planChanged, this, [this] {
        fieldTimes_.clear(); // the last plan's, until this one's are worked out
        rebuild();
    });
    rebuild();
}

void LegendPanel::rebuild() {
    sections_.clear();
    if (document_->hasMap()) {
        sections_ = render::planLegend(document_->classes(), document_->plan(),
                                       io::robotNames(document_->mission()), document_->grid());
        render::addFlightReach(sections_, io::flightReachesMetres(io::robotVehicles(document_->mission())));
        if (document_->raster() != nullptr)
            render::addAreaOutline(sections_, document_->raster()->area);
        render::addFieldTimes(sections_, fieldTimes_);
    }
    setMinimumSize(sizeHint());
    updateGeometry();
    update();
}

void LegendPanel::showFieldTimes(std::vector<render::FieldTime> times) {
    fieldTimes_ = std::move(times);
    rebuild();
}

QSize LegendPanel::sizeHint() const {
    const QSizeF size = render::legendSize(sections_, font());
    return {static_cast<int>(size.width()) + 2 * kPadding, static_cast<int>(size.height()) + 2 * kPadding};
}

void LegendPanel::paintEvent(QPaintEvent* /*event*/) {
    QPainter painter(this);
    if (sections_.empty()) {
        painter.setPen(palette().color(QPalette::PlaceholderText));
        painter.drawText(rect().adjusted(kPadding, kPadding, -kPadding, -kPadding),
                         Qt::AlignLeft | Qt::TextWordWrap, tr("Open a map to see its legend."));
        return;
    }
    render::paintLegend(painter, QPointF(kPadding, kPadding), sections_);
}

} // namespace mcpp::ui
