#pragma once
/// What the window tests share: the test main (UiTestMain.cpp, linked into every window test)
/// and a drop of files as the platform makes it.

#include <QStringList>

class QWidget;

namespace marbler::test {

/// Drags files onto a widget the way the platform does: an enter (which picks the drop target
/// and must be accepted: a gtest failure otherwise), then the drop.
void dropFiles(QWidget* target, const QStringList& files);

} // namespace marbler::test
