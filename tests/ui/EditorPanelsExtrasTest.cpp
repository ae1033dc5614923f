// The editor's panels, issue 27: the timeline's play speed and compare captions, Export
// animation's labels and duration, deleting an ink and palette presets (PaletteEditor.h with
// EditorDocument::removePaletteColor).

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

} // namespace panels_extras_test
