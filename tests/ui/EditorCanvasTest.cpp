// The editor's canvas: what each tool's gesture makes (Gestures.h, pure), the same gestures made
// with the mouse on the canvas (EditorCanvas.h), its handles, the ink picker, its renders (exact
// at any zoom, a solid's chosen cross-section) and the tool panel (ToolOptions.h).

#include "editor/EditorCanvas.h"
#include "WaitFor.h"
#include "editor/Gestures.h"
#include "editor/ToolOptions.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Tools.h"
#include "shared/RenderService.h"

#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QTest>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// The tool bar's tools, read from the registry (and the editor's own): no list kept here.
const std::vector<EditorTool> AllTools = editorTools();

Genome flatDesign() {
    Genome g;
    g.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}};
    Operation drop = defaultOperation(Tool::Drop, 2, {300, 300, 0});
    drop.radius = 120;
    drop.color = 1;
    g.initial.push_back(drop);
    Operation comb = defaultOperation(Tool::Comb, 2, {500, 500, 0});
    comb.angle = 90;
    g.operations.push_back(comb);
    return g;
}

Genome solidDesign() {
    Genome g;
    g.dimension = 3;
    g.size = {600, 600, 600};
    g.palette = {{200, 30, 30}, {30, 30, 200}};
    Operation drop = defaultOperation(Tool::Drop, 3, {300, 300, 300});
    drop.radius = 150;
    g.initial.push_back(drop);
    return g;
}

void expectValid(const Genome& design, const std::vector<Operation>& ops, const char* what) {
    EXPECT_NO_THROW(validateGenome(withSteps(design, ops), what)) << what;
}

double dist(glm::dvec3 a, glm::dvec3 b) {
    return glm::length(a - b);
}

TEST(GesturesTest, EachFlatToolMakesWhatItsDragSays) {
    const Genome g = flatDesign();
    ToolSettings s;
    s.color = 2;
    s.spacing = 55;
    s.lambda = 17;
    s.wavelength = 190;
    s.alpha = 33;
    s.core = 4;
    const glm::dvec3 a{200, 400, 0}, b{500, 800, 0}; // 300 across, 400 down: length 500
    const double angle = std::atan2(400.0, 300.0) * 180.0 / std::numbers::pi;

    auto drop = gestureSteps(Tool::Drop, s, a, b, g);
    ASSERT_EQ(drop.size(), 1u);
    EXPECT_EQ(drop[0].tool, Tool::Drop);
    EXPECT_EQ(drop[0].center, a);
    EXPECT_DOUBLE_EQ(drop[0].radius, 500.0);
    EXPECT_EQ(drop[0].color, 2);
    auto click = gestureSteps(Tool::Drop, s, a, a, g);
    ASSERT_EQ(click.size(), 1u);
    EXPECT_DOUBLE_EQ(click[0].radius, s.radius);

    auto spray = gestureSteps(Tool::Spray, s, a, b, g);
    ASSERT_EQ(int(spray.size()), s.sprayCount);
    for (const Operation& op : spray) {
        EXPECT_EQ(op.tool, Tool::Spray);
        EXPECT_EQ(op.color, 2);
        EXPECT_DOUBLE_EQ(op.radius, s.sprayRadius);
        // Within the brush of the segment a-b.
        const double t = std::clamp(glm::dot(op.center - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        EXPECT_LE(dist(op.center, a + t * (b - a)), s.brush + 1e-9);
    }
    EXPECT_EQ(spray, gestureSteps(Tool::Spray, s, a, b, g)) << "the same seed sprays the same drops";
    s.seed = 2;
    EXPECT_NE(spray, gestureSteps(Tool::Spray, s, a, b, g));

    auto line = gestureSteps(EditorTool::DropLine, s, a, b, g);
    ASSERT_EQ(int(line.size()), s.patternCount);
    EXPECT_EQ(line.front().center, a);
    EXPECT_NEAR(dist(line.back().center, b), 0.0, 1e-9);

    auto rings = gestureSteps(EditorTool::DropRings, s, a, b, g);
    ASSERT_EQ(int(rings.size()), s.patternCount);
    for (const Operation& op : rings)
        EXPECT_EQ(op.center, a);
    EXPECT_NEAR(rings[0].radius * std::sqrt(double(s.patternCount)), 500.0, 1e-9)
        << "the last ring ends at the drag";
    EXPECT_NE(rings[0].color, rings[1].color);

    auto scatter = gestureSteps(EditorTool::DropScatter, s, a, b, g);
    ASSERT_GE(scatter.size(), 2u);
    for (std::size_t i = 0; i < scatter.size(); ++i) {
        EXPECT_LE(dist(scatter[i].center, a), 500.0);
        for (std::size_t j = 0; j < i; ++j)
            EXPECT_GT(dist(scatter[i].center, scatter[j].center), scatter[i].radius + scatter[j].radius);
    }

    for (EditorTool tool : {Tool::Line, Tool::Comb}) {
        auto ops = gestureSteps(tool, s, a, b, g);
        ASSERT_EQ(ops.size(), 1u);
        EXPECT_EQ(ops[0].tool, tool == Tool::Line ? Tool::Line : Tool::Comb);
        EXPECT_EQ(ops[0].center, a);
        EXPECT_NEAR(ops[0].angle, angle, 1e-9);
        EXPECT_DOUBLE_EQ(ops[0].alpha, 500.0);
        EXPECT_DOUBLE_EQ(ops[0].lambda, 17.0);
        if (tool == Tool::Comb) {
            EXPECT_DOUBLE_EQ(ops[0].spacing, 55.0);
        }
        EXPECT_TRUE(gestureSteps(tool, s, a, a + glm::dvec3(0.5, 0, 0), g).empty()) << "too short a stroke";
    }
    auto wave = gestureSteps(Tool::Wave, s, a, b, g);
    ASSERT_EQ(wave.size(), 1u);
    EXPECT_NEAR(wave[0].angle, angle, 1e-9);
    EXPECT_DOUBLE_EQ(wave[0].amplitude.x, 500.0);
    EXPECT_DOUBLE_EQ(wave[0].wavelength.x, 190.0);

    auto circle = gestureSteps(Tool::Circle, s, a, b, g);
    ASSERT_EQ(circle.size(), 1u);
    EXPECT_EQ(circle[0].tool, Tool::Circle);
    EXPECT_EQ(circle[0].center, a);
    EXPECT_DOUBLE_EQ(circle[0].radius, 500.0);
    EXPECT_DOUBLE_EQ(circle[0].alpha, 33.0);
    EXPECT_DOUBLE_EQ(circle[0].core, 4.0);
    auto vortex = gestureSteps(Tool::Vortex, s, a, b, g);
    ASSERT_EQ(vortex.size(), 1u);
    EXPECT_EQ(vortex[0].center, a);
    EXPECT_DOUBLE_EQ(vortex[0].alpha, 500.0);
    EXPECT_DOUBLE_EQ(vortex[0].lambda, 17.0);

    auto stretch = gestureSteps(Tool::Stretch, s, a, b, g);
    ASSERT_EQ(stretch.size(), 1u);
    EXPECT_NEAR(stretch[0].angle, angle, 1e-9);
    EXPECT_DOUBLE_EQ(stretch[0].shift, 500.0);
    EXPECT_EQ(int(stretch[0].teeth.size()), s.teeth);
    EXPECT_DOUBLE_EQ(stretch[0].power, s.power);

    auto flow = gestureSteps(Tool::Flow, s, a, b, g);
    ASSERT_EQ(flow.size(), 1u);
    EXPECT_EQ(flow[0].extent, glm::dvec2(300, 400));
    EXPECT_DOUBLE_EQ(flow[0].speed, s.speed);
    EXPECT_GE(flow[0].steps, minimumFlowSteps(flow[0]));

    EXPECT_TRUE(gestureSteps(EditorTool::Pick, s, a, b, g).empty());
    for (EditorTool tool : AllTools) {
        auto ops = gestureSteps(tool, s, a, b, g);
        if (tool != EditorTool::Pick) {
            // A solid's own tool (the sphere) makes nothing on a flat design.
            EXPECT_EQ(ops.empty(), !toolAvailable(tool, 2)) << toolId(tool);
        }
        expectValid(g, ops, "flat gesture");
        expectValid(g, gestureSteps(tool, s, a, a, g), "flat click");
    }
    Genome noInk = g;
    noInk.palette.clear();
    noInk.initial.clear();
    EXPECT_TRUE(gestureSteps(Tool::Drop, s, a, b, noInk).empty()) << "no palette, no ink";
}

TEST(GesturesTest, AFreeHandDragMakesOneStylusStepAlongItsPath) {
    // A wavy drag with the stylus: one step whose smoothed path follows the drag, points a few
    // units apart (not one a pointer event), starting and ending where the drag does, with the
    // fewest valid steps; a solid or a click makes nothing.
    const Genome g = flatDesign();
    ToolSettings s;
    std::vector<glm::dvec3> drag;
    for (int i = 0; i <= 400; ++i) {
        const double x = 200.0 + i;
        drag.push_back({x, 500.0 + 40.0 * std::sin(x / 40.0), 0.0});
    }
    auto ops = pathSteps(Tool::Stylus, s, drag, g);
    ASSERT_EQ(ops.size(), 1u);
    const Operation& op = ops[0];
    EXPECT_EQ(op.tool, Tool::Stylus);
    ASSERT_GE(op.path.size(), 20u);
    EXPECT_LT(op.path.size(), drag.size() / 2) << "points a few units apart, not one an event";
    EXPECT_EQ(op.path.front(), glm::dvec2(drag.front()));
    EXPECT_EQ(op.path.back(), glm::dvec2(drag.back()));
    for (const glm::dvec2& p : op.path) // on the drag's curve, within the smoothing's reach
        EXPECT_NEAR(p.y, 500.0 + 40.0 * std::sin(p.x / 40.0), 1.0) << p.x;
    EXPECT_EQ(op.steps, minimumStylusSteps(op));
    expectValid(g, ops, "stylus drag");
    EXPECT_TRUE(pathSteps(Tool::Stylus, s, {drag[0], drag[0]}, g).empty()) << "a click draws nothing";
    EXPECT_TRUE(pathSteps(Tool::Line, s, drag, g).empty()) << "only a path tool draws a path";
}

TEST(GesturesTest, SolidToolsWorkInTheSectionPlane) {
    const Genome g = solidDesign();
    ToolSettings s;
    EXPECT_FALSE(toolAvailable(Tool::Stretch, 3));
    EXPECT_FALSE(toolAvailable(Tool::Flow, 3));
    EXPECT_TRUE(toolAvailable(Tool::Comb, 3));
    EXPECT_TRUE(toolAvailable(Tool::Flow, 2));
    // On the plane y = 200 (axis 1): the drag runs along x and z.
    const glm::dvec3 a{100, 200, 150}, b{100, 200, 450};
    auto drop = gestureSteps(Tool::Drop, s, a, b, g, 1);
    ASSERT_EQ(drop.size(), 1u);
    EXPECT_EQ(drop[0].center, a);
    EXPECT_DOUBLE_EQ(drop[0].radius, 300.0);
    auto comb = gestureSteps(Tool::Comb, s, a, b, g, 1);
    ASSERT_EQ(comb.size(), 1u);
    EXPECT_NEAR(dist(comb[0].direction, {0, 0, 1}), 0.0, 1e-12);
    EXPECT_NEAR(dist(comb[0].normal, {1, 0, 0}), 0.0, 1e-12) << "across the drag, in the plane";
    auto circle = gestureSteps(Tool::Circle, s, a, b, g, 1);
    ASSERT_EQ(circle.size(), 1u);
    EXPECT_NEAR(dist(circle[0].axis, {0, 1, 0}), 0.0, 1e-12);
    auto scatter = gestureSteps(EditorTool::DropScatter, s, a, b, g, 1);
    for (const Operation& op : scatter)
        EXPECT_DOUBLE_EQ(op.center.y, 200.0) << "drops stay on the plane";
    auto rings = gestureSteps(EditorTool::DropRings, s, a, b, g, 1);
    ASSERT_FALSE(rings.empty());
    EXPECT_NEAR(rings[0].radius * std::cbrt(double(rings.size())), 300.0, 1e-9) << "the volume law";
    for (EditorTool tool : AllTools) {
        auto ops = gestureSteps(tool, s, a, b, g, 1);
        EXPECT_EQ(!ops.empty(), tool != EditorTool::Pick && toolAvailable(tool, 3)) << toolId(tool);
        expectValid(g, ops, "solid gesture");
    }
}

TEST(ToolOptionsTest, ShowsTheToolsRowsAndEditsItsSettings) {
    ToolOptions options;
    options.setPalette(flatDesign().palette);
    options.show();
    std::optional<ToolSettings> got;
    QObject::connect(&options, &ToolOptions::settingsChanged, [&](const ToolSettings& s) { got = s; });
    auto* spacing = options.findChild<QDoubleSpinBox*>(QStringLiteral("toolSpacing"));
    auto* brush = options.findChild<QDoubleSpinBox*>(QStringLiteral("toolBrush"));
    ASSERT_TRUE(spacing && brush);
    options.setTool(Tool::Comb);
    EXPECT_TRUE(spacing->isVisible());
    EXPECT_FALSE(brush->isVisible());
    options.setTool(Tool::Spray);
    EXPECT_FALSE(spacing->isVisible());
    EXPECT_TRUE(brush->isVisible());
    brush->setValue(75);
    ASSERT_TRUE(got);
    EXPECT_DOUBLE_EQ(got->brush, 75.0);
    EXPECT_FALSE(brush->toolTip().isEmpty());
    for (EditorTool tool : AllTools) {
        EXPECT_FALSE(toolName(tool).isEmpty());
        EXPECT_FALSE(toolTip(tool).isEmpty());
        EXPECT_FALSE(toolShortcut(tool).isEmpty());
        for (EditorTool other : AllTools)
            if (other != tool) {
                EXPECT_NE(toolShortcut(tool), toolShortcut(other));
            }
    }
}

// RenderRequest::slice: a solid shown by that cross-section, not on its object, fitted to the
// slice's own plane when no region is given.
TEST(RenderServiceSliceTest, RendersTheCrossSectionAsked) {
    Genome g = solidDesign();
    g.size = {600, 400, 200};
    g.initial[0].center = {300, 200, 100};
    RenderService service(RenderService::Backend::Cpu);
    QImage final;
    QObject::connect(&service, &RenderService::rendered,
                     [&](std::uint64_t, const QImage& image, bool isFinal) {
                         if (isFinal) final = image;
                     });
    RenderRequest request;
    request.genome = g;
    request.size = QSize(256, 256);
    request.slice = Slice{0, 320.0};
    service.request(7, request);
    MARBLER_WAIT(!final.isNull(), 30000);
    EXPECT_EQ(final.size(), QSize(256, 128)) << "the y-z plane, 400 x 200";
    RenderSettings settings;
    settings.width = 256;
    settings.height = 128;
    settings.aa = "rgss";
    settings.slice = Slice{0, 320.0};
    EXPECT_EQ(final, toQImage(CpuRenderer(g).render(settings)).convertToFormat(final.format()));
}

/// A canvas of 400 x 400 on a CPU render service, showing `design` fitted (0.4 px a unit).
class CanvasTest : public ::testing::Test {
protected:
    void SetUp() override {
        mCanvas = std::make_unique<EditorCanvas>(&mService);
        mCanvas->resize(400, 400);
        mCanvas->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mCanvas.get()));
        QObject::connect(mCanvas.get(), &EditorCanvas::stepsMade,
                         [this](const std::vector<Operation>& ops, const QString& text) {
                             mMade.push_back(ops);
                             mText = text;
                         });
    }
    void TearDown() override { mCanvas.reset(); }

    /// Presses at `from`, moves halfway and to `to`, releases there (design points).
    void drag(glm::dvec3 from, glm::dvec3 to) {
        const QPoint a = mCanvas->toWidget(from).toPoint(), b = mCanvas->toWidget(to).toPoint();
        QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, a);
        QTest::mouseMove(mCanvas.get(), (a + b) / 2);
        QTest::mouseMove(mCanvas.get(), b);
        QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, b);
    }

    RenderService mService{RenderService::Backend::Cpu};
    std::unique_ptr<EditorCanvas> mCanvas;
    std::vector<std::vector<Operation>> mMade;
    QString mText;
};

TEST_F(CanvasTest, EachToolsMouseGestureMakesItsSteps) {
    const Genome g = flatDesign();
    mCanvas->setDesign(g);
    EXPECT_DOUBLE_EQ(mCanvas->view().scale(), 0.4);
    ToolSettings s;
    s.color = 1;
    s.spacing = 66;
    s.alpha = 21;
    mCanvas->setToolSettings(s);
    const glm::dvec3 a{250, 500, 0}, b{650, 800, 0};
    // Whole pixels: the points the mouse lands on, read back through the view.
    const glm::dvec3 pa = mCanvas->toDesign(mCanvas->toWidget(a).toPoint()),
                     pb = mCanvas->toDesign(mCanvas->toWidget(b).toPoint());
    EXPECT_LT(dist(pa, a), 2.5);
    EXPECT_LT(dist(pb, b), 2.5);
    for (EditorTool tool : AllTools) {
        if (tool == EditorTool::Pick) continue;
        mMade.clear();
        mCanvas->setTool(tool);
        drag(a, b);
        if (!toolAvailable(tool, 2)) {
            EXPECT_TRUE(mMade.empty()) << toolId(tool) << " is a solid's own tool";
            continue;
        }
        ASSERT_EQ(mMade.size(), 1u) << toolId(tool);
        const std::vector<Operation>& ops = mMade[0];
        if (gestureOf(tool) == EditorGesture::Path) {
            // A free-hand tool draws through every point the pointer passed.
            const QPoint wa = mCanvas->toWidget(a).toPoint(), wb = mCanvas->toWidget(b).toPoint();
            const glm::dvec3 pm = mCanvas->toDesign((wa + wb) / 2);
            EXPECT_EQ(ops, pathSteps(tool, s, {pa, pm, pb}, g)) << toolId(tool);
        } else {
            EXPECT_EQ(ops, gestureSteps(tool, s, pa, pb, g)) << toolId(tool);
        }
        EXPECT_FALSE(mText.isEmpty());
        EXPECT_TRUE(mCanvas->pendingSteps().empty());
        ASSERT_FALSE(ops.empty());
        expectValid(g, ops, "canvas gesture");
        const Operation& op = ops.front();
        EXPECT_EQ(op.tool, genomeTool(tool)) << toolId(tool);
        if (tool == Tool::Drop) {
            EXPECT_EQ(op.color, 1);
            EXPECT_NEAR(op.radius, 500.0, 5.0);
            EXPECT_LT(dist(op.center, a), 2.5);
        } else if (tool == Tool::Line || tool == Tool::Comb) {
            EXPECT_NEAR(op.angle, std::atan2(300.0, 400.0) * 180 / std::numbers::pi, 0.5);
            EXPECT_NEAR(op.alpha, 500.0, 5.0);
            if (tool == Tool::Comb) {
                EXPECT_DOUBLE_EQ(op.spacing, 66.0);
            }
        } else if (tool == Tool::Circle) {
            EXPECT_NEAR(op.radius, 500.0, 5.0);
            EXPECT_DOUBLE_EQ(op.alpha, 21.0);
        }
    }
    // A click of a stroke tool makes nothing; a click of the drop tool drops.
    mMade.clear();
    mCanvas->setTool(Tool::Comb);
    drag(a, a);
    EXPECT_TRUE(mMade.empty());
    mCanvas->setTool(Tool::Drop);
    drag(a, a);
    ASSERT_EQ(mMade.size(), 1u);
    EXPECT_DOUBLE_EQ(mMade[0][0].radius, s.radius);
}

TEST_F(CanvasTest, PreviewWhileDraggingThenSharpAtEveryZoom) {
    mCanvas->setDesign(flatDesign());
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    // The whole design fits 400 x 400: rendered at that size, not scaled.
    EXPECT_EQ(mCanvas->image().size(), QSize(400, 400));
    // Zoomed in, only the part in view is rendered, again pixel for pixel.
    mCanvas->view().zoomBy(4.0, QPointF(100, 100));
    mCanvas->zoomIn();
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    EXPECT_EQ(mCanvas->image().size(), QSize(400, 400));
    EXPECT_GT(mCanvas->view().scale(), 0.4 * 4.0);
    mCanvas->fitView();
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);

    // During a gesture the pending steps are shown, coarse; release renders sharp again.
    mCanvas->setTool(Tool::Drop);
    const QPoint a = mCanvas->toWidget({700, 700, 0}).toPoint();
    QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, a);
    QTest::mouseMove(mCanvas.get(), a + QPoint(30, 0));
    ASSERT_EQ(mCanvas->pendingSteps().size(), 1u);
    MARBLER_WAIT(!mCanvas->image().isNull() && mCanvas->image().width() < 400, 20000);
    EXPECT_FALSE(mCanvas->imageFinal());
    QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, a + QPoint(30, 0));
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    // The new drop (colour 0, red) is drawn at its centre.
    const QColor seen = mCanvas->image().pixelColor(a);
    EXPECT_GT(seen.red(), 150);
    EXPECT_LT(seen.blue(), 100);

    // A parameter dragged elsewhere: coarse only until it is let go.
    mCanvas->setDragging(true);
    mCanvas->setDesign(flatDesign());
    MARBLER_WAIT(!mService.idle() || mCanvas->image().width() < 400, 20000);
    MARBLER_WAIT(mService.idle(), 20000);
    EXPECT_FALSE(mCanvas->imageFinal());
    EXPECT_LT(mCanvas->image().width(), 400);
    mCanvas->setDragging(false);
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    EXPECT_EQ(mCanvas->image().width(), 400);
}

TEST_F(CanvasTest, HandlesMoveTheSelectedStep) {
    const Genome g = flatDesign();
    mCanvas->setDesign(g);
    std::vector<std::tuple<std::size_t, Operation, bool>> moved;
    QObject::connect(
        mCanvas.get(), &EditorCanvas::handleDragged,
        [&](std::size_t i, const Operation& op, bool final) { moved.emplace_back(i, op, final); });
    auto handle = [&](EditorCanvas::Handle which) {
        for (const auto& [h, point] : mCanvas->handlePoints())
            if (h == which) return point.toPoint();
        ADD_FAILURE() << "no such handle";
        return QPoint();
    };
    auto dragHandle = [&](QPoint from, QPoint to) {
        moved.clear();
        QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, from);
        QTest::mouseMove(mCanvas.get(), (from + to) / 2);
        QTest::mouseMove(mCanvas.get(), to);
        QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, to);
    };
    mCanvas->setTool(Tool::Comb); // handles come before the tool
    // The comb (step 1): its origin and its direction.
    mCanvas->setHandlesFor(1);
    ASSERT_EQ(mCanvas->handlePoints().size(), 2u);
    const QPoint origin = handle(EditorCanvas::Handle::Centre);
    dragHandle(origin, origin + QPoint(40, -20)); // 100 and -50 design units
    ASSERT_GE(moved.size(), 2u);
    EXPECT_FALSE(std::get<2>(moved.front()));
    ASSERT_TRUE(std::get<2>(moved.back()));
    EXPECT_EQ(std::get<0>(moved.back()), 1u);
    Operation comb = std::get<1>(moved.back());
    EXPECT_NEAR(comb.center.x, 600.0, 3.0);
    EXPECT_NEAR(comb.center.y, 450.0, 3.0);
    EXPECT_DOUBLE_EQ(comb.angle, 90.0);
    EXPECT_TRUE(mMade.empty()) << "a handle drag is no gesture";

    const QPoint arm = handle(EditorCanvas::Handle::Direction);
    const QPoint centre = mCanvas->toWidget(g.operations[0].center).toPoint();
    dragHandle(arm, centre + QPoint(-50, 0)); // pointing left: 180 degrees
    ASSERT_FALSE(moved.empty());
    comb = std::get<1>(moved.back());
    EXPECT_NEAR(std::abs(comb.angle), 180.0, 1.0);
    EXPECT_EQ(comb.center, g.operations[0].center);

    // The drop (step 0): its radius.
    mCanvas->setHandlesFor(0);
    const QPoint rim = handle(EditorCanvas::Handle::Radius);
    dragHandle(rim, rim + QPoint(20, 0)); // 50 units wider
    ASSERT_FALSE(moved.empty());
    EXPECT_EQ(std::get<0>(moved.back()), 0u);
    EXPECT_NEAR(std::get<1>(moved.back()).radius, 170.0, 3.0);
    for (const auto& [i, op, final] : moved) {
        Genome edited = g;
        edited.initial[0] = op;
        EXPECT_NO_THROW(validateGenome(edited, "handle"));
    }
}

TEST_F(CanvasTest, PickNamesTheInkAndItsStep) {
    Genome g = flatDesign();
    Operation second = defaultOperation(Tool::Drop, 2, {800, 200, 0});
    second.color = 2;
    g.initial.push_back(second);
    mCanvas->setDesign(g);
    mCanvas->setTool(EditorTool::Pick);
    std::vector<std::pair<int, std::optional<std::size_t>>> picked;
    QObject::connect(mCanvas.get(), &EditorCanvas::inkPicked,
                     [&](int color, std::optional<std::size_t> step) { picked.emplace_back(color, step); });
    QTest::mouseClick(mCanvas.get(), Qt::LeftButton, {}, mCanvas->toWidget({800, 200, 0}).toPoint());
    // The first drop (radius 120 at 300, 300), moved by the comb across it: traced back.
    const glm::dvec3 inFirst = mCanvas->toDesign(mCanvas->toWidget({300, 300, 0}).toPoint());
    const int firstColor = traceColor(prepare(g), inFirst);
    QTest::mouseClick(mCanvas.get(), Qt::LeftButton, {}, mCanvas->toWidget({300, 300, 0}).toPoint());
    QTest::mouseClick(mCanvas.get(), Qt::LeftButton, {}, mCanvas->toWidget({980, 980, 0}).toPoint());
    ASSERT_EQ(picked.size(), 3u);
    EXPECT_EQ(picked[0].first, 2);
    EXPECT_EQ(picked[0].second, std::optional<std::size_t>(1));
    EXPECT_EQ(picked[1].first, firstColor);
    if (firstColor == 1) {
        EXPECT_EQ(picked[1].second, std::optional<std::size_t>(0));
    }
    EXPECT_EQ(picked[2].first, -1) << "the bath";
    EXPECT_FALSE(picked[2].second);
    EXPECT_TRUE(mMade.empty());
}

TEST_F(CanvasTest, SolidsShowTheSliceAndToolsLandOnIt) {
    const Genome g = solidDesign();
    mCanvas->setDesign(g);
    mCanvas->setSlice(Slice{0, 250.0});
    MARBLER_WAIT(mCanvas->imageFinal(), 30000);
    // The canvas's image is the renderer's cross-section x = 250 (fitted 400 x 400).
    RenderSettings settings;
    settings.width = 400;
    settings.height = 400;
    settings.aa = "rgss";
    settings.slice = Slice{0, 250.0};
    settings.region = mCanvas->view().visibleWindow()->region;
    const QImage expected = toQImage(CpuRenderer(g).render(settings));
    EXPECT_EQ(mCanvas->image(), expected.convertToFormat(mCanvas->image().format()));

    mCanvas->setTool(Tool::Drop);
    drag({0, 100, 100}, {0, 100, 200}); // the x given is replaced by the slice's
    ASSERT_EQ(mMade.size(), 1u);
    const Operation& drop = mMade[0][0];
    EXPECT_DOUBLE_EQ(drop.center.x, 250.0);
    EXPECT_NEAR(drop.center.y, 100.0, 2.5);
    EXPECT_NEAR(drop.center.z, 100.0, 2.5);
    EXPECT_NEAR(drop.radius, 100.0, 4.0);
    expectValid(g, mMade[0], "solid canvas gesture");
    mMade.clear();
    mCanvas->setTool(Tool::Flow);
    drag({0, 100, 100}, {0, 100, 200});
    EXPECT_TRUE(mMade.empty()) << "no flat-only tool on a solid";
}

} // namespace
