#pragma once

#include "render/MapLayers.hpp"

#include <QWidget>

class QCheckBox;

namespace mcpp::ui {

// One visibility toggle per map layer.
class LayersPanel : public QWidget {
    Q_OBJECT

  public:
    explicit LayersPanel(QWidget* parent = nullptr);
    [[nodiscard]] render::MapLayers layers() const;
    void setLayers(const render::MapLayers& layers);

  signals:
    void layersChanged(const mcpp::render::MapLayers& layers);

  private:
    static constexpr int togglesPerRow = 3;
    QCheckBox* addToggle(const QString& objectName, const QString& text, const QString& toolTip);

    QCheckBox* landCover_;
    QCheckBox* quadTree_;
    QCheckBox* regions_;
    QCheckBox* paths_;
    QCheckBox* starts_;
    QCheckBox* unreachable_;
    QCheckBox* crossings_;
    QCheckBox* detection_;
    QCheckBox* area_;
};

} // namespace mcpp::ui
