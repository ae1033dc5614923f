#include "workbench/StatusLine.h"

#include "shared/SavedFiles.h"

#include <QLabel>
#include <QMainWindow>
#include <QStatusBar>

#include <algorithm>

namespace marbler::ui {

StatusLine::StatusLine(QMainWindow* window)
    : QObject(window) {
    // Passing messages over the generation's summary on the left; on the right the last file
    // saved and what the window is doing. Which renderer draws is in Help ▸ About.
    mGeneration = new QLabel(window);
    mGeneration->setObjectName(QStringLiteral("generationLabel"));
    window->statusBar()->addWidget(mGeneration, 1);
    mSavedNotice = new SavedFileNotice(window);
    window->statusBar()->addPermanentWidget(mSavedNotice);
    mTask = new QLabel(window);
    mTask->setObjectName(QStringLiteral("taskLabel"));
    mTask->setToolTip(
        tr("What the window is doing. Help ▸ About Marbler says which renderer draws the designs."));
    window->statusBar()->addPermanentWidget(mTask);
}

void StatusLine::setGeneration(const QString& text) {
    mGeneration->setText(text);
}

void StatusLine::setPending(int pending) {
    if (pending == 0) {
        mRenderBatch = 0;
        mTask->setText(tr("Ready"));
        return;
    }
    mRenderBatch = std::max(mRenderBatch, pending);
    mTask->setText(tr("Rendering %1 of %2…").arg(mRenderBatch - pending + 1).arg(mRenderBatch));
}

} // namespace marbler::ui
