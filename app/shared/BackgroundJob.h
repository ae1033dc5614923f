#pragma once
/// One piece of a window's long work (an export, a bake, a sheet, an animation, an image with
/// its design) on a thread of its own: the GUI thread stays free, a window-modal progress box
/// shows how far it is and cancels it, and the outcome is told on the GUI thread once the work
/// has returned and the box is gone. Every window job goes through here, so each one cancels,
/// reports and cleans up the same way.

#include <QObject>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>

class QProgressDialog;
class QThread;
class QTimer;
class QWidget;

namespace marbler {
struct RenderControl;
}

namespace marbler::ui {

/// How a job ended.
struct JobOutcome {
    enum class Kind { Done, Cancelled, Failed };
    Kind kind = Kind::Done;
    QString error; ///< what went wrong (Failed only)

    bool done() const { return kind == Kind::Done; }
    bool cancelled() const { return kind == Kind::Cancelled; }
    bool failed() const { return kind == Kind::Failed; }
};

/// What a job shows while it runs.
struct JobBox {
    JobBox(QWidget* parent, QString label, QString objectName = {})
        : parent(parent)
        , label(std::move(label))
        , objectName(std::move(objectName)) {}

    QWidget* parent;    ///< the window the progress box is modal to
    QString label;      ///< "Exporting design.png…"
    QString objectName; ///< the box's object name (tests find it by this)
    /// A box with no percentage (for work that cannot say how far it is, as SVG tracing).
    bool busy = false;
    /// How long the work may run before the box shows.
    int minimumDurationMs = 300;
};

/// A job: made by start(), owned by `owner` (a window or a button). Destroying the owner cancels
/// the work and waits for it, and then `finished` is not called.
class BackgroundJob : public QObject {
public:
    /// The work: runs on the job's thread with a control whose cancel flag it checks and whose
    /// progress (0 to 1) it reports. It throws Cancelled when cancelled (or just returns), and
    /// any other exception is the failure reported.
    using Work = std::function<void(const RenderControl& control)>;
    /// Told on the GUI thread after the work has returned and the progress box has closed.
    using Finished = std::function<void(const JobOutcome& outcome)>;

    /// Starts `work` and shows `box`. The job deletes itself after `finished` has run.
    static BackgroundJob* start(QObject* owner, const JobBox& box, Work work, Finished finished);

    /// Runs `work` as a job and waits for it, for short work the user asked to wait for (a
    /// generation being bred): the window keeps drawing, but takes no clicks, keys or closing
    /// meanwhile (a busy cursor says so), and the box shows if the work outlasts its minimum
    /// duration. Returns how it ended: Cancelled also when the application quits or the owner
    /// goes first. The work may outlive the wait then, so it must own what it writes to.
    static JobOutcome runWaiting(QObject* owner, const JobBox& box, Work work);

    /// Cancels and waits for the thread.
    ~BackgroundJob() override;

    /// Asks the work to stop; `finished` then says Cancelled (unless the work had already done).
    void cancel();
    /// The progress box (for tests and for callers that relabel it).
    QProgressDialog* progressBox() const { return mBox; }

private:
    BackgroundJob(QObject* owner, const JobBox& box, Work work, Finished finished);
    void end();

    Finished mFinished;
    QThread* mThread = nullptr;
    QProgressDialog* mBox = nullptr;
    QTimer* mPoll = nullptr;
    bool mBusy = false;
    // Shared with the thread, which may outlive nothing here but reads them to the end.
    std::shared_ptr<std::atomic<bool>> mCancel = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<double>> mProgress = std::make_shared<std::atomic<double>>(0.0);
    std::shared_ptr<JobOutcome> mOutcome = std::make_shared<JobOutcome>();
};

} // namespace marbler::ui
