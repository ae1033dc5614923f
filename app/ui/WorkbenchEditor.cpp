// The workbench's doors to the editor: Open in editor, New design, Send to grid and the
// recovery of designs an editor left unsaved.

#include "ui/WorkbenchWindow.h"

#include "editor/EditorWindow.h"
#include "editor/Recovery.h"
#include "marbler/Error.h"
#include "marbler/GenomeImage.h"
#include "ui/PopulationModel.h"

#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QStatusBar>

namespace marbler::ui {

EditorWindow* WorkbenchWindow::openEditor(const Genome& design, const QString& file) {
    // A top-level window of its own (a QMainWindow is one, with its own place in the task
    // switcher), owned by the workbench, which finds its editors and closes them first.
    auto* editor = new EditorWindow(design, mRenderer, file, this);
    connect(editor, &EditorWindow::sendToGrid, this, [this](const Genome& edited) {
        const LineageInfo info = lineageOf(edited);
        placeOpened({edited}, {info.displayName()}, -1, tr("From the editor: %1").arg(info.displayName()));
    });
    connect(editor, &EditorWindow::fileSaved, this, &WorkbenchWindow::noteSavedFile);
    connect(editor, &EditorWindow::openEditorRequested, this,
            [this](const Genome& other, const QString& otherFile) { openEditor(other, otherFile); });
    editor->show();
    emit editorOpened(editor);
    return editor;
}

std::vector<EditorWindow*> WorkbenchWindow::offerRecoveries(const QString& folder,
                                                            std::function<bool(const QString& name)> accept) {
    std::vector<EditorWindow*> opened;
    if (folder.isEmpty()) return opened;
    for (const RecoveredDesign& r : pendingRecoveries(folder)) {
        const LineageInfo info = lineageOf(r.design);
        const QString name = r.originalFile.isEmpty() ? info.displayName() : QFileInfo(r.originalFile).fileName();
        bool yes;
        if (accept) {
            yes = accept(name);
        } else {
            yes = QMessageBox::question(
                      this, tr("Recover a design"),
                      tr("Marbler stopped before the changes to “%1” were saved (autosaved %2). Open them in the "
                         "editor?")
                          .arg(name, QLocale().toString(r.saved, QLocale::ShortFormat)),
                      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes)
                  == QMessageBox::Yes;
        }
        if (yes) {
            // The design as it was being edited, muted steps and all, still unsaved.
            EditorWindow* editor = openEditor(r.design, r.originalFile);
            editor->document()->markModified();
            // Its own autosave now, before the old one goes: a second crash loses nothing.
            editor->autosave()->flush();
            opened.push_back(editor);
            statusBar()->showMessage(tr("Recovered “%1”").arg(name), 5000);
        }
        discardRecovery(r.recoveryFile);
    }
    return opened;
}

} // namespace marbler::ui
