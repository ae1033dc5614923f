// The editor window as a user meets it: opened from the workbench, a gesture on its canvas, undo
// and redo from the keyboard, a past step edited from the form, the timeline's ends, the
// unsaved-changes question, Save, Send to grid, and the recovery of an autosaved design.

#include "editor/EditorWindow.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/ParamForm.h"
#include "editor/Recovery.h"
#include "editor/StepList.h"
#include "editor/Timeline.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "shared/DesignDialog.h"
#include "shared/SavedFiles.h"
#include "workbench/OpenPlacement.h"

#include <QAbstractButton>
#include <QFileInfo>
#include <QListWidget>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QUndoView>

#include <gtest/gtest.h>

#include <algorithm>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// Genomes compared as their file text, so a failure shows what differs.
std::string text(const Genome& g) {
    return serializeGenome(g);
}

class EditorWindowTest : public test::EditorTest {
protected:
    /// A click or drag on the canvas between two design points.
    static void drag(EditorCanvas* canvas, glm::dvec2 from, glm::dvec2 to) {
        const double z = canvas->slice().value;
        const QPoint a = canvas->toWidget(glm::dvec3(from, z)).toPoint();
        const QPoint b = canvas->toWidget(glm::dvec3(to, z)).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, a);
        if (a != b) {
            for (int i = 1; i <= 4; ++i)
                QTest::mouseMove(canvas, a + (b - a) * i / 4);
        }
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, b);
    }
};

TEST_F(EditorWindowTest, OpensFromTheWorkbenchAndTheLargeView) {
    const Genome design = *model().cell(4);
    EditorWindow* editor = mWindow->openEditor(design);
    ASSERT_NE(editor, nullptr);
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    EXPECT_EQ(text(editor->document()->renderedDesign()), text(design));
    EXPECT_FALSE(editor->document()->isModified());
    editor->close();

    DesignDialog* large = mWindow->openDesign(2);
    ASSERT_NE(large, nullptr);
    auto* button = large->findChild<QPushButton*>(QStringLiteral("openInEditor"));
    ASSERT_NE(button, nullptr);
    EXPECT_TRUE(button->isEnabled());
    EditorWindow* opened = nullptr;
    QObject::connect(mWindow.get(), &WorkbenchWindow::editorOpened, [&](EditorWindow* e) { opened = e; });
    button->click();
    ASSERT_NE(opened, nullptr);
    opened->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    EXPECT_EQ(text(opened->document()->renderedDesign()), text(*model().cell(2)));
    opened->close();
    large->close();
}

TEST_F(EditorWindowTest, AClickDropsInkAndUndoRedoAreExact) {
    EditorWindow* editor = open(blankDesign(2));
    const Genome before = editor->document()->design();
    editor->setTool(Tool::Drop);
    EditorCanvas* canvas = editor->canvas();
    MARBLER_WAIT(canvas->view().scale() > 0.0, 30000);
    drag(canvas, {400.0, 600.0}, {400.0, 600.0});
    ASSERT_EQ(editor->document()->stepCount(), 1u);
    const Operation& drop = editor->document()->step(0);
    EXPECT_EQ(drop.tool, Tool::Drop);
    const double pixel = 2.0 / canvas->view().scale(); // a click lands within a pixel or two
    EXPECT_NEAR(drop.center.x, 400.0, pixel);
    EXPECT_NEAR(drop.center.y, 600.0, pixel);
    EXPECT_TRUE(editor->document()->isModified());
    const Genome after = editor->document()->design();

    // The keys as the user presses them: to the focused canvas of the active window.
    ASSERT_TRUE(test::activate(editor));
    canvas->setFocus();
    QTest::keyClick(canvas, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(text(editor->document()->design()), text(before));
    QTest::keyClick(canvas, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(text(editor->document()->design()), text(after));
    EXPECT_GE(editor->historyView()->stack()->count(), 1);
    editor->close();
}

TEST_F(EditorWindowTest, EditingAPastStepFromTheFormGivesTheDesignEditedByHand) {
    Genome design = randomGenome(7, 2);
    ASSERT_GE(design.operations.size(), 2u);
    EditorWindow* editor = open(design);
    const std::size_t past = design.initial.size(); // the first stroke, with later ones after it
    editor->selectStep(past);
    Operation op = editor->document()->step(past);
    const std::string key(toolSpec(op.tool).params(2)[0].key);
    // The form's signal as a finished edit of the first parameter.
    Operation changed = op;
    changed.center += glm::dvec3(10.0, -5.0, 0.0);
    changed.angle += 7.0;
    emit editor->paramForm()->edited(changed, QString::fromStdString(key), false);
    Genome byHand = design;
    byHand.operations[0] = changed;
    EXPECT_EQ(text(editor->document()->renderedDesign()), text(byHand));
    // The canvas shows the design re-formed.
    EXPECT_EQ(text(editor->shownDesign()), text(byHand));
    editor->document()->undoStack()->undo();
    EXPECT_EQ(text(editor->document()->renderedDesign()), text(design));
    editor->close();
}

TEST_F(EditorWindowTest, TheTimelineShowsTheBareBathFirstAndTheWholeDesignLast) {
    const Genome design = randomGenome(11, 2);
    EditorWindow* editor = open(design);
    Timeline* timeline = editor->timeline();
    timeline->setGrowth(0.0);
    const Genome first = editor->shownDesign();
    EXPECT_TRUE(first.initial.empty());
    EXPECT_TRUE(first.operations.empty());
    EXPECT_EQ(first.palette, design.palette);
    timeline->setGrowth(double(stepCount(design)));
    EXPECT_EQ(text(editor->shownDesign()), text(design));
    editor->close();
}

TEST_F(EditorWindowTest, SaveWritesTheDesignAndTheQuestionGuardsUnsavedChanges) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("mine.marble.json"));
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) { return file; });
    EditorWindow* editor = open(blankDesign(2));
    editor->setTool(Tool::Drop);
    MARBLER_WAIT(editor->canvas()->view().scale() > 0.0, 30000);
    drag(editor->canvas(), {500.0, 500.0}, {560.0, 500.0});
    ASSERT_TRUE(editor->document()->isModified());
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Cancel);
    EXPECT_FALSE(editor->close()) << "Cancel keeps the editor open";
    EXPECT_TRUE(editor->isVisible());
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Save);
    QPointer<EditorWindow> guard(editor);
    EXPECT_TRUE(editor->close());
    setSaveFileAsker({});
    const Genome saved = loadDesign(file.toStdString());
    ASSERT_EQ(saved.initial.size(), 1u);
    EXPECT_EQ(saved.initial[0].tool, Tool::Drop);
    EXPECT_TRUE(EditorWindow::recentFiles().contains(QFileInfo(file).absoluteFilePath()));
    EXPECT_TRUE(pendingRecoveries(mRecovery.path()).empty()) << "a normal close leaves nothing to recover";
}

TEST_F(EditorWindowTest, SendToGridPutsTheDesignIntoTheGrid) {
    Genome design = randomGenome(21, 2);
    EditorWindow* editor = mWindow->openEditor(design);
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    const Genome edited = editor->document()->renderedDesign();
    int asked = 0;
    setOpenChooser([&](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> {
        ++asked;
        return OpenChoice::NewGeneration;
    });
    const int generations = int(model().history().size());
    emit editor->sendToGrid(edited);
    setOpenChooser({});
    EXPECT_LE(asked, 1);
    EXPECT_EQ(int(model().history().size()), generations + 1) << "a new generation to breed from";
    bool found = false;
    for (int i = 0; i < CellCount; ++i)
        if (const Genome* g = model().cell(i))
            found = found || (g->operations == edited.operations && g->palette == edited.palette);
    EXPECT_TRUE(found);
    editor->close();
}

TEST_F(EditorWindowTest, ARecoveredAutosaveIsTheDesignThatWasBeingEdited) {
    Genome design = randomGenome(5, 2);
    Genome edited;
    {
        EditorWindow* editor = open(design);
        editor->document()->removeStep(0);
        editor->document()->setBackground(Color{10, 20, 30});
        editor->document()->setMuted(1, true);
        edited = editor->document()->design();
        editor->autosave()->flush();
        // A crash: the window goes without closing, so the autosave stays.
        delete editor;
    }
    ASSERT_EQ(pendingRecoveries(mRecovery.path()).size(), 1u);
    QStringList asked;
    const auto editors = mWindow->offerRecoveries(mRecovery.path(), [&](const QString& name) {
        asked << name;
        return true;
    });
    ASSERT_EQ(editors.size(), 1u);
    EXPECT_EQ(asked.size(), 1);
    EditorWindow* back = editors[0];
    back->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    EXPECT_EQ(text(back->document()->design()), text(edited));
    EXPECT_TRUE(back->document()->isMuted(1));
    EXPECT_TRUE(back->document()->isModified()) << "recovered changes are not saved yet";

    // A second crash before any edit loses nothing either: the recovered design was written
    // again at once, before the old recovery file went.
    const QString second = back->autosave()->file();
    ASSERT_TRUE(QFile::exists(second));
    const QString folder = QFileInfo(second).absolutePath();
    delete back;
    const auto again = pendingRecoveries(folder);
    const auto it = std::find_if(again.begin(), again.end(),
                                 [&](const RecoveredDesign& r) { return r.recoveryFile == second; });
    ASSERT_NE(it, again.end());
    EXPECT_EQ(text(EditorDocument(it->design).design()), text(edited));
    EXPECT_TRUE(discardRecovery(it->recoveryFile));
    EXPECT_TRUE(pendingRecoveries(mRecovery.path()).empty());
}

TEST_F(EditorWindowTest, StepKeysWorkFromTheStepListAndTheCanvas) {
    // Ctrl+D, M and Del are the step list's and the Edit menu's alike: one action each, so that
    // where both apply the key is not ambiguous (Qt would then run neither).
    EditorWindow* editor = open(randomGenome(8, 2));
    EditorDocument* doc = editor->document();
    const std::size_t steps = doc->stepCount();
    ASSERT_GE(steps, 3u);
    ASSERT_TRUE(test::activate(editor));
    editor->selectStep(1);
    QWidget* list = editor->findChild<StepList*>()->list();
    list->setFocus();
    QTest::keyClick(list, Qt::Key_D, Qt::ControlModifier);
    EXPECT_EQ(doc->stepCount(), steps + 1) << "Ctrl+D in the list duplicates";
    editor->selectStep(1);
    QTest::keyClick(list, Qt::Key_M);
    EXPECT_TRUE(doc->isMuted(1)) << "M in the list mutes";
    editor->canvas()->setFocus();
    editor->selectStep(2);
    QTest::keyClick(editor->canvas(), Qt::Key_Delete);
    EXPECT_EQ(doc->stepCount(), steps) << "Del on the canvas deletes";
    QTest::keyClick(editor->canvas(), Qt::Key_D, Qt::ControlModifier);
    EXPECT_EQ(doc->stepCount(), steps) << "nothing selected after a delete: Ctrl+D does nothing";
    editor->selectStep(0);
    QTest::keyClick(editor->canvas(), Qt::Key_D, Qt::ControlModifier);
    EXPECT_EQ(doc->stepCount(), steps + 1) << "Ctrl+D on the canvas duplicates";
    editor->close();
}

TEST_F(EditorWindowTest, APickedInkIsTheInkTheToolsLay) {
    Genome design = blankDesign(2);
    design.palette = {Color{200, 30, 30}, Color{30, 30, 200}};
    EditorWindow* editor = open(design);
    EditorCanvas* canvas = editor->canvas();
    MARBLER_WAIT(canvas->view().scale() > 0.0, 30000);
    // A drop of ink 1, then ink 2 chosen in the palette, then the drop picked: ink 1 again.
    editor->setTool(Tool::Drop);
    drag(canvas, {500.0, 400.0}, {500.0, 400.0});
    ASSERT_EQ(editor->document()->stepCount(), 1u);
    ASSERT_EQ(editor->document()->step(0).color, 0);
    auto* second = editor->findChild<QAbstractButton*>(QStringLiteral("inkSwatch1"));
    ASSERT_NE(second, nullptr);
    second->click();
    EXPECT_EQ(canvas->toolSettings().color, 1);
    editor->setTool(EditorTool::Pick);
    const double inside = 0.5 * editor->document()->step(0).radius; // off the centre's handle
    drag(canvas, {500.0, 400.0 + inside}, {500.0, 400.0 + inside});
    EXPECT_EQ(canvas->toolSettings().color, 0) << "the picked ink is the one the tools lay next; "
                                               << editor->statusBar()->currentMessage().toStdString();
    editor->setTool(Tool::Drop);
    drag(canvas, {200.0, 200.0}, {200.0, 200.0});
    ASSERT_EQ(editor->document()->stepCount(), 2u);
    EXPECT_EQ(editor->document()->step(1).color, 0);
    editor->close();
}

TEST_F(EditorWindowTest, TheSelectedStepStaysInViewAsTheListIsResized) {
    // A long design opened on its last step: the step list shows that row, and still does when
    // the window (so the list's dock) is made smaller.
    Genome design = blankDesign(2);
    for (int i = 0; i < 120; ++i)
        design.initial.push_back(defaultOperation(Tool::Drop, 2, {5.0 * i, 400.0, 0.0}));
    auto* editor = new EditorWindow(design, mService.get(), {}, mWindow.get(), mRecovery.path());
    editor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
    editor->selectStep(119);
    editor->resize(1200, 850);
    editor->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(editor));
    QListWidget* view = editor->findChild<StepList*>()->list();
    ASSERT_EQ(view->currentRow(), 119);
    const auto inView = [view] {
        return view->viewport()->rect().contains(view->visualItemRect(view->item(119)).center());
    };
    MARBLER_WAIT(inView(), 5000);
    // The window made smaller under it (the row was centred in the taller list): still in view.
    editor->resize(1200, 420);
    MARBLER_WAIT(view->viewport()->height() < 200, 5000);
    MARBLER_WAIT(inView(), 5000);
    editor->close();
}

TEST_F(EditorWindowTest, ASolidIsEditedOnItsCrossSectionBesideItsObject) {
    EditorWindow* editor = open(blankDesign(3));
    ASSERT_NE(editor->findChild<QWidget*>(QStringLiteral("objectView")), nullptr);
    editor->setSlice(Slice{2, 300.0});
    editor->setTool(Tool::Drop);
    MARBLER_WAIT(editor->canvas()->view().scale() > 0.0, 30000);
    drag(editor->canvas(), {250.0, 700.0}, {250.0, 700.0});
    ASSERT_EQ(editor->document()->stepCount(), 1u);
    const Operation& drop = editor->document()->step(0);
    EXPECT_NEAR(drop.center.z, 300.0, 1e-9) << "the click fixes a point on the section's plane";
    EXPECT_NEAR(drop.center.x, 250.0, 2.0 / editor->canvas()->view().scale());
    editor->close();
}

} // namespace
