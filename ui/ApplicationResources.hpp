#pragma once

#include <QIcon>
#include <QString>

namespace mcpp::ui {

// An icon of resources/icons (name without ".svg"), from the resources compiled into mcpp_ui.
[[nodiscard]] QIcon actionIcon(const char* name);
// The About box's text: version, bundled data and their licences, libraries (resources/about.html).
[[nodiscard]] QString aboutText();

} // namespace mcpp::ui
