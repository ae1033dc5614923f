#include "ui/DesignDialog.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Sampling.h"
#include "ui/ErrorReport.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"
#include "ui/SavedFiles.h"

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

#include <algorithm>
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

} // namespace

QString exportSizeProblem(QSize pixels) {
    const std::int64_t w = pixels.width(), h = pixels.height();
    if (w < 1 || h < 1) return QObject::tr("The image would be %1 × %2 pixels: choose a size of at least 1 pixel.").arg(w).arg(h);
    if (w > MaxImageSide || h > MaxImageSide || w * h > MaxImagePixels)
        return QObject::tr("The image would be %L1 × %L2 pixels (%L3 megapixels); Marbler renders at most %L4 pixels "
                           "a side and %L5 megapixels. Choose a smaller size or a lower resolution.")
            .arg(w)
            .arg(h)
            .arg(double(w) * double(h) / 1e6, 0, 'f', 0)
            .arg(MaxImageSide)
            .arg(double(MaxImagePixels) / 1e6, 0, 'f', 0);
    return {};
}

ExportSettingsDialog::ExportSettingsDialog(const Genome& genome, QWidget* parent)
    : QDialog(parent), mAspect(genome.size.y / genome.size.x) {
    setWindowTitle(tr("Export image"));
    auto* form = new QFormLayout;
    mWidth = new QDoubleSpinBox(this);
    mWidth->setObjectName(QStringLiteral("exportWidth"));
    // Wide enough for any unit at any dpi; the size check says what is too large.
    mWidth->setDecimals(0);
    mWidth->setRange(1, 1e7);
    mWidth->setValue(mPixelWidth);
    mWidth->setToolTip(tr("The image's width in the unit beside; the height follows the design's proportions"));
    mUnit = new QComboBox(this);
    mUnit->setObjectName(QStringLiteral("exportUnit"));
    mUnit->addItem(tr("pixels"), 0.0);
    mUnit->addItem(tr("cm"), 2.54);
    mUnit->addItem(tr("mm"), 25.4);
    mUnit->addItem(tr("inches"), 1.0);
    mUnit->setToolTip(tr("Pixels, or a print size at the resolution below; changing it converts the width"));
    mDpi = new QSpinBox(this);
    mDpi->setObjectName(QStringLiteral("exportDpi"));
    mDpi->setRange(10, 4800);
    mDpi->setValue(300);
    mDpi->setToolTip(tr("Dots per inch: turns a print size into pixels, and is written into the file"));
    mAa = new QComboBox(this);
    mAa->setObjectName(QStringLiteral("exportAa"));
    for (const std::string& name : aaPatternNames()) mAa->addItem(QString::fromStdString(name));
    mAa->setCurrentText(QStringLiteral("rgss"));
    mAa->setToolTip(tr("Antialiasing pattern: more samples, smoother edges, slower"));
    mPixels = new QLabel(this);
    mPixels->setObjectName(QStringLiteral("exportPixels"));
    mPixels->setWordWrap(true);
    form->addRow(tr("&Width"), mWidth);
    form->addRow(tr("&Unit"), mUnit);
    form->addRow(tr("&Resolution (dpi)"), mDpi);
    form->addRow(tr("&Antialiasing"), mAa);
    form->addRow(tr("Image"), mPixels);
    if (genome.dimension == 3)
        form->addRow(new QLabel(tr("A solid design exports its middle cross-section (z = depth / 2)."), this));
    mButtons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(mButtons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(mButtons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(mButtons);
    // Every field in reading order, then the buttons.
    setTabOrder(mWidth, mUnit);
    setTabOrder(mUnit, mDpi);
    setTabOrder(mDpi, mAa);
    setTabOrder(mAa, mButtons->button(QDialogButtonBox::Ok));
    setTabOrder(mButtons->button(QDialogButtonBox::Ok), mButtons->button(QDialogButtonBox::Cancel));

    connect(mUnit, &QComboBox::currentIndexChanged, this, [this] { showWidth(); });
    connect(mWidth, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        if (mShowing) return;
        // What the user typed, in pixels; the unit and dpi only change how it is shown.
        mPixelWidth = perInch() > 0.0 ? value / perInch() * mDpi->value() : value;
        updateSummary();
    });
    connect(mDpi, &QSpinBox::valueChanged, this, [this] {
        // A print size keeps its size at another resolution (so the pixels change); a pixel
        // size keeps its pixels.
        if (perInch() > 0.0) mPixelWidth = mWidth->value() / perInch() * mDpi->value();
        updateSummary();
    });
    updateSummary();
}

double ExportSettingsDialog::perInch() const { return mUnit->currentData().toDouble(); }

void ExportSettingsDialog::showWidth() {
    mShowing = true;
    mWidth->setDecimals(perInch() > 0.0 ? 3 : 0);
    mWidth->setMinimum(perInch() > 0.0 ? 0.001 : 1.0);
    mWidth->setValue(perInch() > 0.0 ? mPixelWidth / mDpi->value() * perInch() : mPixelWidth);
    mShowing = false;
    updateSummary();
}

void ExportSettingsDialog::updateSummary() {
    const QSize s = pixels();
    const QString problem = exportSizeProblem(s);
    QString text = tr("%L1 × %L2 pixels").arg(s.width()).arg(s.height());
    if (perInch() <= 0.0)
        text += tr(" (%1 × %2 in at %3 dpi)")
                    .arg(s.width() / double(mDpi->value()), 0, 'f', 2)
                    .arg(s.height() / double(mDpi->value()), 0, 'f', 2)
                    .arg(mDpi->value());
    mPixels->setText(problem.isEmpty() ? text : problem);
    mPixels->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #c03030"));
    mButtons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
}

void ExportSettingsDialog::setUnit(const QString& unit) {
    const int index = mUnit->findText(unit);
    if (index >= 0) mUnit->setCurrentIndex(index);
}

QString ExportSettingsDialog::unit() const { return mUnit->currentText(); }
double ExportSettingsDialog::widthValue() const { return mWidth->value(); }
void ExportSettingsDialog::setWidthValue(double value) { mWidth->setValue(value); }
void ExportSettingsDialog::setDpi(int dpi) { mDpi->setValue(dpi); }

QSize ExportSettingsDialog::pixels() const {
    const double w = std::round(mPixelWidth);
    const double h = std::round(w * mAspect);
    // Clamped only so the numbers fit an int; the size check refuses what is too large.
    const auto fit = [](double v) { return int(std::clamp(v, 0.0, 2e9)); };
    return {std::max(1, fit(w)), std::max(1, fit(h))};
}

std::optional<double> ExportSettingsDialog::dpi() const { return double(mDpi->value()); }
std::string ExportSettingsDialog::aa() const { return mAa->currentText().toStdString(); }

void ExportSettingsDialog::accept() {
    if (const QString problem = exportSizeProblem(pixels()); !problem.isEmpty()) {
        reportError(this, tr("The image is too large"), problem);
        return;
    }
    QDialog::accept();
}

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
    connect(save, &QPushButton::clicked, this, [this] {
        if (const QString file = saveGenomeWithDialog(this, mGenome); !file.isEmpty()) emit fileSaved(file);
    });
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

QString DesignDialog::suggestedExportFile() const {
    const QSettings settings;
    return suggestedFile(mGenome, settings.value(QStringLiteral("files/exportDir")).toString(),
                         settings.value(QStringLiteral("files/exportExtension"), QStringLiteral(".png")).toString());
}

void DesignDialog::exportImage() {
    ExportSettingsDialog settingsDialog(mGenome, this);
    if (settingsDialog.exec() != QDialog::Accepted) return;
    QString file = askSaveFile(this, tr("Export image"), suggestedExportFile(),
                               tr("Images (*.png *.tif *.tiff *.exr *.jpg *.jpeg)"));
    if (file.isEmpty()) return;
    QSettings settings;
    // A name typed without a format gets the one offered.
    if (QFileInfo(file).suffix().isEmpty())
        file += settings.value(QStringLiteral("files/exportExtension"), QStringLiteral(".png")).toString();
    settings.setValue(QStringLiteral("files/exportDir"), QFileInfo(file).absolutePath());
    settings.setValue(QStringLiteral("files/exportExtension"), QStringLiteral(".") + QFileInfo(file).suffix().toLower());

    exportTo(file, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()), settingsDialog.dpi());
}

bool DesignDialog::saveTo(const QString& file) {
    if (!saveGenomeTo(this, mGenome, file)) return false;
    emit fileSaved(file);
    return true;
}

bool DesignDialog::exportTo(const QString& file, QSize pixels, const QString& aa, std::optional<double> dpi) {
    if (mExportCancel) return false;
    if (const QString problem = exportSizeProblem(pixels); !problem.isEmpty()) {
        reportError(this, tr("Cannot export the image"), problem);
        return false;
    }
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
    dialog->setObjectName(QStringLiteral("exportProgress"));
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setMinimumDuration(300);
    dialog->setAutoReset(false);
    dialog->setAutoClose(false);
    auto* poll = new QTimer(dialog);
    connect(poll, &QTimer::timeout, dialog, [dialog, progress] { dialog->setValue(int(progress->load() * 999)); });
    connect(dialog, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
    connect(thread, &QThread::finished, this, [this, thread, dialog, poll, cancel, error, file] {
        // The progress box goes before any message: a stale one must never cover an error,
        // and its poll must not show it again (setValue shows a box past its minimum duration).
        poll->stop();
        dialog->reset();
        dialog->hide();
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
        if (written) emit fileSaved(file);
    });
    poll->start(100);
    thread->start();
    return true;
}

void DesignDialog::cancelExport() {
    if (mExportCancel) mExportCancel->store(true);
}

QString saveGenomeWithDialog(QWidget* parent, const Genome& genome) {
    QSettings settings;
    const QString suggested =
        suggestedFile(genome, settings.value(QStringLiteral("files/saveDir")).toString(), QStringLiteral(".marble.json"));
    QString file = askSaveFile(parent, QObject::tr("Save design"), suggested, QObject::tr("Marbler genomes (*.marble.json)"));
    if (file.isEmpty()) return {};
    if (!file.endsWith(QStringLiteral(".json"))) file += QStringLiteral(".marble.json");
    settings.setValue(QStringLiteral("files/saveDir"), QFileInfo(file).absolutePath());
    return saveGenomeTo(parent, genome, file) ? file : QString();
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
