#pragma once

#include <QFrame>

class QLabel;
class QPushButton;

namespace mcpp::ui {

// A strip above the map about the class table: where it came from after a raster opens (the product it
// was recognised as, or that it was not and every speed and field of view is a default to check), and,
// while it lasts, that its fields of view are too fine to plan the map on this machine, with a button
// that scales them to fit.
class ClassTableBanner : public QFrame {
    Q_OBJECT

  public:
    explicit ClassTableBanner(QWidget* parent = nullptr);
    // recognised: a calm note; otherwise a warning the user should act on.
    void showExplanation(const QString& text, bool recognised);
    void clearExplanation();
    void showSizeWarning(const QString& text, const QString& fitButtonText);
    void clearSizeWarning();
    [[nodiscard]] QString text() const;
    [[nodiscard]] bool isWarning() const;
    [[nodiscard]] bool hasSizeWarning() const { return !sizeWarning_.isEmpty(); }

  signals:
    void fitRequested();

  private:
    void refresh();

    QLabel* label_;
    QPushButton* fitButton_;
    QString explanation_;
    bool recognised_ = true;
    QString sizeWarning_;
};

} // namespace mcpp::ui
