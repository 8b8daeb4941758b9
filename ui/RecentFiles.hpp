#pragma once

#include <QStringList>

namespace mcpp::ui {

// The most recently opened missions and rasters, newest first, kept in QSettings.
class RecentFiles {
  public:
    static constexpr int kMaximum = 10;

    [[nodiscard]] static QStringList list();
    static void add(const QString& path);
    static void remove(const QString& path);
};

} // namespace mcpp::ui
