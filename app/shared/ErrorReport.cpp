#include "shared/ErrorReport.h"

#include <QMessageBox>

namespace marbler::ui {

namespace {
ErrorHandler& handler() {
    static ErrorHandler instance;
    return instance;
}
} // namespace

void setErrorHandler(ErrorHandler h) {
    handler() = std::move(h);
}

void reportError(QWidget* parent, const QString& title, const QString& message) {
    if (handler()) {
        handler()(parent, title, message);
        return;
    }
    QMessageBox box(QMessageBox::Warning, title, message, QMessageBox::Ok, parent);
    box.setTextInteractionFlags(Qt::TextSelectableByMouse);
    box.exec();
}

} // namespace marbler::ui
