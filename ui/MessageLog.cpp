#include "ui/MessageLog.hpp"

#include <QTime>

namespace mcpp::ui {

namespace {
constexpr int kKeptMessages = 2000; // hours of work; older ones scroll away
} // namespace

MessageLog::MessageLog(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName(QStringLiteral("messageLog"));
    setReadOnly(true);
    setMaximumBlockCount(kKeptMessages);
    setLineWrapMode(QPlainTextEdit::WidgetWidth);
    setPlaceholderText(tr("Messages from opening files, planning and exporting appear here."));
}

void MessageLog::add(const QString& message) {
    if (message.isEmpty() || (!messages_.isEmpty() && messages_.back() == message))
        return;
    messages_.append(message);
    if (messages_.size() > kKeptMessages)
        messages_.removeFirst();
    appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss")) + QStringLiteral("  ") +
                    message);
}

} // namespace mcpp::ui
