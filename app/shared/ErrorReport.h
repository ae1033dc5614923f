#pragma once
/// Where the window's error messages go: a QMessageBox by default, anything a test installs
/// instead (so no modal dialog ever blocks a headless test).

#include <QString>

#include <functional>

class QWidget;

namespace marbler::ui {

/// Receives an error for the user: the dialog's parent, a title and the message.
using ErrorHandler = std::function<void(QWidget* parent, const QString& title, const QString& message)>;

/// Installs a handler; an empty one restores the message box.
void setErrorHandler(ErrorHandler handler);
/// Shows an error through the installed handler.
void reportError(QWidget* parent, const QString& title, const QString& message);

} // namespace marbler::ui
