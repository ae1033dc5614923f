#include "ui/BakeObject.h"

#include "marbler/Bake.h"
#include "marbler/Error.h"
#include "marbler/gl/Meshes.h"
#include "ui/ErrorReport.h"
#include "ui/SavedFiles.h"

#include <QFileInfo>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QThread>
#include <QTimer>

#include <atomic>
#include <memory>

namespace marbler::ui {
namespace {

/// One bake in flight: owned by the button, so closing the view cancels the bake and waits for
/// it instead of destroying a running thread.
class BakeJob : public QObject {
public:
    BakeJob(QPushButton* button, Genome genome, QString mesh, QString file, int textureSize,
            std::function<void(const QString&)> written)
        : QObject(button)
        , mButton(button)
        , mFile(file)
        , mWritten(std::move(written)) {
        auto cancel = mCancel;
        auto progress = mProgress;
        auto error = mError;
        mThread =
            QThread::create([genome = std::move(genome), mesh, file, textureSize, cancel, progress, error] {
                RenderControl control;
                control.cancel = cancel.get();
                control.progress = [progress](double p) { progress->store(p, std::memory_order_relaxed); };
                try {
                    MeshData data = gl::meshByNameOrFile(mesh.toStdString());
                    if (!hasUsableUvs(data)) data = withGeneratedUvs(data, textureSize);
                    BakeSettings settings;
                    settings.textureSize = textureSize;
                    const BakedTexture baked = bakeTexture(genome, data, settings, &control);
                    const std::string name = genome.meta.name.value_or("marbled");
                    writeTexturedMesh(data, baked.image, file.toStdString(), name);
                } catch (const Cancelled&) {
                } catch (const std::exception& e) {
                    *error = QString::fromStdString(e.what());
                }
            });
        mDialog = new QProgressDialog(QObject::tr("Baking %1…").arg(QFileInfo(file).fileName()),
                                      QObject::tr("Cancel"), 0, 1000, button->window());
        mDialog->setObjectName(QStringLiteral("bakeProgress"));
        mDialog->setWindowModality(Qt::WindowModal);
        mDialog->setMinimumDuration(300);
        mDialog->setAutoReset(false);
        mDialog->setAutoClose(false);
        auto* poll = new QTimer(this);
        connect(poll, &QTimer::timeout, this, [this] { mDialog->setValue(int(mProgress->load() * 999)); });
        connect(mDialog, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
        connect(mThread, &QThread::finished, this, [this, poll] {
            poll->stop();
            finish();
        });
        button->setEnabled(false);
        poll->start(100);
        mThread->start();
    }

    ~BakeJob() override {
        if (!mThread) return;
        mCancel->store(true);
        mThread->wait();
        delete mThread;
        delete mDialog;
    }

private:
    void finish() {
        // The progress box goes before any message, so a stale one never covers an error.
        mDialog->reset();
        mDialog->hide();
        delete mDialog;
        mDialog = nullptr;
        mThread->wait(); // `finished` comes just before the thread has quite ended
        delete mThread;
        mThread = nullptr;
        mButton->setEnabled(true);
        if (!mError->isEmpty())
            reportError(mButton->window(), QObject::tr("Cannot bake onto the object"), *mError);
        else if (!mCancel->load() && mWritten)
            mWritten(mFile);
        deleteLater();
    }

    QPushButton* mButton;
    QString mFile;
    std::function<void(const QString&)> mWritten;
    QThread* mThread = nullptr;
    QProgressDialog* mDialog = nullptr;
    std::shared_ptr<std::atomic<bool>> mCancel = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<double>> mProgress = std::make_shared<std::atomic<double>>(0.0);
    std::shared_ptr<QString> mError = std::make_shared<QString>();
};

} // namespace

QPushButton* makeBakeButton(QWidget* parent, std::function<Genome()> genome, QString mesh,
                            std::function<void(const QString&)> written, int textureSize) {
    auto* button = new QPushButton(QObject::tr("&Bake onto object…"), parent);
    button->setObjectName(QStringLiteral("bakeObject"));
    button->setToolTip(
        QObject::tr("Write the object with the design baked into its texture, for other 3D tools "
                    "(glTF .glb or .gltf, OBJ; a %1 × %1 texture)")
            .arg(textureSize));
    QObject::connect(button, &QPushButton::clicked, button, [button, genome, mesh, written, textureSize] {
        const Genome design = genome();
        QSettings settings;
        QString file =
            askSaveFile(button->window(), QObject::tr("Bake onto object"),
                        suggestedFile(design, settings.value(QStringLiteral("files/bakeDir")).toString(),
                                      QStringLiteral(".glb")),
                        QObject::tr("3D objects (*.glb *.gltf *.obj)"));
        if (file.isEmpty()) return;
        // A name typed without a format gets glTF binary, one file that carries its texture.
        const QString suffix = QFileInfo(file).suffix().toLower();
        if (suffix.isEmpty())
            file += QStringLiteral(".glb");
        else if (suffix != QStringLiteral("glb") && suffix != QStringLiteral("gltf") &&
                 suffix != QStringLiteral("obj")) {
            reportError(button->window(), QObject::tr("Cannot bake onto the object"),
                        QObject::tr("%1: choose .glb, .gltf or .obj").arg(QFileInfo(file).fileName()));
            return;
        }
        settings.setValue(QStringLiteral("files/bakeDir"), QFileInfo(file).absolutePath());
        new BakeJob(button, design, mesh, file, textureSize, written);
    });
    return button;
}

} // namespace marbler::ui
