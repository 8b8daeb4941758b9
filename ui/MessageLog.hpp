#pragma once

#include <QPlainTextEdit>

namespace mcpp::ui {

// Every message the window shows, whole and in order, with its time: the status bar shows one message
// for a few seconds and cuts long ones; here nothing is cut or lost.
class MessageLog : public QPlainTextEdit {
    Q_OBJECT

  public:
    explicit MessageLog(QWidget* parent = nullptr);
    void add(const QString& message);
    [[nodiscard]] QStringList messages() const { return messages_; }

  private:
    QStringList messages_;
};

} // namespace mcpp::ui
