// Export animation (AnimationExport.h).

#include "editor/AnimationExport.h"

#include "marbler/Animation.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "shared/BackgroundJob.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <memory>

namespace marbler::ui {

QString animationExtension(AnimationFormat format) {
    switch (format) {
    case AnimationFormat::PngFrames:
        return {};
    case AnimationFormat::Gif:
        return QStringLiteral("gif");
    case AnimationFormat::WebP:
        return QStringLiteral("webp");
    case AnimationFormat::Mp4:
        return QStringLiteral("mp4");
    case AnimationFormat::WebM:
        return QStringLiteral("webm");
    }
    return {};
}

AnimationExportDialog::AnimationExportDialog(const Genome& design, const AnimationExportSettings& start,
                                             QWidget* parent)
    : QDialog(parent)
    , mFormat(new QComboBox(this))
    , mPath(new QLineEdit(this))
    , mWidth(new QSpinBox(this))
    , mHeight(new QSpinBox(this))
    , mFrames(new QSpinBox(this))
    , mFps(new QDoubleSpinBox(this))
    , mDuration(new QDoubleSpinBox(this))
    , mSlice(start.slice) {
    setObjectName(QStringLiteral("animationExportDialog"));
    setWindowTitle(tr("Export animation"));
    mFormat->setObjectName(QStringLiteral("animationFormat"));
    mFormat->addItem(tr("PNG frames (a folder)"), int(AnimationFormat::PngFrames));
    mFormat->addItem(tr("GIF"), int(AnimationFormat::Gif));
    mFormat->addItem(tr("WebP (animated)"), int(AnimationFormat::WebP));
    mFormat->addItem(tr("MP4 (H.264)"), int(AnimationFormat::Mp4));
    mFormat->addItem(tr("WebM (VP9)"), int(AnimationFormat::WebM));
    mFormat->setCurrentIndex(std::max(0, mFormat->findData(int(start.format))));
    mFormat->setToolTip(
        tr("What to write: a folder of PNG frames (each carries the design it shows), an animated "
           "image or a video"));
    mPath->setObjectName(QStringLiteral("animationPath"));
    mPath->setText(start.path);
    mPath->setToolTip(tr("The file to write, or for PNG frames a new or empty folder"));
    auto* browseButton = new QPushButton(tr("&Browse…"), this);
    browseButton->setToolTip(tr("Choose where to write the animation"));
    mWidth->setObjectName(QStringLiteral("animationWidth"));
    mHeight->setObjectName(QStringLiteral("animationHeight"));
    for (QSpinBox* side : {mWidth, mHeight}) {
        side->setRange(16, 8192);
        side->setSuffix(tr(" px"));
    }
    mWidth->setToolTip(tr("Width of each frame in pixels"));
    mHeight->setToolTip(tr("Height of each frame in pixels"));
    mWidth->setValue(start.width);
    const double aspect = design.size.y > 0 ? design.size.x / design.size.y : 1.0;
    mHeight->setValue(std::max(16, int(std::lround(start.width / aspect))));
    mFrames->setObjectName(QStringLiteral("animationFrames"));
    mFrames->setRange(2, 100000);
    mFrames->setValue(start.frames);
    mFrames->setToolTip(tr("Number of frames: the first shows the bare bath, the last the whole design"));
    mFps->setObjectName(QStringLiteral("animationFps"));
    mFps->setRange(0.1, 1000.0);
    mFps->setValue(start.fps);
    mFps->setToolTip(tr("Frames a second of a video or animated image"));
    mDuration->setObjectName(QStringLiteral("animationDuration"));
    mDuration->setRange(0.01, 100000.0);
    mDuration->setDecimals(2);
    mDuration->setSuffix(tr(" s"));
    mDuration->setToolTip(
        tr("How long the animation plays: the frames at the frame rate (changing it sets the "
           "number of frames)"));
    const auto showDuration = [this] {
        if (mSyncing) return;
        mSyncing = true;
        mDuration->setValue(mFrames->value() / mFps->value());
        mSyncing = false;
    };
    showDuration();
    connect(mFrames, &QSpinBox::valueChanged, this, showDuration);
    connect(mFps, &QDoubleSpinBox::valueChanged, this, showDuration);
    connect(mDuration, &QDoubleSpinBox::valueChanged, this, [this](double seconds) {
        if (mSyncing) return;
        mSyncing = true;
        mFrames->setValue(
            std::clamp(int(std::lround(seconds * mFps->value())), mFrames->minimum(), mFrames->maximum()));
        mSyncing = false;
    });

    auto* form = new QFormLayout(this);
    form->addRow(tr("&Format:"), mFormat);
    auto* pathRow = new QHBoxLayout;
    pathRow->addWidget(mPath, 1);
    pathRow->addWidget(browseButton);
    // A row that is a layout gets no buddy from the form: its label would show the & itself.
    auto* pathLabel = new QLabel(tr("&Save to:"), this);
    pathLabel->setBuddy(mPath);
    form->addRow(pathLabel, pathRow);
    auto* sizeRow = new QHBoxLayout;
    sizeRow->addWidget(mWidth);
    sizeRow->addWidget(mHeight);
    auto* sizeLabel = new QLabel(tr("Si&ze:"), this);
    sizeLabel->setBuddy(mWidth);
    form->addRow(sizeLabel, sizeRow);
    form->addRow(tr("F&rames:"), mFrames);
    form->addRow(tr("Frames a &second:"), mFps);
    form->addRow(tr("&Duration:"), mDuration);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browseButton, &QPushButton::clicked, this, &AnimationExportDialog::browse);
    connect(mFormat, &QComboBox::currentIndexChanged, this, &AnimationExportDialog::formatChosen);
}

void AnimationExportDialog::formatChosen() {
    // The path follows the format: its extension, or none for a folder of frames.
    const auto format = AnimationFormat(mFormat->currentData().toInt());
    QString path = mPath->text();
    if (path.isEmpty()) return;
    const QFileInfo info(path);
    QString base = info.path() + QStringLiteral("/") + info.completeBaseName();
    const QString ext = animationExtension(format);
    mPath->setText(ext.isEmpty() ? base : base + QStringLiteral(".") + ext);
}

void AnimationExportDialog::browse() {
    const auto format = AnimationFormat(mFormat->currentData().toInt());
    QString chosen;
    if (format == AnimationFormat::PngFrames)
        chosen = QFileDialog::getExistingDirectory(this, tr("Folder for the PNG frames"), mPath->text());
    else {
        const QString ext = animationExtension(format);
        chosen = withAnimationExtension(
            QFileDialog::getSaveFileName(this, tr("Export animation"), mPath->text(),
                                         tr("%1 files (*.%2)").arg(ext.toUpper(), ext)),
            format);
    }
    if (!chosen.isEmpty()) mPath->setText(chosen);
}

QString withAnimationExtension(const QString& path, AnimationFormat format) {
    const QString ext = animationExtension(format);
    if (ext.isEmpty() || path.isEmpty() || QFileInfo(path).suffix().toLower() == ext) return path;
    return path + QStringLiteral(".") + ext;
}

AnimationExportSettings AnimationExportDialog::settings() const {
    AnimationExportSettings s;
    s.format = AnimationFormat(mFormat->currentData().toInt());
    s.path = withAnimationExtension(mPath->text(), s.format);
    s.width = mWidth->value();
    s.height = mHeight->value();
    s.frames = mFrames->value();
    s.fps = mFps->value();
    s.slice = mSlice;
    return s;
}

void writeAnimationExport(const Genome& design, const AnimationExportSettings& settings,
                          const RenderControl& control) {
    RenderSettings render;
    render.width = settings.width;
    render.height = settings.height;
    render.slice = settings.slice;
    const std::filesystem::path out = withAnimationExtension(settings.path, settings.format).toStdString();
    const bool frames = settings.format == AnimationFormat::PngFrames;
    std::error_code ec;
    if (std::filesystem::exists(out, ec)) {
        const bool dir = std::filesystem::is_directory(out, ec);
        if (frames ? !dir || !std::filesystem::is_empty(out, ec) : dir)
            throw InputError(out.string() + ": already exists; choose a new or empty folder for PNG frames");
    }
    const int count = settings.frames;
    writeAnimation(design, render, out, count, settings.fps, control.cancel,
                   [&control, count](int frame, double within) {
                       if (control.progress) control.progress((frame + within) / count);
                   });
}

AnimationExportJob::AnimationExportJob(QObject* parent)
    : QObject(parent) {}

AnimationExportJob::~AnimationExportJob() {
    // Before the QObject goes: the thread may still tell this object its progress.
    delete mJob;
}

bool AnimationExportJob::start(const Genome& design, const AnimationExportSettings& settings) {
    if (mJob) return false;
    // Progress is told in thousandths, each once, as the frames' threads reach it.
    auto last = std::make_shared<std::atomic<int>>(-1);
    mJob = BackgroundJob::start(
        this,
        JobBox(qobject_cast<QWidget*>(parent()), tr("Writing the making of the design…"),
               QStringLiteral("animationProgress")),
        [this, design, settings, last](const RenderControl& control) {
            RenderControl told = control;
            told.progress = [this, &control, last](double fraction) {
                if (control.progress) control.progress(fraction);
                const int permille = int(fraction * 1000.0);
                if (last->exchange(permille) == permille) return;
                QMetaObject::invokeMethod(
                    this, [this, permille] { emit progress(permille / 1000.0); }, Qt::QueuedConnection);
            };
            writeAnimationExport(design, settings, told);
        },
        [this](const JobOutcome& outcome) {
            mJob = nullptr;
            emit finished(outcome.done(), outcome.error);
        });
    return true;
}

void AnimationExportJob::cancel() {
    if (mJob) mJob->cancel();
}

} // namespace marbler::ui

// The moc output here, not in marbler_ui's mocs_compilation: a test of the panels links only them.
#include "moc_AnimationExport.cpp"
