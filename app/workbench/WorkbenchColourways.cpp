// The workbench's Colourways mode (Breed ▸ Colourways): the grid breeds only palettes of one
// structure (marbler/Colourways.h), and Breed ▸ Export colourway sheet… writes the grid's
// designs as one image (marbler/Sheet.h) off the GUI thread.

#include "shared/ErrorReport.h"
#include "shared/SavedFiles.h"
#include "workbench/WorkbenchWindow.h"

#include "marbler/Error.h"
#include "marbler/Sheet.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QPointer>
#include <QProgressDialog>
#include <QStatusBar>
#include <QThread>
#include <QToolBar>

#include <atomic>
#include <memory>

namespace marbler::ui {

void WorkbenchWindow::buildColourwayActions(QMenu* breedMenu, QToolBar* bar) {
    breedMenu->addSeparator();
    mColourways = breedMenu->addAction(tr("&Colourways"));
    mColourways->setObjectName(QStringLiteral("colourwaysAction"));
    mColourways->setCheckable(true);
    mColourways->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_5));
    mColourways->setToolTip(
        tr("Breed only palettes, as textile designers make colourways: with one design picked, "
           "fills the grid with it and eight colourways of it (Ctrl+5)"));
    mColourways->setStatusTip(mColourways->toolTip());
    connect(mColourways, &QAction::toggled, this, &WorkbenchWindow::onColourwaysToggled);
    mExportSheet =
        breedMenu->addAction(tr("&Export colourway sheet…"), this, [this] { exportColourwaySheet(); });
    mExportSheet->setObjectName(QStringLiteral("exportSheetAction"));
    mExportSheet->setStatusTip(tr("The grid's designs side by side in one PNG or TIFF image"));
    bar->addAction(mColourways);
}

bool WorkbenchWindow::colourwaysMode() const {
    return mColourways && mColourways->isChecked();
}

void WorkbenchWindow::setColourwaysMode(bool on) {
    mColourways->setChecked(on);
}

void WorkbenchWindow::onColourwaysToggled(bool on) {
    updateActions();
    if (!on) {
        statusBar()->showMessage(tr("Colourways off: the operators breed whole designs again"), 5000);
        return;
    }
    const auto selected = mModel->selectedCells();
    if (selected.size() != 1 || !mModel->whyNoColourways(false).isEmpty()) {
        statusBar()->showMessage(
            tr("Colourways on: Alter varies the picked design's palette, Recombine mixes the "
               "parents' palettes; the structure stays"),
            8000);
        return;
    }
    const QString name = lineageOf(*mModel->cell(selected.front())).displayName();
    try {
        mModel->applyColourways(false, 1.0, tr("Colourways of %1").arg(name));
    } catch (const Error& e) {
        reportError(this, tr("Cannot make colourways"), QString::fromStdString(e.what()));
        return;
    }
    statusBar()->showMessage(tr("Generation %1: %2 and eight colourways of it")
                                 .arg(mModel->generationLabel(mModel->currentIndex()), name),
                             8000);
}

void WorkbenchWindow::updateColourwayActions() {
    if (!mColourways) return;
    mExportSheet->setEnabled(!mModel->isEmptyWorkbench() && !mSheetRunning);
    if (!colourwaysMode()) return;
    const auto palettes = [&](QAction* action, bool mix, const QString& ready) {
        const QString why = mModel->whyNoColourways(mix);
        action->setEnabled(why.isEmpty());
        action->setToolTip(why.isEmpty() ? ready : why);
    };
    palettes(
        mAlter, false,
        tr("Colourways of the parent: its palette varied, its structure kept; the slider sets how much"));
    palettes(mRecombine, true,
             tr("Colourways whose palettes mix the parents' inks; the structure of each is kept"));
    for (QAction* action : {mSwap, mReinit}) {
        action->setEnabled(false);
        action->setToolTip(tr("Off in Colourways mode: %1 changes the structure, which colourways keep. Turn "
                              "Breed ▸ Colourways off to use it")
                               .arg(action == mSwap ? operatorLabel(GeneticOperator::Swap)
                                                    : operatorLabel(GeneticOperator::Reinit)));
    }
}

bool WorkbenchWindow::applyColourwayOperator(GeneticOperator op) {
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
        statusBar()->showMessage(why, 5000);
        return false;
    }
    try {
        mModel->applyColourways(mix, mix ? 1.0 : strength());
    } catch (const Error& e) {
        reportError(this, tr("Cannot make colourways"), QString::fromStdString(e.what()));
        return false;
    }
    statusBar()->showMessage(
        tr("Colourways: generation %1").arg(mModel->generationLabel(mModel->currentIndex())), 5000);
    return true;
}

bool WorkbenchWindow::exportColourwaySheet(const QString& chosen) {
    if (mSheetRunning) {
        statusBar()->showMessage(tr("A colourway sheet is being written already"), 5000);
        return false;
    }
    std::vector<Genome> designs;
    for (int i = 0; i < CellCount; ++i)
        if (const Genome* g = mModel->cell(i)) designs.push_back(*g);
    if (designs.empty()) {
        statusBar()->showMessage(tr("No designs to put on a sheet yet"), 5000);
        return false;
    }
    QString file = chosen;
    if (file.isEmpty()) {
        file = askSaveFile(this, tr("Export colourway sheet"),
                           suggestedFile(designs.front(), {}, QStringLiteral(" colourways.png")),
                           tr("PNG image (*.png);;TIFF image (*.tif *.tiff)"));
        if (file.isEmpty()) return false;
    }
    if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".png");

    SheetSettings settings;
    settings.cellWidth = mSheetCellWidth;
    settings.gap = std::max(4, mSheetCellWidth / 25);
    settings.aa = "rgss";
    try {
        sheetLayout(designs, settings); // a bad layout is said before any work starts
    } catch (const Error& e) {
        reportError(this, tr("Cannot export the colourway sheet"), QString::fromStdString(e.what()));
        return false;
    }

    // The render runs on its own thread (on every core); the dialog shows its progress and
    // cancels it. The thread owns copies of everything it reads.
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    auto failure = std::make_shared<QString>();
    auto* progress = new QProgressDialog(tr("Rendering the colourway sheet…"), tr("Cancel"), 0, 1000, this);
    progress->setWindowTitle(tr("Export colourway sheet"));
    progress->setMinimumDuration(500);
    progress->setAttribute(Qt::WA_DeleteOnClose);
    connect(progress, &QProgressDialog::canceled, this, [cancel] { cancel->store(true); });
    QPointer<QProgressDialog> guard(progress);
    const std::filesystem::path path = file.toStdString();
    QThread* thread = QThread::create([designs = std::move(designs), settings, path, cancel, failure, guard] {
        RenderControl control;
        control.cancel = cancel.get();
        control.progress = [guard](double f) {
            QMetaObject::invokeMethod(
                guard.data(),
                [guard, f] {
                    if (guard) guard->setValue(int(f * 1000.0));
                },
                Qt::QueuedConnection);
        };
        try {
            writeSheet(designs, settings, path, &control);
        } catch (const Cancelled&) {
            *failure = QStringLiteral("cancelled");
        } catch (const std::exception& e) {
            *failure = QString::fromStdString(e.what());
            if (failure->isEmpty()) *failure = QStringLiteral("unknown error");
        }
    });
    mSheetRunning = true;
    updateActions();
    connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    // A window closed meanwhile stops the render (the thread then ends by itself).
    connect(this, &QObject::destroyed, thread, [cancel] { cancel->store(true); });
    connect(thread, &QThread::finished, this, [this, file, failure, guard] {
        mSheetRunning = false;
        // Closing the dialog says "canceled": what happened is read from the thread first.
        const bool cancelled = *failure == QLatin1String("cancelled");
        if (guard) {
            guard->disconnect(this);
            guard->close();
        }
        updateActions();
        if (cancelled) {
            statusBar()->showMessage(tr("Colourway sheet cancelled"), 5000);
        } else if (!failure->isEmpty()) {
            reportError(this, tr("Cannot export the colourway sheet"), tr("%1: %2").arg(file, *failure));
        } else {
            noteSavedFile(file);
        }
    });
    thread->start();
    return true;
}

} // namespace marbler::ui
