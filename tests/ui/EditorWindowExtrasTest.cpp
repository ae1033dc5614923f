// The editor window, issue 27: the compare panes' captions, the repeat preview on the canvas,
// New design's bath shapes, and deleting an ink and choosing a preset from the palette.

#include "WaitFor.h"
#include "editor/BathSizes.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "editor/PaletteEditor.h"
#include "editor/Timeline.h"
#include "marbler/Params.h"
#include "shared/RenderService.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace window_extras_test {

Genome design() {
    Genome g;
    g.size = {1000, 600, 1000};
    g.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}};
    // A drop off centre, so the mirror of the design differs from the design.
    Operation drop = defaultOperation(Tool::Drop, 2, {250, 200, 0});
    drop.radius = 150;
    drop.color = 0;
    g.initial.push_back(drop);
    Operation second = defaultOperation(Tool::Drop, 2, {700, 420, 0});
    second.radius = 90;
    second.color = 1;
    g.initial.push_back(second);
    return g;
}

class EditorWindowExtrasTest : public ::testing::Test {
protected:
    void SetUp() override {
        mEditor = std::make_unique<EditorWindow>(design(), &mService, QString(), nullptr, QString());
        mEditor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
        mEditor->setAttribute(Qt::WA_DeleteOnClose, false);
        mEditor->resize(1200, 850);
        mEditor->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mEditor.get()));
        mCanvas = mEditor->findChild<EditorCanvas*>(QStringLiteral("editorCanvas"));
        ASSERT_NE(mCanvas, nullptr);
    }
    void TearDown() override { mEditor.reset(); }
    QAction* action(const QString& name) const { return mEditor->findChild<QAction*>(name); }
    /// The canvas as the person sees it, once its render is the final one.
    QImage seen(EditorCanvas* canvas) const {
        EXPECT_TRUE(QTest::qWaitFor([canvas] { return canvas->imageFinal(); }, 30000)) << "the final render";
        return canvas->grab().toImage();
    }

    RenderService mService{RenderService::Backend::Cpu};
    std::unique_ptr<EditorWindow> mEditor;
    EditorCanvas* mCanvas = nullptr;
};

TEST_F(EditorWindowExtrasTest, ComparePanesSayWhichStateTheyShow) {
    auto* timeline = mEditor->findChild<Timeline*>(QStringLiteral("timeline"));
    auto* compare = mEditor->findChild<EditorCanvas*>(QStringLiteral("compareCanvas"));
    ASSERT_NE(timeline, nullptr);
    ASSERT_NE(compare, nullptr);
    EXPECT_TRUE(mCanvas->caption().isEmpty()) << "one pane needs no caption";
    const QImage plain = seen(mCanvas);
    timeline->setComparing(true);
    timeline->setCompareGrowth(1.0);
    EXPECT_EQ(mCanvas->caption(), QStringLiteral("Now"));
    EXPECT_EQ(compare->caption(), QStringLiteral("Step 1 of 2"));
    // Drawn on the canvas: its top left differs from the same design without it.
    timeline->setGrowth(timeline->stepCount());
    const QImage captioned = seen(mCanvas);
    QTest::qWait(1); // paint
    int differing = 0;
    const QImage a = plain.scaled(captioned.size());
    for (int y = 8; y < 30; ++y)
        for (int x = 8; x < 60; ++x)
            differing += a.pixel(x, y) != captioned.pixel(x, y);
    EXPECT_GT(differing, 50) << "the caption is drawn";
    timeline->setComparing(false);
    EXPECT_TRUE(mCanvas->caption().isEmpty());
    EXPECT_TRUE(compare->caption().isEmpty());
}

TEST_F(EditorWindowExtrasTest, RepeatPreviewTilesTheDesignOnTheCanvas) {
    QAction* plain = action(QStringLiteral("repeatPlain"));
    QAction* mirror = action(QStringLiteral("repeatMirror"));
    QAction* off = action(QStringLiteral("repeatOff"));
    ASSERT_NE(plain, nullptr);
    ASSERT_NE(mirror, nullptr);
    ASSERT_NE(off, nullptr);
    EXPECT_FALSE(mirror->shortcut().isEmpty());
    EXPECT_TRUE(off->isChecked());

    const double ratio = mCanvas->devicePixelRatioF();
    auto colourAt = [&](const QImage& image, glm::dvec3 p) {
        const QPointF w = mCanvas->toWidget(p) * ratio;
        return image.pixelColor(int(w.x()), int(w.y()));
    };
    auto near = [](QColor a, QColor b) {
        return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) <
               30;
    };
    const glm::dvec3 inside{250, 200, 0}; // on the first drop
    const glm::dvec3 right{1000 + 250, 200, 0}, mirroredRight{2000 - 250, 200, 0};
    const glm::dvec3 below{250, 600 + 200, 0}, mirroredBelow{250, 1200 - 200, 0};

    plain->trigger();
    EXPECT_EQ(mCanvas->repeatPreview(), EditorCanvas::RepeatPreview::Plain);
    QImage image = seen(mCanvas);
    const QColor ink = colourAt(image, inside);
    EXPECT_TRUE(near(ink, QColor(200, 30, 30))) << ink.name().toStdString();
    EXPECT_TRUE(near(colourAt(image, right), ink)) << "the tile to the right repeats the design";
    EXPECT_TRUE(near(colourAt(image, below), ink));
    EXPECT_FALSE(near(colourAt(image, mirroredRight), ink));

    mirror->trigger();
    image = seen(mCanvas);
    EXPECT_TRUE(near(colourAt(image, mirroredRight), ink)) << "the tile to the right is the design mirrored";
    EXPECT_TRUE(near(colourAt(image, mirroredBelow), ink));
    EXPECT_FALSE(near(colourAt(image, right), ink));

    off->trigger();
    image = seen(mCanvas);
    EXPECT_TRUE(near(colourAt(image, inside), ink));
    const QPointF outside = mCanvas->toWidget(right);
    if (mCanvas->rect().contains(outside.toPoint())) {
        EXPECT_FALSE(near(colourAt(image, right), ink)) << "no tiles";
    }
}

TEST_F(EditorWindowExtrasTest, NewDesignOffersTheBathsShapes) {
    auto* flat = mEditor->findChild<QMenu*>(QStringLiteral("newFlatSizeMenu"));
    auto* solid = mEditor->findChild<QMenu*>(QStringLiteral("newSolidSizeMenu"));
    ASSERT_NE(flat, nullptr);
    ASSERT_NE(solid, nullptr);
    ASSERT_EQ(flat->actions().size(), qsizetype(bathSizes().size()));
    std::vector<Genome> opened;
    QObject::connect(mEditor.get(), &EditorWindow::openEditorRequested,
                     [&opened](const Genome& g, const QString&) { opened.push_back(g); });
    // A4 portrait: taller than wide, by √2.
    QAction* a4 = nullptr;
    for (QAction* a : flat->actions())
        if (a->text().remove(QLatin1Char('&')) == QStringLiteral("A4 portrait")) a4 = a;
    ASSERT_NE(a4, nullptr);
    EXPECT_FALSE(a4->toolTip().isEmpty());
    a4->trigger();
    ASSERT_EQ(opened.size(), 1);
    const Genome made = opened.front();
    EXPECT_EQ(made.dimension, 2);
    EXPECT_NEAR(made.size.y / made.size.x, std::sqrt(2.0), 0.01);
    EXPECT_NO_THROW(validateGenome(made, "new"));
    solid->actions().at(3)->trigger(); // 16:9
    ASSERT_EQ(opened.size(), 2);
    const Genome block = opened.back();
    EXPECT_EQ(block.dimension, 3);
    EXPECT_NEAR(block.size.x / block.size.y, 16.0 / 9.0, 1e-9);
    EXPECT_DOUBLE_EQ(block.size.z, block.size.y);
}

TEST_F(EditorWindowExtrasTest, DeletingAnInkAndAPresetAreUndoSteps) {
    auto* palette = mEditor->findChild<PaletteEditor*>(QStringLiteral("paletteEditor"));
    ASSERT_NE(palette, nullptr);
    EditorDocument* doc = mEditor->document();
    // Ink 3 is laid by no step: it goes at once.
    palette->removeInk(2);
    ASSERT_EQ(doc->design().palette.size(), 2u);
    EXPECT_EQ(palette->findChild<QToolButton*>(QStringLiteral("inkSwatch2")), nullptr)
        << "its swatch went too";
    doc->undoStack()->undo();
    EXPECT_EQ(doc->design().palette.size(), 3u);

    auto* presets = palette->findChild<QToolButton*>(QStringLiteral("palettePresetsButton"));
    ASSERT_NE(presets, nullptr);
    presets->menu()->actions().at(0)->trigger();
    const PalettePreset& preset = palettePresets()[0];
    EXPECT_EQ(doc->design().palette[0], preset.inks[0]);
    EXPECT_EQ(doc->design().background, preset.background);
    EXPECT_EQ(doc->undoStack()->undoText(), QStringLiteral("Palette: %1").arg(preset.name));
    doc->undoStack()->undo();
    EXPECT_EQ(doc->design().palette, design().palette);
}

} // namespace window_extras_test
