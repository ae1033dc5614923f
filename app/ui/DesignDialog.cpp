#include "ui/DesignDialog.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Sampling.h"
#include "ui/ErrorReport.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>

#include <atomic>
#include <cmath>
#include <memory>

namespace marbler::ui {

namespace {

/// Large views get keys of their own, far from the grid's and the shelf's.
std::uint64_t nextDialogKey() {
    static std::uint64_t next = 1'000'000;
    return next++;
}

/// The size and antialiasing of an exported image, in pixels or as a print size at a dpi.
class ExportSettingsDialog : public QDialog {
public:
    ExportSettingsDialog(const Genome& genome, QWidget* parent) : QDialog(parent), mAspect(genome.size.y / genome.size.x) {
        setWindowTitle(tr("Export image"));
        auto* form = new QFormLayout;
        mUnit = new QComboBox(this);
        mUnit->addItem(tr("pixels"), 0.0);
        mUnit->addItem(tr("cm"), 2.54);
        mUnit->addItem(tr("mm"), 25.4);
        mUnit->addItem(tr("inches"), 1.0);
        mWidth = new QDoubleSpinBox(this);
        mWidth->setRange(0.01, 65536);
        mWidth->setDecimals(2);
        mWidth->setValue(2048);
        mDpi = new QSpinBox(this);
        mDpi->setRange(10, 4800);
        mDpi->setValue(300);
        mDpi->setToolTip(tr("Dots per inch for a print size; written into the file"));
        mAa = new QComboBox(this);
        for (const std::string& name : aaPatternNames()) mAa->addItem(QString::fromStdString(name));
        mAa->setCurrentText(QStringLiteral("rgss"));
        mAa->setToolTip(tr("Antialiasing pattern: more samples, smoother edges, slower"));
        mPixels = new QLabel(this);
        form->addRow(tr("Width"), mWidth);
        form->addRow(tr("Unit"), mUnit);
        form->addRow(tr("Resolution (dpi)"), mDpi);
        form->addRow(tr("Antialiasing"), mAa);
        form->addRow(tr("Image"), mPixels);
        if (genome.dimension == 3)
            form->addRow(new QLabel(tr("A solid design exports its middle cross-section (z = depth / 2)."), this));
        auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
        connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
        connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
        auto* layout = new QVBoxLayout(this);
        layout->addLayout(form);
        layout->addWidget(buttons);
        const auto update = [this] {
            mDpi->setEnabled(perInch() > 0.0);
            const QSize s = pixels();
            mPixels->setText(tr("%1 × %2 pixels").arg(s.width()).arg(s.height()));
        };
        connect(mUnit, &QComboBox::currentIndexChanged, this, update);
        connect(mWidth, &QDoubleSpinBox::valueChanged, this, update);
        connect(mDpi, &QSpinBox::valueChanged, this, update);
        update();
    }

    double perInch() const { return mUnit->currentData().toDouble(); }
    QSize pixels() const {
        double w = mWidth->value();
        if (perInch() > 0.0) w = w / perInch() * mDpi->value();
        const int width = std::max(1, int(std::lround(w)));
        return {width, std::max(1, int(std::lround(width * mAspect)))};
    }
    std::optional<double> dpi() const { return perInch() > 0.0 ? std::optional<double>(mDpi->value()) : std::nullopt; }
    std::string aa() const { return mAa->currentText().toStdString(); }

private:
    double mAspect;
    QComboBox* mUnit;
    QDoubleSpinBox* mWidth;
    QSpinBox* mDpi;
    QComboBox* mAa;
    QLabel* mPixels;
};

} // namespace

DesignDialog::DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent)
    : QDialog(parent), mGenome(std::move(genome)), mRenderer(renderer), mMesh(mesh), mKey(nextDialogKey()) {
    const LineageInfo info = lineageOf(mGenome);
    setWindowTitle(tr("Design %1").arg(info.name.isEmpty() ? info.id : info.name));
    mView = new QLabel(tr("rendering…"), this);
    mView->setAlignment(Qt::AlignCenter);
    mView->setMinimumSize(320, 320);
    mView->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    if (mGenome.dimension == 3) mView->setToolTip(tr("Drag to turn the object"));

    auto* save = new QPushButton(tr("&Save genome…"), this);
    save->setShortcut(QKeySequence::Save);
    save->setToolTip(tr("Save the design as a genome file (Ctrl+S)"));
    auto* exportButton = new QPushButton(tr("&Export image…"), this);
    exportButton->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    exportButton->setToolTip(tr("Render the design to PNG, TIFF, EXR or JPEG at any size (Ctrl+E)"));
    auto* editor = new QPushButton(tr("Open in editor"), this);
    editor->setEnabled(false);
    editor->setToolTip(tr("The editor arrives in a later version"));
    auto* close = new QPushButton(tr("Close"), this);
    connect(save, &QPushButton::clicked, this, [this] { saveGenomeWithDialog(this, mGenome); });
    connect(exportButton, &QPushButton::clicked, this, &DesignDialog::exportImage);
    connect(close, &QPushButton::clicked, this, &QDialog::close);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(save);
    buttons->addWidget(exportButton);
    buttons->addWidget(editor);
    buttons->addStretch();
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(mView, 1);
    layout->addLayout(buttons);
    resize(720, 780);

    connect(mRenderer, &RenderService::rendered, this, [this](std::uint64_t key, const QImage& image, bool) {
        if (key != mKey) return;
        mImage = image;
        mView->setPixmap(QPixmap::fromImage(image));
    });
    connect(mRenderer, &RenderService::failed, this, [this](std::uint64_t key, const QString& message) {
        if (key == mKey) mView->setText(tr("Cannot render: %1").arg(message));
    });
}

DesignDialog::~DesignDialog() {
    mRenderer->cancel(mKey);
    // Closing the view stops its export; renderToFile leaves no partial file.
    if (mExportThread) {
        mExportCancel->store(true);
        mExportThread->wait();
    }
}

void DesignDialog::resizeEvent(QResizeEvent* event) {
    QDialog::resizeEvent(event);
    requestRender();
}

void DesignDialog::requestRender(bool previewOnly) {
    RenderRequest request;
    request.genome = mGenome;
    request.size = (mView->size() * devicePixelRatioF()).expandedTo(QSize(32, 32));
    request.mesh = mMesh;
    request.yaw = mYaw;
    request.pitch = mPitch;
    request.previewOnly = previewOnly;
    mRenderer->request(mKey, std::move(request));
}

void DesignDialog::mousePressEvent(QMouseEvent* event) {
    mLastPos = event->position().toPoint();
    mDragging = mGenome.dimension == 3 && event->button() == Qt::LeftButton;
}

void DesignDialog::mouseMoveEvent(QMouseEvent* event) {
    if (!mDragging) return;
    const QPoint d = event->position().toPoint() - mLastPos;
    mLastPos = event->position().toPoint();
    mYaw = std::fmod(mYaw + d.x() * 0.5, 360.0);
    mPitch = std::clamp(mPitch + d.y() * 0.5, -89.0, 89.0);
    requestRender(true);
}

void DesignDialog::mouseReleaseEvent(QMouseEvent*) {
    if (!mDragging) return;
    mDragging = false;
    requestRender();
}

void DesignDialog::exportImage() {
    ExportSettingsDialog settingsDialog(mGenome, this);
    if (settingsDialog.exec() != QDialog::Accepted) return;
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("files/exportDir")).toString();
    const QString file = QFileDialog::getSaveFileName(this, tr("Export image"), dir,
                                                      tr("Images (*.png *.tif *.tiff *.exr *.jpg *.jpeg)"));
    if (file.isEmpty()) return;
    settings.setValue(QStringLiteral("files/exportDir"), QFileInfo(file).absolutePath());

    exportTo(file, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()), settingsDialog.dpi());
}

bool DesignDialog::saveTo(const QString& file) { return saveGenomeTo(this, mGenome, file); }

bool DesignDialog::exportTo(const QString& file, QSize pixels, const QString& aa, std::optional<double> dpi) {
    if (mExportCancel) return false;
    RenderSettings render;
    render.width = std::max(1, pixels.width());
    render.height = std::max(1, pixels.height());
    render.aa = aa.toStdString();
    if (mGenome.dimension == 3) render.slice = Slice{2, mGenome.size.z / 2.0};
    ExportOptions options;
    options.dpi = dpi;

    // The export runs on its own thread; the dialog polls its progress so the worker never
    // touches a widget.
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    mExportCancel = cancel;
    auto progress = std::make_shared<std::atomic<double>>(0.0);
    auto error = std::make_shared<QString>();
    QThread* thread = QThread::create([genome = mGenome, render, file, options, cancel, progress, error] {
        RenderControl control;
        control.cancel = cancel.get();
        control.progress = [progress](double p) { progress->store(p, std::memory_order_relaxed); };
        try {
            renderToFile(genome, render, file.toStdString(), options, &control);
        } catch (const Cancelled&) {
        } catch (const std::exception& e) {
            *error = QString::fromStdString(e.what());
        }
    });
    thread->setParent(this);
    mExportThread = thread;
    auto* dialog = new QProgressDialog(tr("Exporting %1…").arg(QFileInfo(file).fileName()), tr("Cancel"), 0, 1000, this);
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    dialog->setAutoReset(false);
    dialog->setAutoClose(false);
    auto* poll = new QTimer(dialog);
    connect(poll, &QTimer::timeout, dialog, [dialog, progress] { dialog->setValue(int(progress->load() * 999)); });
    connect(dialog, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
    connect(thread, &QThread::finished, this, [this, thread, dialog, cancel, error, file] {
        dialog->deleteLater();
        thread->deleteLater();
        mExportCancel.reset();
        mExportThread = nullptr;
        const bool written = error->isEmpty() && !cancel->load();
        if (!error->isEmpty())
            reportError(this, tr("Cannot export the image"), *error);
        else if (written)
            setWindowTitle(tr("Exported %1").arg(QFileInfo(file).fileName()));
        emit exportFinished(file, written, *error);
    });
    poll->start(100);
    thread->start();
    return true;
}

void DesignDialog::cancelExport() {
    if (mExportCancel) mExportCancel->store(true);
}

bool saveGenomeWithDialog(QWidget* parent, const Genome& genome) {
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("files/saveDir")).toString();
    const LineageInfo info = lineageOf(genome);
    const QString suggested = QDir(dir).filePath((info.name.isEmpty() ? info.id.left(8) : info.name) + QStringLiteral(".marble.json"));
    QString file = QFileDialog::getSaveFileName(parent, QObject::tr("Save design"), suggested,
                                                QObject::tr("Marbler genomes (*.marble.json)"));
    if (file.isEmpty()) return false;
    if (!file.endsWith(QStringLiteral(".json"))) file += QStringLiteral(".marble.json");
    settings.setValue(QStringLiteral("files/saveDir"), QFileInfo(file).absolutePath());
    return saveGenomeTo(parent, genome, file);
}

bool saveGenomeTo(QWidget* parent, const Genome& genome, const QString& file) {
    try {
        saveGenome(genome, file.toStdString());
    } catch (const Error& e) {
        reportError(parent, QObject::tr("Cannot save the design"), QString::fromStdString(e.what()));
        return false;
    }
    return true;
}

} // namespace marbler::ui
