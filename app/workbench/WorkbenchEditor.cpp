// The workbench's doors to the editor: Open in editor, New design, Send to grid and the
// recovery of designs an editor left unsaved.

#include "workbench/WorkbenchWindow.h"

#include "editor/EditorWindow.h"
#include "editor/Recovery.h"
#include "marbler/Error.h"
#include "marbler/GenomeImage.h"
#include "workbench/PopulationModel.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>
#include <QVBoxLayout>

#include <memory>

namespace marbler::ui {

namespace {

/// How a recovered design is named to the user: its file's name, else its own.
QString recoveryName(const RecoveredDesign& r) {
    return r.originalFile.isEmpty() ? lineageOf(r.design).displayName()
                                    : QFileInfo(r.originalFile).fileName();
}

} // namespace

EditorWindow* WorkbenchWindow::openEditor(const Genome& design, const QString& file) {
    // A file is edited in one window at a time: two would overwrite each other's saves.
    if (EditorWindow* open = EditorWindow::editorFor(file)) {
        open->showNormal();
        open->raise();
        open->activateWindow();
        statusBar()->showMessage(tr("“%1” is open in an editor already").arg(QFileInfo(file).fileName()),
                                 5000);
        return open;
    }
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
    connect(editor, &EditorWindow::recoveriesRequested, this, [this] { showRecoveries(); });
    editor->show();
    emit editorOpened(editor);
    return editor;
}

EditorWindow* WorkbenchWindow::recover(const RecoveredDesign& r) {
    // The design as it was being edited, muted steps and all, still unsaved.
    EditorWindow* editor = openEditor(r.design, r.originalFile);
    editor->document()->markModified();
    // Its own autosave now, before the old one goes: a second crash loses nothing.
    if (editor->autosave()) editor->autosave()->flush();
    discardRecovery(r.recoveryFile);
    statusBar()->showMessage(tr("Recovered “%1”").arg(recoveryName(r)), 5000);
    return editor;
}

std::vector<EditorWindow*> WorkbenchWindow::offerRecoveries(const QString& folder,
                                                            std::function<bool(const QString& name)> accept) {
    std::vector<EditorWindow*> opened;
    if (folder.isEmpty()) return opened;
    purgeOldRecoveries(folder);
    for (const RecoveredDesign& r : pendingRecoveries(folder)) {
        if (r.declined) continue; // asked once; File ▸ Recover unsaved designs… keeps it
        const QString name = recoveryName(r);
        bool yes;
        if (accept) {
            yes = accept(name);
        } else {
            yes =
                QMessageBox::question(
                    this, tr("Recover a design"),
                    tr("Marbler stopped before the changes to “%1” were saved (autosaved %2). Open them in "
                       "the "
                       "editor?\n\nIf not, they are kept for %3 days under File ▸ Recover unsaved designs….")
                        .arg(name, QLocale().toString(r.saved, QLocale::ShortFormat))
                        .arg(RecoveryKeepDays),
                    QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes) == QMessageBox::Yes;
        }
        if (yes)
            opened.push_back(recover(r));
        else
            declineRecovery(r.recoveryFile);
    }
    return opened;
}

QDialog* WorkbenchWindow::showRecoveries(const QString& folderGiven) {
    const QString folder = folderGiven.isEmpty() ? defaultRecoveryFolder() : folderGiven;
    auto* dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("recoveriesDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Recover unsaved designs"));
    auto* layout = new QVBoxLayout(dialog);
    auto* intro =
        new QLabel(tr("Designs that editors left unsaved when Marbler stopped. Each is kept for %1 days "
                      "after its last autosave, until you open or discard it.")
                       .arg(RecoveryKeepDays),
                   dialog);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    auto* list = new QListWidget(dialog);
    list->setObjectName(QStringLiteral("recoveryList"));
    layout->addWidget(list, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QPushButton* open = buttons->addButton(tr("Open in editor"), QDialogButtonBox::AcceptRole);
    open->setObjectName(QStringLiteral("recoverOpen"));
    QPushButton* discard = buttons->addButton(tr("Discard…"), QDialogButtonBox::DestructiveRole);
    discard->setObjectName(QStringLiteral("recoverDiscard"));
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);

    auto designs = std::make_shared<std::vector<RecoveredDesign>>();
    const auto fill = [list, designs, folder, open, discard] {
        *designs = pendingRecoveries(folder);
        list->clear();
        for (const RecoveredDesign& r : *designs)
            list->addItem(tr("%1 — autosaved %2")
                              .arg(recoveryName(r), QLocale().toString(r.saved, QLocale::ShortFormat)));
        if (designs->empty()) list->addItem(tr("Nothing to recover"));
        list->setCurrentRow(0);
        open->setEnabled(!designs->empty());
        discard->setEnabled(!designs->empty());
    };
    fill();
    const auto chosen = [list, designs]() -> const RecoveredDesign* {
        const int row = list->currentRow();
        return row >= 0 && row < int(designs->size()) ? &(*designs)[std::size_t(row)] : nullptr;
    };
    connect(open, &QPushButton::clicked, dialog, [this, chosen, fill] {
        if (const RecoveredDesign* r = chosen()) {
            recover(*r);
            fill();
        }
    });
    connect(discard, &QPushButton::clicked, dialog, [dialog, chosen, fill] {
        const RecoveredDesign* r = chosen();
        if (!r) return;
        if (dialog->property("discardWithoutAsking").toBool() ||
            QMessageBox::question(dialog, tr("Discard a design"),
                                  tr("Discard the unsaved changes to “%1” for good?").arg(recoveryName(*r)),
                                  QMessageBox::Discard | QMessageBox::Cancel,
                                  QMessageBox::Cancel) == QMessageBox::Discard)
            discardRecovery(r->recoveryFile);
        fill();
    });
    dialog->resize(520, 320);
    dialog->show();
    return dialog;
}

} // namespace marbler::ui
