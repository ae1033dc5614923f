// Looking closely: zoom and pan of the large view (re-rendered exactly for the window shown),
// the view angle a solid design carries in meta.view, and solid objects framed to fill their
// cell. Runs in ui_workbench_test, whose main (WorkbenchTest.cpp) sets up the application.

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/HybridMesh.h"
#include "marbler/gl/Meshes.h"
#include "shared/DesignDialog.h"
#include "shared/RenderService.h"
#include "shared/ViewController.h"
#include "workbench/DesignCell.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/WorkbenchWindow.h"

#include <QApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <cmath>

using namespace marbler;
using namespace marbler::ui;

namespace {

void expectSamePoint(QPointF a, QPointF b, double tolerance = 1e-6) {
    EXPECT_NEAR(a.x(), b.x(), tolerance);
    EXPECT_NEAR(a.y(), b.y(), tolerance);
}

double regionWidth(const Region& r) {
    return r.x1 - r.x0;
}

TEST(ViewControllerTest, ZoomKeepsTheAnchoredPointFitShowsAllAndPanMoves) {
    ViewController view;
    view.setDesignSize(1000.0, 600.0);
    view.setViewport(QSize(700, 500));
    EXPECT_TRUE(view.isFitted());
    EXPECT_DOUBLE_EQ(view.scale(), 0.7); // the width limits
    expectSamePoint(view.centre(), QPointF(500.0, 300.0));
    auto whole = view.visibleWindow();
    ASSERT_TRUE(whole);
    EXPECT_EQ(whole->pixels, QRect(0, 40, 700, 420));
    EXPECT_NEAR(whole->region.x0, 0.0, 1e-9);
    EXPECT_NEAR(whole->region.x1, 1000.0, 1e-9);

    // Zooming about a point keeps the design point under it, wherever it is.
    for (QPointF anchor : {QPointF(100.0, 80.0), QPointF(650.0, 470.0), QPointF(350.0, 250.0)}) {
        const QPointF before = view.toDesign(anchor);
        view.zoomBy(2.5, anchor);
        expectSamePoint(view.toDesign(anchor), before);
        view.zoomBy(1.0 / 2.5, anchor);
        expectSamePoint(view.toDesign(anchor), before);
    }
    EXPECT_FALSE(view.isFitted());
    // The window rendered covers exactly its pixels: 4 x the scale, a quarter of the width.
    view.fit();
    view.zoomBy(4.0, QPointF(350.0, 250.0));
    auto zoomed = view.visibleWindow();
    ASSERT_TRUE(zoomed);
    EXPECT_EQ(zoomed->pixels, QRect(0, 0, 700, 500));
    EXPECT_NEAR(regionWidth(zoomed->region), 250.0, 1e-9);
    EXPECT_NEAR(regionWidth(zoomed->region) * view.scale(), zoomed->pixels.width(), 1e-9);

    // 1:1 is one design unit to a pixel; a fitted view follows the viewport, a zoomed one not.
    view.oneToOne();
    EXPECT_DOUBLE_EQ(view.scale(), 1.0);
    view.setViewport(QSize(300, 300));
    EXPECT_DOUBLE_EQ(view.scale(), 1.0);
    view.fit();
    view.setViewport(QSize(400, 400));
    EXPECT_DOUBLE_EQ(view.scale(), 0.4);

    // A drag moves the design with the pointer; the view's centre never leaves the design.
    view.setScale(2.0, QPointF(200.0, 200.0));
    const QPointF centre = view.centre();
    view.panBy(QPointF(40.0, -20.0));
    expectSamePoint(view.centre(), centre - QPointF(20.0, -10.0));
    view.panBy(QPointF(1e7, 1e7));
    expectSamePoint(view.centre(), QPointF(0.0, 0.0));
    ASSERT_TRUE(view.visibleWindow());
    // Zooming out stops at a quarter of the fitted scale, in at MaxScale.
    view.zoomBy(1e-9, QPointF(0.0, 0.0));
    EXPECT_DOUBLE_EQ(view.scale(), ViewController::MinFitFraction * view.fitScale());
    view.zoomBy(1e12, QPointF(0.0, 0.0));
    EXPECT_DOUBLE_EQ(view.scale(), ViewController::MaxScale);
}

TEST(ViewControllerTest, ZoomKeysAreTheSameInEveryView) {
    // One table of keys for the large view and the editor's canvas: + and = zoom in, - out, 0
    // fits, 1 shows one to one, with or without Ctrl or the keypad; any other key is left to the
    // widget.
    QStringList done;
    const ViewController::ZoomKeyActions actions{[&] { done << "in"; }, [&] { done << "out"; },
                                                 [&] { done << "fit"; }, [&] { done << "one"; }};
    const auto press = [&](int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        QKeyEvent event(QEvent::KeyPress, key, modifiers);
        return ViewController::handleKey(&event, actions);
    };
    EXPECT_TRUE(press(Qt::Key_Plus));
    EXPECT_TRUE(press(Qt::Key_Equal, Qt::ControlModifier));
    EXPECT_TRUE(press(Qt::Key_Minus, Qt::KeypadModifier));
    EXPECT_TRUE(press(Qt::Key_0));
    EXPECT_TRUE(press(Qt::Key_1));
    EXPECT_FALSE(press(Qt::Key_2));
    EXPECT_FALSE(press(Qt::Key_Space));
    EXPECT_EQ(done, QStringList({"in", "in", "out", "fit", "one"}));

    // An action a view lacks leaves its key to the widget.
    done.clear();
    QKeyEvent one(QEvent::KeyPress, Qt::Key_1, Qt::NoModifier);
    EXPECT_FALSE(ViewController::handleKey(&one, {[&] { done << "in"; }, {}, {}, {}}));
    EXPECT_TRUE(done.isEmpty());
}

TEST(ViewAngleTest, KeptInMetaViewAndReadBackFromFiles) {
    Genome genome = randomGenome(4, 3);
    EXPECT_EQ(viewAngleOf(genome), (ViewAngle{30.0, 20.0})) << "the default when meta has none";
    setViewAngle(genome, ViewAngle{-75.5, 12.25});
    EXPECT_EQ(genome.meta.toJson()["view"]["yaw"], -75.5);
    EXPECT_EQ(genome.meta.toJson()["view"]["pitch"], 12.25);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string file = dir.filePath(QStringLiteral("turned.marble.json")).toStdString();
    saveGenome(genome, file);
    EXPECT_EQ(viewAngleOf(loadGenome(file)), (ViewAngle{-75.5, 12.25}));
    // Nonsense reads as the default, the pitch stays short of the poles.
    nlohmann::ordered_json meta = genome.meta.toJson();
    meta["view"] = {{"yaw", "east"}, {"pitch", 400}};
    genome.meta = Meta::fromJson(meta);
    EXPECT_EQ(viewAngleOf(genome), (ViewAngle{30.0, 89.0}));
    EXPECT_EQ((ViewAngle{350.0, 80.0}.dragged(40.0, 40.0)), (ViewAngle{10.0, 89.0}));
}

class ViewTest : public test::WindowTest {
protected:
    ViewTest()
        : WindowTest(/*populate=*/false) {}
    /// The cell of the current population that is quickest to render: these tests are about the
    /// view, not the renderer, and a random population may hold a design whose rakes take minutes
    /// at full size on a CPU (a stylus costs its integration steps times its tines a point).
    int lightestCell() {
        const auto work = [](const Genome& design) {
            double sum = 0.0;
            for (const auto* list : {&design.initial, &design.operations})
                for (const Operation& op : *list)
                    sum +=
                        op.tool == Tool::Stylus || op.tool == Tool::Flow ? double(op.steps) * op.tines : 1.0;
            return sum;
        };
        int best = 0;
        for (int i = 1; i < 9; ++i)
            if (work(*model().cell(i)) < work(*model().cell(best))) best = i;
        return best;
    }
    /// Opens a cell large and waits for its final image.
    DesignDialog* openAndRender(int cell) {
        DesignDialog* dialog = mWindow->openDesign(cell);
        if (!dialog) return nullptr;
        if (!QTest::qWaitForWindowExposed(dialog)) return nullptr;
        [&] { MARBLER_WAIT(dialog->imageIsFinal(), 120000); }();
        return dialog->imageIsFinal() ? dialog : nullptr;
    }
};

/// A wheel turn over a widget: `notches` of 120.
void wheel(QWidget* target, QPointF pos, int notches, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QWheelEvent event(pos, target->mapToGlobal(pos), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                      modifiers, Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &event);
}

TEST_F(ViewTest, WheelZoomsAboutThePointerAndRendersTheWindowSharp) {
    mWindow->newRandomPopulation(2);
    const int cell = lightestCell();
    DesignDialog* dialog = openAndRender(cell);
    ASSERT_NE(dialog, nullptr);
    const double ratio = dialog->canvas()->devicePixelRatioF();
    const auto first = dialog->requestedRegion();
    ASSERT_TRUE(first);
    EXPECT_NEAR(regionWidth(*first), model().cell(cell)->size.x, 2.0 / dialog->viewController().scale())
        << "fitted: the whole design, to a pixel";
    const QImage before = dialog->image();

    // Two notches at a point off centre: 2x, and the design point under the pointer stays.
    const QPointF pointer(90.0, 120.0);
    const QPointF under = dialog->viewController().toDesign(pointer * ratio);
    const double fitted = dialog->viewController().scale();
    wheel(dialog->canvas(), pointer, 2);
    EXPECT_NEAR(dialog->viewController().scale(), 2.0 * fitted, 1e-9);
    expectSamePoint(dialog->viewController().toDesign(pointer * ratio), under, 1e-6);
    EXPECT_EQ(dialog->zoomText(), QStringLiteral("%L1 %").arg(200.0 * fitted, 0, 'f', 0));
    EXPECT_EQ(dialog->findChild<QLabel*>(QStringLiteral("zoomLevel"))->text(), dialog->zoomText());
    EXPECT_FALSE(dialog->imageIsFinal()) << "the old image stands in, scaled, until the new one comes";
    const auto zoomed = dialog->requestedRegion();
    ASSERT_TRUE(zoomed);
    EXPECT_LT(regionWidth(*zoomed), 0.75 * regionWidth(*first)) << "a smaller window of the design";

    // The final image is an exact render of that window at the new scale, not the old one
    // enlarged.
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    ASSERT_TRUE(dialog->imageIsFinal());
    const QImage after = dialog->image();
    RenderSettings settings;
    settings.width = after.width();
    settings.height = after.height();
    settings.region = *zoomed;
    settings.aa = "rgss";
    EXPECT_EQ(after, toQImage(CpuRenderer(*model().cell(cell)).render(settings)));
    EXPECT_NEAR(regionWidth(*zoomed) * dialog->viewController().scale(), after.width(), 1e-6);
    const QImage enlarged = before.scaled(after.size());
    EXPECT_NE(after, enlarged);

    // Ctrl+wheel zooms alike; wheeling back out returns to the fitted scale.
    wheel(dialog->canvas(), pointer, -1, Qt::ControlModifier);
    wheel(dialog->canvas(), pointer, -1);
    EXPECT_NEAR(dialog->viewController().scale(), fitted, 1e-9);
    dialog->close();
}

TEST_F(ViewTest, KeysAndButtonsFitShowOneToOneAndZoom) {
    mWindow->newRandomPopulation(2);
    DesignDialog* dialog = openAndRender(lightestCell());
    ASSERT_NE(dialog, nullptr);
    const ViewController& view = dialog->viewController();
    const double fitted = view.scale();
    QTest::keyClick(dialog, Qt::Key_Plus);
    EXPECT_NEAR(view.scale(), fitted * std::sqrt(2.0), 1e-9);
    QTest::keyClick(dialog, Qt::Key_Minus);
    QTest::keyClick(dialog, Qt::Key_Minus);
    EXPECT_NEAR(view.scale(), fitted / std::sqrt(2.0), 1e-9);
    QTest::keyClick(dialog, Qt::Key_1);
    EXPECT_DOUBLE_EQ(view.scale(), 1.0);
    EXPECT_EQ(dialog->zoomText(), QStringLiteral("100 %"));
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    // At 1:1 a render is as many pixels as the design units it shows.
    EXPECT_NEAR(regionWidth(*dialog->requestedRegion()), dialog->image().width(), 1e-6);
    QTest::keyClick(dialog, Qt::Key_0);
    EXPECT_TRUE(view.isFitted());
    EXPECT_DOUBLE_EQ(view.scale(), fitted);

    // The buttons do the same, and their tooltips name the keys.
    struct Button {
        const char* name;
        const char* key;
    };
    for (Button b : {Button{"zoomIn", "(+"}, Button{"zoomOut", "(-"}, Button{"zoomFit", "(0)"},
                     Button{"zoomOneToOne", "(1)"}}) {
        auto* button = dialog->findChild<QToolButton*>(QString::fromLatin1(b.name));
        ASSERT_NE(button, nullptr) << b.name;
        EXPECT_TRUE(button->toolTip().contains(QString::fromLatin1(b.key)))
            << button->toolTip().toStdString();
    }
    dialog->findChild<QToolButton*>(QStringLiteral("zoomIn"))->click();
    EXPECT_NEAR(view.scale(), fitted * std::sqrt(2.0), 1e-9);
    dialog->findChild<QToolButton*>(QStringLiteral("zoomOneToOne"))->click();
    EXPECT_DOUBLE_EQ(view.scale(), 1.0);
    dialog->findChild<QToolButton*>(QStringLiteral("zoomFit"))->click();
    EXPECT_TRUE(view.isFitted());
    dialog->close();
}

TEST_F(ViewTest, DragPansTheView) {
    mWindow->newRandomPopulation(2);
    DesignDialog* dialog = openAndRender(lightestCell());
    ASSERT_NE(dialog, nullptr);
    dialog->zoomIn();
    dialog->zoomIn();
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    const double ratio = dialog->canvas()->devicePixelRatioF();
    const QPointF centre = dialog->viewController().centre();
    const Region region = *dialog->requestedRegion();
    QWidget* canvas = dialog->canvas();
    const QPoint from = canvas->rect().center();
    const QPoint to = from + QPoint(-30, 20);
    QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(canvas, from + QPoint(-10, 5));
    QTest::mouseMove(canvas, to);
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, to);
    // The design follows the pointer: the view's centre moves the other way.
    const QPointF moved = QPointF(30.0, -20.0) * ratio / dialog->viewController().scale();
    expectSamePoint(dialog->viewController().centre(), centre + moved, 1e-6);
    const Region panned = *dialog->requestedRegion();
    EXPECT_NE(panned.x0, region.x0);
    EXPECT_NEAR(regionWidth(panned), regionWidth(region), 2.0 / dialog->viewController().scale());
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    dialog->close();
}

TEST_F(ViewTest, ViewAngleFollowsTheDesignIntoAnotherCellAndASession) {
    QTemporaryDir sessionDir;
    ASSERT_TRUE(sessionDir.isValid());
    const QString sessionFile = sessionFilePath(sessionDir.path());
    mWindow->newRandomPopulation(3);
    model().setSessionFile(sessionFile); // written now: the generation's text is cached
    const std::size_t generations = model().history().size();

    // Turning a cell's object writes the angle into its design, once, on release.
    QSignalSpy changed(&model(), &PopulationModel::cellChanged);
    emit mWindow->cell(2)->orbitDragged(2, QPoint(12, -6), false);
    emit mWindow->cell(2)->orbitDragged(2, QPoint(8, -4), false);
    EXPECT_EQ(viewAngleOf(*model().cell(2)), ViewAngle{}) << "not while dragging";
    EXPECT_EQ(changed.size(), 0);
    emit mWindow->cell(2)->orbitDragged(2, QPoint(0, 0), true);
    const ViewAngle turned{30.0 + 10.0, 20.0 - 5.0}; // half a degree a pixel
    EXPECT_EQ(viewAngleOf(*model().cell(2)), turned);
    EXPECT_EQ(changed.size(), 1);
    EXPECT_EQ(model().history().size(), generations) << "not a new generation";
    EXPECT_EQ(viewAngleOf(*model().cell(3)), ViewAngle{}) << "other cells keep theirs";
    // The session written before is written again with the angle, not from a stale cache.
    EXPECT_EQ(viewAngleOf(*loadSession(sessionFile).history.back().cells[2]), turned);

    // The design takes its angle along: onto the shelf and back into another cell.
    ASSERT_TRUE(mWindow->keepFavourite(2));
    mWindow->restoreFavourite(0, 7);
    EXPECT_EQ(viewAngleOf(*model().cell(7)), turned);

    // The session saved after the change has it, and a resumed session brings it back.
    model().setCellView(5, ViewAngle{-120.0, 45.0});
    SavedSession saved = loadSession(sessionFile);
    PopulationModel resumed;
    resumed.restoreSession(std::move(saved));
    ASSERT_NE(resumed.cell(5), nullptr);
    EXPECT_EQ(viewAngleOf(*resumed.cell(5)), (ViewAngle{-120.0, 45.0}));
    EXPECT_EQ(viewAngleOf(*resumed.cell(7)), turned);
}

TEST_F(ViewTest, LargeViewTurnsTheDesignAndZoomsTheObject) {
    mWindow->newRandomPopulation(3);
    model().setCellView(6, ViewAngle{10.0, 5.0});
    DesignDialog* dialog = mWindow->openDesign(6);
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    EXPECT_EQ(dialog->viewAngle(), (ViewAngle{10.0, 5.0})) << "the design's own angle";
    QWidget* canvas = dialog->canvas();
    const QPoint from = canvas->rect().center();
    QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(canvas, from + QPoint(40, 20));
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, from + QPoint(40, 20));
    const ViewAngle turned{30.0, 15.0};
    EXPECT_EQ(dialog->viewAngle(), turned);
    EXPECT_EQ(viewAngleOf(dialog->genome()), turned) << "saved with the design";
    EXPECT_EQ(viewAngleOf(*model().cell(6)), turned) << "and given back to its cell";

    // The wheel and the keys zoom the object; 0 frames it again; 1:1 means nothing for it.
    wheel(canvas, QPointF(from), 2);
    EXPECT_NEAR(dialog->objectZoom(), 2.0, 1e-9);
    EXPECT_EQ(dialog->zoomText(), QStringLiteral("200 %"));
    QTest::keyClick(dialog, Qt::Key_Minus);
    EXPECT_NEAR(dialog->objectZoom(), std::sqrt(2.0), 1e-9);
    // With no GL here the CPU draws the object itself (no longer a cross-section standing in),
    // magnified: its final image is the object zoomed, rendered anew.
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    ASSERT_TRUE(dialog->imageIsFinal());
    const QImage magnified = dialog->image();
    QTest::keyClick(dialog, Qt::Key_0);
    EXPECT_DOUBLE_EQ(dialog->objectZoom(), 1.0);
    EXPECT_FALSE(dialog->findChild<QToolButton*>(QStringLiteral("zoomOneToOne"))->isEnabled());
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    const Genome& g = *model().cell(6);
    MeshSettings settings;
    settings.width = magnified.width();
    settings.height = magnified.height();
    settings.yaw = turned.yaw;
    settings.pitch = turned.pitch;
    settings.zoom = std::sqrt(2.0);
    settings.supersample = 3;
    EXPECT_EQ(magnified, toQImage(renderObjectOnCpu(g, builtinMesh(DefaultMesh), settings)));
    EXPECT_EQ(dialog->image().size(), magnified.size());
    EXPECT_NE(dialog->image(), magnified);
    dialog->close();
}

/// The share of the width and the height that the object covers (the bounding box of the
/// pixels unlike the clear colour).
std::pair<double, double> coverage(const Image& image, Color clear) {
    int x0 = image.width, y0 = image.height, x1 = -1, y1 = -1;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.row(y) + x * 3;
            if (std::abs(p[0] - clear.r) + std::abs(p[1] - clear.g) + std::abs(p[2] - clear.b) <= 6) continue;
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
        }
    if (x1 < 0) return {0.0, 0.0};
    return {double(x1 - x0 + 1) / image.width, double(y1 - y0 + 1) / image.height};
}

TEST(SolidFramingTest, EveryObjectFillsItsCellOnGlAndTheCpuPath) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    gl::GlRenderer renderer;
    const Genome genome = randomGenome(5, 3);
    for (const std::string& name : gl::builtinMeshNames()) {
        for (QSize size : {QSize(120, 120), QSize(160, 100), QSize(90, 140)}) {
            for (ViewAngle angle : {ViewAngle{}, ViewAngle{-70.0, 55.0}, ViewAngle{180.0, -10.0}}) {
                gl::MeshSettings settings;
                settings.width = size.width();
                settings.height = size.height();
                settings.mesh = name;
                settings.yaw = angle.yaw;
                settings.pitch = angle.pitch;
                settings.supersample = 1;
                const auto [w, h] = coverage(renderer.renderMesh(genome, settings), settings.clearColor);
                const std::string what = name + " at " + std::to_string(size.width()) + "x" +
                                         std::to_string(size.height()) + ", yaw " + std::to_string(angle.yaw);
                EXPECT_GE(std::max(w, h), 0.8) << what << ": " << w << " x " << h;
                EXPECT_LT(std::max(w, h), 0.99) << what << ": a margin stays";
                const auto [hw, hh] =
                    coverage(gl::renderMeshHybrid(renderer, genome, settings), settings.clearColor);
                EXPECT_NEAR(hw, w, 0.03) << what << " on the CPU path";
                EXPECT_NEAR(hh, h, 0.03) << what << " on the CPU path";
            }
        }
    }
}

} // namespace
