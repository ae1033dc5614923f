#pragma once
/// The large view's export pipeline: a design rendered to an image file (flat, a solid's
/// cross-section, a solid on its object as the view shows it, or a flat design's mirror repeat
/// tile) or traced to SVG, one at a time, as a BackgroundJob with its progress box.

#include "marbler/Genome.h"
#include "marbler/PrintProfile.h"
#include "shared/BackgroundJob.h"
#include "shared/ExportSettingsDialog.h"
#include "shared/ViewController.h"

#include <QObject>
#include <QPointer>
#include <QSize>
#include <QString>

#include <optional>

class QWidget;

namespace marbler::ui {

/// What a window's status bar says when an export of `file` was cancelled.
QString exportCancelledMessage(const QString& file);

class DesignExport : public QObject {
    Q_OBJECT
public:
    /// Exports for `window`: the progress box is modal to it, failures are reported over it, and
    /// it owns the export (closing it cancels the export and waits for it).
    explicit DesignExport(QWidget* window);
    ~DesignExport() override;

    /// How the view shows a solid on its object, for the object view's export.
    struct ObjectView {
        QString mesh;
        ViewAngle angle;
        double zoom = 1.0;
        bool useGl = false; ///< the window's back end renders on the GPU (RenderService::usesGl)
    };

    /// Starts rendering `genome` to an image file; see DesignDialog::exportTo. Returns false when
    /// an export is already running or the size is beyond the renderer's limits (reported).
    bool exportTo(const Genome& genome, const ObjectView& object, const QString& file, QSize pixels,
                  const QString& aa, std::optional<double> dpi, std::optional<SolidExport> solid,
                  int bitsPerSample, bool mirrorRepeatTile, bool straightRepeatTile = false);
    /// Starts rendering `genome` (flat) to a CMYK TIFF in the colours of the printer profile
    /// `profile` (marbler/PrintProfile.h, as marbler render --icc); see DesignDialog::exportCmykTo.
    bool exportCmykTo(const Genome& genome, const QString& file, QSize pixels, const QString& aa,
                      std::optional<double> dpi, const QString& profile, RenderingIntent intent,
                      int bitsPerSample);
    /// Starts writing `genome`'s separations into `folder` (marbler/Separations.h, as marbler
    /// render --separations); see DesignDialog::exportSeparationsTo.
    bool exportSeparationsTo(const Genome& genome, const QString& folder, QSize pixels, const QString& aa,
                             std::optional<double> dpi, int maskBits);
    /// Starts writing `genome` as SVG; see DesignDialog::exportSvgTo.
    bool exportSvgTo(const Genome& genome, const QString& file, double tolerance);
    /// Stops a running export; no file is left behind.
    void cancel();
    bool isRunning() const { return !mJob.isNull(); }

signals:
    /// An export ended: written (complete), or cancelled or failed (`error` says why; a failure
    /// has been reported already). Nothing is left behind unless written.
    void finished(const QString& file, bool written, const QString& error);

private:
    bool start(const QString& file, BackgroundJob::Work work, bool busy = false);

    QWidget* mWindow;
    QPointer<BackgroundJob> mJob; ///< the export running, if any
};

} // namespace marbler::ui
