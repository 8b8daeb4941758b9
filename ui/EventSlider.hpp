#pragma once

#include <QSlider>
#include <vector>

namespace mcpp::ui {

// A horizontal slider with marks where the mission's events happen, as values of the slider.
class EventSlider : public QSlider {
    Q_OBJECT

  public:
    explicit EventSlider(QWidget* parent = nullptr);
    void setMarks(std::vector<int> values);

  protected:
    void paintEvent(QPaintEvent* event) override;

  private:
    std::vector<int> marks_;
};

} // namespace mcpp::ui
