// The one way a window runs long work (BackgroundJob.h): the outcome told once, after the box has
// gone; Cancel stops the work; a closed owner cancels and waits instead of leaving a thread.

#include "shared/BackgroundJob.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <QAction>
#include <QKeySequence>
#include <QProgressDialog>
#include <QPushButton>
#include <QTest>
#include <QTimer>
#include <QWidget>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <thread>

namespace marbler::ui {
namespace {

/// Work that runs until cancelled, saying how far it is.
void untilCancelled(const RenderControl& control, std::atomic<bool>& started) {
    started = true;
    for (int i = 0; !control.cancelled(); ++i) {
        control.progress(std::min(0.99, i / 1000.0));
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    throw Cancelled();
}

TEST(BackgroundJob, TellsDoneOnceAfterTheBoxHasGone) {
    QWidget window;
    std::optional<JobOutcome> outcome;
    int calls = 0;
    bool boxGone = false;
    BackgroundJob* job = BackgroundJob::start(
        &window, {&window, QStringLiteral("Working…"), QStringLiteral("jobProgress")},
        [](const RenderControl& control) { control.progress(1.0); },
        [&](const JobOutcome& o) {
            ++calls;
            outcome = o;
            boxGone = window.findChild<QProgressDialog*>(QStringLiteral("jobProgress")) == nullptr;
        });
    ASSERT_NE(job->progressBox(), nullptr);
    MARBLER_WAIT(outcome.has_value(), 10000);
    EXPECT_TRUE(outcome->done());
    EXPECT_TRUE(boxGone);
    QCoreApplication::processEvents();
    EXPECT_EQ(calls, 1);
}

TEST(BackgroundJob, SaysWhatWentWrong) {
    QWidget window;
    std::optional<JobOutcome> outcome;
    BackgroundJob::start(
        &window, {&window, QStringLiteral("Working…")},
        [](const RenderControl&) { throw RuntimeFailure("disk full while writing x.png"); },
        [&](const JobOutcome& o) { outcome = o; });
    MARBLER_WAIT(outcome.has_value(), 10000);
    EXPECT_TRUE(outcome->failed());
    EXPECT_EQ(outcome->error, QStringLiteral("disk full while writing x.png"));
}

TEST(BackgroundJob, CancelInTheBoxStopsTheWork) {
    QWidget window;
    std::atomic<bool> started = false;
    std::optional<JobOutcome> outcome;
    JobBox box(&window, QStringLiteral("Working…"));
    box.minimumDurationMs = 0;
    BackgroundJob* job = BackgroundJob::start(
        &window, box, [&](const RenderControl& control) { untilCancelled(control, started); },
        [&](const JobOutcome& o) { outcome = o; });
    MARBLER_WAIT(started.load(), 10000);
    emit job->progressBox()->canceled(); // what the box's Cancel button says
    MARBLER_WAIT(outcome.has_value(), 10000);
    EXPECT_TRUE(outcome->cancelled());
    EXPECT_TRUE(outcome->error.isEmpty());
}

TEST(BackgroundJob, AClosedOwnerCancelsAndWaitsWithoutTellingAnyone) {
    std::atomic<bool> started = false;
    std::atomic<bool> returned = false;
    bool told = false;
    {
        QWidget window;
        BackgroundJob::start(
            &window, {&window, QStringLiteral("Working…")},
            [&](const RenderControl& control) {
                try {
                    untilCancelled(control, started);
                } catch (...) {
                    returned = true;
                    throw;
                }
            },
            [&](const JobOutcome&) { told = true; });
        MARBLER_WAIT(started.load(), 10000);
    }
    // The window's end waited for the work: it has returned, and nothing was told.
    EXPECT_TRUE(returned.load());
    QCoreApplication::processEvents();
    EXPECT_FALSE(told);
}

TEST(BackgroundJob, RunWaitingReturnsHowTheWorkEnded) {
    QWidget window;
    auto value = std::make_shared<int>(0);
    const JobOutcome done = BackgroundJob::runWaiting(
        &window, {&window, QStringLiteral("Working…")}, [value](const RenderControl&) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            *value = 7;
        });
    EXPECT_TRUE(done.done());
    EXPECT_EQ(*value, 7);
    const JobOutcome failed =
        BackgroundJob::runWaiting(&window, {&window, QStringLiteral("Working…")}, [](const RenderControl&) {
            throw RuntimeFailure("every cell is a parent");
        });
    EXPECT_TRUE(failed.failed());
    EXPECT_EQ(failed.error, QStringLiteral("every cell is a parent"));
}

TEST(BackgroundJob, RunWaitingTakesNoClicksButTheBoxCancels) {
    QWidget window;
    auto* button = new QPushButton(QStringLiteral("Alter"), &window);
    window.show();
    int clicks = 0, shortcuts = 0;
    QObject::connect(button, &QPushButton::clicked, [&] { ++clicks; });
    auto* action = new QAction(QStringLiteral("Recombine"), &window);
    action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_2));
    window.addAction(action);
    QObject::connect(action, &QAction::triggered, [&] { ++shortcuts; });
    ASSERT_TRUE(test::activate(&window)); // shortcuts need an active window
    std::atomic<bool> started = false;
    JobBox box(&window, QStringLiteral("Breeding…"), QStringLiteral("waitBox"));
    box.minimumDurationMs = 0;
    bool boxFound = false;
    // While the window waits: a click on its button and its action's shortcut, then Cancel in
    // the box.
    QTimer::singleShot(0, &window, [&] {
        QTest::mouseClick(button, Qt::LeftButton);
        QTest::keyClick(button, Qt::Key_2, Qt::ControlModifier);
        auto* progress = window.findChild<QProgressDialog*>(QStringLiteral("waitBox"));
        boxFound = progress != nullptr;
        if (progress) emit progress->canceled();
    });
    const JobOutcome outcome = BackgroundJob::runWaiting(
        &window, box, [&](const RenderControl& control) { untilCancelled(control, started); });
    EXPECT_TRUE(boxFound);
    EXPECT_TRUE(outcome.cancelled());
    EXPECT_EQ(clicks, 0) << "a click landed while the window waited";
    EXPECT_EQ(shortcuts, 0) << "a shortcut ran while the window waited";
    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_EQ(clicks, 1) << "the window takes clicks again once the wait is over";
    QTest::keyClick(button, Qt::Key_2, Qt::ControlModifier);
    EXPECT_EQ(shortcuts, 1) << "and its shortcuts";
}

} // namespace
} // namespace marbler::ui
