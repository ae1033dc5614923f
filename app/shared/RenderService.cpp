#include "shared/RenderService.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/Meshes.h"
#include "marbler/gl/RenderView.h"
#include "shared/SourcePermissions.h"

#include <QApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QTimer>

#include <QMetaObject>
#include <QSettings>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace marbler::ui {

/// The work shared between the GUI thread (which adds and supersedes) and the worker (which
/// takes). One job per key: a newer request simply replaces the older job.
struct RenderQueue {
    struct Job {
        std::uint64_t ticket = 0;
        RenderRequest request;
        bool previewDone = false;
        /// The genome prepared by the preview's CPU pass, kept for the final one.
        std::shared_ptr<const CpuRenderer> prepared;
    };
    std::mutex mutex;
    std::map<std::uint64_t, Job> jobs;
    /// A back-end preference the worker has yet to act on (set at start and by setPreference);
    /// taken before the next job, so a change applies from the next pass on.
    std::optional<gl::BackendPreference> pendingPreference;
    /// The job the worker is rendering (ticket 0: none), and the flag that stops its CPU
    /// render early once it is superseded, cancelled or the service closes.
    std::uint64_t inFlightKey = 0, inFlightTicket = 0;
    std::atomic<bool> abort{false};
    /// Under the mutex: stops the in-flight render when it is for this key.
    void abortIfInFlight(std::uint64_t key) {
        if (inFlightTicket != 0 && inFlightKey == key) abort.store(true, std::memory_order_relaxed);
    }
};

/// Lives on the service's thread; owns the GL renderer, which must stay on the thread that made it.
class RenderWorker : public QObject {
    Q_OBJECT
public:
    RenderWorker(std::shared_ptr<RenderQueue> queue, bool glAllowed)
        : mQueue(std::move(queue))
        , mGlAllowed(glAllowed) {}

    /// Renders until no job is left. Previews of every waiting job come before final passes,
    /// so a whole new generation appears quickly and then sharpens.
    void work() {
        for (;;) {
            std::uint64_t key = 0;
            RenderQueue::Job job;
            std::optional<gl::BackendPreference> preference;
            {
                std::lock_guard lock(mQueue->mutex);
                preference = std::exchange(mQueue->pendingPreference, std::nullopt);
            }
            if (preference) choose(*preference);
            {
                std::lock_guard lock(mQueue->mutex);
                if (mQueue->jobs.empty()) return;
                auto it = std::find_if(mQueue->jobs.begin(), mQueue->jobs.end(),
                                       [](const auto& entry) { return !entry.second.previewDone; });
                if (it == mQueue->jobs.end()) it = mQueue->jobs.begin();
                key = it->first;
                job = it->second;
                mQueue->inFlightKey = key;
                mQueue->inFlightTicket = job.ticket;
                mQueue->abort.store(false, std::memory_order_relaxed);
            }
            const bool final = job.previewDone;
            QImage image;
            QString error;
            bool aborted = false;
            try {
                image = renderPass(job.request, final, job.prepared);
            } catch (const Cancelled&) {
                aborted = true; // superseded or cancelled: a newer job (if any) is waiting
            } catch (const std::exception& e) {
                error = QString::fromStdString(e.what());
            }
            bool current = false;
            {
                std::lock_guard lock(mQueue->mutex);
                mQueue->inFlightTicket = 0;
                if (aborted) continue;
                auto it = mQueue->jobs.find(key);
                if (it != mQueue->jobs.end() && it->second.ticket == job.ticket) {
                    current = true;
                    if (final || job.request.previewOnly || !error.isEmpty()) {
                        mQueue->jobs.erase(it);
                    } else {
                        it->second.previewDone = true;
                        it->second.prepared = job.prepared;
                    }
                }
            }
            // A superseded result is not worth the trip to the GUI thread.
            if (current)
                emit result(key, job.ticket, image, final || job.request.previewOnly || !error.isEmpty(),
                            error);
        }
    }

signals:
    void result(std::uint64_t key, std::uint64_t ticket, const QImage& image, bool final,
                const QString& error);
    void backendChosen(const QString& name, const QString& why, bool useGl);
    void meshFailed(const QString& mesh, const QString& message);

private:
    /// Chooses the back end for a preference (already overridden by the environment).
    void choose(gl::BackendPreference preference) {
        gl::BackendChoice choice{false, "OpenGL is not used by this render service"};
        if (mGlAllowed) choice = gl::chooseBackend(gl::probeGl(), preference);
        mUseGl = choice.useGl && glRenderer();
        if (choice.useGl && !mUseGl) choice.why = "OpenGL failed: " + mGlError;
        const QString name =
            mUseGl ? QStringLiteral("OpenGL (%1)").arg(QString::fromStdString(mGl->rendererName()))
                   : QStringLiteral("CPU (%1 threads)").arg(cpuThreads());
        emit backendChosen(name, QString::fromStdString(choice.why), mUseGl);
    }

    static int cpuThreads() { return std::max(1, int(std::thread::hardware_concurrency())); }

    /// The GL renderer, made on first need (a GPU render, or an object's rasterising for the
    /// CPU back end), so a CPU session that shows only flat designs never pays for a context.
    /// Null where none can be made.
    gl::GlRenderer* glRenderer() {
        if (mGl || !mGlAllowed || !mGlError.empty()) return mGl.get();
        const gl::GlProbe probe = gl::probeGl();
        if (!probe.available) {
            mGlError = probe.reason;
            return nullptr;
        }
        try {
            mGl = std::make_unique<gl::GlRenderer>();
        } catch (const std::exception& e) {
            mGlError = e.what();
        }
        return mGl.get();
    }

    /// An object, loaded once and kept: a built-in by its name, a file by its path, size and time
    /// (a file changed on disk is read again). Throws InputError (and emits meshFailed for a
    /// file) when it cannot be read, or when a flat design needs texture coordinates it lacks.
    std::shared_ptr<const MeshData> mesh(const QString& nameOrFile, bool needsUvs) {
        QString id = nameOrFile;
        const bool builtin = isBuiltinMesh(nameOrFile.toStdString());
        if (!builtin) {
            const QFileInfo info(nameOrFile);
            id += QStringLiteral("|%1|%2").arg(info.size()).arg(info.lastModified().toMSecsSinceEpoch());
        }
        std::shared_ptr<const MeshData> data;
        try {
            if (auto it = mMeshes.find(id); it != mMeshes.end()) {
                data = it->second;
            } else {
                if (!builtin && !QFileInfo(nameOrFile).isFile())
                    throw InputError(nameOrFile.toStdString() + ": no such mesh file");
                data = std::make_shared<const MeshData>(gl::meshByNameOrFile(nameOrFile.toStdString()));
                // A few objects are plenty: the grid shows one, a large view or an editor another.
                if (mMeshes.size() >= 4) mMeshes.clear();
                mMeshes.emplace(id, data);
            }
            if (needsUvs && (data->uvs.size() != data->positions.size() || data->uvsArePatches))
                throw InputError(nameOrFile.toStdString() +
                                 ": the mesh has no texture coordinates (UVs) to lay a flat design on");
        } catch (const InputError& e) {
            if (!builtin) emit meshFailed(nameOrFile, QString::fromUtf8(e.what()));
            throw;
        }
        return data;
    }

    QImage renderPass(const RenderRequest& request, bool final,
                      std::shared_ptr<const CpuRenderer>& prepared) {
        const Genome& genome = request.genome;
        RenderControl control;
        control.cancel = &mQueue->abort;
        gl::ViewRequest view;
        view.useGl = mUseGl;
        if (!request.slice && (genome.dimension == 3 || request.flatOnObject)) {
            const bool flat = genome.dimension != 3;
            gl::MeshSettings object;
            const QSize size = final ? request.size : request.size / 2;
            object.width = std::max(size.width(), 8);
            object.height = std::max(size.height(), 8);
            object.mesh = request.mesh.toStdString();
            object.yaw = request.yaw;
            object.pitch = request.pitch;
            object.zoom = request.zoom;
            object.supersample = final ? 3 : 1;
            view.object = object;
            // Read first, so a file that cannot be shown says so on every back end.
            const std::shared_ptr<const MeshData> data = mesh(request.mesh, flat);
            if (mUseGl) {
                try {
                    return toQImage(gl::renderView(genome, view, mGl.get(), &control));
                } catch (const Cancelled&) {
                    throw;
                } catch (const std::exception&) {
                    // A GL that cannot draw a flat design on an object: the CPU can.
                    if (!flat) throw;
                }
            } else if (!flat) {
                // On the CPU back end GL, where there is any, rasterises a solid's object.
                if (gl::GlRenderer* renderer = glRenderer())
                    return toQImage(gl::renderView(genome, view, renderer, &control));
            }
            return toQImage(renderObjectOnCpu(genome, *data, object, &control));
        }
        QSize full = request.size;
        if (!request.region) {
            // The whole plane the render shows (a solid's slice: x-z across y, y-z across x).
            Genome plane;
            plane.size = glm::dvec3(slicePlane(genome, request.slice).extent(genome.size), 1.0);
            full = fitDesign(plane, request.size);
        }
        // A quick third-size preview; a region keeps its proportions in it as best whole
        // pixels allow.
        const QSize size = final ? full : (full / 3).expandedTo(QSize(8, 8));
        RenderSettings& settings = view.raster;
        settings.width = size.width();
        settings.height = size.height();
        settings.region = request.region;
        settings.aa = final ? request.aa.toStdString() : std::string("none");
        if (genome.dimension == 3) settings.slice = request.slice.value_or(Slice{2, genome.size.z / 2.0});
        if (mUseGl) {
            try {
                return toQImage(gl::renderView(genome, view, mGl.get()));
            } catch (const RuntimeFailure&) {
                // A driver failure on one design should not blank the grid: the CPU can do it.
            }
        }
        // The genome prepared by the preview's pass serves the final one.
        if (!prepared) prepared = std::make_shared<const CpuRenderer>(genome);
        view.useGl = false;
        return toQImage(gl::renderView(genome, view, nullptr, &control, prepared.get()));
    }

    std::shared_ptr<RenderQueue> mQueue;
    const bool mGlAllowed;
    bool mUseGl = false;
    std::unique_ptr<gl::GlRenderer> mGl;
    std::string mGlError; ///< why no GL renderer could be made (made once, never retried)
    /// The objects loaded so far (mesh()), by name, or by a file's path, size and time.
    std::map<QString, std::shared_ptr<const MeshData>> mMeshes;
};

RenderService::RenderService(Backend backend, QObject* parent)
    : QObject(parent) {
    start(backend, storedPreference());
}

RenderService::RenderService(gl::BackendPreference preference, QObject* parent)
    : QObject(parent) {
    start(Backend::Auto, preference);
}

void RenderService::start(Backend backend, gl::BackendPreference preference) {
    mQueue = std::make_shared<RenderQueue>();
    mGlAllowed = backend == Backend::Auto;
    mThread.setObjectName(QStringLiteral("marbler-render"));
    mWorker = new RenderWorker(mQueue, mGlAllowed); // deleted on the worker thread when it finishes
    mWorker->moveToThread(&mThread);
    connect(&mThread, &QThread::finished, mWorker, &QObject::deleteLater);
    connect(mWorker, &RenderWorker::result, this, &RenderService::onResult);
    connect(mWorker, &RenderWorker::meshFailed, this, &RenderService::meshUnreadable);
    connect(mWorker, &RenderWorker::backendChosen, this,
            [this](const QString& name, const QString& why, bool useGl) {
                mBackendName = name;
                mBackendReason = why;
                mUsesGl = useGl;
                emit backendReady(name);
            });
    mThread.start();
    setPreference(preference);
}

gl::BackendPreference RenderService::storedPreference() {
    const QString text =
        QSettings().value(QStringLiteral("view/renderer"), QStringLiteral("auto")).toString();
    return gl::parseBackendPreference(text.toStdString()).value_or(gl::BackendPreference::Auto);
}

std::optional<gl::BackendPreference> RenderService::environmentPreference() {
    return gl::environmentBackendPreference();
}

void RenderService::setPreference(gl::BackendPreference preference) {
    mPreference = preference;
    {
        std::lock_guard lock(mQueue->mutex);
        mQueue->pendingPreference = environmentPreference().value_or(preference);
    }
    // The worker takes the new choice before its next job, or now when idle.
    QMetaObject::invokeMethod(mWorker, &RenderWorker::work, Qt::QueuedConnection);
}

RenderService::~RenderService() {
    {
        std::lock_guard lock(mQueue->mutex);
        mQueue->jobs.clear();
        mQueue->abort.store(true, std::memory_order_relaxed);
    }
    mThread.quit();
    mThread.wait();
}

std::uint64_t RenderService::request(std::uint64_t key, RenderRequest request) {
    const std::uint64_t ticket = mNextTicket++;
    mHeld.remove(key);
    mOutstanding[key] = ticket;
    if (!request.genome.allowExternalSource) {
        if (const QString image = SourcePermissions::externalImage(request.genome); !image.isEmpty()) {
            const std::optional<bool> answer = SourcePermissions::session().answer(image);
            if (!answer) {
                // Asked from the event loop, not from inside this call: the caller may be in the
                // middle of laying out a generation, and the question's own event loop would
                // run into it.
                dropJob(key);
                mHeld.insert(key, Held{ticket, std::move(request), image});
                if (!mAsking.contains(image)) {
                    mAsking.insert(image);
                    QTimer::singleShot(0, this, [this, image] { askAbout(image); });
                }
                return ticket;
            }
            if (!*answer) {
                dropJob(key);
                QMetaObject::invokeMethod(
                    this,
                    [this, key, ticket, image] {
                        onResult(key, ticket, QImage(), true, refusedSourceMessage(image));
                    },
                    Qt::QueuedConnection);
                return ticket;
            }
            request.genome.allowExternalSource = true;
        }
    }
    enqueue(key, ticket, std::move(request));
    return ticket;
}

void RenderService::enqueue(std::uint64_t key, std::uint64_t ticket, RenderRequest request) {
    {
        std::lock_guard lock(mQueue->mutex);
        mQueue->jobs[key] = RenderQueue::Job{ticket, std::move(request), false, nullptr};
        mQueue->abortIfInFlight(key);
    }
    QMetaObject::invokeMethod(mWorker, &RenderWorker::work, Qt::QueuedConnection);
}

void RenderService::dropJob(std::uint64_t key) {
    std::lock_guard lock(mQueue->mutex);
    mQueue->jobs.erase(key);
    mQueue->abortIfInFlight(key);
}

void RenderService::askAbout(const QString& image) {
    QString design;
    for (const Held& held : std::as_const(mHeld))
        if (held.image == image) {
            design = QString::fromStdString(held.request.genome.fileName);
            break;
        }
    const bool allowed = askExternalSource(QApplication::activeWindow(), design, image);
    SourcePermissions::session().setAnswer(image, allowed);
    mAsking.remove(image);
    // Taken out first: a result's receiver may request again, which changes mHeld.
    std::vector<std::pair<std::uint64_t, Held>> waiting;
    for (auto it = mHeld.begin(); it != mHeld.end();) {
        if (it->image != image) {
            ++it;
            continue;
        }
        waiting.emplace_back(it.key(), std::move(it.value()));
        it = mHeld.erase(it);
    }
    for (auto& [key, held] : waiting) {
        if (allowed) {
            held.request.genome.allowExternalSource = true;
            enqueue(key, held.ticket, std::move(held.request));
        } else {
            onResult(key, held.ticket, QImage(), true, refusedSourceMessage(image));
        }
    }
}

void RenderService::cancel(std::uint64_t key) {
    mHeld.remove(key);
    dropJob(key);
    if (mOutstanding.remove(key) && mOutstanding.isEmpty()) emit becameIdle();
}

void RenderService::onResult(std::uint64_t key, std::uint64_t ticket, const QImage& image, bool final,
                             const QString& error) {
    auto it = mOutstanding.find(key);
    if (it == mOutstanding.end() || it.value() != ticket) return; // superseded or cancelled
    if (final) mOutstanding.erase(it);
    if (!error.isEmpty())
        emit failed(key, error);
    else
        emit rendered(key, image, final);
    if (final && mOutstanding.isEmpty()) emit becameIdle();
}

QImage toQImage(const marbler::Image& image) {
    QImage result(image.width, image.height, QImage::Format_RGB888);
    for (int y = 0; y < image.height; ++y)
        std::copy_n(image.row(y), std::size_t(image.width) * 3, result.scanLine(y));
    return result;
}

QSize fitDesign(const Genome& genome, QSize box) {
    const double w = genome.size.x, h = genome.size.y;
    if (!(w > 0 && h > 0) || box.isEmpty()) return box.expandedTo(QSize(1, 1));
    const double scale = std::min(box.width() / w, box.height() / h);
    return QSize(std::max(1, int(w * scale)), std::max(1, int(h * scale)));
}

} // namespace marbler::ui

#include "RenderService.moc"
