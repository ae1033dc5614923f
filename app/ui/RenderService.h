#pragma once
/// Renders designs for the window (and later the editor) off the GUI thread. One worker thread
/// owns an offscreen GL renderer when one can be made, else renders with the CPU renderer.
/// Requests are keyed (a grid cell, a thumbnail): a newer request for a key supersedes an older
/// one that has not finished, and only the newest result of a key is delivered. Each request is
/// rendered twice: a fast preview, then the antialiased final image.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <QHash>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>
#include <QThread>

#include <cstdint>
#include <memory>

namespace marbler::ui {

/// What to render for one key.
struct RenderRequest {
    Genome genome;
    QSize size{256, 256};
    QString aa = QStringLiteral("rgss"); ///< the final pass's antialiasing pattern
    /// Solid (3D) genomes are shown on this object, seen from this orbit.
    QString mesh = QStringLiteral("vase");
    double yaw = 30.0, pitch = 20.0;
    /// Only the fast pass (while the user drags an object around).
    bool previewOnly = false;
};

class RenderWorker;
struct RenderQueue;

/// The shared render queue. Lives on the GUI thread; results arrive through queued signals.
class RenderService : public QObject {
    Q_OBJECT
public:
    enum class Backend { Auto, Cpu };

    /// Starts the worker thread. With Backend::Cpu the GL renderer is never tried (tests).
    explicit RenderService(Backend backend = Backend::Auto, QObject* parent = nullptr);
    ~RenderService() override;

    /// Queues a request for a key (superseding any unfinished one); returns its ticket.
    std::uint64_t request(std::uint64_t key, RenderRequest request);
    /// Drops a key's unfinished request; a result already on its way is not delivered.
    void cancel(std::uint64_t key);
    /// Whether no request is waiting or being rendered.
    bool idle() const { return mOutstanding.isEmpty(); }
    /// "OpenGL (renderer)" or "CPU"; empty until the worker has started.
    QString backendName() const { return mBackendName; }

signals:
    /// A result for a key: the preview (final false) or the final image.
    void rendered(std::uint64_t key, const QImage& image, bool final);
    /// A request failed (a bad source image, a GL failure); the message says why.
    void failed(std::uint64_t key, const QString& message);
    /// Every request has been delivered.
    void becameIdle();
    /// The worker chose its back end.
    void backendReady(const QString& name);

private:
    void onResult(std::uint64_t key, std::uint64_t ticket, const QImage& image, bool final, const QString& error);

    QThread mThread;
    RenderWorker* mWorker = nullptr; ///< owned by mThread's lifetime (deleteLater on finish)
    std::shared_ptr<RenderQueue> mQueue;
    /// Newest ticket of each key with work not yet delivered (GUI thread only).
    QHash<std::uint64_t, std::uint64_t> mOutstanding;
    std::uint64_t mNextTicket = 1;
    QString mBackendName;
};

/// Converts a renderer image to a QImage (deep copy).
QImage toQImage(const marbler::Image& image);

/// The largest size with the design's aspect (its plane, for a solid on a slice) inside `box`.
QSize fitDesign(const Genome& genome, QSize box);

} // namespace marbler::ui
