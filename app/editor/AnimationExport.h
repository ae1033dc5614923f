#pragma once
/// Export animation: the making of a design written as PNG frames, a GIF, an animated WebP, an
/// MP4 or a WebM, by the same library code as `marbler animate` (Animation.h), off the GUI
/// thread, with progress and cancel.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <QDialog>
#include <QObject>
#include <QString>

#include <optional>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace marbler {
struct RenderControl;
}

namespace marbler::ui {

class BackgroundJob;

/// The formats of Export animation.
enum class AnimationFormat { PngFrames, Gif, WebP, Mp4, WebM };

/// What to write.
struct AnimationExportSettings {
    QString path; ///< the file, or for PNG frames the folder (new or empty)
    AnimationFormat format = AnimationFormat::Gif;
    int width = 512, height = 512;
    int frames = 100; ///< at least 2
    double fps = 25.0;
    std::optional<Slice> slice; ///< the cross-section of a solid
};

/// The file extension of a format (empty for PNG frames).
QString animationExtension(AnimationFormat format);
/// `path` with the format's extension added when it lacks it (as it is for PNG frames).
QString withAnimationExtension(const QString& path, AnimationFormat format);

/// The dialog of Export animation: format, path, size, frames, frame rate and the duration they
/// make.
class AnimationExportDialog : public QDialog {
    Q_OBJECT
public:
    /// For `design` (its aspect sets the default height), starting from `start`.
    AnimationExportDialog(const Genome& design, const AnimationExportSettings& start,
                          QWidget* parent = nullptr);
    /// The settings chosen.
    AnimationExportSettings settings() const;

private:
    void formatChosen();
    void browse();
    QComboBox* mFormat;
    QLineEdit* mPath;
    QSpinBox *mWidth, *mHeight, *mFrames;
    QDoubleSpinBox* mFps;
    QDoubleSpinBox* mDuration; ///< frames / fps, in seconds; editing it sets the frames
    bool mSyncing = false;
    std::optional<Slice> mSlice;
};

/// Writes the making of `design` as `settings` say, on the calling thread: the folder of frames
/// must be new or empty; `control` cancels it and hears how far it is. Throws InputError,
/// RuntimeFailure, Cancelled (nothing is left at the path then).
void writeAnimationExport(const Genome& design, const AnimationExportSettings& settings,
                          const RenderControl& control);

/// Writes one animation as a BackgroundJob (BackgroundJob.h): its progress box
/// ("animationProgress") is modal to the parent when the parent is a widget. Lives on the GUI
/// thread; its signals arrive there.
class AnimationExportJob : public QObject {
    Q_OBJECT
public:
    explicit AnimationExportJob(QObject* parent = nullptr);
    /// Cancels and waits for the thread.
    ~AnimationExportJob() override;
    /// Starts writing the making of `design`. False (and nothing started) while a job runs.
    bool start(const Genome& design, const AnimationExportSettings& settings);
    /// Stops the job; nothing is left at the path. finished(false, "") follows.
    void cancel();
    /// Whether a job is writing (until finished is emitted).
    bool running() const { return mJob != nullptr; }

signals:
    /// Done so far, 0 to 1.
    void progress(double fraction);
    /// The job ended: written (`ok`), cancelled (not ok, empty error) or failed (the error).
    void finished(bool ok, const QString& error);

private:
    BackgroundJob* mJob = nullptr; ///< the job writing now (a child), null between jobs
};

} // namespace marbler::ui
