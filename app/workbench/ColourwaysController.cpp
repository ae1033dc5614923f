#include "workbench/ColourwaysController.h"

#include "shared/BackgroundJob.h"
#include "shared/ErrorReport.h"
#include "shared/SavedFiles.h"
#include "workbench/PopulationModel.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/ImageFile.h"
#include "marbler/Sheet.h"

#include <QAction>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QPainter>
#include <QProgressDialog>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>

#include <algorithm>

namespace marbler::ui {

void drawSheetTexts(Image& sheet, const std::vector<SheetText>& texts) {
    // Painted straight into the sheet's pixels (a QImage over its buffer), on the job's thread.
    QImage image(sheet.rgb.data(), sheet.width, sheet.height, sheet.width * 3, QImage::Format_RGB888);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::TextAntialiasing);
    for (const SheetText& text : texts) {
        QFont font = painter.font();
        font.setPixelSize(std::max(8, text.height * 7 / 10));
        painter.setFont(font);
        // Dark on a light sheet: the sheet's paper is white.
        painter.setPen(QColor(0x33, 0x33, 0x33));
        const QRect box(text.x, text.y, text.width, text.height);
        const QString line = QString::fromStdString(text.text);
        painter.drawText(box, Qt::AlignLeft | Qt::AlignVCenter,
                         painter.fontMetrics().elidedText(line, Qt::ElideRight, box.width()));
    }
}

ColourwaysController::ColourwaysController(QMainWindow* window, PopulationModel* model,
                                           std::function<QAction*(GeneticOperator)> operatorAction,
                                           std::function<void(const QString&)> noteSavedFile)
    : QObject(window)
    , mWindow(window)
    , mModel(model)
    , mOperatorAction(std::move(operatorAction))
    , mNoteSavedFile(std::move(noteSavedFile)) {}

void ColourwaysController::buildActions(QMenu* breedMenu, QToolBar* bar) {
    breedMenu->addSeparator();
    mMode = breedMenu->addAction(tr("&Colourways"));
    mMode->setObjectName(QStringLiteral("colourwaysAction"));
    mMode->setCheckable(true);
    mMode->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_5));
    mMode->setToolTip(tr("Breed only palettes, as textile designers make colourways: with one design picked, "
                         "fills the grid with it and eight colourways of it (Ctrl+5)"));
    mMode->setStatusTip(mMode->toolTip());
    connect(mMode, &QAction::toggled, this, &ColourwaysController::onToggled);
    mExportSheet = breedMenu->addAction(tr("&Export colourway sheet…"), this, [this] { exportSheet(); });
    mExportSheet->setObjectName(QStringLiteral("exportSheetAction"));
    mExportSheet->setStatusTip(tr("The grid's designs side by side in one PNG or TIFF image, each named"));
    mSheetChips = breedMenu->addAction(tr("Colourway sheet with ink c&hips"));
    mSheetChips->setObjectName(QStringLiteral("sheetChipsAction"));
    mSheetChips->setCheckable(true);
    mSheetChips->setChecked(QSettings().value(QStringLiteral("sheet/chips"), false).toBool());
    mSheetChips->setStatusTip(
        tr("Put each design's inks, with their hex values, under its name on the sheet"));
    connect(mSheetChips, &QAction::toggled, this,
            [](bool on) { QSettings().setValue(QStringLiteral("sheet/chips"), on); });
    bar->addAction(mMode);
}

bool ColourwaysController::isOn() const {
    return mMode && mMode->isChecked();
}

void ColourwaysController::setOn(bool on) {
    mMode->setChecked(on);
}

void ColourwaysController::onToggled(bool on) {
    emit actionsChanged();
    QStatusBar* status = mWindow->statusBar();
    if (!on) {
        status->showMessage(tr("Colourways off: the operators breed whole designs again"), 5000);
        return;
    }
    const auto selected = mModel->selectedCells();
    if (selected.size() != 1 || !mModel->whyNoColourways(false).isEmpty()) {
        status->showMessage(tr("Colourways on: Alter varies the picked design's palette, Recombine mixes the "
                               "parents' palettes; the structure stays"),
                            8000);
        return;
    }
    const QString name = lineageOf(*mModel->cell(selected.front())).displayName();
    try {
        mModel->applyColourways(false, 1.0, tr("Colourways of %1").arg(name));
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot make colourways"), QString::fromStdString(e.what()));
        return;
    }
    status->showMessage(tr("Generation %1: %2 and eight colourways of it")
                            .arg(mModel->generationLabel(mModel->currentIndex()), name),
                        8000);
}

void ColourwaysController::updateActions() {
    if (!mMode) return;
    mExportSheet->setEnabled(!mModel->isEmptyWorkbench() && !mSheetRunning);
    if (!isOn()) return;
    const auto palettes = [&](QAction* action, bool mix, const QString& ready) {
        const QString why = mModel->whyNoColourways(mix);
        action->setEnabled(why.isEmpty());
        action->setToolTip(why.isEmpty() ? ready : why);
    };
    palettes(
        mOperatorAction(GeneticOperator::Alter), false,
        tr("Colourways of the parent: its palette varied, its structure kept; the slider sets how much"));
    palettes(mOperatorAction(GeneticOperator::Recombine), true,
             tr("Colourways whose palettes mix the parents' inks; the structure of each is kept"));
    for (GeneticOperator op : {GeneticOperator::Swap, GeneticOperator::Reinit}) {
        QAction* action = mOperatorAction(op);
        action->setEnabled(false);
        action->setToolTip(tr("Off in Colourways mode: %1 changes the structure, which colourways keep. Turn "
                              "Breed ▸ Colourways off to use it")
                               .arg(operatorLabel(op)));
    }
}

bool ColourwaysController::applyOperator(GeneticOperator op, double strength) {
    const bool mix = op == GeneticOperator::Recombine;
    QString why;
    switch (op) {
    case GeneticOperator::Alter:
    case GeneticOperator::Recombine:
        why = mModel->whyNoColourways(mix);
        break;
    case GeneticOperator::Swap:
    case GeneticOperator::Reinit:
        why = tr("%1 is off in Colourways mode: colourways keep the structure").arg(operatorLabel(op));
        break;
    }
    if (!why.isEmpty()) {
        mWindow->statusBar()->showMessage(why, 5000);
        return false;
    }
    try {
        mModel->applyColourways(mix, mix ? 1.0 : strength);
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot make colourways"), QString::fromStdString(e.what()));
        return false;
    }
    mWindow->statusBar()->showMessage(
        tr("Colourways: generation %1").arg(mModel->generationLabel(mModel->currentIndex())), 5000);
    return true;
}

bool ColourwaysController::exportSheet(const QString& chosen) {
    if (mSheetRunning) {
        mWindow->statusBar()->showMessage(tr("A colourway sheet is being written already"), 5000);
        return false;
    }
    std::vector<Genome> designs;
    for (int i = 0; i < CellCount; ++i)
        if (const Genome* g = mModel->cell(i)) designs.push_back(*g);
    if (designs.empty()) {
        mWindow->statusBar()->showMessage(tr("No designs to put on a sheet yet"), 5000);
        return false;
    }
    QString file = chosen;
    if (file.isEmpty()) {
        // Named after the design the colourways are of: the generation's parent when it was bred.
        const Genome* parent = nullptr;
        for (int i : mModel->current().parentCells)
            if (!parent) parent = mModel->cell(i);
        file = askSaveFile(
            mWindow, tr("Export colourway sheet"),
            suggestedFile(parent ? *parent : designs.front(), {}, QStringLiteral(" colourways.png")),
            tr("PNG image (*.png);;TIFF image (*.tif *.tiff)"));
        if (file.isEmpty()) return false;
    }
    if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".png");

    SheetSettings settings;
    settings.cellWidth = mSheetCellWidth;
    settings.gap = std::max(4, mSheetCellWidth / 25);
    settings.aa = "rgss";
    settings.labels = true;
    settings.chips = mSheetChips && mSheetChips->isChecked();
    try {
        sheetLayout(designs, settings); // a bad layout is said before any work starts
    } catch (const Error& e) {
        reportError(mWindow, tr("Cannot export the colourway sheet"), QString::fromStdString(e.what()));
        return false;
    }

    // The render runs on its own thread (on every core); the box shows its progress and cancels
    // it. The work owns copies of everything it reads; a window closed meanwhile stops it.
    JobBox box(mWindow, tr("Rendering the colourway sheet…"));
    box.minimumDurationMs = 500;
    const std::filesystem::path path = file.toStdString();
    mSheetRunning = true;
    emit actionsChanged();
    BackgroundJob* job = BackgroundJob::start(
        this, box,
        [designs = std::move(designs), settings, path](const RenderControl& control) {
            Image sheet = renderSheet(designs, settings, &control);
            drawSheetTexts(sheet, sheetTexts(designs, sheetLayout(designs, settings), settings));
            writeImage(sheet, path);
        },
        [this, file](const JobOutcome& outcome) {
            mSheetRunning = false;
            emit actionsChanged();
            if (outcome.cancelled())
                mWindow->statusBar()->showMessage(tr("Colourway sheet cancelled"), 5000);
            else if (outcome.failed())
                reportError(mWindow, tr("Cannot export the colourway sheet"),
                            tr("%1: %2").arg(file, outcome.error));
            else
                mNoteSavedFile(file);
        });
    job->progressBox()->setWindowTitle(tr("Export colourway sheet"));
    return true;
}

} // namespace marbler::ui
