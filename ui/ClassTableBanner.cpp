#include "ui/ClassTableBanner.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace mcpp::ui {

ClassTableBanner::ClassTableBanner(QWidget* parent) : QFrame(parent), label_(new QLabel(this)) {
    setObjectName(QStringLiteral("classTableBanner"));
    setFrameShape(QFrame::StyledPanel);
    label_->setObjectName(QStringLiteral("classTableBannerText"));
    label_->setWordWrap(true);
    label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* close = new QToolButton(this);
    close->setObjectName(QStringLiteral("classTableBannerClose"));
    close->setText(QStringLiteral("✕"));
    close->setAutoRaise(true);
    close->setToolTip(tr("Hide this note (it stays in the Messages panel)"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(8, 4, 4, 4);
    layout->addWidget(label_, 1);
    layout->addWidget(close, 0, Qt::AlignTop);
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    hide();
}

void ClassTableBanner::showExplanation(const QString& text, bool recognised) {
    warning_ = !recognised;
    // Fixed light colours with dark text read the same under light and dark desktop themes.
    setStyleSheet(recognised
                      ? QStringLiteral("#classTableBanner { background: #e3f0fb; border: 1px solid #9cc3e6; }"
                                       " QLabel { color: #1d3b57; }")
                      : QStringLiteral("#classTableBanner { background: #fff4d6; border: 1px solid #e0b84c; }"
                                       " QLabel { color: #4a3800; }"));
    label_->setText(text);
    show();
}

QString ClassTableBanner::text() const {
    return label_->text();
}

} // namespace mcpp::ui
