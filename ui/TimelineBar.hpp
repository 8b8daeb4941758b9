#pragma once

#include <QWidget>
#include <vector>

class QLabel;
class QTimer;
class QToolButton;

namespace mcpp::ui {

class EventSlider;

// Under the map for a plan simulated over time: a play button, a slider over the mission's time with its
// events marked, and the time it shows. The map draws each robot where it is at that time and its path as
// driven so far.
class TimelineBar : public QWidget {
    Q_OBJECT

  public:
    explicit TimelineBar(QWidget* parent = nullptr);

    // The mission's length and when its events happen; the bar starts at the end (the whole plan).
    void setTimeline(double makespanSeconds, const std::vector<double>& eventSeconds);
    [[nodiscard]] double seconds() const;
    void setSeconds(double seconds);
    [[nodiscard]] bool isPlaying() const;
    void stop();

  signals:
    void secondsChanged(double seconds);

  private:
    void togglePlay();
    void step();
    void showTime();

    static constexpr int steps = 1000; // slider positions over the mission
    QToolButton* play_;
    EventSlider* slider_;
    QLabel* label_;
    QTimer* timer_;
    double makespanSeconds_ = 0.0;
};

} // namespace mcpp::ui
