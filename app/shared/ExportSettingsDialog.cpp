#include "shared/ExportSettingsDialog.h"

#include "marbler/Error.h"
#include "shared/ErrorReport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdint>

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

/// An antialiasing pattern as the dialog names it (issue 29: "rgss", "rooks8" are jargon).
struct AaChoice {
    QString label;
    QString tip;
};

AaChoice aaChoice(const std::string& name) {
    const int samples = int(aaPattern(name).offsets.size());
    if (name == "none")
        return {QObject::tr("Off (1 sample, fastest)"),
                QObject::tr("One sample a pixel: hard, stepped edges")};
    if (name == "rgss")
        return {QObject::tr("Smooth (4 samples, default)"),
                QObject::tr("Four samples a pixel on a rotated grid: smooth edges at a small cost")};
    if (name == "quincunx")
        return {QObject::tr("Soft (5 samples)"),
                QObject::tr("Five samples a pixel, the centre weighted most: slightly soft edges")};
    if (name == "checker4")
        return {QObject::tr("Fine checkerboard (%1 samples)").arg(samples),
                QObject::tr("Samples on every other square of a 4 × 4 grid")};
    if (name == "rooks8")
        return {QObject::tr("Fine (%1 samples)").arg(samples),
                QObject::tr("Eight samples a pixel, each in a row and a column of its own: fine edges")};
    if (name.rfind("grid", 0) == 0) {
        const int n = name.back() - '0';
        return {
            QObject::tr("Grid %1 × %1 (%2 samples)").arg(n).arg(samples),
            QObject::tr("Samples on a regular %1 × %1 grid a pixel: finer and slower as it grows").arg(n)};
    }
    return {QString::fromStdString(name), QString()};
}

/// Where Export image keeps what was chosen last (issue 29: it forgot, back to 2,048 px).
const QString WidthKey = QStringLiteral("files/exportWidthPixels");
const QString UnitKey = QStringLiteral("files/exportUnit");
const QString DpiKey = QStringLiteral("files/exportDpi");
const QString AaKey = QStringLiteral("files/exportAa");
const QString ProfileKey = QStringLiteral("files/exportPrintProfile");
const QString CmykKey = QStringLiteral("files/exportConvertToProfile");
const QString IntentKey = QStringLiteral("files/exportIntent");
const QString MaskBitsKey = QStringLiteral("files/exportMaskBits");

/// The format item of separations (a folder, not a file extension).
const QString SeparationsFormat = QStringLiteral(".separations");

ProfileChooser& profileChooser() {
    static ProfileChooser chooser = [](QWidget* parent, const QString& current) {
        return QFileDialog::getOpenFileName(parent, QObject::tr("Printer profile"), current,
                                            QObject::tr("ICC profiles (*.icc *.icm);;All files (*)"));
    };
    return chooser;
}

} // namespace

void setProfileChooser(ProfileChooser chooser) {
    profileChooser() = std::move(chooser);
}

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
    if (genome.dimension != 3) {
        mFormat->addItem(tr("SVG (vector)"), QStringLiteral(".svg"));
        // What marbler render --separations writes (issue 29), into a folder.
        mFormat->addItem(tr("Separations (a mask per ink and an indexed PNG, in a folder)"),
                         SeparationsFormat);
        mFormat->setItemData(
            mFormat->count() - 1,
            tr("For screen and block printers: one greyscale mask per ink and the background, "
               "and an indexed PNG whose palette is the inks (marbler render --separations)"),
            Qt::ToolTipRole);
    }
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
    // Plain words for the patterns; the command line's name (--aa) is the item's data and is
    // said in its tooltip, so a user can repeat an export from a script.
    for (const std::string& name : aaPatternNames()) {
        const AaChoice choice = aaChoice(name);
        mAa->addItem(choice.label, QString::fromStdString(name));
        mAa->setItemData(mAa->count() - 1,
                         tr("%1 (marbler render --aa %2)").arg(choice.tip, QString::fromStdString(name)),
                         Qt::ToolTipRole);
    }
    mAa->setToolTip(tr("Antialiasing: more samples a pixel give smoother edges and a slower render"));
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
        if (genome.wrap && genome.lattice == Lattice::Straight) { // half-drop and brick: issue 29
            // A bath that wraps: the render's edges meet exactly, so the design repeats as it is.
            mStraight = new QCheckBox(tr("Straight repeat tile (2 × 2): the design repeated, twice the width "
                                         "and height"),
                                      this);
            mStraight->setObjectName(QStringLiteral("exportStraightRepeat"));
            mStraight->setToolTip(tr("This design's bath wraps, so the design is a straight-repeat tile: "
                                     "each edge meets the opposite one without a seam. Ticked, the export "
                                     "shows it 2 × 2 (unticked, the plain export is the tile itself)"));
            form->addRow(QString(), mStraight);
            connect(mStraight, &QCheckBox::toggled, this, [this](bool on) {
                if (on) mRepeat->setChecked(false);
                updateSummary();
            });
            connect(mRepeat, &QCheckBox::toggled, this, [this](bool on) {
                if (on) mStraight->setChecked(false);
            });
        }
        mTolerance = new QDoubleSpinBox(this);
        mTolerance->setObjectName(QStringLiteral("exportTolerance"));
        mTolerance->setDecimals(3);
        mTolerance->setRange(0.001, 1000.0);
        mTolerance->setValue(1.0);
        mTolerance->setToolTip(
            tr("SVG: the largest distance between neighbouring vertices of an outline, in design "
               "units; larger gives smaller files (marbler svg --tolerance)"));
        form->addRow(tr("&Tolerance"), mTolerance);
        // ---- A CMYK TIFF for a printer's profile (issue 29; marbler render --icc) ----
        const QSettings settings;
        mCmyk = new QCheckBox(tr("Convert to printer profile (CMYK TIFF)…"), this);
        mCmyk->setObjectName(QStringLiteral("exportCmyk"));
        mCmyk->setToolTip(tr("Converts the TIFF from sRGB to the CMYK colours of a printer's ICC profile, "
                             "which the print shop gives, and embeds it (marbler render --icc)"));
        mProfile = new QLineEdit(settings.value(ProfileKey).toString(), this);
        mProfile->setObjectName(QStringLiteral("exportProfile"));
        mProfile->setPlaceholderText(tr("the printer's .icc file"));
        mProfile->setToolTip(tr("The CMYK output profile of the press or paper, an .icc or .icm file"));
        mChooseProfile = new QPushButton(tr("C&hoose…"), this);
        mChooseProfile->setObjectName(QStringLiteral("exportChooseProfile"));
        mChooseProfile->setToolTip(tr("Choose the printer's ICC profile"));
        connect(mChooseProfile, &QPushButton::clicked, this, [this] {
            const QString file = profileChooser()(this, mProfile->text());
            if (file.isEmpty()) return;
            mProfile->setText(file);
            mCmyk->setChecked(true);
        });
        mIntent = new QComboBox(this);
        mIntent->setObjectName(QStringLiteral("exportIntent"));
        mIntent->addItem(tr("Perceptual (default: the whole image fitted to the press)"));
        mIntent->addItem(tr("Relative colorimetric (exact where printable)"));
        mIntent->addItem(tr("Saturation (vivid, for graphics)"));
        mIntent->addItem(tr("Absolute colorimetric (proofing, paper white kept)"));
        mIntent->setToolTip(tr("How colours the press cannot print are brought into its range "
                               "(marbler render --intent)"));
        mIntent->setCurrentIndex(std::clamp(settings.value(IntentKey, 0).toInt(), 0, 3));
        auto* profileRow = new QHBoxLayout;
        profileRow->addWidget(mProfile, 1);
        profileRow->addWidget(mChooseProfile);
        form->addRow(tr("C&olours"), mCmyk);
        // A row of a layout has no buddy of its own: the label's mnemonic goes to the file field.
        auto* profileLabel = new QLabel(tr("&Printer profile"), this);
        profileLabel->setBuddy(mProfile);
        form->addRow(profileLabel, profileRow);
        form->addRow(tr("&Intent"), mIntent);
        mCmyk->setChecked(settings.value(CmykKey, false).toBool() && !mProfile->text().isEmpty());
        // The CMYK TIFF is of the design itself, not of a repeat tile.
        connect(mCmyk, &QCheckBox::toggled, this, [this](bool on) {
            if (on) {
                mRepeat->setChecked(false);
                if (mStraight) mStraight->setChecked(false);
            }
            updateSummary();
        });
        for (QCheckBox* tile : {mRepeat, mStraight})
            if (tile)
                connect(tile, &QCheckBox::toggled, this, [this](bool on) {
                    if (on) mCmyk->setChecked(false);
                });
        // ---- Separations' masks ----
        mMaskBits = new QComboBox(this);
        mMaskBits->setObjectName(QStringLiteral("exportMaskBits"));
        mMaskBits->addItem(tr("8-bit coverage (antialiased edges)"), 8);
        mMaskBits->addItem(tr("1-bit (on or off, for screens)"), 1);
        mMaskBits->setToolTip(
            tr("Separations: each mask's pixels as the share of the ink in them, or on where "
               "at least half the pixel is the ink (marbler render --mask-bits)"));
        setMaskBits(settings.value(MaskBitsKey, 8).toInt());
        form->addRow(tr("&Masks"), mMaskBits);
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
        // A turned section: its normal typed (issue 23); the position is then p·normal.
        mNormal = new QLineEdit(this);
        mNormal->setObjectName(QStringLiteral("exportNormal"));
        mNormal->setPlaceholderText(tr("across the axis"));
        mNormal->setToolTip(tr("A turned cross-section's normal as x, y, z (e.g. 1, 1, 0); empty: across "
                               "the axis"));
        auto showAxis = [this] {
            const Slice slice = chosenSlice();
            glm::dvec2 range(0.0, mGenome.size[slice.axis]);
            if (slice.normal) range = sliceOffsetRange(*slice.normal, mGenome.size);
            // The middle of the new axis: its old position may not lie inside it.
            mPosition->setRange(range.x, range.y);
            mPosition->setValue(0.5 * (range.x + range.y));
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
        connect(mNormal, &QLineEdit::editingFinished, this, [this, showAxis] {
            showAxis();
            updateSummary();
        });
        connect(mSolidView, &QComboBox::currentIndexChanged, this, enable);
        connect(mSolidView, &QComboBox::currentIndexChanged, mNormal,
                [this] { mNormal->setEnabled(mSolidView->currentIndex() == 1); });
        form->addRow(tr("&Show"), mSolidView);
        form->addRow(tr("A&xis"), mAxis);
        form->addRow(tr("&Normal"), mNormal);
        form->addRow(tr("&Position"), mPosition);
        mAxis->setEnabled(false);
        mPosition->setEnabled(false);
        mNormal->setEnabled(false);
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
        if (mStraight) {
            setTabOrder(mRepeat, mStraight);
            setTabOrder(mStraight, mTolerance);
        } else {
            setTabOrder(mRepeat, mTolerance);
        }
        setTabOrder(mTolerance, mCmyk);
        setTabOrder(mCmyk, mProfile);
        setTabOrder(mProfile, mChooseProfile);
        setTabOrder(mChooseProfile, mIntent);
        setTabOrder(mIntent, mMaskBits);
        last = mMaskBits;
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
    {
        // The size, unit, resolution and antialiasing of the last export, kept in pixels so the
        // unit shows them as they were chosen.
        const QSettings settings;
        mDpi->setValue(settings.value(DpiKey, 300).toInt());
        const int aa = mAa->findData(settings.value(AaKey, QStringLiteral("rgss")).toString());
        mAa->setCurrentIndex(aa >= 0 ? aa : mAa->findData(QStringLiteral("rgss")));
        mPixelWidth = std::clamp(settings.value(WidthKey, 2048.0).toDouble(), 1.0, 1e7);
        const int unit = mUnit->findText(settings.value(UnitKey, tr("pixels")).toString());
        mUnit->setCurrentIndex(std::max(unit, 0));
        showWidth();
    }
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
    if (mStraight) mStraight->setEnabled(!svg);
    if (mCmyk) {
        const bool tiff = extension() == QStringLiteral(".tif");
        mCmyk->setEnabled(tiff);
        // Choosing a profile ticks the conversion, so the button is there for any TIFF.
        mChooseProfile->setEnabled(tiff);
        mProfile->setEnabled(tiff && mCmyk->isChecked());
        mIntent->setEnabled(tiff && mCmyk->isChecked());
        mMaskBits->setEnabled(separations());
        mRepeat->setEnabled(!svg && !separations());
        if (mStraight) mStraight->setEnabled(!svg && !separations());
    }
    if (svg) {
        mPixels->setText(
            tr("Vector outlines in design units (%L1 × %L2)").arg(mGenome.size.x).arg(mGenome.size.y));
        mPixels->setStyleSheet(QString());
        mButtons->button(QDialogButtonBox::Ok)->setEnabled(true);
        growToShowWrapped(this, mPixels);
        return;
    }
    const bool tile = mirrorRepeatTile() || straightRepeatTile();
    const QSize s = tile ? pixels() * 2 : pixels();
    const QString problem = exportSizeProblem(s);
    QString text = tr("%L1 × %L2 pixels").arg(s.width()).arg(s.height());
    if (tile) text += tr(", the tile of a %L1 × %L2 render").arg(pixels().width()).arg(pixels().height());
    if (perInch() <= 0.0)
        text += tr(" (%1 × %2 in at %3 dpi)")
                    .arg(s.width() / double(mDpi->value()), 0, 'f', 2)
                    .arg(s.height() / double(mDpi->value()), 0, 'f', 2)
                    .arg(mDpi->value());
    mPixels->setText(problem.isEmpty() ? text : problem + QLatin1Char(' ') + widestThatFits(tile ? 2 : 1));
    mPixels->setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("color: #c03030"));
    mButtons->button(QDialogButtonBox::Ok)->setEnabled(problem.isEmpty());
    growToShowWrapped(this, mPixels);
}

QString ExportSettingsDialog::widestThatFits(int tiles) const {
    // The largest width whose image (times the tile's 2 x 2) keeps within every limit.
    const double a = aspect();
    double w = std::min(double(MaxImageSide) / tiles, double(MaxImageSide) / (tiles * std::max(a, 1e-9)));
    w = std::min(w, std::sqrt(double(MaxImagePixels) / (tiles * tiles * std::max(a, 1e-9))));
    w = std::floor(w);
    while (w > 1 && !exportSizeProblem(QSize(int(w) * tiles, int(std::round(w * a)) * tiles)).isEmpty())
        w -= 1;
    if (perInch() <= 0.0)
        return tr("The widest that fits is %L1 pixels: type at most that in Width.").arg(w, 0, 'f', 0);
    const double inUnit = std::floor(w / mDpi->value() * perInch() * 1000.0) / 1000.0;
    return tr("The widest that fits is %L1 %2 at %3 dpi: type at most that in Width, or lower the "
              "resolution.")
        .arg(inUnit, 0, 'f', 3)
        .arg(unit())
        .arg(mDpi->value());
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
    const glm::dvec2 plane = slicePlane(mGenome.dimension, chosenSlice(), size).extent(size);
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
    return mRepeat && mRepeat->isChecked() && !isSvg() && !separations();
}
void ExportSettingsDialog::setMirrorRepeatTile(bool on) {
    if (mRepeat) mRepeat->setChecked(on);
}
bool ExportSettingsDialog::straightRepeatTile() const {
    return mStraight && mStraight->isChecked() && !isSvg() && !separations();
}

std::optional<QString> ExportSettingsDialog::printProfile() const {
    if (!mCmyk || !mCmyk->isChecked() || extension() != QStringLiteral(".tif")) return std::nullopt;
    return mProfile->text().trimmed();
}
void ExportSettingsDialog::setPrintProfile(const QString& file) {
    if (!mCmyk) return;
    mProfile->setText(file);
    mCmyk->setChecked(!file.isEmpty());
}
RenderingIntent ExportSettingsDialog::intent() const {
    return mIntent ? static_cast<RenderingIntent>(mIntent->currentIndex()) : RenderingIntent::Perceptual;
}
bool ExportSettingsDialog::separations() const {
    return mFormat->currentData().toString() == SeparationsFormat;
}
int ExportSettingsDialog::maskBits() const {
    return mMaskBits ? mMaskBits->currentData().toInt() : 8;
}
void ExportSettingsDialog::setMaskBits(int bits) {
    if (mMaskBits) mMaskBits->setCurrentIndex(std::max(0, mMaskBits->findData(bits)));
}
void ExportSettingsDialog::setStraightRepeatTile(bool on) {
    if (mStraight) mStraight->setChecked(on);
}

std::optional<SolidExport> ExportSettingsDialog::solidExport() const {
    if (mGenome.dimension != 3) return std::nullopt;
    SolidExport solid;
    solid.objectView = mSolidView->currentIndex() == 0;
    solid.slice = chosenSlice();
    return solid;
}

Slice ExportSettingsDialog::chosenSlice() const {
    Slice slice{mAxis->currentIndex(), mPosition->value()};
    if (mNormal && !mNormal->text().trimmed().isEmpty())
        slice.normal = parseDirection(mNormal->text().trimmed().toStdString(), "Normal");
    return slice;
}

void ExportSettingsDialog::setSolidExport(const SolidExport& solid) {
    if (mGenome.dimension != 3) return;
    mSolidView->setCurrentIndex(solid.objectView ? 0 : 1);
    mAxis->setCurrentIndex(std::clamp(solid.slice.axis, 0, 2));
    if (solid.slice.normal) {
        const glm::dvec3 n = *solid.slice.normal;
        mNormal->setText(QStringLiteral("%1, %2, %3")
                             .arg(QString::number(n.x, 'g', 6), QString::number(n.y, 'g', 6),
                                  QString::number(n.z, 'g', 6)));
        const glm::dvec2 range = sliceOffsetRange(n, mGenome.size);
        mPosition->setRange(range.x, range.y);
    } else {
        mNormal->clear();
        mPosition->setRange(0.0, mGenome.size[std::clamp(solid.slice.axis, 0, 2)]);
    }
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
    return mAa->currentData().toString().toStdString();
}

void ExportSettingsDialog::accept() {
    if (const QString problem =
            isSvg() ? QString()
                    : exportSizeProblem(mirrorRepeatTile() || straightRepeatTile() ? pixels() * 2 : pixels());
        !problem.isEmpty()) {
        reportError(this, tr("The image is too large"), problem);
        return;
    }
    if (const std::optional<QString> profile = printProfile()) {
        // Checked here, so a wrong file is said before the file name is asked.
        if (profile->isEmpty()) {
            reportError(this, tr("No printer profile"),
                        tr("Choose the printer's ICC profile (an .icc file from the print shop), or untick "
                           "Convert to printer profile."));
            return;
        }
        try {
            loadPrintProfile(profile->toStdString());
        } catch (const InputError& e) {
            reportError(this, tr("Cannot use the printer profile"), QString::fromStdString(e.what()));
            return;
        }
    }
    QSettings settings;
    if (mCmyk) {
        settings.setValue(CmykKey, mCmyk->isChecked());
        if (!mProfile->text().trimmed().isEmpty()) settings.setValue(ProfileKey, mProfile->text().trimmed());
        settings.setValue(IntentKey, mIntent->currentIndex());
        settings.setValue(MaskBitsKey, maskBits());
    }
    settings.setValue(WidthKey, mPixelWidth);
    settings.setValue(UnitKey, unit());
    settings.setValue(DpiKey, mDpi->value());
    settings.setValue(AaKey, QString::fromStdString(aa()));
    QDialog::accept();
}

} // namespace marbler::ui
