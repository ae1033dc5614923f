#pragma once
/// Renders designs for the window and the editor off the GUI thread. One worker thread
/// renders either with the GL shaders or with the CPU kernel on every core, as
/// gl::chooseBackend decides from the GL probe and the user's preference (a GPU renders on GL; a
/// software rasteriser such as llvmpipe, or no GL, on the CPU). On the CPU, solid designs are
/// still shown on their object where any GL context exists: GL rasterises only the object's
/// positions and normals and the kernel colours them (gl::renderMeshHybrid); with no GL at all,
/// and for flat designs on an object's texture coordinates wherever GL cannot draw them, the CPU
/// rasterises the object too (renderObjectOnCpu). Objects are loaded (a built-in generated, a
/// file read) once and kept, not once per cell and frame.
/// Requests are keyed (a grid cell, a thumbnail): a newer request for a key supersedes an older
/// one that has not finished, and only the newest result of a key is delivered. Each request is
/// rendered twice: a fast preview, then the antialiased final image; the previews of all waiting
/// requests come before any final pass.
/// A design whose source image lies outside its folder is rendered only once the user allowed
/// it (SourcePermissions.h): its request waits for the question, asked once per image; a
/// refused one fails with a message saying so.

#include "marbler/Genome.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "marbler/gl/Backend.h"

#include <QHash>
#include <QImage>
#include <QObject>
#include <QSet>
#include <QSize>
#include <QString>
#include <QThread>

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

namespace marbler::ui {

/// What to render for one key.
struct RenderRequest {
    Genome genome;
    QSize size{256, 256};
    QString aa = QStringLiteral("rgss"); ///< the final pass's antialiasing pattern
    /// The design-space rectangle shown (of the slice plane for a solid shown by its
    /// cross-section), rendered exactly at `size`, whose proportions it must have: a zoomed or
    /// panned view. Unset: the whole design, fitted into `size` with its own proportions.
    std::optional<Region> region;
    /// Solid (3D) genomes, and flat ones when `flatOnObject`, are shown on this object (a built-in
    /// name or a mesh file's path), seen from this orbit, framed and then magnified by `zoom`
    /// (gl::MeshSettings).
    QString mesh = QString::fromLatin1(DefaultMesh);
    /// A flat design shown on `mesh`, laid on its texture coordinates (FlatOnUvs), instead of flat.
    bool flatOnObject = false;
    double yaw = 30.0, pitch = 20.0;
    double zoom = 1.0;
    /// Only the fast pass (while the user drags an object around).
    bool previewOnly = false;
    /// A solid shown by this cross-section instead of on its object (the editor's canvas);
    /// `region` is then of the slice's plane. Ignored for a flat design.
    std::optional<Slice> slice;
};

class RenderWorker;
struct RenderQueue;

/// The shared render queue. Lives on the GUI thread; results arrive through queued signals.
class RenderService : public QObject {
    Q_OBJECT
public:
    /// Auto: the back end follows the preference (storedPreference() unless given) and the GL
    /// probe. Cpu: no GL context is ever made, not even to rasterise objects (headless tests).
    enum class Backend { Auto, Cpu };

    /// Starts the worker thread, which probes GL and chooses the back end (backendReady).
    explicit RenderService(Backend backend = Backend::Auto, QObject* parent = nullptr);
    /// Starts with this preference instead of the stored one (tests, tools).
    explicit RenderService(gl::BackendPreference preference, QObject* parent = nullptr);
    ~RenderService() override;

    /// The preference remembered in the settings ("view/renderer": auto, gpu, cpu).
    static gl::BackendPreference storedPreference();
    /// MARBLER_RENDERER's preference when set and valid: it overrides the setting.
    static std::optional<gl::BackendPreference> environmentPreference();

    /// Chooses the back end again for a new preference (MARBLER_RENDERER still overrides it);
    /// backendReady follows. Requests keep their place in the queue.
    void setPreference(gl::BackendPreference preference);
    /// The preference asked for (before the environment's override).
    gl::BackendPreference preference() const { return mPreference; }

    /// `count` consecutive keys no other view has, from the one returned: for a view that
    /// renders many images (the grid's cells, the favourites). Every view takes its keys here,
    /// so no two views ever share one, however many windows share the service.
    std::uint64_t newKeys(std::uint64_t count) { return std::exchange(mNextKey, mNextKey + count); }
    /// A key no other view has: a large view, an editor's canvas, a lineage thumbnail.
    std::uint64_t newKey() { return newKeys(1); }

    /// Queues a request for a key (superseding any unfinished one); returns its ticket.
    std::uint64_t request(std::uint64_t key, RenderRequest request);
    /// Drops a key's unfinished request; a result already on its way is not delivered.
    void cancel(std::uint64_t key);
    /// Whether no request is waiting or being rendered.
    bool idle() const { return mOutstanding.isEmpty(); }
    /// "OpenGL (renderer)" or "CPU (n threads)"; empty until the worker has chosen.
    QString backendName() const { return mBackendName; }
    /// Why that back end (gl::BackendChoice::why); empty until the worker has chosen.
    QString backendReason() const { return mBackendReason; }
    /// Whether the chosen back end is GL (false until the worker has chosen).
    bool usesGl() const { return mUsesGl; }

signals:
    /// A result for a key: the preview (final false) or the final image.
    void rendered(std::uint64_t key, const QImage& image, bool final);
    /// A request failed (a bad source image, a GL failure); the message says why.
    void failed(std::uint64_t key, const QString& message);
    /// Every request has been delivered.
    void becameIdle();
    /// The worker chose its back end (at start, and after each setPreference).
    void backendReady(const QString& name);
    /// A mesh file could not be shown (missing, unreadable, no triangles, or no texture
    /// coordinates for a flat design): the requests on it fail (failed) and this says why, so a
    /// window can choose another object. Emitted for each request that met it.
    void meshUnreadable(const QString& mesh, const QString& message);

private:
    void start(Backend backend, gl::BackendPreference preference);
    void onResult(std::uint64_t key, std::uint64_t ticket, const QImage& image, bool final,
                  const QString& error);
    /// Hands a request to the worker.
    void enqueue(std::uint64_t key, std::uint64_t ticket, RenderRequest request);
    /// Drops the worker's job of a key (not the outstanding ticket).
    void dropJob(std::uint64_t key);
    /// Asks about an outside image and releases (or fails) the requests waiting on it.
    void askAbout(const QString& image);

    /// A request waiting for the answer about the outside image it reads.
    struct Held {
        std::uint64_t ticket = 0;
        RenderRequest request;
        QString image;
    };
    QHash<std::uint64_t, Held> mHeld;
    /// Images whose question is asked or about to be.
    QSet<QString> mAsking;

    QThread mThread;
    RenderWorker* mWorker = nullptr; ///< owned by mThread's lifetime (deleteLater on finish)
    std::shared_ptr<RenderQueue> mQueue;
    /// Newest ticket of each key with work not yet delivered (GUI thread only).
    QHash<std::uint64_t, std::uint64_t> mOutstanding;
    std::uint64_t mNextTicket = 1;
    QString mBackendName;
    std::uint64_t mNextKey = 1; ///< newKeys' next (the GUI thread's only)
    QString mBackendReason;
    bool mUsesGl = false;
    bool mGlAllowed = true;
    gl::BackendPreference mPreference = gl::BackendPreference::Auto;
};

/// Converts a renderer image to a QImage (deep copy).
QImage toQImage(const marbler::Image& image);

/// The largest size with the design's aspect (its plane, for a solid on a slice) inside `box`.
QSize fitDesign(const Genome& genome, QSize box);

} // namespace marbler::ui
