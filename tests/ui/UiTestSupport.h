#pragma once
/// What the window tests share (UiTestMain.cpp, linked into every window test): the test main,
/// a window fixture, error capture and a drop of files as the platform makes it.

#include "shared/RenderService.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QStringList>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>

class QWidget;

namespace marbler::test {

/// A workbench window rendering on the CPU, with favourites in a folder of its own and session
/// seed 42; `populate`: with a first random flat population.
class WindowTest : public ::testing::Test {
protected:
    explicit WindowTest(bool populate = true)
        : mPopulate(populate) {}
    void SetUp() override;
    void TearDown() override;
    ui::PopulationModel& model() { return *mWindow->model(); }

    QTemporaryDir mFavourites;
    std::unique_ptr<ui::RenderService> mService;
    std::unique_ptr<ui::WorkbenchWindow> mWindow;

private:
    bool mPopulate;
};

/// A workbench window with editors opened over it, each autosaving into a folder of the test's
/// own: open() shows one at 1200 x 850, answering Discard to the unsaved question.
class EditorTest : public WindowTest {
protected:
    ui::EditorWindow* open(const Genome& design, const QString& file = {});
    QTemporaryDir mRecovery;
};

/// Captures errors instead of showing a modal message box ("title: message" each).
struct ErrorCapture {
    QStringList messages;
    ErrorCapture();
    ~ErrorCapture();
};

/// Drags files onto a widget the way the platform does: an enter (which picks the drop target
/// and must be accepted: a gtest failure otherwise), then the drop.
void dropFiles(QWidget* target, const QStringList& files);

/// Makes a window the active one and waits until it is. Under Xvfb, with no window manager,
/// activation is a request another window may overtake on a loaded machine: it is asked again,
/// three times in all.
bool activate(QWidget* window);

} // namespace marbler::test
