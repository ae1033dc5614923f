// The editor's panels, issue 27: the timeline's play speed and compare captions, Export
// animation's labels and duration, deleting an ink and palette presets (PaletteEditor.h with
// EditorDocument::removePaletteColor).

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/AnimationExport.h"
#include "editor/EditorDocument.h"
#include "editor/PaletteEditor.h"
#include "editor/Timeline.h"
#include "marbler/Params.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace panels_extras_test {

Genome threeInks() {
    Genome g;
    g.palette = {{200, 30, 30}, {30, 30, 200}, {210, 40, 40}};
    for (int c : {0, 1, 0}) {
        Operation drop = defaultOperation(Tool::Drop, 2, {300.0 + 100 * c, 300, 0});
        drop.color = c;
        g.initial.push_back(drop);
    }
    g.operations.push_back(defaultOperation(Tool::Comb, 2, {500, 500, 0}));
    return g;
}

TEST(TimelineSpeedTest, TheSpeedBoxSetsHowLongPlayTakes) {
    Timeline timeline;
    timeline.show();
    timeline.setStepCount(2000);
    auto* speed = timeline.findChild<QComboBox*>(QStringLiteral("playSpeed"));
    ASSERT_NE(speed, nullptr);
    EXPECT_FALSE(speed->toolTip().isEmpty());
    EXPECT_EQ(speed->currentText(), QStringLiteral("1×"));
    EXPECT_DOUBLE_EQ(timeline.playSeconds(), 12.0) << "2,000 steps play in 12 s at 1×, never 0.6 s each";
    timeline.setPlaySpeed(16.0);
    EXPECT_EQ(speed->currentText(), QStringLiteral("16×"));
    EXPECT_DOUBLE_EQ(timeline.playSeconds(), 0.75);

    // Play from the start: the label reaches the end in well under the 1× time.
    timeline.setGrowth(0.0);
    QElapsedTimer clock;
    clock.start();
    timeline.play();
    EXPECT_TRUE(timeline.playing());
    MARBLER_WAIT(!timeline.playing(), 10000);
    EXPECT_LT(clock.elapsed(), 6000);
    auto* label = timeline.findChild<QLabel*>(QStringLiteral("timelineLabel"));
    ASSERT_NE(label, nullptr);
    EXPECT_EQ(label->text(), QStringLiteral("2000 / 2000"));

    // Slower: [ steps the speed down, a quarter at the slowest.
    for (int i = 0; i < 10; ++i)
        speed->setCurrentIndex(std::max(0, speed->currentIndex() - 1));
    EXPECT_EQ(speed->currentText(), QStringLiteral("0.25×"));
    EXPECT_DOUBLE_EQ(timeline.playSeconds(), 48.0);
}

TEST(TimelineSpeedTest, SpeedKeysStepTheBox) {
    Timeline timeline;
    timeline.show();
    ASSERT_TRUE(test::activate(&timeline));
    auto* speed = timeline.findChild<QComboBox*>(QStringLiteral("playSpeed"));
    ASSERT_NE(speed, nullptr);
    QTest::keyClick(&timeline, Qt::Key_BracketRight);
    EXPECT_EQ(speed->currentText(), QStringLiteral("2×"));
    QTest::keyClick(&timeline, Qt::Key_BracketLeft);
    QTest::keyClick(&timeline, Qt::Key_BracketLeft);
    EXPECT_EQ(speed->currentText(), QStringLiteral("0.5×"));
}

TEST(TimelineCaptionTest, ComparePanesSayWhichStateTheyShow) {
    Timeline timeline;
    timeline.setStepCount(40);
    QSignalSpy captions(&timeline, &Timeline::captionsChanged);
    timeline.setComparing(true);
    ASSERT_FALSE(captions.isEmpty());
    EXPECT_EQ(captions.last().at(0).toString(), QStringLiteral("Now"));
    EXPECT_EQ(captions.last().at(1).toString(), QStringLiteral("Bare bath"));
    timeline.setCompareGrowth(12.0);
    EXPECT_EQ(captions.last().at(1).toString(), QStringLiteral("Step 12 of 40"));
    timeline.setGrowth(7.5);
    EXPECT_EQ(captions.last().at(0).toString(), QStringLiteral("Step 7.5 of 40"));
    timeline.setComparing(false);
    EXPECT_TRUE(captions.last().at(0).toString().isEmpty());
    EXPECT_TRUE(captions.last().at(1).toString().isEmpty());
}

TEST(AnimationExportLabelsTest, NoLabelShowsALiteralAmpersand) {
    AnimationExportDialog dialog(threeInks(), AnimationExportSettings{});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    int labelled = 0;
    for (QLabel* label : dialog.findChildren<QLabel*>()) {
        if (!label->text().contains(QLatin1Char('&'))) continue;
        ++labelled;
        // A mnemonic is drawn as an underline only when the label has a buddy; otherwise the
        // person reads "&Save to:".
        EXPECT_NE(label->buddy(), nullptr) << label->text().toStdString();
    }
    EXPECT_GE(labelled, 5);
}

TEST(AnimationExportLabelsTest, DurationSetsTheFramesAndFollowsThem) {
    AnimationExportSettings start;
    start.frames = 100;
    start.fps = 25;
    AnimationExportDialog dialog(threeInks(), start);
    auto* duration = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("animationDuration"));
    auto* frames = dialog.findChild<QSpinBox*>(QStringLiteral("animationFrames"));
    auto* fps = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("animationFps"));
    ASSERT_NE(duration, nullptr);
    EXPECT_FALSE(duration->toolTip().isEmpty());
    EXPECT_DOUBLE_EQ(duration->value(), 4.0);
    duration->setValue(10.0);
    EXPECT_EQ(frames->value(), 250);
    EXPECT_EQ(dialog.settings().frames, 250);
    fps->setValue(50.0);
    EXPECT_DOUBLE_EQ(duration->value(), 5.0);
    frames->setValue(500);
    EXPECT_DOUBLE_EQ(duration->value(), 10.0);
}

TEST(RemoveInkTest, AnUnusedInkGoesAndItsUndoBringsItBack) {
    Genome g = threeInks();
    g.palette.push_back({1, 2, 3}); // ink 4, laid by no step
    EditorDocument doc(g);
    EXPECT_EQ(doc.inkUseCount(3), 0u);
    ASSERT_TRUE(doc.removePaletteColor(3));
    EXPECT_EQ(doc.design().palette.size(), 3u);
    EXPECT_EQ(doc.undoStack()->undoText().toStdString(), "Delete ink 4: #010203");
    doc.undoStack()->undo();
    EXPECT_EQ(doc.design().palette.size(), 4u);
}

TEST(RemoveInkTest, AUsedInkNeedsAnotherForItsSteps) {
    EditorDocument doc(threeInks());
    EXPECT_EQ(doc.inkUseCount(0), 2u);
    EXPECT_FALSE(doc.removePaletteColor(0)) << "its steps would lay no ink";
    EXPECT_FALSE(doc.removePaletteColor(0, 0));
    EXPECT_FALSE(doc.removePaletteColor(7, 1));
    EXPECT_EQ(doc.design().palette.size(), 3u);
    ASSERT_TRUE(doc.removePaletteColor(0, 2));
    // Ink 3 became ink 2; ink 2 became ink 1; the comb (no ink) is untouched.
    const Genome& d = doc.design();
    ASSERT_EQ(d.palette.size(), 2u);
    EXPECT_EQ(d.palette[1], (Color{210, 40, 40}));
    EXPECT_EQ(d.initial[0].color, 1);
    EXPECT_EQ(d.initial[1].color, 0);
    EXPECT_EQ(d.initial[2].color, 1);
    EXPECT_NO_THROW(validateGenome(doc.fileGenome(), "after"));
    doc.undoStack()->undo();
    EXPECT_EQ(doc.design().palette, threeInks().palette);
    EXPECT_EQ(doc.design().initial[0].color, 0);
    EXPECT_EQ(doc.design().initial[1].color, 1);
}

TEST(RemoveInkTest, ThePaletteAsksBeforeReMappingUsedInks) {
    PaletteEditor palette;
    palette.setDesign(threeInks());
    palette.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&palette));
    QSignalSpy removed(&palette, &PaletteEditor::inkRemoved);
    auto* swatch = palette.findChild<QToolButton*>(QStringLiteral("inkSwatch0"));
    ASSERT_NE(swatch, nullptr);
    QAction* remove = nullptr;
    for (QAction* a : swatch->actions())
        if (a->objectName() == QStringLiteral("deleteInk0")) remove = a;
    ASSERT_NE(remove, nullptr) << "the swatch's menu has Delete ink";
    remove->trigger();
    QMessageBox* question = palette.removeQuestion();
    ASSERT_NE(question, nullptr);
    EXPECT_TRUE(question->isVisible());
    EXPECT_TRUE(question->text().contains(QStringLiteral("2 steps lay ink 1")))
        << question->text().toStdString();
    EXPECT_TRUE(question->text().contains(QStringLiteral("ink 3, the nearest colour")))
        << question->text().toStdString();
    question->button(QMessageBox::Cancel)->click();
    EXPECT_TRUE(removed.isEmpty()) << "cancelled: nothing deleted";

    palette.removeInk(0);
    auto* remap = palette.removeQuestion()->findChild<QAbstractButton*>(QStringLiteral("remapInkButton"));
    ASSERT_NE(remap, nullptr);
    remap->click();
    ASSERT_EQ(removed.size(), 1);
    EXPECT_EQ(removed.front().at(0).toInt(), 0);
    EXPECT_EQ(removed.front().at(1).toInt(), 2);

    // An ink no step lays goes at once, from the − button for the current ink.
    Genome g = threeInks();
    g.palette.push_back({9, 9, 9});
    palette.setDesign(g);
    palette.setCurrentInk(3);
    auto* minus = palette.findChild<QToolButton*>(QStringLiteral("removeInkButton"));
    ASSERT_NE(minus, nullptr);
    EXPECT_FALSE(minus->toolTip().isEmpty());
    minus->click();
    ASSERT_EQ(removed.size(), 2);
    EXPECT_EQ(removed.last().at(0).toInt(), 3);
    EXPECT_EQ(removed.last().at(1).toInt(), -1);

    // The only ink, laid by steps: a clear message, nothing deleted.
    Genome one;
    one.palette = {{1, 1, 1}};
    one.initial.push_back(defaultOperation(Tool::Drop, 2, {10, 10, 0}));
    palette.setDesign(one);
    palette.removeInk(0);
    ASSERT_NE(palette.removeQuestion(), nullptr);
    EXPECT_TRUE(palette.removeQuestion()->text().contains(QStringLiteral("only ink")));
    palette.removeQuestion()->button(QMessageBox::Ok)->click();
    EXPECT_EQ(removed.size(), 2);
}

TEST(PalettePresetTest, PresetsReplaceTheInksAndKeepEveryStepsInk) {
    PaletteEditor palette;
    palette.setDesign(threeInks());
    auto* button = palette.findChild<QToolButton*>(QStringLiteral("palettePresetsButton"));
    ASSERT_NE(button, nullptr);
    ASSERT_NE(button->menu(), nullptr);
    ASSERT_GE(palettePresets().size(), 3u);
    EXPECT_EQ(button->menu()->actions().size(), qsizetype(palettePresets().size()));
    QSignalSpy chosen(&palette, &PaletteEditor::presetChosen);
    button->menu()->actions().at(2)->trigger();
    ASSERT_EQ(chosen.size(), 1);
    EXPECT_EQ(chosen.front().at(0).toInt(), 2);

    Genome g = threeInks();
    g.palette.push_back({1, 2, 3});
    g.palette.push_back({4, 5, 6});
    g.initial[0].color = 4;
    const PalettePreset& preset = palettePresets()[2];
    ASSERT_LT(preset.inks.size(), g.palette.size());
    const Genome applied = withPalettePreset(g, preset);
    EXPECT_EQ(applied.background, preset.background);
    for (std::size_t i = 0; i < preset.inks.size(); ++i)
        EXPECT_EQ(applied.palette[i], preset.inks[i]);
    EXPECT_EQ(applied.palette.size(), g.palette.size()) << "the ink step 1 lays is kept";
    EXPECT_NO_THROW(validateGenome(applied, "preset"));

    // Applied through the document: one undo step.
    EditorDocument doc(threeInks());
    doc.replaceDesign(withPalettePreset(doc.fileGenome(), preset), QStringLiteral("Palette: x"));
    EXPECT_EQ(doc.design().palette[0], preset.inks[0]);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.design().palette, threeInks().palette);
    EXPECT_EQ(doc.design().initial[0].color, 0);
    EXPECT_EQ(doc.design().initial[1].color, 1);
}

} // namespace panels_extras_test
