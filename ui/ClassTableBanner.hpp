#pragma once

#include <QFrame>

class QLabel;

namespace mcpp::ui {

// A strip above the map saying where the class table came from after a raster opens: the product it was
// recognised as, or that it was not and every speed and field of view is a default to check.
class ClassTableBanner : public QFrame {
    Q_OBJECT

  public:
    explicit ClassTableBanner(QWidget* parent = nullptr);
    // recognised: a calm note; otherwise a warning the user should act on.
    void showExplanation(const QString& text, bool recognised);
    [[nodiscard]] QString text() const;
    [[nodiscard]] bool isWarning() const { return warning_; }

  private:
    QLabel* label_;
    bool warning_ = false;
};

} // namespace mcpp::ui
