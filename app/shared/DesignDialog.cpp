#include "shared/DesignDialog.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Sampling.h"
#include "shared/BakeObject.h"
#include "shared/DesignExport.h"
#include "shared/DesignView.h"
#include "shared/ErrorReport.h"
#include "shared/GenomeClipboard.h"
#include "shared/Lineage.h"
#include "shared/RenameDialog.h"
#include "shared/RenderService.h"
#include "shared/SavedFiles.h"
#include "shared/SectionControls.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace marbler::ui {

namespace {
/// What the repeat swatch shows, for its button: the mirror repeat, or a bath that wraps on its
/// own lattice (DesignView::setRepeatSwatch); `solid`: shown on an object, with no swatch.
QString swatchTip(const Genome& genome, bool solid) {
    if (solid) return DesignDialog::tr("Flat designs only: a solid has no repeat tile");
    if (!genome.wrap)
        return DesignDialog::tr(
            "Show the whole design tiled as its mirror repeat, 2 × 2, to judge the repeat (R)");
    switch (genome.lattice) {
    case Lattice::Straight:
        return DesignDialog::tr(
            "Show the design repeated 2 × 2 as its straight repeat, to judge the repeat (R)");
    case Lattice::HalfDrop:
        return DesignDialog::tr(
            "Show the design repeated 2 × 2 as its half-drop repeat, to judge the repeat (R)");
    case Lattice::Brick:
        return DesignDialog::tr(
            "Show the design repeated 2 × 2 as its brick repeat, to judge the repeat (R)");
    }
    return {};
}
} // namespace

DesignDialog::DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent,
                           const QString& flatMesh)
    : QDialog(parent)
    , mGenome(std::move(genome))
    , mRenderer(renderer)
    , mMesh(mesh) {
    const LineageInfo info = lineageOf(mGenome);
    setWindowTitle(tr("Design %1").arg(info.name.isEmpty() ? info.id : info.name));
    // A flat design on an object is seen as a solid is: turned, zoomed about the object, no swatch.
    const bool flatOnObject = mGenome.dimension != 3 && !flatMesh.isEmpty();
    const bool solid = mGenome.dimension == 3 || flatOnObject;
    // The swatch is set before the first render request (the canvas's first resize): no wasted
    // render.
    const bool swatch = !solid && QSettings().value(QStringLiteral("view/repeatSwatch"), false).toBool();
    mView = new DesignView(mGenome, mRenderer, flatOnObject ? flatMesh : mMesh, swatch, this, flatOnObject);
    mExport = new DesignExport(this);

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
    mSwatchButton = tool(QStringLiteral("repeatSwatch"), tr("Repeat swatch"), swatchTip(mGenome, solid));
    mSwatchButton->setCheckable(true);
    mSwatchButton->setEnabled(!solid);
    connect(mSwatchButton, &QToolButton::toggled, this, &DesignDialog::setRepeatSwatch);
    zoomBar->addWidget(mSwatchButton);
    // A solid: a cross-section instead of the object, across an axis or turned to any normal.
    if (mGenome.dimension == 3) {
        mLastSection = Slice{2, mGenome.size.z / 2.0};
        mSectionButton =
            tool(QStringLiteral("showSection"), tr("Section"),
                 tr("Show a cross-section of the solid instead of the object; move it and turn it "
                    "to any angle below (S)"));
        mSectionButton->setCheckable(true);
        connect(mSectionButton, &QToolButton::toggled, this,
                [this](bool on) { setSection(on ? std::optional<Slice>(mLastSection) : std::nullopt); });
        zoomBar->addWidget(mSectionButton);
        mSectionControls = new SectionControls([this] { return mGenome.size; }, mLastSection, this, false);
        mSectionControls->setObjectName(QStringLiteral("sectionControls"));
        mSectionControls->hide();
        connect(mSectionControls, &SectionControls::sliceChosen, this,
                [this](const Slice& slice) { setSection(slice); });
    }

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
        Genome saved;
        const QString file = saveGenomeWithDialog(this, mGenome, &saved);
        if (file.isEmpty()) return;
        if (saved.meta.name != mGenome.meta.name) {
            rename(QString::fromStdString(saved.meta.name.value_or("")), noteOf(saved));
            emit renamed(mGenome);
        }
        emit fileSaved(file);
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
    if (mSectionButton) addKey(QStringLiteral("showSectionAction"), QKeySequence(Qt::Key_S), mSectionButton);
    auto* renameAction = new QAction(tr("Rename…"), this);
    renameAction->setObjectName(QStringLiteral("renameDesignAction"));
    renameAction->setShortcut(QKeySequence(Qt::Key_F2));
    connect(renameAction, &QAction::triggered, this, [this] { askName(); });
    addAction(renameAction);
    connect(close, &QPushButton::clicked, this, &QDialog::close);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(save);
    buttons->addWidget(exportButton);
    buttons->addWidget(copy);
    buttons->addWidget(editor);
    // Flat and solid designs alike: onto the object shown (a flat one's only when it is on one),
    // a built-in or a mesh file.
    buttons->addWidget(makeBakeButton(
        this, [this] { return mGenome; }, mGenome.dimension == 3 ? mMesh : flatMesh,
        [this](const QString& file) { emit fileSaved(file); }));
    buttons->addStretch();
    buttons->addWidget(close);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(zoomBar);
    layout->addWidget(mView, 1);
    if (mSectionControls) layout->addWidget(mSectionControls);
    layout->addLayout(buttons);
    // Enter in a field (the section's normal) confirms that field; it is no click of a button.
    for (QPushButton* button : findChildren<QPushButton*>()) {
        button->setAutoDefault(false);
        button->setDefault(false);
    }
    resize(720, 800);
    mZoomLabel->setText(zoomText());
    if (swatch) {
        const QSignalBlocker block(mSwatchButton);
        mSwatchButton->setChecked(true);
    }
    connect(mView, &DesignView::zoomChanged, this, [this] { mZoomLabel->setText(zoomText()); });
    connect(mView, &DesignView::viewAngleChanged, this, [this](const ViewAngle& angle) {
        // The angle belongs to the design: saved with it, and given back to its cell.
        setViewAngle(mGenome, angle);
        emit viewAngleChanged(angle);
    });
    connect(mExport, &DesignExport::finished, this,
            [this](const QString& file, bool written, const QString& error) {
                // The title keeps naming the design (issue 29); where the file went is said by
                // the window's status bar (fileSaved), a cancel by exportFinished's receivers.
                emit exportFinished(file, written, error);
                if (written) emit fileSaved(file);
            });
}

DesignDialog::~DesignDialog() {
    // Closing the view stops its render and its export, and waits for the export; renderToFile
    // leaves no partial file.
    delete mView;
    delete mExport;
}

QWidget* DesignDialog::canvas() const {
    return mView;
}
const ViewController& DesignDialog::viewController() const {
    return mView->viewController();
}
double DesignDialog::objectZoom() const {
    return mView->objectZoom();
}
ViewAngle DesignDialog::viewAngle() const {
    return mView->viewAngle();
}
QString DesignDialog::zoomText() const {
    return mView->zoomText();
}
const QImage& DesignDialog::image() const {
    return mView->image();
}
bool DesignDialog::imageIsFinal() const {
    return mView->imageIsFinal();
}
std::optional<Region> DesignDialog::requestedRegion() const {
    return mView->requestedRegion();
}
void DesignDialog::zoomIn() {
    mView->zoomIn();
}
void DesignDialog::zoomOut() {
    mView->zoomOut();
}
void DesignDialog::zoomAt(double factor, QPointF anchor) {
    mView->zoomAt(factor, anchor);
}
void DesignDialog::fitView() {
    mView->fitView();
}
void DesignDialog::showOneToOne() {
    mView->showOneToOne();
}
void DesignDialog::panBy(QPointF delta) {
    mView->panBy(delta);
}
bool DesignDialog::repeatSwatch() const {
    return mView->repeatSwatch();
}

void DesignDialog::setSection(const std::optional<Slice>& slice) {
    if (mGenome.dimension != 3) return;
    if (slice) mLastSection = *slice;
    {
        const QSignalBlocker block(mSectionButton);
        mSectionButton->setChecked(slice.has_value());
    }
    mSectionControls->setVisible(slice.has_value());
    if (slice) mSectionControls->showSlice(*slice);
    mView->setSection(slice);
    mZoomLabel->setText(zoomText());
}

const std::optional<Slice>& DesignDialog::section() const {
    return mView->section();
}

void DesignDialog::setRepeatSwatch(bool on) {
    if (mGenome.dimension == 3) on = false;
    if (mSwatchButton->isChecked() != on) {
        const QSignalBlocker block(mSwatchButton);
        mSwatchButton->setChecked(on);
    }
    QSettings().setValue(QStringLiteral("view/repeatSwatch"), on);
    mView->setRepeatSwatch(on);
}

void DesignDialog::keyPressEvent(QKeyEvent* event) {
    if (ViewController::handleKey(event, {[this] { zoomIn(); }, [this] { zoomOut(); }, [this] { fitView(); },
                                          [this] { showOneToOne(); }}))
        return;
    QDialog::keyPressEvent(event);
}

QString DesignDialog::suggestedExportFile() const {
    const QSettings settings;
    return suggestedFile(
        mGenome, settings.value(QStringLiteral("files/exportDir")).toString(),
        settings.value(QStringLiteral("files/exportExtension"), QStringLiteral(".png")).toString());
}

void DesignDialog::exportImage() {
    ExportSettingsDialog settingsDialog(mGenome, this);
    // The cross-section shown is the one exported, until the user chooses otherwise.
    if (const auto& section = mView->section()) settingsDialog.setSolidExport(SolidExport{false, *section});
    if (settingsDialog.exec() != QDialog::Accepted) return;
    QSettings settings;
    const QString extension = settingsDialog.extension();
    settings.setValue(QStringLiteral("files/exportExtension"), extension);
    settings.setValue(QStringLiteral("files/exportBits"), settingsDialog.bitsPerSample());
    if (settingsDialog.separations()) {
        // A folder for the masks and the indexed PNG (made if missing, as render --separations).
        const QFileInfo suggested(suggestedExportFile());
        const QString folder = askSaveFile(this, tr("Export separations into a folder"),
                                           suggested.absolutePath() + QLatin1Char('/') +
                                               suggested.completeBaseName() + tr(" separations"),
                                           tr("Folders (*)"));
        if (folder.isEmpty()) return;
        settings.setValue(QStringLiteral("files/exportDir"), QFileInfo(folder).absolutePath());
        exportSeparationsTo(folder, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()),
                            settingsDialog.dpi(), settingsDialog.maskBits());
        return;
    }
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
    if (const std::optional<QString> profile = settingsDialog.printProfile()) {
        exportCmykTo(file, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()),
                     settingsDialog.dpi(), *profile, settingsDialog.intent(), settingsDialog.bitsPerSample());
        return;
    }
    exportTo(file, settingsDialog.pixels(), QString::fromStdString(settingsDialog.aa()), settingsDialog.dpi(),
             settingsDialog.solidExport(), settingsDialog.bitsPerSample(), settingsDialog.mirrorRepeatTile(),
             settingsDialog.straightRepeatTile());
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
                            std::optional<SolidExport> solid, int bitsPerSample, bool mirrorRepeatTile,
                            bool straightRepeatTile) {
    const DesignExport::ObjectView object{mMesh, mView->viewAngle(), mView->objectZoom(),
                                          mRenderer->usesGl()};
    return mExport->exportTo(mGenome, object, file, pixels, aa, dpi, solid, bitsPerSample, mirrorRepeatTile,
                             straightRepeatTile);
}

bool DesignDialog::exportSvgTo(const QString& file, double tolerance) {
    return mExport->exportSvgTo(mGenome, file, tolerance);
}

bool DesignDialog::exportCmykTo(const QString& file, QSize pixels, const QString& aa,
                                std::optional<double> dpi, const QString& profile, RenderingIntent intent,
                                int bitsPerSample) {
    return mExport->exportCmykTo(mGenome, file, pixels, aa, dpi, profile, intent, bitsPerSample);
}

bool DesignDialog::exportSeparationsTo(const QString& folder, QSize pixels, const QString& aa,
                                       std::optional<double> dpi, int maskBits) {
    return mExport->exportSeparationsTo(mGenome, folder, pixels, aa, dpi, maskBits);
}

void DesignDialog::cancelExport() {
    mExport->cancel();
}
bool DesignDialog::isExporting() const {
    return mExport->isRunning();
}

RenameDialog* DesignDialog::askName() {
    return askRename(this, mGenome, [this](const QString& name, const QString& note) {
        rename(name, note);
        emit renamed(mGenome);
    });
}

void DesignDialog::rename(const QString& name, const QString& note) {
    setNameAndNote(mGenome, name, note);
    setWindowTitle(tr("Design %1").arg(name));
}

QString saveGenomeWithDialog(QWidget* parent, const Genome& genome, Genome* saved) {
    QSettings settings;
    const QString suggested = suggestedFile(
        genome, settings.value(QStringLiteral("files/saveDir")).toString(), QStringLiteral(".marble.json"));
    QString file = askSaveFile(parent, QObject::tr("Save design"), suggested,
                               QObject::tr("Marbler genomes (*.marble.json)"));
    if (file.isEmpty()) return {};
    if (!file.endsWith(QStringLiteral(".json"))) file += QStringLiteral(".marble.json");
    settings.setValue(QStringLiteral("files/saveDir"), QFileInfo(file).absolutePath());
    // A file name the user typed names the design: reopened, it is called what its file is.
    Genome named = genome;
    if (QFileInfo(file).fileName() != QFileInfo(suggested).fileName()) adoptFileName(named, file);
    if (!saveGenomeTo(parent, named, file)) return {};
    if (saved) *saved = std::move(named);
    return file;
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
