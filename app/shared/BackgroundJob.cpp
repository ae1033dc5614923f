#include "shared/BackgroundJob.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <QApplication>
#include <QEventLoop>
#include <QPointer>
#include <QProgressDialog>
#include <QThread>
#include <QTimer>

namespace marbler::ui {

BackgroundJob* BackgroundJob::start(QObject* owner, const JobBox& box, Work work, Finished finished) {
    return new BackgroundJob(owner, box, std::move(work), std::move(finished));
}

BackgroundJob::BackgroundJob(QObject* owner, const JobBox& box, Work work, Finished finished)
    : QObject(owner)
    , mFinished(std::move(finished))
    , mBusy(box.busy) {
    mThread =
        QThread::create([work = std::move(work), cancel = mCancel, progress = mProgress, outcome = mOutcome] {
            RenderControl control;
            control.cancel = cancel.get();
            control.progress = [progress](double p) { progress->store(p, std::memory_order_relaxed); };
            try {
                work(control);
                if (cancel->load()) outcome->kind = JobOutcome::Kind::Cancelled;
            } catch (const Cancelled&) {
                outcome->kind = JobOutcome::Kind::Cancelled;
            } catch (const std::exception& e) {
                outcome->kind = JobOutcome::Kind::Failed;
                outcome->error = QString::fromStdString(e.what());
                if (outcome->error.isEmpty()) outcome->error = QObject::tr("an unknown error");
            }
        });
    mBox = new QProgressDialog(box.label, QObject::tr("Cancel"), 0, box.busy ? 0 : 1000, box.parent);
    mBox->setObjectName(box.objectName);
    mBox->setWindowModality(Qt::WindowModal);
    mBox->setMinimumDuration(box.minimumDurationMs);
    mBox->setAutoReset(false);
    mBox->setAutoClose(false);
    mPoll = new QTimer(this);
    connect(mPoll, &QTimer::timeout, this, [this] {
        // A busy box (range 0 to 0) still needs setValue to show itself past its minimum duration.
        mBox->setValue(mBusy ? 0 : int(mProgress->load(std::memory_order_relaxed) * 999));
    });
    connect(mBox, &QProgressDialog::canceled, this, &BackgroundJob::cancel);
    connect(mThread, &QThread::finished, this, &BackgroundJob::end);
    mPoll->start(100);
    mThread->start();
}

BackgroundJob::~BackgroundJob() {
    if (mThread) {
        mCancel->store(true);
        mThread->wait();
        delete mThread;
    }
    delete mBox;
}

void BackgroundJob::cancel() {
    mCancel->store(true);
}

namespace {

/// While a window waits on work it asked for: no input reaches it but its progress box.
class InputBlock : public QObject {
public:
    explicit InputBlock(QWidget* window)
        : mWindow(window) {
        qApp->installEventFilter(this);
    }
    ~InputBlock() override { qApp->removeEventFilter(this); }
    void allow(QWidget* box) { mBox = box; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonRelease:
        case QEvent::MouseButtonDblClick:
        case QEvent::Wheel:
        case QEvent::KeyPress:
        case QEvent::KeyRelease:
        case QEvent::ShortcutOverride:
        case QEvent::Shortcut:
        case QEvent::ContextMenu:
        case QEvent::Drop:
        case QEvent::Close:
            break;
        default:
            return false;
        }
        if (!mWindow) return false;
        // A shortcut goes to its action, not to a widget: none runs while the window waits, in any
        // window, for the moment it lasts (the box cancels by Escape, a key press of its own).
        if (event->type() == QEvent::Shortcut) return true;
        auto* widget = qobject_cast<QWidget*>(watched);
        if (!widget) return false;
        if (mBox && (widget == mBox || mBox->isAncestorOf(widget))) return false;
        if (event->type() == QEvent::Close) {
            if (widget != mWindow.data()) return false;
            event->ignore(); // closed once the work is done, with another click
            return true;
        }
        return widget->window() == mWindow.data();
    }

private:
    QPointer<QWidget> mWindow;
    QPointer<QWidget> mBox;
};

} // namespace

JobOutcome BackgroundJob::runWaiting(QObject* owner, const JobBox& box, Work work) {
    QEventLoop loop;
    auto result = std::make_shared<std::optional<JobOutcome>>();
    InputBlock block(box.parent ? box.parent->window() : nullptr);
    QApplication::setOverrideCursor(Qt::BusyCursor);
    // The job may end after the wait has (the application quitting): it then tells no one.
    BackgroundJob* job = start(owner, box, std::move(work),
                               [result, waiting = QPointer<QEventLoop>(&loop)](const JobOutcome& outcome) {
                                   *result = outcome;
                                   if (waiting) waiting->quit();
                               });
    block.allow(job->progressBox());
    // The owner gone first (the job cancelled and waited for), or the application quitting,
    // ends the wait too.
    QObject::connect(job, &QObject::destroyed, &loop, &QEventLoop::quit);
    loop.exec();
    QApplication::restoreOverrideCursor();
    if (*result) return **result;
    return {JobOutcome::Kind::Cancelled, {}};
}

void BackgroundJob::end() {
    // The progress box goes before any message: a stale one must never cover an error, and the
    // poll must not show it again (setValue shows a box past its minimum duration).
    mPoll->stop();
    QObject::disconnect(mBox, nullptr, this, nullptr);
    mBox->reset();
    mBox->hide();
    delete mBox;
    mBox = nullptr;
    mThread->wait(); // `finished` comes just before the thread has quite ended
    delete mThread;
    mThread = nullptr;
    // Taken out first: the handler may start the next job, or close the owner.
    const Finished finished = std::exchange(mFinished, nullptr);
    const JobOutcome outcome = *mOutcome;
    deleteLater();
    if (finished) finished(outcome);
}

} // namespace marbler::ui
