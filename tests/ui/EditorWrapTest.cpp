// The editor on a design whose bath wraps (docs/genome-format.md, "Wrapping bath"): only the
// tools that can wrap are offered, a stretch drawn by hand runs along an axis with its teeth
// spanning the design, an edit that would not wrap is refused with the reason (the file would not
// load again), and Edit ▸ Bath wraps turns the wrap off and on, one undo step each.

#include "UiTestSupport.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <QAction>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace editor_wrap_test {

Genome wrapped() {
    return parseGenome(R"({
      "format": "marbler-genome", "version": 3, "dimension": 2, "size": [1000, 600],
      "background": "#203040", "palette": ["#203040", "#e0b040", "#b03020"],
      "wrap": true,
      "initial": [
        {"tool": "spray", "center": [100, 100], "radius": 120, "color": 1},
        {"tool": "spray", "center": [700, 400], "radius": 90, "color": 2}
      ],
      "operations": [
        {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [0, 200, 400, 600], "shift": 60, "power": 1}
      ]
    })",
                       "wrapped");
}

class EditorWrapTest : public test::EditorTest {
protected:
    QAction* action(EditorWindow* editor, const char* name) const {
        return editor->findChild<QAction*>(QString::fromLatin1(name));
    }
    static void drag(EditorCanvas* canvas, glm::dvec2 from, glm::dvec2 to) {
        const QPoint a = canvas->toWidget(glm::dvec3(from, 0.0)).toPoint();
        const QPoint b = canvas->toWidget(glm::dvec3(to, 0.0)).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, a);
        for (int i = 1; i <= 4; ++i)
            QTest::mouseMove(canvas, a + (b - a) * i / 4);
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, b);
    }
};

TEST_F(EditorWrapTest, OnlyTheToolsThatWrapAreOffered) {
    EditorWindow* editor = open(wrapped());
    ASSERT_NE(editor, nullptr);
    for (const char* name : {"tool-drop", "tool-line", "tool-comb", "tool-circle"}) {
        QAction* a = action(editor, name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_FALSE(a->isEnabled()) << name << " cannot lie in a bath that wraps";
        EXPECT_TRUE(a->toolTip().contains(QStringLiteral("Bath wraps"))) << a->toolTip().toStdString();
    }
    for (const char* name : {"tool-spray", "tool-stretch"}) {
        QAction* a = action(editor, name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_TRUE(a->isEnabled()) << name;
    }
    // The drop, the editor's first tool, gave way to the spray.
    EXPECT_TRUE(action(editor, "tool-spray")->isChecked());
    QAction* wraps = action(editor, "bathWraps");
    ASSERT_NE(wraps, nullptr);
    EXPECT_TRUE(wraps->isChecked());
}

TEST_F(EditorWrapTest, AStretchDrawnByHandRunsAlongAnAxisAndWraps) {
    EditorWindow* editor = open(wrapped());
    ASSERT_NE(editor, nullptr);
    auto* canvas = editor->findChild<EditorCanvas*>(QStringLiteral("editorCanvas"));
    ASSERT_NE(canvas, nullptr);
    action(editor, "tool-stretch")->trigger();
    const std::size_t before = editor->document()->stepCount();
    // A drag a little off the horizontal: the pass runs along x, its teeth across the height.
    drag(canvas, {300, 300}, {600, 340});
    ASSERT_EQ(editor->document()->stepCount(), before + 1) << "the stretch was added";
    const Operation& made = editor->document()->step(before);
    ASSERT_EQ(made.tool, Tool::Stretch);
    EXPECT_EQ(std::fmod(made.angle, 90.0), 0.0) << made.angle;
    ASSERT_GE(made.teeth.size(), 2u);
    const double period = std::fmod(std::abs(made.angle), 180.0) == 0.0 ? 600.0 : 1000.0;
    EXPECT_DOUBLE_EQ(made.teeth.back() - made.teeth.front(), period);
    // What the editor saves loads again.
    const Genome saved = editor->document()->fileGenome();
    EXPECT_TRUE(saved.wrap);
    EXPECT_NO_THROW(parseGenome(serializeGenome(saved), "saved"));
}

TEST_F(EditorWrapTest, AnEditThatCannotWrapIsRefusedWithTheReason) {
    EditorWindow* editor = open(wrapped());
    ASSERT_NE(editor, nullptr);
    EditorDocument* doc = editor->document();
    const std::string before = serializeGenome(doc->fileGenome());
    QSignalSpy refused(doc, &EditorDocument::editRefused);
    // A drop (pasted or dropped in: its tool is disabled).
    doc->addStep(defaultOperation(Tool::Drop, 2, {500, 300, 0}));
    // The stretch turned off its axis in the form.
    Operation turned = doc->step(2);
    turned.angle = 30;
    doc->setStep(2, turned);
    ASSERT_EQ(refused.count(), 2);
    EXPECT_TRUE(refused.at(0).at(0).toString().contains(QStringLiteral("a drop pushes")))
        << refused.at(0).at(0).toString().toStdString();
    EXPECT_TRUE(refused.at(1).at(0).toString().contains(QStringLiteral("operations[0].angle")))
        << refused.at(1).at(0).toString().toStdString();
    EXPECT_EQ(serializeGenome(doc->fileGenome()), before) << "nothing changed";
    EXPECT_FALSE(doc->isModified());
    EXPECT_TRUE(editor->statusBar()->currentMessage().contains(QStringLiteral("Bath wraps")));
}

TEST_F(EditorWrapTest, BathWrapsTurnsTheWrapOffAndOnAsOneUndoStep) {
    EditorWindow* editor = open(wrapped());
    ASSERT_NE(editor, nullptr);
    EditorDocument* doc = editor->document();
    QAction* wraps = action(editor, "bathWraps");
    ASSERT_NE(wraps, nullptr);
    wraps->trigger();
    EXPECT_FALSE(doc->design().wrap);
    EXPECT_TRUE(action(editor, "tool-drop")->isEnabled()) << "every tool, once the bath does not wrap";
    doc->addStep(defaultOperation(Tool::Drop, 2, {500, 300, 0}));
    EXPECT_EQ(doc->stepCount(), 4u);
    // With a drop in it, the bath cannot wrap again: the action says why.
    EXPECT_FALSE(wraps->isEnabled());
    EXPECT_TRUE(wraps->toolTip().contains(QStringLiteral("drop"))) << wraps->toolTip().toStdString();
    doc->undoStack()->undo(); // the drop
    EXPECT_TRUE(wraps->isEnabled());
    doc->undoStack()->undo(); // the unwrap
    EXPECT_TRUE(doc->design().wrap);
    EXPECT_TRUE(wraps->isChecked());
    EXPECT_FALSE(action(editor, "tool-drop")->isEnabled());
}

} // namespace editor_wrap_test
