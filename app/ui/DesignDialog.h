#pragma once
/// One design shown large: save its genome, export an image at a chosen size, and (later) open
/// it in the editor.

#include "marbler/Genome.h"

#include <QDialog>
#include <QImage>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

class QLabel;
class QThread;

namespace marbler::ui {

class RenderService;

class DesignDialog : public QDialog {
    Q_OBJECT
public:
    DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent = nullptr);
    ~DesignDialog() override;

    const Genome& genome() const { return mGenome; }
    /// Saves the genome to a file (atomically: a temporary renamed over it); errors are
    /// reported. Returns success.
    bool saveTo(const QString& file);
    /// Starts rendering the design to an image file (format by extension) at a pixel size on a
    /// thread of its own, written atomically; exportFinished follows. Returns false when an
    /// export is already running.
    bool exportTo(const QString& file, QSize pixels, const QString& aa = QStringLiteral("rgss"),
                  std::optional<double> dpi = std::nullopt);
    /// Stops a running export; no file is left behind.
    void cancelExport();
    bool isExporting() const { return bool(mExportCancel); }

signals:
    /// An export ended: written (the file is complete), or cancelled or failed (`error` says
    /// why for a failure; nothing is left behind either way).
    void exportFinished(const QString& file, bool written, const QString& error);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void requestRender(bool previewOnly = false);
    void exportImage();

    Genome mGenome;
    RenderService* mRenderer;
    QString mMesh;
    std::uint64_t mKey;
    QLabel* mView = nullptr;
    QImage mImage;
    double mYaw = 30.0, mPitch = 20.0;
    QPoint mLastPos;
    bool mDragging = false;
    std::shared_ptr<std::atomic<bool>> mExportCancel; ///< set while an export runs
    QThread* mExportThread = nullptr;
};

/// Asks for a file name and saves the genome atomically; errors are reported. Returns success.
bool saveGenomeWithDialog(QWidget* parent, const Genome& genome);
/// Saves the genome atomically to a file; errors are reported. Returns success.
bool saveGenomeTo(QWidget* parent, const Genome& genome, const QString& file);

} // namespace marbler::ui
