#pragma once

namespace mcpp::render {

// Which parts of a plan are drawn. Shared by the batch image writer and the GUI layers panel.
struct MapLayers {
    bool landCover = true;
    bool quadTree = true;
    bool regions = true;
    bool paths = true;
    bool starts = true;
    bool unreachable = true;
    bool crossings = true; // cells whose path crosses small impassable patches
    bool detection = true; // what a detection plan's passes see, in place of the region tint
    bool area = true;      // the area of interest's and no-go zones' edges

    friend bool operator==(const MapLayers&, const MapLayers&) = default;
};

} // namespace mcpp::render
