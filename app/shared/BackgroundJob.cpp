#include "shared/BackgroundJob.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

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
