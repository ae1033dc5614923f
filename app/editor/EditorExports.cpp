// The editor's exports (EditorExports.h).

#include "editor/EditorExports.h"

#include "editor/AnimationExport.h"
#include "editor/EditorDocument.h"
#include "editor/EditorFiles.h"
#include "editor/SolidObjectView.h"
#include "marbler/Mesh.h"
#include "shared/DesignDialog.h"
#include "shared/DesignExport.h"
#include "shared/ErrorReport.h"
#include "shared/SavedFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace marbler::ui {

EditorExports::EditorExports(EditorDocument* document, RenderService* renderer, EditorFiles* files,
                             QWidget* window, std::function<Slice()> slice, SolidObjectView* object)
    : QObject(window)
    , mDocument(document)
    , mRenderer(renderer)
    , mFiles(files)
    , mWindow(window)
    , mSlice(std::move(slice))
    , mObject(object) {}

void EditorExports::exportImage() {
    // The large view exports at print size, in vector form and on objects; it opens on the design.
    auto* dialog = new DesignDialog(mDocument->renderedDesign(), mRenderer,
                                    mObject ? mObject->mesh() : QString::fromLatin1(DefaultMesh), mWindow);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &DesignDialog::fileSaved, this, &EditorExports::fileSaved);
    connect(dialog, &DesignDialog::exportFinished, this,
            [this](const QString& file, bool written, const QString& error) {
                if (!written && error.isEmpty()) emit message(exportCancelledMessage(file), 8000);
            });
    // It is open in this editor already.
    if (auto* again = dialog->findChild<QWidget*>(QStringLiteral("openInEditor"))) again->hide();
    dialog->show();
}

void EditorExports::exportAnimation() {
    if (mAnimationJob && mAnimationJob->running()) {
        emit message(tr("An animation is being written already"), 4000);
        return;
    }
    const Genome design = mDocument->renderedDesign();
    AnimationExportSettings start;
    const QString folder = QSettings().value(QStringLiteral("files/exportDir")).toString();
    start.path = suggestedFile(design, folder, QStringLiteral(".gif"));
    if (design.dimension == 3) start.slice = mSlice();
    AnimationExportDialog dialog(design, start, mWindow);
    if (dialog.exec() != QDialog::Accepted) return;
    const AnimationExportSettings settings = dialog.settings();
    if (!mFiles->mayOverwrite(withAnimationExtension(settings.path, settings.format))) return;
    QSettings().setValue(QStringLiteral("files/exportDir"), QFileInfo(settings.path).absolutePath());
    if (!mAnimationJob) {
        // A child of the window, so that its progress box is modal to it.
        mAnimationJob = new AnimationExportJob(mWindow);
        connect(mAnimationJob, &AnimationExportJob::finished, this, [this](bool ok, const QString& error) {
            if (ok) {
                emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(mWrittenPath)), 5000);
                emit fileSaved(mWrittenPath);
            } else if (!error.isEmpty()) {
                reportError(mWindow, tr("Cannot write the animation"), error);
            } else {
                emit message(tr("Animation cancelled; nothing was written"), 4000);
            }
        });
    }
    mWrittenPath = settings.path;
    if (!mAnimationJob->start(design, settings))
        emit message(tr("An animation is being written already"), 4000);
}

} // namespace marbler::ui
