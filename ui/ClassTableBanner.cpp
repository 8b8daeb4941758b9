#include "ui/ClassTableBanner.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>

namespace mcpp::ui {

ClassTableBanner::ClassTableBanner(QWidget* parent)
    : QFrame(parent), label_(new QLabel(this)), fitButton_(new QPushButton(this)) {
    setObjectName(QStringLiteral("classTableBanner"));
    setFrameShape(QFrame::StyledPanel);
    label_->setObjectName(QStringLiteral("classTableBannerText"));
    label_->setWordWrap(true);
    label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    fitButton_->setObjectName(QStringLiteral("classTableFitButton"));
    fitButton_->hide();
    auto* close = new QToolButton(this);
    close->setObjectName(QStringLiteral("classTableBannerClose"));
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    close->setToolTip(tr("Hide this note (it stays in the Messages panel)"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 4, 4);
    layout->addWidget(label_, 1);
    layout->addWidget(fitButton_, 0, Qt::AlignVCenter);
    layout->addWidget(close, 0, Qt::AlignTop);
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    connect(fitButton_, &QPushButton::clicked, this, &ClassTableBanner::fitRequested);
    hide();
}

void ClassTableBanner::showExplanation(const QString& text, bool recognised) {
    explanation_ = text;
    recognised_ = recognised;
    refresh();
}

void ClassTableBanner::clearExplanation() {
    explanation_.clear();
    recognised_ = true;
    refresh();
}

void ClassTableBanner::showSizeWarning(const QString& text, const QString& fitButtonText) {
    const bool changed = text != sizeWarning_;
    sizeWarning_ = text;
    fitButton_->setText(fitButtonText);
    if (changed)
        refresh();
}

void ClassTableBanner::clearSizeWarning() {
    if (sizeWarning_.isEmpty())
        return;
    sizeWarning_.clear();
    refresh();
}

QString ClassTableBanner::text() const {
    return label_->text();
}

bool ClassTableBanner::isWarning() const {
    return !recognised_ || !sizeWarning_.isEmpty();
}

void ClassTableBanner::refresh() {
    QStringList parts;
    if (!explanation_.isEmpty())
        parts << explanation_;
    if (!sizeWarning_.isEmpty())
        parts << sizeWarning_;
    label_->setText(parts.join(QLatin1Char('\n')));
    fitButton_->setVisible(!sizeWarning_.isEmpty() && !fitButton_->text().isEmpty());
    // Fixed light colours with dark text read the same under light and dark desktop themes.
    setStyleSheet(isWarning()
                      ? QStringLiteral("#classTableBanner { background: #fff4d6; border: 1px solid #e0b84c; }"
                                       " QLabel { color: #4a3800; }")
                      : QStringLiteral("#classTableBanner { background: #e3f0fb; border: 1px solid #9cc3e6; }"
                                       " QLabel { color: #1d3b57; }"));
    setVisible(!parts.isEmpty());
}

} // namespace mcpp::ui
