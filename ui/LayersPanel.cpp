#include "ui/LayersPanel.hpp"

#include <QCheckBox>
#include <QGridLayout>

namespace mcpp::ui {

LayersPanel::LayersPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("layersPanel"));
    // Three toggles a row: in a column they took nine rows of a dock that shows three at 1600 x 1000.
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->setVerticalSpacing(2);
    landCover_ =
        addToggle(QStringLiteral("layerLandCover"), tr("Land cover"), tr("The raster in its class colours"));
    quadTree_ = addToggle(QStringLiteral("layerQuadTree"), tr("Cells"),
                          tr("The planner's cells (quadtree or grid), darker for larger cells"));
    regions_ = addToggle(QStringLiteral("layerRegions"), tr("Regions"),
                         tr("Each robot's cells, tinted in its colour"));
    paths_ = addToggle(QStringLiteral("layerPaths"), tr("Paths"),
                       tr("Coverage paths with arrows in the direction of travel"));
    starts_ = addToggle(QStringLiteral("layerStarts"), tr("Start points"),
                        tr("Numbered start markers; drag to move"));
    unreachable_ = addToggle(QStringLiteral("layerUnreachable"), tr("Unreachable"),
                             tr("Hatched: passable cells no robot can reach"));
    crossings_ = addToggle(QStringLiteral("layerCrossings"), tr("Obstacles crossed"),
                           tr("Dashed: cells with some impassable land that the path crosses, as the "
                              "blocked threshold allows; hover over one for the figures"));
    detection_ = addToggle(QStringLiteral("layerDetection"), tr("Detection"),
                           tr("For CPPIED plans: how likely the passes see a target in each cell, from red "
                              "(not seen) to green (the required probability), in place of the region tint"));
    area_ = addToggle(QStringLiteral("layerArea"), tr("Area edges"),
                      tr("Dashed: the edge of the area of interest as drawn or read from its file, and the "
                         "no-go zones, hatched red; cells along the edge may reach past it"));
    layout->setRowStretch(layout->rowCount(), 1);
}

QCheckBox* LayersPanel::addToggle(const QString& objectName, const QString& text, const QString& toolTip) {
    auto* box = new QCheckBox(text, this);
    box->setObjectName(objectName);
    box->setToolTip(toolTip);
    box->setChecked(true);
    auto* grid = static_cast<QGridLayout*>(layout());
    const int placed = grid->count();
    grid->addWidget(box, placed / togglesPerRow, placed % togglesPerRow);
    connect(box, &QCheckBox::toggled, this, [this] { emit layersChanged(layers()); });
    return box;
}

render::MapLayers LayersPanel::layers() const {
    render::MapLayers layers;
    layers.landCover = landCover_->isChecked();
    layers.quadTree = quadTree_->isChecked();
    layers.regions = regions_->isChecked();
    layers.paths = paths_->isChecked();
    layers.starts = starts_->isChecked();
    layers.unreachable = unreachable_->isChecked();
    layers.crossings = crossings_->isChecked();
    layers.detection = detection_->isChecked();
    layers.area = area_->isChecked();
    return layers;
}

void LayersPanel::setLayers(const render::MapLayers& layers) {
    const QSignalBlocker blockers[] = {
        QSignalBlocker(landCover_), QSignalBlocker(quadTree_),  QSignalBlocker(regions_),
        QSignalBlocker(paths_),     QSignalBlocker(starts_),    QSignalBlocker(unreachable_),
        QSignalBlocker(crossings_), QSignalBlocker(detection_), QSignalBlocker(area_)};
    landCover_->setChecked(layers.landCover);
    quadTree_->setChecked(layers.quadTree);
    regions_->setChecked(layers.regions);
    paths_->setChecked(layers.paths);
    starts_->setChecked(layers.starts);
    unreachable_->setChecked(layers.unreachable);
    crossings_->setChecked(layers.crossings);
    detection_->setChecked(layers.detection);
    area_->setChecked(layers.area);
    emit layersChanged(this->layers());
}

} // namespace mcpp::ui
