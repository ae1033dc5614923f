// The editor window's parts, each on its own (issue 22, "One home for every concept"): the
// document's numbering of rendered steps and its merging of a drag, the History panel, the
// window's files (a design saved, a design written into an image in the background) and the
// animation export's progress box.

#include "WaitFor.h"
#include "editor/AnimationExport.h"
#include "editor/EditorDocument.h"
#include "editor/EditorFiles.h"
#include "editor/EditorWindow.h"
#include "editor/HistoryDock.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Params.h"
#include "shared/SectionControls.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QListWidget>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

Operation partsDrop(double x, double y, double r, int color) {
    Operation op = defaultOperation(Tool::Drop, 2, {x, y, 0.0});
    op.radius = r;
    op.color = color;
    return op;
}

/// Three drops of three inks.
Genome partsDesign() {
    Genome g = blankDesign(2);
    g.initial = {partsDrop(300, 300, 150, 0), partsDrop(600, 500, 150, 1), partsDrop(500, 700, 120, 2)};
    return g;
}

QString partsLastMessage(const QSignalSpy& spy) {
    return spy.isEmpty() ? QString() : spy.last().at(0).toString();
}

} // namespace

TEST(EditorParts, TheDocumentNumbersRenderedStepsAroundMutedOnesAndKeepsADragOneUndoStep) {
    EditorDocument document(partsDesign());
    document.setMuted(1, true);
    EXPECT_EQ(document.documentIndex(0), std::optional<std::size_t>(0));
    EXPECT_EQ(document.documentIndex(1), std::optional<std::size_t>(2)) << "the muted step is skipped";
    EXPECT_EQ(document.documentIndex(2), std::nullopt);
    EXPECT_EQ(document.renderedIndex(1), std::nullopt) << "a muted step is not drawn";
    EXPECT_EQ(document.renderedIndex(2), std::optional<std::size_t>(1));

    // A colour dragged: every edit from press to release is one undo step.
    const int before = document.undoStack()->count();
    EXPECT_FALSE(document.dragActive());
    document.setPaletteColor(0, Color{10, 20, 30}, document.mergeFor(true));
    EXPECT_TRUE(document.dragActive());
    document.setPaletteColor(0, Color{40, 50, 60}, document.mergeFor(true));
    document.setPaletteColor(0, Color{70, 80, 90}, document.mergeFor(false));
    EXPECT_FALSE(document.dragActive());
    EXPECT_EQ(document.undoStack()->count(), before + 1);
    EXPECT_EQ(document.renderedDesign().palette[0], (Color{70, 80, 90}));
    // The next edit is a step of its own.
    document.setPaletteColor(0, Color{1, 2, 3}, document.mergeFor(false));
    EXPECT_EQ(document.undoStack()->count(), before + 2);
    document.undoStack()->undo();
    EXPECT_EQ(document.renderedDesign().palette[0], (Color{70, 80, 90}));
}

TEST(EditorParts, TheHistoryPanelListsABranchLeftByAnEditAfterUndoAndSwitchesToItWithAClick) {
    EditorDocument document(partsDesign());
    HistoryDock dock(&document);
    QSignalSpy messages(&dock, &HistoryDock::message);
    dock.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dock));
    QListWidget* branches = dock.branchList();
    EXPECT_EQ(branches->objectName(), QStringLiteral("branchList"));
    EXPECT_FALSE(branches->isVisible()) << "no branches yet";

    document.addStep(partsDrop(200, 800, 90, 0));
    document.undoStack()->undo();
    document.addStep(partsDrop(800, 200, 90, 1)); // leaves the undone drop as a branch
    ASSERT_EQ(branches->count(), 1);
    EXPECT_TRUE(branches->isVisible());
    EXPECT_TRUE(branches->item(0)->text().startsWith(QStringLiteral("After the opened design")))
        << branches->item(0)->text().toStdString();
    EXPECT_EQ(document.step(3).center.x, 800.0);

    QListWidgetItem* item = branches->item(0);
    QTest::mouseClick(branches->viewport(), Qt::LeftButton, {}, branches->visualItemRect(item).center());
    EXPECT_EQ(document.step(3).center.x, 200.0) << "the branch's drop is back";
    EXPECT_EQ(partsLastMessage(messages), QStringLiteral("Switched to another branch of the history"));
    ASSERT_EQ(branches->count(), 1) << "the line left is a branch now";
}

TEST(EditorParts, TheFilesSaveTheDesignAndWriteItIntoAnImageInTheBackground) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QWidget window;
    window.resize(300, 200);
    window.show();
    EditorDocument document(partsDesign(), &window);
    EditorFiles files(&document, &window, [] { return Slice{2, 0.0}; });
    QSignalSpy messages(&files, &EditorFiles::message);
    QSignalSpy saved(&files, &EditorFiles::fileSaved);

    const QString json = dir.filePath(QStringLiteral("drops.marble.json"));
    ASSERT_TRUE(files.saveTo(json));
    EXPECT_EQ(serializeGenome(loadGenome(json.toStdString())), serializeGenome(document.fileGenome()));
    EXPECT_EQ(partsLastMessage(messages), QStringLiteral("Saved %1").arg(QDir::toNativeSeparators(json)));
    EXPECT_EQ(files.displayName(), QStringLiteral("drops.marble.json"));

    // The design into an image at the image's size, with the design inside; one at a time.
    const QString png = dir.filePath(QStringLiteral("drops.png"));
    RenderSettings small;
    small.width = 40;
    small.height = 30;
    renderToFile(blankDesign(2), small, png.toStdString());
    document.setMuted(0, true);
    ASSERT_TRUE(files.writeDesignImage(png));
    EXPECT_NE(window.findChild<QProgressDialog*>(QStringLiteral("imageProgress")), nullptr);
    EXPECT_FALSE(files.writeDesignImage(png));
    EXPECT_EQ(partsLastMessage(messages), QStringLiteral("The image is being written already"));
    MARBLER_WAIT(saved.count() == 2, 30000);
    EXPECT_EQ(saved.last().at(0).toString(), png);
    EXPECT_EQ(document.fileName(), png);
    EXPECT_FALSE(document.isModified());
    EXPECT_EQ(QImage(png).size(), QSize(40, 30));
    EXPECT_EQ(serializeGenome(loadDesign(png.toStdString())), serializeGenome(document.fileGenome()));
    EXPECT_EQ(window.findChild<QProgressDialog*>(QStringLiteral("imageProgress")), nullptr)
        << "the progress box is gone";
    EXPECT_EQ(partsLastMessage(messages),
              QStringLiteral("Wrote %1 with the design inside").arg(QDir::toNativeSeparators(png)));
}

TEST(EditorParts, AnAnimationShowsItsProgressBoxOverTheWindowAndItsCancelWritesNothing) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QWidget window;
    window.resize(300, 200);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    AnimationExportJob job(&window);
    QSignalSpy finished(&job, &AnimationExportJob::finished);
    AnimationExportSettings settings;
    settings.format = AnimationFormat::Gif;
    settings.path = dir.filePath(QStringLiteral("long.gif"));
    settings.width = settings.height = 400;
    settings.frames = 2000;
    ASSERT_TRUE(job.start(partsDesign(), settings));
    auto* box = window.findChild<QProgressDialog*>(QStringLiteral("animationProgress"));
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->labelText(), QStringLiteral("Writing the making of the design…"));
    MARBLER_WAIT(box->isVisible(), 10000);
    auto* cancel = box->findChild<QPushButton*>();
    ASSERT_NE(cancel, nullptr);
    QTest::mouseClick(cancel, Qt::LeftButton);
    MARBLER_WAIT(finished.count() == 1, 30000);
    EXPECT_FALSE(finished.last().at(0).toBool());
    EXPECT_TRUE(finished.last().at(1).toString().isEmpty()) << "a cancel is no error";
    EXPECT_FALSE(job.running());
    EXPECT_EQ(window.findChild<QProgressDialog*>(QStringLiteral("animationProgress")), nullptr);
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden).isEmpty());
}

TEST(EditorParts, TheSectionControlsSayWhereTheSectionIsAndWhatTheUserChose) {
    SectionControls controls([] { return glm::dvec3(1000.0, 800.0, 600.0); }, Slice{2, 300.0});
    QSignalSpy chosen(&controls, &SectionControls::sliceChosen);
    controls.showSlice(Slice{1, 200.0});
    auto* axis = controls.findChild<QComboBox*>(QStringLiteral("sliceAxis"));
    auto* position = controls.findChild<QSlider*>(QStringLiteral("slicePosition"));
    auto* value = controls.findChild<QDoubleSpinBox*>(QStringLiteral("sliceValue"));
    ASSERT_TRUE(axis && position && value);
    EXPECT_EQ(axis->currentText(), QStringLiteral("y"));
    EXPECT_EQ(value->text(), QStringLiteral("y = 200.0"));
    EXPECT_EQ(position->value(), 250) << "200 of 800";
    EXPECT_TRUE(chosen.isEmpty()) << "showing a section is no choice";

    position->setValue(500);
    ASSERT_EQ(chosen.count(), 1);
    const auto slice = chosen.last().at(0).value<Slice>();
    EXPECT_EQ(slice.axis, 1);
    EXPECT_DOUBLE_EQ(slice.value, 400.0);
    value->setValue(900.0); // past the block: held to its side
    EXPECT_DOUBLE_EQ(chosen.last().at(0).value<Slice>().value, 800.0);
}
