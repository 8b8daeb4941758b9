#include "ui/TimelineBar.hpp"

#include "core/model/HumanUnits.hpp"
#include "ui/EventSlider.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QStyle>
#include <QTimer>
#include <QToolButton>
#include <algorithm>
#include <cmath>

namespace mcpp::ui {
namespace {

// Playing shows the whole mission in about 20 seconds, whatever its length.
constexpr int frameMilliseconds = 40;
constexpr int stepsPerFrame = 2;

} // namespace

TimelineBar::TimelineBar(QWidget* parent)
    : QWidget(parent), play_(new QToolButton(this)), slider_(new EventSlider(this)), label_(new QLabel(this)),
      timer_(new QTimer(this)) {
    setObjectName(QStringLiteral("timelineBar"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    play_->setObjectName(QStringLiteral("timelinePlayButton"));
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    play_->setToolTip(tr("Play the mission: each robot where it is, its path as driven so far"));
    slider_->setObjectName(QStringLiteral("timelineSlider"));
    slider_->setRange(0, steps);
    slider_->setToolTip(tr("Time since the start; the marks are the mission's events"));
    label_->setMinimumWidth(
        label_->fontMetrics().horizontalAdvance(QStringLiteral("00 d 00 h 00 min of 00 d 00 h")));
    layout->addWidget(play_);
    layout->addWidget(slider_, 1);
    layout->addWidget(label_);
    timer_->setInterval(frameMilliseconds);
    connect(play_, &QToolButton::clicked, this, &TimelineBar::togglePlay);
    connect(timer_, &QTimer::timeout, this, &TimelineBar::step);
    connect(slider_, &QSlider::valueChanged, this, [this] {
        showTime();
        emit secondsChanged(seconds());
    });
}

void TimelineBar::setTimeline(double makespanSeconds, const std::vector<double>& eventSeconds) {
    stop();
    makespanSeconds_ = makespanSeconds;
    // A mission of no length has nothing to play.
    play_->setEnabled(makespanSeconds > 0.0);
    slider_->setEnabled(makespanSeconds > 0.0);
    std::vector<int> marks;
    for (const double time : eventSeconds)
        if (makespanSeconds > 0.0 && time <= makespanSeconds)
            marks.push_back(static_cast<int>(std::lround(time / makespanSeconds * steps)));
    slider_->setMarks(std::move(marks));
    slider_->setValue(steps);
    showTime();
}

double TimelineBar::seconds() const {
    return makespanSeconds_ * static_cast<double>(slider_->value()) / steps;
}

void TimelineBar::setSeconds(double seconds) {
    if (makespanSeconds_ > 0.0)
        slider_->setValue(
            static_cast<int>(std::lround(std::clamp(seconds / makespanSeconds_, 0.0, 1.0) * steps)));
}

bool TimelineBar::isPlaying() const {
    return timer_->isActive();
}

void TimelineBar::stop() {
    timer_->stop();
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
}

void TimelineBar::togglePlay() {
    if (timer_->isActive()) {
        stop();
        return;
    }
    if (slider_->value() >= steps)
        slider_->setValue(0);
    timer_->start();
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPause));
}

void TimelineBar::step() {
    slider_->setValue(std::min(steps, slider_->value() + stepsPerFrame));
    if (slider_->value() >= steps)
        togglePlay();
}

void TimelineBar::showTime() {
    label_->setText(tr("%1 of %2")
                        .arg(QString::fromStdString(formatDuration(seconds())),
                             QString::fromStdString(formatDuration(makespanSeconds_))));
}

} // namespace mcpp::ui
