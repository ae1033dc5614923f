// The editor never loses a user's work (issue "The editor, tried by a newcomer"): a design opened
// from an image is never saved as JSON under the image's name; a file is edited in one window and
// a file changed on disk is never overwritten without a question; a declined recovery is kept; no
// state of the history is unreachable (branches); exports ask before replacing a file and
// designs get their extension. And new steps land where the user works: after the selected
// step, at the timeline's point, shown at once.

#include "TestUtil.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "editor/Recovery.h"
#include "editor/Timeline.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "marbler/RenderToFile.h"
#include "shared/SavedFiles.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

std::string text(const Genome& g) {
    return serializeGenome(g);
}

QByteArray bytesOf(const QString& file) {
    QFile f(file);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

Operation dropAt(double x, double y, double r, int color) {
    Operation op = defaultOperation(Tool::Drop, 2, {x, y, 0.0});
    op.radius = r;
    op.color = color;
    return op;
}

/// Two drops and a comb through them.
Genome combed() {
    Genome g = blankDesign(2);
    g.initial = {dropAt(500, 500, 200, 0), dropAt(500, 500, 120, 1)};
    Operation comb = defaultOperation(Tool::Comb, 2, {0.0, 0.0, 0.0});
    comb.angle = 90;
    comb.spacing = 80;
    g.operations = {comb};
    validateGenome(g, "combed");
    return g;
}

class EditorWorkTest : public test::EditorTest {
protected:
    void TearDown() override {
        setSaveFileAsker({});
        test::EditorTest::TearDown();
    }
    static void click(EditorCanvas* canvas, glm::dvec2 at) {
        const QPoint p = canvas->toWidget(glm::dvec3(at, canvas->slice().value)).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, p);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, p);
    }
    QTemporaryDir mDir;
};

/// Answers the next modal box (a QMessageBox or dialog) by running `answer` on it once it shows.
void answerNextModal(std::function<void(QWidget*)> answer) {
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, [timer, answer] {
        if (QWidget* modal = QApplication::activeModalWidget()) {
            timer->stop();
            timer->deleteLater();
            answer(modal);
        }
    });
    timer->start();
}

// 1. Ctrl+S on a design opened from an image.
TEST_F(EditorWorkTest, SavingADesignOpenedFromAnImageNeverWritesJsonIntoTheImage) {
    const Genome design = combed();
    const QString png = mDir.filePath(QStringLiteral("export.png"));
    RenderSettings settings;
    settings.width = 48;
    settings.height = 48;
    renderToFile(design, settings, png.toStdString());
    const QByteArray original = bytesOf(png);
    ASSERT_FALSE(original.isEmpty());

    EditorWindow* editor = open(loadDesign(png.toStdString()), png);
    editor->document()->setMuted(2, true);
    QString offered;
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return suggested;
    });
    editor->setImageSaveAnswer(EditorWindow::ImageSaveAnswer::DesignFile);
    ASSERT_TRUE(test::activate(editor));
    QTest::keyClick(editor, Qt::Key_S, Qt::ControlModifier);
    EXPECT_EQ(bytesOf(png), original) << "the image is untouched";
    const QString json = mDir.filePath(QStringLiteral("export.marble.json"));
    EXPECT_EQ(offered.toStdString(), json.toStdString()) << "a design file beside the image is offered";
    ASSERT_TRUE(QFileInfo::exists(json));
    EXPECT_EQ(editor->document()->fileName(), json);
    EXPECT_FALSE(editor->document()->isModified());
    EXPECT_EQ(text(loadDesign(json.toStdString())), text(editor->document()->fileGenome()));

    // Or the image written again at its size, with the design (muted step too) inside.
    EditorWindow* second = open(loadDesign(png.toStdString()), png);
    second->document()->setMuted(0, true);
    second->setImageSaveAnswer(EditorWindow::ImageSaveAnswer::UpdateImage);
    ASSERT_TRUE(second->save());
    MARBLER_WAIT(!second->document()->isModified(), 20000);
    const QByteArray written = bytesOf(png);
    EXPECT_NE(written, original);
    EXPECT_EQ(imageKindOf(std::span(reinterpret_cast<const unsigned char*>(written.constData()), 16)),
              ImageKind::Png);
    EXPECT_EQ(QImage(png).size(), QSize(48, 48));
    EXPECT_EQ(text(loadDesign(png.toStdString())), text(second->document()->fileGenome()));
    EXPECT_EQ(second->document()->fileName(), png);

    // Cancel writes nothing.
    second->document()->setMuted(1, true);
    second->setImageSaveAnswer(EditorWindow::ImageSaveAnswer::Cancel);
    EXPECT_FALSE(second->save());
    EXPECT_EQ(bytesOf(png), written);
}

// 2. The same file in two editors, and a file changed on disk.
TEST_F(EditorWorkTest, AFileIsEditedInOneWindowAndAChangeOnDiskIsNeverOverwrittenSilently) {
    const QString file = mDir.filePath(QStringLiteral("shared.marble.json"));
    saveGenome(combed(), file.toStdString());
    EditorWindow* a = mWindow->openEditor(loadDesign(file.toStdString()), file);
    a->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    EditorWindow* again =
        mWindow->openEditor(loadDesign(file.toStdString()), mDir.path() + "/./shared.marble.json");
    EXPECT_EQ(again, a) << "the window already open on the file comes forward";

    // Another program writes the file; then this editor saves.
    Genome theirs = combed();
    theirs.operations.clear();
    saveGenome(theirs, file.toStdString());
    const QByteArray theirBytes = bytesOf(file);
    a->document()->setMuted(0, true);
    ASSERT_TRUE(a->document()->fileChangedOnDisk());
    a->setDiskChangeAnswer(EditorWindow::DiskChangeAnswer::Cancel);
    EXPECT_FALSE(a->save());
    EXPECT_EQ(bytesOf(file), theirBytes) << "cancelled: their file stays";

    // Reload: their design, clean; Undo brings this editor's changes back.
    a->setDiskChangeAnswer(EditorWindow::DiskChangeAnswer::Reload);
    const Genome mine = a->document()->fileGenome();
    EXPECT_FALSE(a->save());
    EXPECT_EQ(text(a->document()->fileGenome()), text(loadGenome(file.toStdString())));
    EXPECT_FALSE(a->document()->isModified());
    a->document()->undoStack()->undo();
    EXPECT_EQ(text(a->document()->fileGenome()), text(mine));

    // Save as: elsewhere, their file untouched.
    saveGenome(combed(), file.toStdString());
    const QByteArray changedAgain = bytesOf(file);
    const QString other = mDir.filePath(QStringLiteral("mine.marble.json"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return other; });
    a->setDiskChangeAnswer(EditorWindow::DiskChangeAnswer::SaveAs);
    EXPECT_TRUE(a->save());
    EXPECT_EQ(bytesOf(file), changedAgain);
    // The file name typed names the design (issue 29); the rest is the user's design.
    Genome mineNamed = mine;
    mineNamed.meta.name = "mine";
    EXPECT_EQ(text(loadGenome(other.toStdString())), text(mineNamed));

    // Overwrite, when the user says so; a save of an unchanged file asks nothing.
    a->setDiskChangeAnswer(std::nullopt);
    a->document()->setMuted(1, true);
    EXPECT_TRUE(a->save()) << "its own file, unchanged since it wrote it: no question";
    saveGenome(theirs, other.toStdString());
    a->document()->setMuted(1, false);
    a->setDiskChangeAnswer(EditorWindow::DiskChangeAnswer::Overwrite);
    EXPECT_TRUE(a->save());
    EXPECT_EQ(text(loadGenome(other.toStdString())), text(a->document()->fileGenome()));
}

// 3. "No" at the crash-recovery question keeps the design.
TEST_F(EditorWorkTest, ADeclinedRecoveryIsKeptUntilDiscardedOrOld) {
    Genome edited;
    {
        EditorWindow* editor = open(randomGenome(7, 2));
        editor->document()->removeStep(0);
        edited = editor->document()->fileGenome();
        editor->autosave()->flush();
        delete editor; // a crash: the autosave stays
    }
    int asked = 0;
    EXPECT_TRUE(
        mWindow->offerRecoveries(mRecovery.path(), [&](const QString&) { return ++asked, false; }).empty());
    EXPECT_EQ(asked, 1);
    auto kept = pendingRecoveries(mRecovery.path());
    ASSERT_EQ(kept.size(), 1u) << "No keeps it";
    EXPECT_TRUE(kept[0].declined);
    EXPECT_TRUE(
        mWindow->offerRecoveries(mRecovery.path(), [&](const QString&) { return ++asked, true; }).empty());
    EXPECT_EQ(asked, 1) << "declined once, not asked at every start";

    // File ▸ Recover unsaved designs… lists it and opens it as it was.
    QDialog* dialog = mWindow->showRecoveries(mRecovery.path());
    auto* list = dialog->findChild<QListWidget*>(QStringLiteral("recoveryList"));
    ASSERT_NE(list, nullptr);
    ASSERT_EQ(list->count(), 1);
    EditorWindow* opened = nullptr;
    const auto connection =
        QObject::connect(mWindow.get(), &WorkbenchWindow::editorOpened, [&](EditorWindow* e) { opened = e; });
    dialog->findChild<QPushButton*>(QStringLiteral("recoverOpen"))->click();
    QObject::disconnect(connection);
    ASSERT_NE(opened, nullptr);
    opened->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    EXPECT_EQ(text(opened->document()->fileGenome()), text(edited));
    EXPECT_TRUE(opened->document()->isModified());
    EXPECT_TRUE(pendingRecoveries(mRecovery.path()).empty());
    dialog->close();

    // Discarded explicitly, or old: gone.
    {
        EditorWindow* editor = open(randomGenome(8, 2));
        editor->document()->removeStep(0);
        editor->autosave()->flush();
        delete editor;
    }
    mWindow->offerRecoveries(mRecovery.path(), [](const QString&) { return false; });
    ASSERT_EQ(pendingRecoveries(mRecovery.path()).size(), 1u);
    EXPECT_EQ(purgeOldRecoveries(mRecovery.path()), 0) << "not old yet";
    dialog = mWindow->showRecoveries(mRecovery.path());
    dialog->setProperty("discardWithoutAsking", true);
    dialog->findChild<QPushButton*>(QStringLiteral("recoverDiscard"))->click();
    EXPECT_TRUE(pendingRecoveries(mRecovery.path()).empty());
    dialog->close();
    {
        EditorWindow* editor = open(randomGenome(9, 2));
        editor->document()->removeStep(0);
        editor->autosave()->flush();
        delete editor;
    }
    EXPECT_EQ(purgeOldRecoveries(mRecovery.path(), RecoveryKeepDays,
                                 QDateTime::currentDateTimeUtc().addDays(RecoveryKeepDays + 1)),
              1);
    EXPECT_TRUE(pendingRecoveries(mRecovery.path()).empty());
}

// 4. Undo, then a new edit: the undone edits stay reachable as a branch.
TEST_F(EditorWorkTest, AnEditAfterUndoKeepsTheUndoneEditsAsABranchOneClickAway) {
    EditorWindow* editor = open(blankDesign(2));
    EditorDocument* doc = editor->document();
    QTemporaryDir dir;
    doc->addStep(dropAt(300, 300, 100, 0));
    ASSERT_TRUE(doc->saveAs(dir.filePath(QStringLiteral("b.marble.json")), nullptr));
    doc->addStep(dropAt(500, 500, 100, 1));
    doc->addStep(dropAt(700, 700, 100, 2));
    const std::string heart = text(doc->design());
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->branches().empty()) << "undo alone makes no branch";
    doc->addStep(dropAt(100, 900, 60, 2));
    const std::string other = text(doc->design());
    ASSERT_EQ(doc->branches().size(), 1u);
    EXPECT_EQ(doc->branches()[0].forkAt, 1);
    EXPECT_EQ(doc->branches()[0].length, 2);
    EXPECT_EQ(doc->undoStack()->count(), 2) << "the current line";

    // The History panel lists it; one click switches.
    QListWidget* branches = editor->branchList();
    ASSERT_EQ(branches->count(), 1);
    EXPECT_TRUE(branches->isVisible());
    EXPECT_TRUE(branches->item(0)->text().contains(QStringLiteral("Add drop 3")))
        << branches->item(0)->text().toStdString();
    QTest::mouseClick(branches->viewport(), Qt::LeftButton, {},
                      branches->visualItemRect(branches->item(0)).center());
    EXPECT_EQ(text(doc->design()), heart);
    EXPECT_EQ(text(editor->canvas()->design()), heart) << "the canvas shows it";
    EXPECT_EQ(doc->undoStack()->count(), 3);
    EXPECT_TRUE(doc->isModified());
    ASSERT_EQ(branches->count(), 1) << "the line left is a branch now";
    doc->undoStack()->setIndex(1);
    EXPECT_FALSE(doc->isModified()) << "the saved state is known on the new line";
    doc->undoStack()->setIndex(3);

    // And back: every state stays reachable, however often one switches.
    doc->switchToBranch(0);
    EXPECT_EQ(text(doc->design()), other);
    ASSERT_EQ(doc->branches().size(), 1u);
    doc->switchToBranch(0);
    EXPECT_EQ(text(doc->design()), heart);
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    doc->undoStack()->undo();
    doc->addStep(dropAt(900, 100, 50, 0));
    EXPECT_EQ(doc->branches().size(), 2u);
}

// 5. Export animation asks before replacing a file; a design gets its extension.
TEST_F(EditorWorkTest, ExportsAskBeforeReplacingAndDesignsGetTheirExtension) {
    EditorWindow* editor = open(combed());
    const QString plain = mDir.filePath(QStringLiteral("noext"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return plain; });
    ASSERT_TRUE(editor->saveAs());
    EXPECT_FALSE(QFileInfo::exists(plain));
    EXPECT_TRUE(QFileInfo::exists(plain + QStringLiteral(".marble.json")));
    EXPECT_EQ(editor->document()->fileName(), plain + QStringLiteral(".marble.json"));
    // Typed again, over a file of the full name: asked.
    editor->setOverwriteAnswer(false);
    editor->document()->setMuted(0, true);
    EXPECT_FALSE(editor->saveAs());
    EXPECT_TRUE(editor->document()->isModified());

    const QString gif = mDir.filePath(QStringLiteral("making.gif"));
    QFile f(gif);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("kept");
    f.close();
    QSettings().setValue(QStringLiteral("files/exportDir"), mDir.path());
    answerNextModal([&](QWidget* dialog) {
        // The export dialog: the file to write is the existing GIF.
        if (auto* path = dialog->findChild<QLineEdit*>(QStringLiteral("animationPath"))) path->setText(gif);
        static_cast<QDialog*>(dialog)->accept();
    });
    editor->exportAnimation();
    QTest::qWait(300);
    EXPECT_EQ(bytesOf(gif), QByteArray("kept")) << "not replaced without a yes";
}

// 6 and 8. A new step goes where the user works, and is seen at once.
TEST_F(EditorWorkTest, NewInkLandsAfterTheSelectedStepOrAtTheTimelinesPointAndIsShown) {
    EditorWindow* editor = open(combed());
    EditorDocument* doc = editor->document();
    EditorCanvas* canvas = editor->canvas();
    MARBLER_WAIT(canvas->view().scale() > 0.0, 30000);
    editor->setTool(Tool::Drop);

    // The last step (the comb) selected: the drop goes on top of it, at the click.
    editor->selectStep(2);
    click(canvas, {200.0, 800.0});
    ASSERT_EQ(doc->stepCount(), 4u);
    EXPECT_EQ(doc->step(3).tool, Tool::Drop) << "after the comb, not combed by it";
    EXPECT_NEAR(doc->step(3).center.x, 200.0, 3.0 / canvas->view().scale());
    EXPECT_TRUE(editor->timeline()->atEnd());
    EXPECT_EQ(editor->selectedStep(), std::optional<std::size_t>(3));

    // Nothing selected, at the end: at the end.
    editor->selectStep(std::nullopt);
    click(canvas, {800.0, 800.0});
    ASSERT_EQ(doc->stepCount(), 5u);
    EXPECT_EQ(doc->step(4).tool, Tool::Drop);
    EXPECT_TRUE(editor->timeline()->atEnd());

    // A step in the middle selected: after it, and the canvas shows the design up to it.
    editor->selectStep(1);
    click(canvas, {500.0, 200.0});
    ASSERT_EQ(doc->stepCount(), 6u);
    EXPECT_EQ(doc->step(2).tool, Tool::Drop);
    EXPECT_TRUE(doc->isInitial(2));
    EXPECT_EQ(doc->step(3).tool, Tool::Comb);
    EXPECT_DOUBLE_EQ(editor->timeline()->growth(), 3.0);
    EXPECT_EQ(text(editor->shownDesign()), text(designAtGrowth(doc->renderedDesign(), 3.0)));

    // Scrubbed back with nothing selected: at the timeline's point, shown there.
    editor->selectStep(std::nullopt);
    editor->timeline()->setGrowth(1.0);
    click(canvas, {900.0, 100.0});
    ASSERT_EQ(doc->stepCount(), 7u);
    EXPECT_EQ(doc->step(1).tool, Tool::Drop);
    EXPECT_NEAR(doc->step(1).center.x, 900.0, 3.0 / canvas->view().scale());
    EXPECT_DOUBLE_EQ(editor->timeline()->growth(), 2.0) << "the new drop is in what the canvas shows";
    const Genome shown = editor->shownDesign();
    ASSERT_EQ(shown.initial.size(), 2u);
    EXPECT_EQ(shown.initial[1], doc->step(1));
}

// 13. Keys the README names and a polished editor has.
TEST_F(EditorWorkTest, SaveAsHelpAndZoomHaveTheirKeys) {
    EditorWindow* editor = open(combed());
    const auto actionFor = [&](const QKeySequence& keys) -> QAction* {
        for (QAction* a : editor->findChildren<QAction*>())
            if (a->shortcuts().contains(keys)) return a;
        return nullptr;
    };
    QAction* saveAs = actionFor(QKeySequence(QStringLiteral("Ctrl+Shift+S")));
    ASSERT_NE(saveAs, nullptr);
    EXPECT_TRUE(saveAs->text().contains(QStringLiteral("as")));
    EXPECT_NE(actionFor(QKeySequence::ZoomIn), nullptr);
    EXPECT_NE(actionFor(QKeySequence::ZoomOut), nullptr);

    ASSERT_TRUE(test::activate(editor));
    const double scale = editor->canvas()->view().scale();
    QTest::keyClick(editor, Qt::Key_Plus, Qt::ControlModifier);
    EXPECT_GT(editor->canvas()->view().scale(), scale);
    QTest::keyClick(editor, Qt::Key_F1);
    auto* guide = editor->findChild<QDialog*>(QStringLiteral("editorGuide"));
    ASSERT_NE(guide, nullptr);
    EXPECT_TRUE(guide->isVisible());
    guide->close();
}

// 14 (the unsaved question). It names the design as the title does: by its file.
TEST_F(EditorWorkTest, TheUnsavedQuestionNamesTheDesignAsTheTitleDoes) {
    const QString file = mDir.filePath(QStringLiteral("hand.marble.json"));
    saveGenome(combed(), file.toStdString());
    EditorWindow* editor = open(loadDesign(file.toStdString()), file);
    editor->setUnsavedAnswer(std::nullopt);
    editor->document()->setMuted(0, true);
    QString asked;
    answerNextModal([&](QWidget* box) {
        asked = static_cast<QMessageBox*>(box)->text();
        static_cast<QMessageBox*>(box)->button(QMessageBox::Cancel)->click();
    });
    EXPECT_FALSE(editor->close());
    EXPECT_TRUE(asked.contains(QStringLiteral("hand.marble.json"))) << asked.toStdString();
    EXPECT_TRUE(editor->windowTitle().contains(QStringLiteral("hand.marble.json")));
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
}

// 12. Undo and Redo work from anywhere in the window, a field with the focus included.
TEST_F(EditorWorkTest, UndoAndRedoWorkWhileAFieldHasTheFocus) {
    EditorWindow* editor = open(combed());
    EditorDocument* doc = editor->document();
    const std::string before = text(doc->design());
    doc->setMuted(0, true);
    const std::string after = text(doc->design());
    ASSERT_TRUE(test::activate(editor));
    const auto fields = editor->findChildren<QAbstractSpinBox*>();
    ASSERT_FALSE(fields.isEmpty());
    for (QAbstractSpinBox* field : fields) {
        if (!field->isVisible()) continue;
        field->setFocus();
        QTest::keyClick(field, Qt::Key_Z, Qt::ControlModifier);
        EXPECT_EQ(text(doc->design()), before) << field->objectName().toStdString();
        QTest::keyClick(field, Qt::Key_Y, Qt::ControlModifier);
        EXPECT_EQ(text(doc->design()), after) << field->objectName().toStdString();
    }
}

// 9 and 10. The editor fits a 1,366 x 768 laptop screen, never moves its canvas by itself, and a
// solid's views come first, its section shown as a number.
TEST_F(EditorWorkTest, TheEditorFitsALaptopScreenAndItsCanvasStaysPut) {
    for (const QString& example : {QStringLiteral("five-stones"), QStringLiteral("slate-block")}) {
        SCOPED_TRACE(example.toStdString());
        const Genome design = test::loadExample((example + QStringLiteral(".marble.json")).toStdString());
        EditorWindow* editor = open(design);
        editor->resize(1366, 768);
        QTest::qWait(50);
        EXPECT_LE(editor->minimumSizeHint().width(), 1366);
        EXPECT_LE(editor->minimumSizeHint().height(), 768);
        EXPECT_EQ(editor->width(), 1366);
        // Every panel lies within the window: the timeline's Export is not cut off.
        for (QPushButton* w : editor->findChildren<QPushButton*>()) {
            if (!w->isVisible() || w->window() != editor) continue;
            const QRect r(w->mapTo(editor, QPoint(0, 0)), w->size());
            EXPECT_LE(r.right(), editor->width()) << w->text().toStdString();
        }
        const QRect canvas = editor->canvas()->geometry();
        const QPoint place = editor->canvas()->mapTo(editor, QPoint(0, 0));
        // Select every step in turn and every tool: the canvas keeps its place and size.
        for (std::size_t i = 0; i < editor->document()->stepCount(); i += 7) {
            editor->selectStep(i);
            QApplication::processEvents();
            ASSERT_EQ(editor->canvas()->geometry(), canvas) << "step " << i;
            ASSERT_EQ(editor->canvas()->mapTo(editor, QPoint(0, 0)), place) << "step " << i;
        }
        for (QAction* tool : editor->findChildren<QAction*>()) {
            if (!tool->objectName().startsWith(QStringLiteral("tool-")) || !tool->isEnabled()) continue;
            tool->trigger();
            QApplication::processEvents();
            ASSERT_EQ(editor->canvas()->geometry(), canvas) << tool->objectName().toStdString();
        }
        if (design.dimension == 3) {
            auto* object = editor->findChild<QWidget*>(QStringLiteral("objectView"));
            ASSERT_NE(object, nullptr);
            // Was 240 and 200 px beside a Steps dock of 770.
            EXPECT_GE(canvas.width(), 360) << "the section comes first";
            EXPECT_GE(canvas.width(), object->width());
            EXPECT_GE(object->width(), 250);
            auto* value = editor->findChild<QDoubleSpinBox*>(QStringLiteral("sliceValue"));
            ASSERT_NE(value, nullptr);
            EXPECT_DOUBLE_EQ(value->value(), design.size.z / 2.0);
            value->setValue(250.0);
            EXPECT_DOUBLE_EQ(editor->slice().value, 250.0) << "the number moves the section";
        } else {
            EXPECT_GE(canvas.width(), 600);
        }
        editor->close();
    }
}

// ---- Issue 22 (docs): the README's editor section names only keys the editor has.
// Each key the README gives for the editor, with the words it is given in: the README must say
// it (so the guide stays current) and an action of the window must have it (so the README is
// true).
TEST_F(EditorWorkTest, EveryKeyTheReadmeGivesTheEditorHasAnAction) {
    QFile readme(QStringLiteral(MARBLER_TEST_DATA "/../../README.md"));
    ASSERT_TRUE(readme.open(QIODevice::ReadOnly | QIODevice::Text));
    const QString all = QString::fromUtf8(readme.readAll());
    const qsizetype start = all.indexOf(QStringLiteral("\n## The editor\n"));
    ASSERT_GE(start, 0) << "the README has a section \"The editor\"";
    const qsizetype end = all.indexOf(QStringLiteral("\n## "), start + 1);
    const QString section = all.mid(start, end < 0 ? -1 : end - start).simplified();

    struct Key {
        const char* words;
        const char* keys;
    };
    const Key keys[] = {
        {"**Pick** (I)", "I"},
        {"**Drop** (D)", "D"},
        {"**Spray** (S)", "S"},
        {"**Line of drops** (L)", "L"},
        {"**Rings** (R)", "R"},
        {"**Scatter** (A,", "A"},
        {"**Line** (N)", "N"},
        {"**Comb** (C)", "C"},
        {"**Wave** (W)", "W"},
        {"**Circle** (O)", "O"},
        {"**Vortex** (V)", "V"},
        {"**Stretch** (T)", "T"},
        {"**Flow** (F)", "F"},
        {"0 fits", "0"},
        {"plainly (Ctrl+Shift+R)", "Ctrl+Shift+R"},
        {"mirror repeat tile (Ctrl+Shift+M)", "Ctrl+Shift+M"},
        {"Ctrl+D duplicates", "Ctrl+D"},
        {"Del deletes", "Del"},
        {"M mutes", "M"},
        {"History (Ctrl+Z, Ctrl+Shift+Z", "Ctrl+Z"},
        {"History (Ctrl+Z, Ctrl+Shift+Z", "Ctrl+Shift+Z"},
        {"growing smoothly (P)", "P"},
        {"([ and ] step it)", "["},
        {"([ and ] step it)", "]"},
        {"Ctrl+K compares two states", "Ctrl+K"},
        {"Export animation (Ctrl+Shift+E)", "Ctrl+Shift+E"},
        {"Save (Ctrl+S)", "Ctrl+S"},
        {"Save As (Ctrl+Shift+S", "Ctrl+Shift+S"},
        {"Send to grid (Ctrl+G)", "Ctrl+G"},
        {"Editor guide (F1)", "F1"},
    };
    EditorWindow* editor = open(combed());
    const auto actions = editor->findChildren<QAction*>();
    for (const Key& key : keys) {
        EXPECT_TRUE(section.contains(QString::fromUtf8(key.words)))
            << "the README's editor section says \"" << key.words << "\"";
        const QKeySequence sequence(QString::fromUtf8(key.keys));
        const bool has = std::any_of(actions.begin(), actions.end(),
                                     [&](QAction* a) { return a->shortcuts().contains(sequence); });
        EXPECT_TRUE(has) << "an action of the editor has the key " << key.keys;
    }
    editor->close();
}

} // namespace
