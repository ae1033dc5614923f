#include "ui/DesignDialog.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Repeat.h"
#include "marbler/Sampling.h"
#include "marbler/Vector.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/RenderView.h"
#include "ui/BackgroundJob.h"
#include "ui/BakeObject.h"
#include "ui/ErrorReport.h"
#include "ui/GenomeClipboard.h"
#include "ui/PopulationModel.h"
#include "ui/RenderService.h"
#include "ui/SavedFiles.h"
#include "ui/SourcePermissions.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QThread>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace marbler::ui {

namespace {

/// Grows `dialog` so that the word-wrapped `label` shows all its lines. A top-level window is
/// laid out for the text its wrapped labels had when shown; a longer text (Export image's line
/// with Mirror repeat ticked) would otherwise be clipped to the old height.
void growToShowWrapped(QWidget* dialog, QLabel* label) {
    if (!dialog->isVisible() || !dialog->layout()) return;
    // As a minimum the layout must keep, the dialog grows to it at once.
    label->setMinimumHeight(label->heightForWidth(label->width()));
    dialog->layout()->activate();
}

/// The mirror repeat of an image as mirrorRepeat (marbler/Repeat.h) lays it out: the image at
/// the top left, its horizontal mirror at the top right, the vertical mirrors of both below.
QImage mirrorTiled(const QImage& image) {
    const QImage source = image.convertToFormat(QImage::Format_RGB32);
    QImage tiled(source.width() * 2, source.height() * 2, QImage::Format_RGB32);
    QPainter p(&tiled);
    p.drawImage(0, 0, source);
    p.drawImage(source.width(), 0, source.mirrored(true, false));
    p.drawImage(0, source.height(), source.mirrored(false, true));
    p.drawImage(source.width(), source.height(), source.mirrored(true, true));
    return tiled;
}

} // namespace

QString exportSizeProblem(QSize pixels) {
    const std::int64_t w = pixels.width(), h = pixels.height();
    if (w < 1 || h < 1)
        return QObject::tr("The image would be %1 × %2 pixels: choose a size of at least 1 pixel.")
            .arg(w)
            .arg(h);
    if (w > MaxImageSide || h > MaxImageSide || w * h > MaxImagePixels)
        return QObject::tr(
                   "The image would be %L1 × %L2 pixels (%L3 megapixels); Marbler renders at most %L4 pixels "
                   "a side and %L5 megapixels. Choose a smaller size or a lower resolution.")
            .arg(w)
            .arg(h)
            .arg(double(w) * double(h) / 1e6, 0, 'f', 0)
            .arg(MaxImageSide)
            .arg(double(MaxImagePixels) / 1e6, 0, 'f', 0);
    return {};
}

ExportSettingsDialog::ExportSettingsDialog(const Genome& genome, QWidget* parent)
    : QDialog(parent)
    , mGenome(genome) {
    setWindowTitle(tr("Export image"));
    auto* form = new QFormLayout;
    // The CLI's writers: PNG and TIFF built in, JPEG and EXR through the image module.
    mFormat = new QComboBox(this);
    mFormat->setObjectName(QStringLiteral("exportFormat"));
    mFormat->addItem(tr("PNG (8-bit sRGB)"), QStringLiteral(".png"));
    mFormat->addItem(tr("JPEG (8-bit sRGB)"), QStringLiteral(".jpg"));
    mFormat->addItem(tr("TIFF (8-bit sRGB)"), QStringLiteral(".tif"));
    mFormat->addItem(tr("TIFF (16-bit sRGB, for print)"), QStringLiteral(".tif/16"));
    mFormat->addItem(tr("OpenEXR (linear half float)"), QStringLiteral(".exr"));
    // Outlines exist for flat designs only (marbler/Vector.h); a source image is refused when
    // tracing, with the library's reason.
    if (genome.dimension != 3) mFormat->addItem(tr("SVG (vector)"), QStringLiteral(".svg"));
    mFormat->setToolTip(tr("The file format; a 16-bit TIFF keeps the smooth gradients of an antialiased "
                           "render for further grading, EXR keeps linear light"));
    {
        const QSettings settings;
        setFormat(settings.value(QStringLiteral("files/exportExtension"), QStringLiteral(".png")).toString(),
                  settings.value(QStringLiteral("files/exportBits"), 8).toInt());
    }
    form->addRow(tr("&Format"), mFormat);
    mWidth = new QDoubleSpinBox(this);
    mWidth->setObjectName(QStringLiteral("exportWidth"));
    // Wide enough for any unit at any dpi; the size check says what is too large.
    mWidth->setDecimals(0);
    mWidth->setRange(1, 1e7);
    mWidth->setValue(mPixelWidth);
    mWidth->setToolTip(
        tr("The image's width in the unit beside; the height follows the design's proportions"));
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
    for (const std::string& name : aaPatternNames())
        mAa->addItem(QString::fromStdString(name));
    mAa->setCurrentText(QStringLiteral("rgss"));
    mAa->setToolTip(tr("Antialiasing pattern: more samples, smoother edges, slower"));
    mPixels = new QLabel(this);
    mPixels->setObjectName(QStringLiteral("exportPixels"));
    mPixels->setWordWrap(true);
    form->addRow(tr("&Width"), mWidth);
    form->addRow(tr("&Unit"), mUnit);
    form->addRow(tr("&Resolution (dpi)"), mDpi);
    form->addRow(tr("&Antialiasing"), mAa);
    if (genome.dimension != 3) {
        mRepeat = new QCheckBox(tr("Mirror repeat tile (2 × 2): twice the width and height"), this);
        mRepeat->setObjectName(QStringLiteral("exportRepeat"));
        mRepeat->setToolTip(
            tr("A seamless tile for print and textiles: the design and its mirror images 2 × 2, so "
               "every edge meets its own mirror image (marbler render --repeat mirror)"));
        form->addRow(tr("&Repeat"), mRepeat);
        mTolerance = new QDoubleSpinBox(this);
        mTolerance->setObjectName(QStringLiteral("exportTolerance"));
        mTolerance->setDecimals(3);
        mTolerance->setRange(0.001, 1000.0);
        mTolerance->setValue(1.0);
        mTolerance->setToolTip(
            tr("SVG: the largest distance between neighbouring vertices of an outline, in design "
               "units; larger gives smaller files (marbler svg --tolerance)"));
        form->addRow(tr("&Tolerance"), mTolerance);
        connect(mRepeat, &QCheckBox::toggled, this, [this] { updateSummary(); });
    }
    form->addRow(tr("Image"), mPixels);
    if (genome.dimension == 3) {
        mSolidView = new QComboBox(this);
        mSolidView->setObjectName(QStringLiteral("exportSolidView"));
        mSolidView->addItem(tr("Object view (as shown)"));
        mSolidView->addItem(tr("Cross-section"));
        mSolidView->setToolTip(
            tr("The design on its object, as the view shows it, or a flat cut through the block"));
        mAxis = new QComboBox(this);
        mAxis->setObjectName(QStringLiteral("exportAxis"));
        mAxis->addItem(tr("x (a y-z plane)"));
        mAxis->addItem(tr("y (an x-z plane)"));
        mAxis->addItem(tr("z (an x-y plane)"));
        mAxis->setCurrentIndex(2);
        mAxis->setToolTip(tr("The axis the cross-section is taken across"));
        mPosition = new QDoubleSpinBox(this);
        mPosition->setObjectName(QStringLiteral("exportPosition"));
        mPosition->setDecimals(2);
        mPosition->setToolTip(tr("Where on its axis the cross-section lies, in design units"));
        auto showAxis = [this] {
            const int axis = mAxis->currentIndex();
            const double side = mGenome.size[axis];
            // The middle of the new axis: its old position may not lie inside it.
            mPosition->setRange(0.0, side);
            mPosition->setValue(side / 2.0);
        };
        showAxis();
        auto enable = [this] {
            const bool slice = mSolidView->currentIndex() == 1;
            mAxis->setEnabled(slice);
            mPosition->setEnabled(slice);
            updateSummary();
        };
        connect(mAxis, &QComboBox::currentIndexChanged, this, [this, showAxis] {
            showAxis();
            updateSummary();
        });
        connect(mSolidView, &QComboBox::currentIndexChanged, this, enable);
        form->addRow(tr("&Show"), mSolidView);
        form->addRow(tr("A&xis"), mAxis);
        form->addRow(tr("&Position"), mPosition);
        mAxis->setEnabled(false);
        mPosition->setEnabled(false);
    }
    mButtons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(mButtons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(mButtons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(mButtons);
    // Every field in reading order, then the buttons.
    setTabOrder(mFormat, mWidth);
    setTabOrder(mWidth, mUnit);
    setTabOrder(mUnit, mDpi);
    setTabOrder(mDpi, mAa);
    QWidget* last = mAa;
    if (mRepeat) {
        setTabOrder(mAa, mRepeat);
        setTabOrder(mRepeat, mTolerance);
        last = mTolerance;
    }
    if (mSolidView) {
        setTabOrder(mAa, mSolidView);
        setTabOrder(mSolidView, mAxis);
        setTabOrder(mAxis, mPosition);
        last = mPosition;
    }
    setTabOrder(last, mButtons->button(QDialogButtonBox::Ok));
    setTabOrder(mButtons->button(QDialogButtonBox::Ok), mButtons->button(QDialogButtonBox::Cancel));

    connect(mUnit, &QComboBox::currentIndexChanged, this, [this] { showWidth(); });
    connect(mFormat, &QComboBox::currentIndexChanged, this, [this] { updateSummary(); });
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

double ExportSettingsDialog::perInch() const {
    return mUnit->currentData().toDouble();
}

void ExportSettingsDialog::showWidth() {
    mShowing = true;
    mWidth->setDecimals(perInch() > 0.0 ? 3 : 0);
    mWidth->setMinimum(perInch() > 0.0 ? 0.001 : 1.0);
    mWidth->setValue(perInch() > 0.0 ? mPixelWidth / mDpi->value() * perInch() : mPixelWidth);
    mShowing = false;
    updateSummary();
}

bool ExportSettingsDialog::isSvg() const {
    return extension() == QStringLiteral(".svg");
}

void ExportSettingsDialog::updateSummary() {
    // An SVG has no pixels: the raster's fields are greyed out, the tolerance is its size.
    const bool svg = isSvg();
    for (QWidget* w : {static_cast<QWidget*>(mWidth), static_cast<QWidget*>(mUnit),
                       static_cast<QWidget*>(mDpi), static_cast<QWidget*>(mAa)})
        w->setEnabled(!svg);
    if (mRepeat) {
        mRepeat->setEnabled(!svg);
        mTolerance->setEnabled(svg);
    }
    if (svg) {
        mPixels->setText(
            tr("Vector outlines in design units (%L1 × %L2)").arg(mGenome.size.x).arg(mGenome.size.y));
        mPixels->setStyleSheet(QString());
        mButtons->button(QDialogButtonBox::Ok)->setEnabled(true);
        growToShowWrapped(this, mPixels);
        return;
    }
    const bool tile = mirrorRepeatTile();
    const QSize s = tile ? pixels() * 2 : pixels();
    const QString problem = exportSizeProblem(s);
    QString text = tr("%L1 × %L2 pixels").arg(s.width()).arg(s.height());
    if (tile) text += tr(", the tile of a %L1 × %L2 render").arg(pixels().width()).arg(pixels().height());
    if (perInch() <= 0.0)
        text += tr(" (%1 × %2 in at %3 dpi)")
                    .arg(s.width() / double(mDpi->value()), 0, 'f', 2)
                    .arg(s.height() / double(mDpi->value()), 0, 'f', 2)
                    .arg(mDpi->value());
    mPixels->setText(problem.isEmpty() ? text : problem);
    mPixels->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #c03030"));
    mButtons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
    growToShowWrapped(this, mPixels);
}

void ExportSettingsDialog::setUnit(const QString& unit) {
    const int index = mUnit->findText(unit);
    if (index >= 0) mUnit->setCurrentIndex(index);
}

QString ExportSettingsDialog::unit() const {
    return mUnit->currentText();
}
double ExportSettingsDialog::widthValue() const {
    return mWidth->value();
}
void ExportSettingsDialog::setWidthValue(double value) {
    mWidth->setValue(value);
}
void ExportSettingsDialog::setDpi(int dpi) {
    mDpi->setValue(dpi);
}

double ExportSettingsDialog::aspect() const {
    const glm::dvec3& size = mGenome.size;
    if (mGenome.dimension != 3) return size.y / size.x;
    if (mSolidView->currentIndex() == 0) return 1.0;
    const glm::dvec2 plane = slicePlane(mGenome.dimension, mAxis->currentIndex()).extent(size);
    return plane.y / plane.x;
}

QString ExportSettingsDialog::extension() const {
    return mFormat->currentData().toString().section('/', 0, 0);
}

int ExportSettingsDialog::bitsPerSample() const {
    return mFormat->currentData().toString().endsWith("/16") ? 16 : 8;
}

void ExportSettingsDialog::setFormat(const QString& extension, int bitsPerSample) {
    QString wanted = extension.toLower();
    if (wanted == ".tiff") wanted = ".tif";
    if (wanted == ".jpeg") wanted = ".jpg";
    if (wanted == ".tif" && bitsPerSample == 16) wanted += "/16";
    const int index = mFormat->findData(wanted);
    mFormat->setCurrentIndex(index >= 0 ? index : 0);
}

double ExportSettingsDialog::tolerance() const {
    return mTolerance ? mTolerance->value() : 1.0;
}
bool ExportSettingsDialog::mirrorRepeatTile() const {
    return mRepeat && mRepeat->isChecked() && !isSvg();
}
void ExportSettingsDialog::setMirrorRepeatTile(bool on) {
    if (mRepeat) mRepeat->setChecked(on);
}

std::optional<SolidExport> ExportSettingsDialog::solidExport() const {
    if (mGenome.dimension != 3) return std::nullopt;
    SolidExport solid;
    solid.objectView = mSolidView->currentIndex() == 0;
    solid.slice = Slice{mAxis->currentIndex(), mPosition->value()};
    return solid;
}

void ExportSettingsDialog::setSolidExport(const SolidExport& solid) {
    if (mGenome.dimension != 3) return;
    mSolidView->setCurrentIndex(solid.objectView ? 0 : 1);
    mAxis->setCurrentIndex(std::clamp(solid.slice.axis, 0, 2));
    mPosition->setValue(solid.slice.value);
}

QSize ExportSettingsDialog::pixels() const {
    const double w = std::round(mPixelWidth);
    const double h = std::round(w * aspect());
    // Clamped only so the numbers fit an int; the size check refuses what is too large.
    const auto fit = [](double v) { return int(std::clamp(v, 0.0, 2e9)); };
    return {std::max(1, fit(w)), std::max(1, fit(h))};
}

std::optional<double> ExportSettingsDialog::dpi() const {
    return double(mDpi->value());
}
std::string ExportSettingsDialog::aa() const {
    return mAa->currentText().toStdString();
}

void ExportSettingsDialog::accept() {
    if (const QString problem =
            isSvg() ? QString() : exportSizeProblem(mirrorRepeatTile() ? pixels() * 2 : pixels());
        !problem.isEmpty()) {
        reportError(this, tr("The image is too large"), problem);
        return;
    }
    QDialog::accept();
}

/// The canvas of the large view: draws the image where the dialog says and hands the wheel,
/// drags and size changes to it.
class DesignCanvas : public QWidget {
public:
    explicit DesignCanvas(DesignDialog* dialog)
        : QWidget(dialog)
        , mDialog(dialog) {
        setObjectName(QStringLiteral("designView"));
        setMinimumSize(320, 320);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        p.fillRect(rect(), palette().color(QPalette::Window).darker(115));
        if (!mDialog->mImage.isNull()) {
            p.setRenderHint(QPainter::SmoothPixmapTransform);
            p.drawImage(mDialog->imageTarget(), mDialog->mImage);
        }
        if (!mDialog->mMessage.isEmpty()) {
            p.setPen(palette().color(QPalette::WindowText));
            p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, mDialog->mMessage);
        }
    }
    void resizeEvent(QResizeEvent*) override { mDialog->canvasResized(); }
    void wheelEvent(QWheelEvent* event) override {
        // Ctrl+wheel zooms too (as in most viewers); a notch (120) is the keys' step, √2.
        const double notches = event->angleDelta().y() / 120.0;
        if (notches != 0.0) mDialog->zoomAt(std::pow(std::sqrt(2.0), notches), event->position());
        event->accept();
    }
    void mousePressEvent(QMouseEvent* event) override { mDialog->canvasPressed(event); }
    void mouseMoveEvent(QMouseEvent* event) override { mDialog->canvasMoved(event); }
    void mouseReleaseEvent(QMouseEvent* event) override { mDialog->canvasReleased(event); }

private:
    DesignDialog* mDialog;
};

DesignDialog::DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent)
    : QDialog(parent)
    , mGenome(std::move(genome))
    , mRenderer(renderer)
    , mMesh(mesh)
    , mKey(renderer->newKey())
    , mAngle(viewAngleOf(mGenome)) {
    const LineageInfo info = lineageOf(mGenome);
    setWindowTitle(tr("Design %1").arg(info.name.isEmpty() ? info.id : info.name));
    const bool solid = mGenome.dimension == 3;
    mViewController.setDesignSize(mGenome.size.x, mGenome.size.y);
    mMessage = tr("rendering…");
    mCanvas = new DesignCanvas(this);
    mCanvas->setToolTip(solid ? tr("Drag to turn the object; wheel, + and - zoom")
                              : tr("Wheel, + and - zoom about the pointer; drag to pan"));

    // The zoom controls: buttons that never take the focus, so the keys keep working.
    auto tool = [this](const QString& name, const QString& text, const QString& tip) {
        auto* button = new QToolButton(this);
        button->setObjectName(name);
        button->setText(text);
        button->setToolTip(tip);
        button->setFocusPolicy(Qt::NoFocus);
        return button;
    };
    auto* zoomOutButton = tool(QStringLiteral("zoomOut"), QStringLiteral("−"), tr("Zoom out (-, wheel)"));
    auto* zoomInButton = tool(QStringLiteral("zoomIn"), QStringLiteral("+"), tr("Zoom in (+, wheel)"));
    auto* fitButton = tool(QStringLiteral("zoomFit"), tr("Fit"),
                           solid ? tr("Frame the whole object (0)") : tr("Show the whole design (0)"));
    auto* oneButton = tool(QStringLiteral("zoomOneToOne"), tr("1:1"),
                           tr("One design unit to a screen pixel, the scale of an export as many pixels "
                              "wide as the design is wide (1)"));
    oneButton->setEnabled(!solid);
    mZoomLabel = new QLabel(this);
    mZoomLabel->setObjectName(QStringLiteral("zoomLevel"));
    mZoomLabel->setToolTip(solid ? tr("Magnification of the framed object")
                                 : tr("Screen pixels per design unit (100 %: one to one)"));
    connect(zoomOutButton, &QToolButton::clicked, this, &DesignDialog::zoomOut);
    connect(zoomInButton, &QToolButton::clicked, this, &DesignDialog::zoomIn);
    connect(fitButton, &QToolButton::clicked, this, &DesignDialog::fitView);
    connect(oneButton, &QToolButton::clicked, this, &DesignDialog::showOneToOne);
    auto* zoomBar = new QHBoxLayout;
    zoomBar->addWidget(zoomOutButton);
    zoomBar->addWidget(zoomInButton);
    zoomBar->addWidget(fitButton);
    zoomBar->addWidget(oneButton);
    zoomBar->addWidget(mZoomLabel);
    zoomBar->addStretch();
    mSwatchButton =
        tool(QStringLiteral("repeatSwatch"), tr("Repeat swatch"),
             solid ? tr("Flat designs only: a solid has no repeat tile")
                   : tr("Show the whole design tiled as its mirror repeat, 2 × 2, to judge the repeat "
                        "(R)"));
    mSwatchButton->setCheckable(true);
    mSwatchButton->setEnabled(!solid);
    connect(mSwatchButton, &QToolButton::toggled, this, &DesignDialog::setRepeatSwatch);
    zoomBar->addWidget(mSwatchButton);

    auto* save = new QPushButton(tr("&Save genome…"), this);
    save->setToolTip(tr("Save the design as a genome file (Ctrl+S)"));
    auto* exportButton = new QPushButton(tr("&Export image…"), this);
    exportButton->setToolTip(
        tr("Render the design to PNG, TIFF, EXR or JPEG at any size, or a flat one to SVG (Ctrl+E)"));
    auto* copy = new QPushButton(tr("&Copy genome"), this);
    copy->setObjectName(QStringLiteral("copyGenome"));
    copy->setToolTip(tr("Put the design's genome on the clipboard as text, to paste into the workbench or "
                        "anywhere else (%1)")
                         .arg(QKeySequence(QKeySequence::Copy).toString(QKeySequence::NativeText)));
    auto* editor = new QPushButton(tr("Open in e&ditor"), this);
    editor->setObjectName(QStringLiteral("openInEditor"));
    editor->setToolTip(tr("Edit this design step by step in the editor (Ctrl+Shift+D)"));
    connect(editor, &QPushButton::clicked, this, [this] { emit openInEditorRequested(mGenome); });
    auto* close = new QPushButton(tr("Close"), this);
    connect(save, &QPushButton::clicked, this, [this] {
        if (const QString file = saveGenomeWithDialog(this, mGenome); !file.isEmpty()) emit fileSaved(file);
    });
    connect(exportButton, &QPushButton::clicked, this, &DesignDialog::exportImage);
    connect(copy, &QPushButton::clicked, this, &DesignDialog::copyGenome);
    // The keys are actions of the dialog, whichever of its widgets has the focus: a button's
    // own shortcut did not fire from the keyboard here (the canvas takes the focus).
    const auto addKey = [this](const QString& name, const QKeySequence& keys, QAbstractButton* button) {
        auto* action = new QAction(button->text().remove(QLatin1Char('&')), this);
        action->setObjectName(name);
        action->setShortcut(keys);
        // A disabled button ignores click(): the key does nothing where the button cannot.
        connect(action, &QAction::triggered, button, &QAbstractButton::click);
        addAction(action);
    };
    addKey(QStringLiteral("saveGenomeAction"), QKeySequence::Save, save);
    addKey(QStringLiteral("exportImageAction"), QKeySequence(Qt::CTRL | Qt::Key_E), exportButton);
    addKey(QStringLiteral("copyGenomeAction"), QKeySequence::Copy, copy);
    addKey(QStringLiteral("repeatSwatchAction"), QKeySequence(Qt::Key_R), mSwatchButton);
    addKey(QStringLiteral("openInEditorAction"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_D), editor);
    connect(close, &QPushButton::clicked, this, &QDialog::close);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(save);
    buttons->addWidget(exportButton);
    buttons->addWidget(copy);
    buttons->addWidget(editor);
    if (solid)
        buttons->addWidget(makeBakeButton(
            this, [this] { return mGenome; }, mMesh, [this](const QString& file) { emit fileSaved(file); }));
    buttons->addStretch();
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(zoomBar);
    layout->addWidget(mCanvas, 1);
    layout->addLayout(buttons);
    resize(720, 800);
    mZoomLabel->setText(zoomText());
    if (!solid && QSettings().value(QStringLiteral("view/repeatSwatch"), false).toBool()) {
        // Before the first render request (the canvas's first resize): no wasted render.
        mSwatch = true;
        const QSignalBlocker block(mSwatchButton);
        mSwatchButton->setChecked(true);
    }

    connect(mRenderer, &RenderService::rendered, this,
            [this](std::uint64_t key, const QImage& image, bool final) {
                if (key != mKey) return;
                // The service delivers only the newest request's results: they show its view.
                mImageSwatch = mRequestSwatch;
                // Tiled once here, not at each paint (the tile is fitted to half the canvas).
                mImage = mImageSwatch ? mirrorTiled(image) : image;
                mImageFinal = final;
                if (mRequestRegion) mImageRegion = *mRequestRegion;
                mImageZoom = mRequestZoom;
                mMessage.clear();
                mCanvas->update();
            });
    connect(mRenderer, &RenderService::failed, this, [this](std::uint64_t key, const QString& message) {
        if (key != mKey) return;
        mImage = QImage();
        mMessage = tr("Cannot render: %1").arg(message);
        mCanvas->update();
    });
}

DesignDialog::~DesignDialog() {
    mRenderer->cancel(mKey);
    // Closing the view stops its export and waits for it; renderToFile leaves no partial file.
    delete mExport;
}

QWidget* DesignDialog::canvas() const {
    return mCanvas;
}

QString DesignDialog::zoomText() const {
    const double percent = 100.0 * (mGenome.dimension == 3 ? mObjectZoom : mViewController.scale());
    return tr("%L1 %").arg(percent, 0, 'f', percent < 10.0 ? 1 : 0);
}

void DesignDialog::canvasResized() {
    mViewController.setViewport(mCanvas->size() * mCanvas->devicePixelRatioF());
    viewChanged();
}

void DesignDialog::zoomIn() {
    zoomAt(std::sqrt(2.0), QRectF(mCanvas->rect()).center());
}
void DesignDialog::zoomOut() {
    zoomAt(1.0 / std::sqrt(2.0), QRectF(mCanvas->rect()).center());
}

void DesignDialog::zoomAt(double factor, QPointF anchor) {
    if (mGenome.dimension == 3)
        // A solid zooms about its framed centre: its camera always looks there.
        mObjectZoom = std::clamp(mObjectZoom * factor, 0.25, 16.0);
    else
        mViewController.zoomBy(factor, anchor * mCanvas->devicePixelRatioF());
    viewChanged();
}

void DesignDialog::fitView() {
    mObjectZoom = 1.0;
    mViewController.fit();
    viewChanged();
}

void DesignDialog::showOneToOne() {
    if (mGenome.dimension == 3) return;
    mViewController.oneToOne();
    viewChanged();
}

void DesignDialog::panBy(QPointF delta) {
    if (mGenome.dimension == 3) return;
    mViewController.panBy(delta * mCanvas->devicePixelRatioF());
    viewChanged();
}

void DesignDialog::viewChanged(bool previewOnly) {
    mZoomLabel->setText(zoomText());
    mCanvas->update(); // the image shown so far, moved and scaled to the new view at once
    requestRender(previewOnly);
}

QRectF DesignDialog::imageTarget() const {
    const double ratio = mCanvas->devicePixelRatioF();
    if (mImageSwatch) {
        // Rendered at its size on the canvas: centred, never scaled.
        QRectF target(QPointF(0, 0), QSizeF(mImage.size()) / ratio);
        target.moveCenter(QRectF(mCanvas->rect()).center());
        return target;
    }
    if (mGenome.dimension != 3) {
        const QRectF r = mViewController.toViewport(mImageRegion);
        return QRectF(r.topLeft() / ratio, r.size() / ratio);
    }
    // A solid's image fills the canvas (a cross-section keeps its proportions), magnified by
    // the zoom asked for since.
    const QRectF area(mCanvas->rect());
    const QSizeF size =
        QSizeF(mImage.size()).scaled(area.size(), Qt::KeepAspectRatio) * (mObjectZoom / mImageZoom);
    QRectF target(QPointF(0, 0), size);
    target.moveCenter(area.center());
    return target;
}

void DesignDialog::requestRender(bool previewOnly) {
    RenderRequest request;
    request.genome = mGenome;
    request.mesh = mMesh;
    request.yaw = mAngle.yaw;
    request.pitch = mAngle.pitch;
    request.zoom = mObjectZoom;
    request.previewOnly = previewOnly;
    const QSize viewport = (mCanvas->size() * mCanvas->devicePixelRatioF()).expandedTo(QSize(32, 32));
    mRequestSwatch = mSwatch && mGenome.dimension != 3;
    if (mGenome.dimension == 3) {
        request.size = viewport;
    } else if (mRequestSwatch) {
        // The whole design, whatever the zoom (the swatch judges the repeat, not a detail),
        // fitted into half the canvas: tiled 2 x 2 it fills the canvas. The service fits the
        // design's proportions into this size.
        request.size = (viewport / 2).expandedTo(QSize(16, 16));
        request.region.reset();
    } else {
        // Only the part of the design in view, at the view's scale: exact at any zoom.
        const auto window = mViewController.visibleWindow();
        if (!window) {
            mRenderer->cancel(mKey);
            mImage = QImage();
            mCanvas->update();
            return;
        }
        request.region = window->region;
        request.size = window->pixels.size();
    }
    mRequestRegion = request.region;
    mRequestZoom = mObjectZoom;
    mImageFinal = false; // what is shown now stands in for the view until its render comes
    mRenderer->request(mKey, std::move(request));
}

void DesignDialog::setRepeatSwatch(bool on) {
    if (mGenome.dimension == 3) on = false;
    if (mSwatchButton->isChecked() != on) {
        const QSignalBlocker block(mSwatchButton);
        mSwatchButton->setChecked(on);
    }
    QSettings().setValue(QStringLiteral("view/repeatSwatch"), on);
    if (on == mSwatch) return;
    mSwatch = on;
    viewChanged();
}

void DesignDialog::keyPressEvent(QKeyEvent* event) {
    if (ViewController::handleKey(event, {[this] { zoomIn(); }, [this] { zoomOut(); }, [this] { fitView(); },
                                          [this] { showOneToOne(); }}))
        return;
    QDialog::keyPressEvent(event);
}

void DesignDialog::canvasPressed(QMouseEvent* event) {
    mLastPos = event->position();
    mDragging = event->button() == Qt::LeftButton;
    if (mDragging && mGenome.dimension != 3) mCanvas->setCursor(Qt::ClosedHandCursor);
}

void DesignDialog::canvasMoved(QMouseEvent* event) {
    if (!mDragging) return;
    const QPointF d = event->position() - mLastPos;
    mLastPos = event->position();
    // While dragging only the quick pass is worth rendering; the release asks for the final one.
    if (mGenome.dimension != 3)
        mViewController.panBy(d * mCanvas->devicePixelRatioF());
    else
        mAngle = mAngle.dragged(d.x(), d.y());
    viewChanged(true);
}

void DesignDialog::canvasReleased(QMouseEvent*) {
    if (!mDragging) return;
    mDragging = false;
    mCanvas->unsetCursor();
    requestRender();
    if (mGenome.dimension != 3) return;
    // The angle belongs to the design: saved with it, and given back to its cell.
    setViewAngle(mGenome, mAngle);
    emit viewAngleChanged(mAngle);
}

QString DesignDialog::suggestedExportFile() const {
    const QSettings settings;
    return suggestedFile(
        mGenome, settings.value(QStringLiteral("files/exportDir")).toString(),
        settings.value(QStringLiteral("files/exportExtension"), QStringLiteral(".png")).toString());
}

void DesignDialog::exportImage() {
    ExportSettingsDialog settingsDialog(mGenome, this);
    if (settingsDialog.exec() != QDialog::Accepted) return;
    QSettings settings;
    const QString extension = settingsDialog.extension();
    settings.setValue(QStringLiteral("files/exportExtension"), extension);
    settings.setValue(QStringLiteral("files/exportBits"), settingsDialog.bitsPerSample());
    const bool svg = extension == QStringLiteral(".svg");
    QString file = askSaveFile(
        this, tr("Export image"), suggestedExportFile(),
        svg ? tr("SVG drawings (*.svg)")
            : tr("Images (*%1);;All images (*.png *.tif *.tiff *.exr *.jpg *.jpeg)").arg(extension));
    if (file.isEmpty()) return;
    // A name typed without a format gets the one chosen.
    if (QFileInfo(file).suffix().isEmpty()) file += extension;
    settings.setValue(QStringLiteral("files/exportDir"), QFileInfo(file).absolutePath());
    settings.setValue(QStringLiteral("files/exportExtension"),
                      QStringLiteral(".") + QFileInfo(file).suffix().toLower());

    if (QFileInfo(file).suffix().toLower() == QStringLiteral("svg")) {
        exportSvgTo(file, settingsDialog.tolerance());
        return;
    }
    exportTo(file, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()), settingsDialog.dpi(),
             settingsDialog.solidExport(), settingsDialog.bitsPerSample(), settingsDialog.mirrorRepeatTile());
}

void DesignDialog::copyGenome() {
    copyGenomeToClipboard(mGenome);
    const LineageInfo info = lineageOf(mGenome);
    emit genomeCopied(info.name.isEmpty() ? tr("the design") : info.name);
}

bool DesignDialog::saveTo(const QString& file) {
    if (!saveGenomeTo(this, mGenome, file)) return false;
    emit fileSaved(file);
    return true;
}

bool DesignDialog::exportTo(const QString& file, QSize pixels, const QString& aa, std::optional<double> dpi,
                            std::optional<SolidExport> solid, int bitsPerSample, bool mirrorRepeatTile) {
    if (mExport) return false;
    const bool tile = mirrorRepeatTile && mGenome.dimension != 3;
    if (const QString problem = exportSizeProblem(tile ? pixels * 2 : pixels); !problem.isEmpty()) {
        reportError(this, tr("Cannot export the image"), problem);
        return false;
    }
    RenderSettings render;
    render.width = std::max(1, pixels.width());
    render.height = std::max(1, pixels.height());
    render.aa = aa.toStdString();
    if (mGenome.dimension == 3) render.slice = solid ? solid->slice : Slice{2, mGenome.size.z / 2.0};
    ExportOptions options;
    options.dpi = dpi;
    options.bitsPerSample = bitsPerSample;
    // The object as the view shows it: the same mesh, angle and zoom, framed at the export's size,
    // on the window's back end (the GPU shades, or GL only rasterises and the CPU kernel colours).
    // A tile is made from one whole render on the CPU, as marbler render --repeat mirror does.
    gl::ViewRequest view;
    view.raster = render;
    if (mGenome.dimension == 3 && solid && solid->objectView && !tile) {
        gl::MeshSettings mesh;
        mesh.width = render.width;
        mesh.height = render.height;
        mesh.mesh = mMesh.toStdString();
        mesh.yaw = mAngle.yaw;
        mesh.pitch = mAngle.pitch;
        mesh.zoom = mObjectZoom;
        view.object = mesh;
        view.useGl = mRenderer->usesGl();
    }
    // A source outside the design's folder is read only when the user allowed it for the view.
    Genome genome = mGenome;
    SourcePermissions::session().apply(genome);

    return startExport(file, [genome, view, file, options, tile](const RenderControl& control) {
        if (tile || view.object) {
            // The tile is made in memory from the whole render. An object needs a GL context of
            // this thread's own: a GL renderer stays on the thread that made it.
            std::optional<gl::GlRenderer> renderer;
            if (view.object) renderer.emplace();
            Image image = gl::renderView(genome, view, renderer ? &*renderer : nullptr, &control);
            if (control.cancelled()) throw Cancelled();
            ExportOptions written = options;
            if (tile) {
                // As marbler render --repeat mirror, the tile carries the genome.
                written.genome = serializeGenome(genome);
                image = mirrorRepeat(image);
            }
            writeImage(image, file.toStdString(), written);
        } else {
            // Rendered and written in strips, so memory stays bounded at any size.
            renderToFile(genome, view.raster, file.toStdString(), options, &control);
        }
    });
}

bool DesignDialog::exportSvgTo(const QString& file, double tolerance) {
    if (mExport) return false;
    VectorOptions options;
    options.tolerance = tolerance;
    return startExport(
        file,
        [genome = mGenome, options, file](const RenderControl& control) {
            // The same steps as marbler svg, so the files are byte for byte the same. Tracing
            // cannot be interrupted; a cancel during it leaves no file.
            const VectorDesign design = traceDesign(genome, options);
            if (control.cancelled()) throw Cancelled();
            writeSvg(design, file.toStdString(), decimalsFor(options.tolerance));
        },
        true);
}

bool DesignDialog::startExport(const QString& file, BackgroundJob::Work job, bool busy) {
    if (mExport) return false;
    JobBox box(this, tr("Exporting %1…").arg(QFileInfo(file).fileName()), QStringLiteral("exportProgress"));
    box.busy = busy;
    mExport = BackgroundJob::start(this, box, std::move(job), [this, file](const JobOutcome& outcome) {
        mExport = nullptr;
        if (outcome.failed())
            reportError(this, tr("Cannot export the image"), outcome.error);
        else if (outcome.done())
            setWindowTitle(tr("Exported %1").arg(QFileInfo(file).fileName()));
        emit exportFinished(file, outcome.done(), outcome.error);
        if (outcome.done()) emit fileSaved(file);
    });
    return true;
}

void DesignDialog::cancelExport() {
    if (mExport) mExport->cancel();
}

QString saveGenomeWithDialog(QWidget* parent, const Genome& genome) {
    QSettings settings;
    const QString suggested = suggestedFile(
        genome, settings.value(QStringLiteral("files/saveDir")).toString(), QStringLiteral(".marble.json"));
    QString file = askSaveFile(parent, QObject::tr("Save design"), suggested,
                               QObject::tr("Marbler genomes (*.marble.json)"));
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
