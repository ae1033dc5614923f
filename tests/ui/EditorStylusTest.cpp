// Drawing with the stylus in the editor (issue 24, "Drawing it"): a free-hand drag draws one
// step along it, previewed live; a pen's pressure goes into `pressure`; the tool panel's values
// land in the step; its path's points are handles; the form edits its path and pressure as text;
// undo and redo are exact; the timeline grows it as the stylus travels.

#include "WaitFor.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "editor/Gestures.h"
#include "editor/ParamForm.h"
#include "editor/Timeline.h"
#include "editor/ToolOptions.h"
#include "marbler/CpuRenderer.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/Params.h"
#include "shared/RenderService.h"

#include <QAction>
#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPointingDevice>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabletEvent>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <memory>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// Two inks in a row of drops across a 1000-unit bath: what a stroke is drawn through.
Genome stylusBath() {
    Genome g;
    g.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}};
    for (int i = 0; i < 4; ++i) {
        Operation drop = defaultOperation(Tool::Drop, 2, {200.0 + 200.0 * i, 500.0, 0.0});
        drop.radius = 80;
        drop.color = i % 2;
        g.initial.push_back(drop);
    }
    return g;
}

/// A gentle curve across the bath, in design units: `count` points from x = 250 to 750.
std::vector<glm::dvec2> curve(int count) {
    std::vector<glm::dvec2> points;
    for (int i = 0; i < count; ++i) {
        const double x = 250.0 + 500.0 * i / (count - 1);
        points.push_back({x, 500.0 + 60.0 * std::sin((x - 250.0) / 80.0)});
    }
    return points;
}

/// The distance from `p` to the polyline through `points`.
double distanceToPolyline(glm::dvec2 p, const std::vector<glm::dvec2>& points) {
    double best = 1e300;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const glm::dvec2 a = points[i - 1], d = points[i] - a;
        const double t = std::clamp(glm::dot(p - a, d) / std::max(glm::dot(d, d), 1e-12), 0.0, 1.0);
        best = std::min(best, glm::length(p - (a + t * d)));
    }
    return best;
}

/// The design points the pointer lands on for each point of `points` (whole widget pixels).
std::vector<glm::dvec2> landed(const EditorCanvas& canvas, const std::vector<glm::dvec2>& points) {
    std::vector<glm::dvec2> out;
    for (const glm::dvec2& p : points) {
        const glm::dvec3 at = canvas.toDesign(canvas.toWidget({p.x, p.y, 0.0}).toPoint());
        out.push_back({at.x, at.y});
    }
    return out;
}

/// A mouse drag through `points` (design units).
void mouseStroke(EditorCanvas* canvas, const std::vector<glm::dvec2>& points) {
    auto widget = [&](glm::dvec2 p) { return canvas->toWidget({p.x, p.y, 0.0}).toPoint(); };
    QTest::mousePress(canvas, Qt::LeftButton, {}, widget(points.front()));
    for (std::size_t i = 1; i < points.size(); ++i)
        QTest::mouseMove(canvas, widget(points[i]));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, widget(points.back()));
}

/// A pen on a tablet: one tablet event to the canvas widget.
bool sendTablet(QWidget* target, QEvent::Type type, QPointF at, double pressure) {
    static const QPointingDevice pen(
        QStringLiteral("test pen"), 4242, QInputDevice::DeviceType::Stylus, QPointingDevice::PointerType::Pen,
        QInputDevice::Capability::Position | QInputDevice::Capability::Pressure, 1, 3);
    const Qt::MouseButton button = type == QEvent::TabletMove ? Qt::NoButton : Qt::LeftButton;
    const Qt::MouseButtons buttons = type == QEvent::TabletRelease ? Qt::NoButton : Qt::LeftButton;
    QTabletEvent event(type, &pen, at, target->mapToGlobal(at), pressure, 0.0f, 0.0f, 0.0f, 0.0, 0.0f,
                       Qt::NoModifier, button, buttons);
    QApplication::sendEvent(target, &event);
    return event.isAccepted();
}

/// A canvas of 400 x 400 on a CPU render service showing the bath fitted (0.4 px a unit).
class StylusCanvasTest : public ::testing::Test {
protected:
    void SetUp() override {
        mCanvas = std::make_unique<EditorCanvas>(&mService);
        mCanvas->resize(400, 400);
        mCanvas->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mCanvas.get()));
        mCanvas->setDesign(mDesign);
        mCanvas->setTool(Tool::Stylus);
        QObject::connect(mCanvas.get(), &EditorCanvas::stepsMade,
                         [this](const std::vector<Operation>& ops, const QString&) { mMade.push_back(ops); });
    }
    void TearDown() override { mCanvas.reset(); }

    RenderService mService{RenderService::Backend::Cpu};
    Genome mDesign = stylusBath();
    std::unique_ptr<EditorCanvas> mCanvas;
    std::vector<std::vector<Operation>> mMade;
};

TEST_F(StylusCanvasTest, AMouseDragDrawsOneStepAlongItLiveAndSharpOnRelease) {
    ToolSettings s;
    s.pull = 20; // a short render: few integration steps
    mCanvas->setToolSettings(s);
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    const std::vector<glm::dvec2> drag = curve(60);
    auto widget = [&](glm::dvec2 p) { return mCanvas->toWidget({p.x, p.y, 0.0}).toPoint(); };

    QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, widget(drag.front()));
    for (std::size_t i = 1; i < drag.size() / 2; ++i)
        QTest::mouseMove(mCanvas.get(), widget(drag[i]));
    // Mid-drag: the track so far and the stroke so far, previewed coarsely as it grows.
    EXPECT_EQ(mCanvas->strokePoints().size(), drag.size() / 2);
    ASSERT_EQ(mCanvas->pendingSteps().size(), 1u);
    const Operation half = mCanvas->pendingSteps()[0];
    EXPECT_EQ(half.tool, Tool::Stylus);
    MARBLER_WAIT(!mCanvas->image().isNull() && mCanvas->image().width() < 400, 20000);
    EXPECT_FALSE(mCanvas->imageFinal());
    // A pointer that never rests still sees the stroke grow: previews are paced, one at a time,
    // rather than each move aborting the render before it.
    int previews = 0;
    QObject::connect(&mService, &RenderService::rendered,
                     [&](std::uint64_t, const QImage&, bool) { ++previews; });
    QElapsedTimer moving;
    moving.start();
    for (std::size_t i = drag.size() / 2; i < drag.size() || (previews == 0 && moving.elapsed() < 30000);
         ++i) {
        // Past the end of the curve it wiggles about its last point.
        const QPoint at =
            widget(drag[std::min(i, drag.size() - 1)]) + QPoint(0, i < drag.size() ? 0 : int(i % 2));
        QTest::mouseMove(mCanvas.get(), at);
        QTest::qWait(3);
    }
    EXPECT_GT(previews, 0) << "no preview came while the pointer moved";
    QTest::mouseMove(mCanvas.get(), widget(drag.back()));
    ASSERT_EQ(mCanvas->pendingSteps().size(), 1u);
    EXPECT_GT(pathLength(mCanvas->pendingSteps()[0]), pathLength(half) * 1.5) << "it grows with the path";
    QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, widget(drag.back()));

    // One step, along the drag: every point of its path near the pointer's track, starting and
    // ending where it did, points a few units apart, the fewest valid steps, no pressure.
    ASSERT_EQ(mMade.size(), 1u);
    ASSERT_EQ(mMade[0].size(), 1u);
    const Operation op = mMade[0][0];
    EXPECT_EQ(op.tool, Tool::Stylus);
    const std::vector<glm::dvec2> track = landed(*mCanvas, drag);
    EXPECT_LT(glm::length(op.path.front() - track.front()), 1e-9);
    EXPECT_LT(glm::length(op.path.back() - track.back()), 1e-9);
    for (const glm::dvec2& p : op.path)
        EXPECT_LT(distanceToPolyline(p, track), 3.0) << p.x << " " << p.y;
    for (const glm::dvec2& p : track)
        EXPECT_LT(distanceToPolyline(p, op.path), 3.0) << "the path covers the drag";
    EXPECT_GE(op.path.size(), 10u);
    EXPECT_EQ(op.steps, minimumStylusSteps(op));
    EXPECT_TRUE(op.pressure.empty()) << "a mouse presses fully: the field is left out";
    EXPECT_DOUBLE_EQ(op.alpha, 20.0);
    EXPECT_TRUE(mCanvas->strokePoints().empty());
    EXPECT_TRUE(mCanvas->pendingSteps().empty());
    EXPECT_NO_THROW(validateGenome(withSteps(mDesign, mMade[0]), "stylus drag"));

    // Sharp on release: the canvas shows the design with the stroke, exactly as the renderer does.
    MARBLER_WAIT(mCanvas->imageFinal(), 60000);
    RenderSettings settings;
    settings.width = 400;
    settings.height = 400;
    settings.aa = "rgss";
    settings.region = mCanvas->view().visibleWindow()->region;
    const QImage expected = toQImage(CpuRenderer(withSteps(mDesign, mMade[0])).render(settings));
    EXPECT_EQ(mCanvas->image(), expected.convertToFormat(mCanvas->image().format()));
    const QImage before = toQImage(CpuRenderer(mDesign).render(settings));
    EXPECT_NE(expected, before) << "the stroke moved ink";
}

TEST_F(StylusCanvasTest, ATabletStrokeFillsPressureWithThePensValues) {
    const std::vector<glm::dvec2> drag = curve(50);
    std::vector<double> pressures;
    for (std::size_t i = 0; i < drag.size(); ++i)
        pressures.push_back(0.2 + 0.7 * double(i) / double(drag.size() - 1)); // pressing harder
    auto widget = [&](glm::dvec2 p) { return QPointF(mCanvas->toWidget({p.x, p.y, 0.0}).toPoint()); };
    EXPECT_TRUE(sendTablet(mCanvas.get(), QEvent::TabletPress, widget(drag[0]), pressures[0]));
    for (std::size_t i = 1; i < drag.size(); ++i)
        EXPECT_TRUE(sendTablet(mCanvas.get(), QEvent::TabletMove, widget(drag[i]), pressures[i]));
    EXPECT_EQ(mCanvas->strokePoints().size(), drag.size());
    EXPECT_TRUE(sendTablet(mCanvas.get(), QEvent::TabletRelease, widget(drag.back()), 0.0));

    ASSERT_EQ(mMade.size(), 1u);
    ASSERT_EQ(mMade[0].size(), 1u);
    const Operation op = mMade[0][0];
    ASSERT_EQ(op.pressure.size(), op.path.size()) << "one value a path point";
    EXPECT_NEAR(op.pressure.front(), pressures.front(), 1e-6);
    EXPECT_NEAR(op.pressure.back(), pressures.back(), 1e-6) << "the pen's lift (0) does not end the stroke";
    // Each point's pressure is the pen's where the path passes (pressure grows with x here).
    const std::vector<glm::dvec2> track = landed(*mCanvas, drag);
    for (std::size_t i = 0; i < op.path.size(); ++i) {
        EXPECT_GE(op.pressure[i], 0.0);
        EXPECT_LE(op.pressure[i], 1.0);
        const double along = (op.path[i].x - track.front().x) / (track.back().x - track.front().x);
        EXPECT_NEAR(op.pressure[i], 0.2 + 0.7 * along, 0.05) << i;
        if (i > 0) {
            EXPECT_GE(op.pressure[i], op.pressure[i - 1] - 1e-9);
        }
    }
    EXPECT_EQ(op.steps, minimumStylusSteps(op));
    // What is kept: the file says the pen's pressure.
    const Genome made = withSteps(mDesign, mMade[0]);
    const auto json = nlohmann::json::parse(serializeGenome(made));
    const auto& written = json.at("operations").back().at("pressure");
    ASSERT_EQ(written.size(), op.path.size());
    for (std::size_t i = 0; i < op.path.size(); ++i)
        EXPECT_DOUBLE_EQ(written[i].get<double>(), op.pressure[i]);

    // Another tool leaves the pen to Qt's mouse events.
    mCanvas->setTool(Tool::Drop);
    EXPECT_FALSE(sendTablet(mCanvas.get(), QEvent::TabletPress, widget(drag[0]), 0.5));
}

TEST_F(StylusCanvasTest, AStrokeTooLongForAStylusIsRefusedWithAMessage) {
    ToolSettings s;
    s.pull = 100000; // a stroke this strong needs far more than 100,000 steps
    mCanvas->setToolSettings(s);
    QStringList said;
    QObject::connect(mCanvas.get(), &EditorCanvas::gestureRefused, [&](const QString& why) { said << why; });
    mouseStroke(mCanvas.get(), curve(30));
    EXPECT_TRUE(mMade.empty());
    ASSERT_EQ(said.size(), 1);
    EXPECT_TRUE(said[0].contains(QStringLiteral("100000"))) << said[0].toStdString();
    EXPECT_TRUE(said[0].contains(QStringLiteral("shorter"))) << said[0].toStdString();
    // A click says nothing: it is simply no stroke.
    mouseStroke(mCanvas.get(), {{500, 500}, {500, 500}});
    EXPECT_EQ(said.size(), 1);
}

TEST_F(StylusCanvasTest, EscapeDropsAStrokeBeingDrawn) {
    const std::vector<glm::dvec2> drag = curve(20);
    auto widget = [&](glm::dvec2 p) { return mCanvas->toWidget({p.x, p.y, 0.0}).toPoint(); };
    QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, widget(drag.front()));
    for (const glm::dvec2& p : drag)
        QTest::mouseMove(mCanvas.get(), widget(p));
    ASSERT_EQ(mCanvas->pendingSteps().size(), 1u);
    QKeyEvent escape(QEvent::KeyPress, Qt::Key_Escape, Qt::NoModifier);
    QApplication::sendEvent(mCanvas.get(), &escape);
    EXPECT_TRUE(escape.isAccepted());
    EXPECT_TRUE(mCanvas->pendingSteps().empty());
    EXPECT_TRUE(mCanvas->strokePoints().empty());
    QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, widget(drag.back()));
    EXPECT_TRUE(mMade.empty()) << "nothing drawn";
    // The design shows as it was, sharp.
    MARBLER_WAIT(mCanvas->imageFinal(), 20000);
    RenderSettings settings;
    settings.width = 400;
    settings.height = 400;
    settings.aa = "rgss";
    settings.region = mCanvas->view().visibleWindow()->region;
    const QImage expected = toQImage(CpuRenderer(mDesign).render(settings));
    EXPECT_EQ(mCanvas->image(), expected.convertToFormat(mCanvas->image().format()))
        << mCanvas->image().width() << " x " << mCanvas->image().height() << " vs " << expected.width()
        << " x " << expected.height();
    if (mCanvas->image() != expected.convertToFormat(mCanvas->image().format())) {
        mCanvas->image().save(QStringLiteral("/tmp/seditor-escape-seen.png"));
        expected.save(QStringLiteral("/tmp/seditor-escape-expected.png"));
    }
}

TEST_F(StylusCanvasTest, AHandleDragMovesAPathPoint) {
    Genome g = mDesign;
    Operation stroke = defaultOperation(Tool::Stylus, 2, {500, 500, 0});
    stroke.path = {{250, 450}, {400, 520}, {550, 480}, {700, 500}};
    stroke.alpha = 20;
    stroke.steps = minimumStylusSteps(stroke);
    g.operations.push_back(stroke);
    mCanvas->setDesign(g);
    const std::size_t index = g.initial.size(); // the stroke, in rendered numbering
    mCanvas->setHandlesFor(index);
    const auto handles = mCanvas->handlePoints();
    ASSERT_EQ(handles.size(), stroke.path.size()) << "a handle on each point, nothing else";
    for (std::size_t i = 0; i < handles.size(); ++i) {
        EXPECT_EQ(handles[i].first, EditorCanvas::Handle::PathPoint);
        EXPECT_LT(
            QLineF(handles[i].second, mCanvas->toWidget({stroke.path[i].x, stroke.path[i].y, 0})).length(),
            1e-9);
    }
    std::vector<std::pair<Operation, bool>> moved;
    QObject::connect(mCanvas.get(), &EditorCanvas::handleDragged,
                     [&](std::size_t i, const Operation& op, bool final) {
                         EXPECT_EQ(i, index);
                         moved.emplace_back(op, final);
                     });
    const QPoint from = handles[1].second.toPoint(), to = from + QPoint(20, 40); // 50 and 100 units
    QTest::mousePress(mCanvas.get(), Qt::LeftButton, {}, from);
    QTest::mouseMove(mCanvas.get(), (from + to) / 2);
    QTest::mouseMove(mCanvas.get(), to);
    QTest::mouseRelease(mCanvas.get(), Qt::LeftButton, {}, to);
    ASSERT_GE(moved.size(), 2u);
    EXPECT_FALSE(moved.front().second);
    ASSERT_TRUE(moved.back().second);
    const Operation op = moved.back().first;
    EXPECT_TRUE(mMade.empty()) << "a handle drag draws no stroke";
    ASSERT_EQ(op.path.size(), stroke.path.size());
    const glm::dvec3 target = mCanvas->toDesign(to);
    EXPECT_LT(glm::length(op.path[1] - glm::dvec2(target.x, target.y)), 1e-9);
    EXPECT_NEAR(op.path[1].x, 450.0, 3.0);
    EXPECT_NEAR(op.path[1].y, 620.0, 3.0);
    for (std::size_t i : {0u, 2u, 3u})
        EXPECT_EQ(op.path[i], stroke.path[i]);
    EXPECT_EQ(op.steps, minimumStylusSteps(op)) << "still the fewest";
    Genome edited = g;
    edited.operations.back() = op;
    EXPECT_NO_THROW(validateGenome(edited, "moved path point"));
}

/// An editor window on the bath, with the stylus tool.
class StylusWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        mEditor =
            std::make_unique<EditorWindow>(stylusBath(), &mService, QString(), nullptr, mRecovery.path());
        mEditor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
        mEditor->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mEditor.get()));
        auto* action = mEditor->findChild<QAction*>(QStringLiteral("tool-stylus"));
        ASSERT_NE(action, nullptr);
        action->trigger();
        ASSERT_EQ(mEditor->tool(), EditorTool(Tool::Stylus));
    }
    void TearDown() override {
        mEditor->close();
        mEditor.reset();
    }

    RenderService mService{RenderService::Backend::Cpu};
    QTemporaryDir mRecovery;
    std::unique_ptr<EditorWindow> mEditor;
};

TEST_F(StylusWindowTest, ThePanelsValuesLandInTheStrokeAndUndoRedoAreExact) {
    ToolOptions* panel = mEditor->toolOptions();
    auto number = [&](const char* name) { return panel->findChild<QDoubleSpinBox*>(QLatin1String(name)); };
    auto* pull = number("toolPull");
    auto* lambda = number("toolStylusLambda");
    auto* reach = number("toolReach");
    auto* spacing = number("toolRakeSpacing");
    auto* tines = panel->findChild<QSpinBox*>(QStringLiteral("toolTines"));
    ASSERT_TRUE(pull && lambda && reach && spacing && tines);
    for (QWidget* box : std::initializer_list<QWidget*>{pull, lambda, reach, spacing, tines}) {
        EXPECT_TRUE(box->isVisible()) << box->objectName().toStdString();
        EXPECT_FALSE(box->toolTip().isEmpty()) << box->objectName().toStdString();
    }
    // They start at the registry's values.
    EXPECT_DOUBLE_EQ(pull->value(), findParam(Tool::Stylus, ParamField::Alpha)->editorValue());
    EXPECT_DOUBLE_EQ(lambda->value(), findParam(Tool::Stylus, ParamField::Lambda)->editorValue());
    EXPECT_DOUBLE_EQ(reach->value(), findParam(Tool::Stylus, ParamField::Reach)->editorValue());
    EXPECT_EQ(tines->value(), int(findParam(Tool::Stylus, ParamField::Tines)->editorValue()));
    EXPECT_DOUBLE_EQ(spacing->value(), findParam(Tool::Stylus, ParamField::Spacing)->editorValue());
    // Not the circle's own rows.
    EXPECT_FALSE(panel->findChild<QDoubleSpinBox*>(QStringLiteral("toolAlpha"))->isVisible());
    pull->setValue(15);
    lambda->setValue(6);
    reach->setValue(50);
    tines->setValue(3);
    spacing->setValue(25);
    // Remembered across tools, as every tool's settings are.
    mEditor->setTool(Tool::Comb);
    EXPECT_FALSE(pull->isVisible());
    mEditor->setTool(Tool::Stylus);
    EXPECT_DOUBLE_EQ(pull->value(), 15.0);
    EXPECT_EQ(tines->value(), 3);

    EditorDocument* doc = mEditor->document();
    const Genome before = doc->design();
    mouseStroke(mEditor->canvas(), curve(25));
    ASSERT_EQ(doc->design().operations.size(), before.operations.size() + 1);
    const Genome after = doc->design();
    const Operation& op = after.operations.back();
    EXPECT_EQ(op.tool, Tool::Stylus);
    EXPECT_DOUBLE_EQ(op.alpha, 15.0);
    EXPECT_DOUBLE_EQ(op.lambda, 6.0);
    EXPECT_DOUBLE_EQ(op.reach, 50.0);
    EXPECT_EQ(op.tines, 3);
    EXPECT_DOUBLE_EQ(op.spacing, 25.0);
    EXPECT_EQ(op.steps, minimumStylusSteps(op));
    EXPECT_EQ(doc->undoStack()->count(), 1) << "one stroke, one undo step";
    // The form shows it, every field.
    EXPECT_EQ(mEditor->selectedStep(),
              std::optional<std::size_t>(before.initial.size() + before.operations.size()));
    auto* pathText = mEditor->paramForm()->findChild<QLineEdit*>(QStringLiteral("edit-path-0"));
    ASSERT_NE(pathText, nullptr);
    EXPECT_EQ(pathText->text().count(QLatin1Char(';')), qsizetype(op.path.size() - 1));

    doc->undoStack()->undo();
    EXPECT_EQ(serializeGenome(doc->design()), serializeGenome(before));
    EXPECT_TRUE(doc->design() == before);
    doc->undoStack()->redo();
    EXPECT_EQ(serializeGenome(doc->design()), serializeGenome(after));
    EXPECT_TRUE(doc->design() == after);
}

TEST_F(StylusWindowTest, AMovedPathPointIsOneUndoStepAndARefusalIsSaid) {
    EditorDocument* doc = mEditor->document();
    mouseStroke(mEditor->canvas(), curve(20));
    ASSERT_EQ(doc->design().operations.size(), 1u);
    const Genome drawn = doc->design();
    EditorCanvas* canvas = mEditor->canvas();
    const auto handles = canvas->handlePoints();
    ASSERT_EQ(handles.size(), drawn.operations[0].path.size())
        << "the new stroke selected, its points handles";
    const QPoint from = handles[handles.size() / 2].second.toPoint(), to = from + QPoint(0, 30);
    QTest::mousePress(canvas, Qt::LeftButton, {}, from);
    QTest::mouseMove(canvas, from + QPoint(0, 10));
    QTest::mouseMove(canvas, to);
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, to);
    const Genome moved = doc->design();
    ASSERT_NE(moved.operations[0].path, drawn.operations[0].path);
    EXPECT_EQ(doc->undoStack()->count(), 2) << "a handle drag is one undo step";
    doc->undoStack()->undo();
    EXPECT_TRUE(doc->design() == drawn);
    doc->undoStack()->redo();
    EXPECT_TRUE(doc->design() == moved);

    // Too strong a stroke: nothing added, the status bar says why.
    mEditor->selectStep(std::nullopt);
    mEditor->toolOptions()->findChild<QDoubleSpinBox*>(QStringLiteral("toolPull"))->setValue(100000);
    mouseStroke(canvas, curve(20));
    EXPECT_EQ(doc->design().operations.size(), 1u);
    EXPECT_TRUE(mEditor->statusBar()->currentMessage().contains(QStringLiteral("shorter strokes")))
        << mEditor->statusBar()->currentMessage().toStdString();
}

TEST_F(StylusWindowTest, TheTimelineGrowsAStrokeAsTheStylusTravels) {
    EditorDocument* doc = mEditor->document();
    mouseStroke(mEditor->canvas(), curve(20));
    ASSERT_EQ(doc->design().operations.size(), 1u);
    const Genome whole = doc->renderedDesign();
    const Operation& stroke = whole.operations[0];
    const double total = double(stepCount(whole));
    mEditor->timeline()->setGrowth(total - 0.5); // the stroke half drawn
    const Genome shown = mEditor->canvas()->design();
    EXPECT_TRUE(shown == designAtGrowth(whole, total - 0.5));
    ASSERT_EQ(shown.operations.size(), 1u);
    const Operation& half = shown.operations[0];
    EXPECT_EQ(half.steps, stroke.steps / 2) << "the first floor(s n) integration steps";
    EXPECT_NEAR(pathLength(half), pathLength(stroke) * half.steps / stroke.steps, 1e-6)
        << "the stylus has travelled that far along its path";
    EXPECT_EQ(half.path.front(), stroke.path.front());
    // The canvas shows it as the renderer draws it.
    MARBLER_WAIT(mEditor->canvas()->imageFinal(), 60000);
    const QImage seen = mEditor->canvas()->image();
    RenderSettings settings;
    settings.width = seen.width();
    settings.height = seen.height();
    settings.aa = "rgss";
    settings.region = mEditor->canvas()->view().visibleWindow()->region;
    EXPECT_EQ(seen, toQImage(CpuRenderer(shown).render(settings)).convertToFormat(seen.format()));
    mEditor->timeline()->setGrowth(total);
    EXPECT_TRUE(mEditor->canvas()->design() == whole);
}

} // namespace

// The form: a stylus's path and pressure as text, each mistake named by its field.
TEST(StylusFormTest, PathAndPressureAreEditedAsTextWithMessagesNamingTheField) {
    ParamForm form;
    form.show();
    Genome g = stylusBath();
    Operation stroke = defaultOperation(Tool::Stylus, 2, {500, 500, 0});
    stroke.path = {{250, 450}, {400, 520}, {550, 480}};
    stroke.steps = minimumStylusSteps(stroke);
    form.setStep(stroke, 2, g);
    QApplication::processEvents(); // the new rows are shown from the event loop
    std::vector<Operation> edits;
    QObject::connect(&form, &ParamForm::edited,
                     [&](const Operation& op, const QString&, bool) { edits.push_back(op); });
    auto* path = form.findChild<QLineEdit*>(QStringLiteral("edit-path-0"));
    auto* pressure = form.findChild<QLineEdit*>(QStringLiteral("edit-pressure-0"));
    auto* pathError = form.findChild<QLabel*>(QStringLiteral("error-path"));
    auto* pressureError = form.findChild<QLabel*>(QStringLiteral("error-pressure"));
    ASSERT_TRUE(path && pressure && pathError && pressureError);
    ASSERT_TRUE(path->isVisible());
    EXPECT_EQ(path->text(), QStringLiteral("250 450; 400 520; 550 480"));
    EXPECT_TRUE(pressure->text().isEmpty());
    for (const char* field : {"alpha", "lambda", "reach", "tines", "spacing", "steps"})
        EXPECT_NE(form.findChild<QWidget*>(QStringLiteral("edit-%1-0").arg(QLatin1String(field))), nullptr)
            << field;

    auto type = [](QLineEdit* line, const QString& text) {
        line->setText(text);
        emit line->editingFinished();
    };
    // A longer path: committed, its steps raised to the fewest valid.
    type(path, QStringLiteral("100 500; 400 520; 700 480; 900 500"));
    ASSERT_EQ(edits.size(), 1u);
    EXPECT_EQ(edits.back().path, (std::vector<glm::dvec2>{{100, 500}, {400, 520}, {700, 480}, {900, 500}}));
    EXPECT_EQ(edits.back().steps, minimumStylusSteps(edits.back()));
    EXPECT_FALSE(pathError->isVisible());

    // Mistakes: nothing emitted, the field's label and the point said.
    type(path, QStringLiteral("100 500; 100 500"));
    EXPECT_EQ(edits.size(), 1u);
    EXPECT_TRUE(pathError->isVisible());
    EXPECT_TRUE(pathError->text().startsWith(QStringLiteral("Path:"))) << pathError->text().toStdString();
    EXPECT_TRUE(pathError->text().contains(QStringLiteral("point 2"))) << pathError->text().toStdString();
    EXPECT_EQ(path->text(), QStringLiteral("100 500; 400 520; 700 480; 900 500")) << "the value kept shown";
    type(path, QStringLiteral("100 500; abc"));
    EXPECT_TRUE(pathError->text().contains(QStringLiteral("not two numbers")))
        << pathError->text().toStdString();
    type(path, QStringLiteral("100 500"));
    EXPECT_TRUE(pathError->text().contains(QStringLiteral("2 to 1000"))) << pathError->text().toStdString();
    EXPECT_EQ(edits.size(), 1u);

    type(pressure, QStringLiteral("0.5 0.5"));
    EXPECT_EQ(edits.size(), 1u);
    EXPECT_TRUE(pressureError->isVisible());
    EXPECT_TRUE(pressureError->text().startsWith(QStringLiteral("Pressure:")))
        << pressureError->text().toStdString();
    EXPECT_TRUE(pressureError->text().contains(QStringLiteral("4 path points")));
    type(pressure, QStringLiteral("0.5 1.5 1 1"));
    EXPECT_TRUE(pressureError->text().contains(QStringLiteral("value 2")))
        << pressureError->text().toStdString();
    type(pressure, QStringLiteral("0.2 0.5 1 0.8"));
    ASSERT_EQ(edits.size(), 2u);
    EXPECT_EQ(edits.back().pressure, (std::vector<double>{0.2, 0.5, 1, 0.8}));
    EXPECT_FALSE(pressureError->isVisible());
    type(pressure, QStringLiteral("1 1 1 1"));
    ASSERT_EQ(edits.size(), 3u);
    EXPECT_TRUE(edits.back().pressure.empty()) << "all 1 is no pressure";

    // A stronger pull takes more steps, not a weaker pull.
    auto* alpha = form.findChild<QDoubleSpinBox*>(QStringLiteral("edit-alpha-0"));
    ASSERT_NE(alpha, nullptr);
    alpha->setValue(120);
    ASSERT_EQ(edits.size(), 4u);
    EXPECT_DOUBLE_EQ(edits.back().alpha, 120.0);
    EXPECT_EQ(edits.back().steps, minimumStylusSteps(edits.back()));
    Genome withStroke = g;
    withStroke.operations.push_back(edits.back());
    EXPECT_NO_THROW(validateGenome(withStroke, "form"));
}
