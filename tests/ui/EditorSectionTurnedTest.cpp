// A solid's section turned to any orientation, and the solid paper's tools drawn on it (issue 23,
// part 2): the plane's mapping (Sampling.h), a section typed or tilted in the editor and rendered
// there as the renderer renders it, a sphere and a circle about a typed axis dragged on a turned
// section with the mouse, placed on that plane, and undone and redone exactly.

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/EditorCanvas.h"
#include "editor/EditorDocument.h"
#include "editor/EditorWindow.h"
#include "editor/Gestures.h"
#include "editor/SolidObjectView.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "shared/DesignDialog.h"
#include "shared/DesignExport.h"
#include "shared/ExportSettingsDialog.h"
#include "shared/RenderService.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace marbler;
using namespace marbler::ui;

namespace turned_section_test {

/// A solid of concentric shells in two inks about its centre, with an off-centre drop of a third:
/// every section through it shows rings that a turn about any axis visibly moves.
Genome shells() {
    Genome g;
    g.dimension = 3;
    g.size = {600, 600, 600};
    g.palette = {{200, 30, 30}, {30, 30, 200}, {240, 200, 40}};
    for (int i = 0; i < 8; ++i) {
        Operation drop = defaultOperation(Tool::Drop, 3, {300, 300, 300});
        drop.radius = 140;
        drop.color = i % 2;
        g.initial.push_back(drop);
    }
    Operation spot = defaultOperation(Tool::Drop, 3, {380, 260, 320});
    spot.radius = 60;
    spot.color = 2;
    g.initial.push_back(spot);
    return g;
}

Image render(const Genome& g, const Slice& slice, int side = 64) {
    RenderSettings settings;
    settings.width = settings.height = side;
    settings.slice = slice;
    return CpuRenderer(g).render(settings);
}

bool samePixels(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (int y = 0; y < a.height; ++y)
        if (!std::equal(a.row(y), a.row(y) + 3 * a.width, b.row(y))) return false;
    return true;
}

TEST(TurnedSectionTest, ANormalAlongAnAxisRendersExactlyAsTheAxisSection) {
    const Genome g = shells();
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 n(0.0);
        n[axis] = 1.0;
        EXPECT_TRUE(samePixels(render(g, Slice{axis, 290.0}), render(g, Slice{2, 290.0, n})))
            << "normal along axis " << axis;
        EXPECT_TRUE(samePixels(render(g, Slice{axis, 290.0}), render(g, Slice{axis, -290.0, -n})))
            << "the opposite normal, the same plane";
    }
}

TEST(TurnedSectionTest, ATurnedPlaneMapsItsCoordinatesOntoItselfAndCoversTheBox) {
    const glm::dvec3 size{600, 400, 500};
    const glm::dvec3 n = glm::normalize(glm::dvec3{1, 2, 2});
    const Slice slice{2, 333.0, n};
    const SlicePlane plane = slicePlane(3, slice, size);
    ASSERT_TRUE(plane.turned);
    EXPECT_NEAR(glm::dot(plane.u(), plane.v()), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(plane.u(), n), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(plane.v(), n), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(plane.normal() - n), 0.0, 1e-12);
    const glm::dvec2 extent = plane.extent(size);
    for (double a : {0.0, 0.3, 1.0})
        for (double b : {0.0, 0.7, 1.0}) {
            const glm::dvec2 q{a * extent.x, b * extent.y};
            const glm::dvec3 p = plane.fromPlane(q);
            EXPECT_NEAR(glm::dot(p, n), 333.0, 1e-9) << "on the plane";
            EXPECT_NEAR(glm::length(plane.toPlane(p) - q), 0.0, 1e-9);
        }
    // Every corner of the box lies within the extent once projected onto the plane.
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 c{corner & 1 ? size.x : 0.0, corner & 2 ? size.y : 0.0, corner & 4 ? size.z : 0.0};
        const glm::dvec2 q = plane.toPlane(c);
        EXPECT_GE(q.x, -1e-9);
        EXPECT_GE(q.y, -1e-9);
        EXPECT_LE(q.x, extent.x + 1e-9);
        EXPECT_LE(q.y, extent.y + 1e-9);
    }
    const glm::dvec2 range = sliceOffsetRange(n, size);
    EXPECT_DOUBLE_EQ(range.x, 0.0);
    EXPECT_DOUBLE_EQ(range.y, n.x * 600 + n.y * 400 + n.z * 500);
    // A bad normal is refused with the slice named.
    RenderSettings settings;
    settings.width = settings.height = 8;
    settings.slice = Slice{2, 0.0, glm::dvec3(0.0)};
    try {
        checkRenderSettings(shells(), settings);
        ADD_FAILURE() << "a zero normal was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("slice normal"), std::string::npos) << e.what();
    }
}

TEST(TurnedSectionTest, GesturesOnATurnedPlaneLieInIt) {
    const Genome g = shells();
    const glm::dvec3 n = glm::normalize(glm::dvec3{2, -1, 3});
    const SlicePlane plane = slicePlane(3, Slice{2, 310.0, n}, g.size);
    const glm::dvec3 press = plane.fromPlane({300, 280}), release = plane.fromPlane({420, 330});
    const double length = glm::length(release - press);
    ToolSettings s;
    const auto sphere = gestureSteps(Tool::Sphere, s, press, release, g, plane);
    ASSERT_EQ(sphere.size(), 1u);
    EXPECT_EQ(sphere[0].tool, Tool::Sphere);
    EXPECT_NEAR(glm::dot(sphere[0].center, n), 310.0, 1e-9);
    EXPECT_DOUBLE_EQ(sphere[0].radius, length);
    EXPECT_NEAR(glm::length(sphere[0].axis - n), 0.0, 1e-12) << "across the section by default";
    s.axis = glm::dvec3{0, 0, 5};
    const auto circle = gestureSteps(Tool::Circle, s, press, release, g, plane);
    ASSERT_EQ(circle.size(), 1u);
    EXPECT_NEAR(glm::length(circle[0].axis - glm::dvec3{0, 0, 1}), 0.0, 1e-12) << "the typed axis, made unit";
    const auto comb = gestureSteps(Tool::Comb, s, press, release, g, plane);
    ASSERT_EQ(comb.size(), 1u);
    EXPECT_NEAR(glm::dot(comb[0].direction, n), 0.0, 1e-12) << "the stroke moves in the plane";
    EXPECT_NEAR(glm::dot(comb[0].normal, n), 0.0, 1e-12);
    for (const auto& ops : {sphere, circle, comb})
        EXPECT_NO_THROW(validateGenome(withSteps(g, ops), "turned gesture"));
}

/// An editor on a CPU render service, shown, on `design`.
class TurnedEditorTest : public ::testing::Test {
protected:
    void open(const Genome& design) {
        mEditor = std::make_unique<EditorWindow>(design, &mService, QString(), nullptr, mRecovery.path());
        mEditor->setUnsavedAnswer(EditorWindow::UnsavedAnswer::Discard);
        mEditor->resize(1100, 800);
        mEditor->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mEditor.get()));
        MARBLER_WAIT(mEditor->canvas()->view().scale() > 0.0, 30000);
    }
    void TearDown() override {
        if (mEditor) mEditor->close();
        mEditor.reset();
    }
    /// Types `text` into the line edit named `name` and presses Enter, as a user does.
    void type(const char* name, const QString& text) {
        auto* edit = mEditor->findChild<QLineEdit*>(QString::fromLatin1(name));
        ASSERT_NE(edit, nullptr) << name;
        edit->setFocus();
        edit->clear();
        QTest::keyClicks(edit, text);
        QTest::keyClick(edit, Qt::Key_Return);
    }
    /// Presses at `from`, moves halfway and to `to`, releases there (design points on the section).
    void drag(const glm::dvec3& from, const glm::dvec3& to) {
        EditorCanvas* canvas = mEditor->canvas();
        const QPoint a = canvas->toWidget(from).toPoint(), b = canvas->toWidget(to).toPoint();
        QTest::mousePress(canvas, Qt::LeftButton, {}, a);
        QTest::mouseMove(canvas, (a + b) / 2);
        QTest::mouseMove(canvas, b);
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, b);
    }
    /// What the canvas shows once its render is final, and the renderer's render of the same
    /// section and region: the person sees exactly the section asked for.
    QImage shownSection(const Genome& design) {
        EditorCanvas* canvas = mEditor->canvas();
        bool final = false;
        (void)QTest::qWaitFor([&] { return canvas->imageFinal() && !canvas->image().isNull(); }, 60000);
        final = canvas->imageFinal();
        EXPECT_TRUE(final) << "the canvas's render never came";
        RenderSettings settings;
        settings.width = canvas->image().width();
        settings.height = canvas->image().height();
        settings.aa = "rgss";
        settings.slice = canvas->slice();
        settings.region = canvas->view().visibleWindow()->region;
        const QImage expected = toQImage(CpuRenderer(design).render(settings));
        EXPECT_EQ(canvas->image(), expected.convertToFormat(canvas->image().format()))
            << "the canvas shows the renderer's section";
        return canvas->image();
    }
    /// The middle of the section shown, and a unit vector along its first axis, in design space.
    void sectionMiddle(glm::dvec3& middle, glm::dvec3& along) const {
        const Genome& design = mEditor->document()->design();
        const SlicePlane plane = slicePlane(3, mEditor->canvas()->slice(), design.size);
        middle = plane.fromPlane(0.5 * plane.extent(design.size));
        along = plane.u();
    }

    RenderService mService{RenderService::Backend::Cpu};
    QTemporaryDir mRecovery;
    std::unique_ptr<EditorWindow> mEditor;
};

/// The fraction of pixels of `a` and `b` that differ by more than a little.
double changed(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return 1.0;
    int diff = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor p = a.pixelColor(x, y), q = b.pixelColor(x, y);
            diff += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green()) +
                        std::abs(p.blue() - q.blue()) >
                    24;
        }
    return double(diff) / (a.width() * a.height());
}

TEST_F(TurnedEditorTest, ASphereDraggedOnATypedTurnedSectionLiesOnItAndUndoesExactly) {
    open(shells());
    type("sliceNormal", QStringLiteral("1, 1, 1"));
    const Slice slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value()) << "the typed normal turned the section";
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 1));
    EXPECT_NEAR(glm::length(*slice.normal - n), 0.0, 1e-12);
    auto* error = mEditor->findChild<QLabel*>(QStringLiteral("sliceNormalError"));
    ASSERT_NE(error, nullptr);
    EXPECT_FALSE(error->isVisible());
    const Genome design = mEditor->document()->design();
    const QImage before = shownSection(design);

    auto* sphere = mEditor->findChild<QAction*>(QStringLiteral("tool-sphere"));
    ASSERT_NE(sphere, nullptr) << "the sphere is on a solid's tool bar";
    EXPECT_EQ(sphere->shortcut(), QKeySequence(Qt::Key_H));
    EXPECT_FALSE(sphere->toolTip().isEmpty());
    sphere->trigger();
    glm::dvec3 middle, along;
    sectionMiddle(middle, along);
    const std::size_t steps = mEditor->document()->stepCount();
    const std::string beforeText = serializeGenome(mEditor->document()->design());
    drag(middle, middle + 120.0 * along);
    ASSERT_EQ(mEditor->document()->stepCount(), steps + 1) << "one step";
    const Genome after = mEditor->document()->design();
    ASSERT_EQ(after.operations.size(), design.operations.size() + 1);
    const Operation& made = after.operations.back();
    EXPECT_EQ(made.tool, Tool::Sphere);
    const double pixel = 2.0 / mEditor->canvas()->view().scale();
    EXPECT_NEAR(glm::dot(made.center, n), slice.value, 1e-6) << "the centre lies on the turned section";
    EXPECT_NEAR(glm::length(made.center - middle), 0.0, pixel) << "where it was pressed";
    EXPECT_NEAR(made.radius, 120.0, pixel) << "the radius is the drag's length";
    EXPECT_NEAR(glm::length(made.axis - n), 0.0, 1e-12) << "no axis typed: across the section";
    EXPECT_NO_THROW(validateGenome(after, "sphere on a turned section"));

    // What the person sees changed where the sphere turned the ink, and is the renderer's.
    const QImage shown = shownSection(after);
    EXPECT_GT(changed(before, shown), 0.01);

    const std::string afterText = serializeGenome(after);
    mEditor->document()->undoStack()->undo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), beforeText) << "undo is exact";
    mEditor->document()->undoStack()->redo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), afterText) << "redo is exact";

    // The selected sphere's axis handle, dragged an arm and a half out along the section's first
    // axis, lays its axis in the section along that axis; undo puts it back across.
    mEditor->selectStep(mEditor->document()->stepCount() - 1);
    EditorCanvas* canvas = mEditor->canvas();
    QPointF axisHandle;
    for (const auto& [handle, point] : canvas->handlePoints())
        if (handle == EditorCanvas::Handle::Axis) axisHandle = point;
    ASSERT_FALSE(axisHandle.isNull()) << "a solid's sphere has an axis handle";
    const QPointF centre = canvas->toWidget(made.center);
    EXPECT_NEAR(std::hypot(axisHandle.x() - centre.x(), axisHandle.y() - centre.y()), 35.0, 1.0)
        << "half an arm out while the axis is across the section";
    const QPointF alongWidget = canvas->toWidget(made.center + along) - centre;
    const QPointF target = centre + 110.0 * alongWidget / std::hypot(alongWidget.x(), alongWidget.y());
    QTest::mousePress(canvas, Qt::LeftButton, {}, axisHandle.toPoint());
    QTest::mouseMove(canvas, ((axisHandle + target) / 2).toPoint());
    QTest::mouseMove(canvas, target.toPoint());
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, target.toPoint());
    const Operation tilted = mEditor->document()->design().operations.back();
    EXPECT_NEAR(glm::dot(tilted.axis, n), 0.0, 0.02) << "lying in the section";
    EXPECT_NEAR(glm::dot(tilted.axis, along), 1.0, 0.02) << "along the drag";
    EXPECT_EQ(tilted.center, made.center);
    mEditor->document()->undoStack()->undo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), afterText)
        << "the handle's edit undoes exactly";
}

TEST_F(TurnedEditorTest, ACircleAboutATypedAxisOnATiltedSectionTurnsAboutThatAxis) {
    open(shells());
    // The tilt handle, dragged to 30 degrees from z.
    auto* tilt = mEditor->findChild<QSlider*>(QStringLiteral("sliceTilt"));
    ASSERT_NE(tilt, nullptr);
    tilt->setValue(30);
    const Slice slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value());
    const glm::dvec3 n = *slice.normal;
    EXPECT_NEAR(std::acos(n.z) * 180.0 / std::numbers::pi, 30.0, 1e-9) << "tilted 30 degrees from z";
    auto* shownNormal = mEditor->findChild<QLineEdit*>(QStringLiteral("sliceNormal"));
    ASSERT_NE(shownNormal, nullptr);
    EXPECT_FALSE(shownNormal->text().isEmpty()) << "the normal box says the handle's normal";
    auto* value = mEditor->findChild<QDoubleSpinBox*>(QStringLiteral("sliceValue"));
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->prefix(), QStringLiteral("n·p = ")) << "the position is along the normal now";
    EXPECT_NEAR(value->value(), slice.value, 0.05);

    auto* circle = mEditor->findChild<QAction*>(QStringLiteral("tool-circle"));
    ASSERT_NE(circle, nullptr);
    circle->trigger();
    auto* axisBox = mEditor->findChild<QLineEdit*>(QStringLiteral("toolAxis"));
    ASSERT_NE(axisBox, nullptr);
    EXPECT_TRUE(axisBox->isVisible()) << "a solid's circle has an axis row";
    // A bad axis is refused with a message naming it, and changes nothing.
    type("toolAxis", QStringLiteral("0, 0, zero"));
    auto* axisError = mEditor->findChild<QLabel*>(QStringLiteral("toolAxisError"));
    ASSERT_NE(axisError, nullptr);
    EXPECT_TRUE(axisError->isVisible());
    EXPECT_TRUE(axisError->text().contains(QStringLiteral("0, 0, zero"))) << axisError->text().toStdString();
    type("toolAxis", QStringLiteral("0, 1, 1"));
    EXPECT_FALSE(axisError->isVisible());

    const Genome design = mEditor->document()->design();
    const QImage before = shownSection(design);
    glm::dvec3 middle, along;
    sectionMiddle(middle, along);
    const std::string beforeText = serializeGenome(design);
    drag(middle, middle + 100.0 * along);
    const Genome after = mEditor->document()->design();
    ASSERT_EQ(after.operations.size(), design.operations.size() + 1);
    const Operation& made = after.operations.back();
    EXPECT_EQ(made.tool, Tool::Circle);
    const double pixel = 2.0 / mEditor->canvas()->view().scale();
    EXPECT_NEAR(glm::dot(made.center, n), slice.value, 1e-6) << "the centre lies on the tilted section";
    EXPECT_NEAR(made.radius, 100.0, pixel);
    EXPECT_NEAR(glm::length(made.axis - glm::normalize(glm::dvec3(0, 1, 1))), 0.0, 1e-12) << "the typed axis";
    EXPECT_NO_THROW(validateGenome(after, "circle about an axis"));
    EXPECT_GT(changed(before, shownSection(after)), 0.01);

    const std::string afterText = serializeGenome(after);
    mEditor->document()->undoStack()->undo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), beforeText);
    mEditor->document()->undoStack()->redo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), afterText);
}

TEST_F(TurnedEditorTest, ABadNormalIsRefusedWithItsTextAndTheSectionStays) {
    open(shells());
    const Slice was = mEditor->canvas()->slice();
    type("sliceNormal", QStringLiteral("0 0 0"));
    auto* error = mEditor->findChild<QLabel*>(QStringLiteral("sliceNormalError"));
    ASSERT_NE(error, nullptr);
    EXPECT_TRUE(error->isVisible());
    EXPECT_TRUE(error->text().contains(QStringLiteral("0 0 0"))) << error->text().toStdString();
    EXPECT_FALSE(mEditor->canvas()->slice().normal.has_value());
    EXPECT_EQ(mEditor->canvas()->slice().axis, was.axis);
    EXPECT_EQ(mEditor->canvas()->slice().value, was.value);
    // Clearing it goes back across the axis.
    type("sliceNormal", QStringLiteral("0, 0.2, 1"));
    EXPECT_TRUE(mEditor->canvas()->slice().normal.has_value());
    type("sliceNormal", QString());
    EXPECT_FALSE(mEditor->canvas()->slice().normal.has_value());
}

TEST(TurnedSectionExportTest, ExportImageWritesTheSectionAtATypedNormal) {
    const Genome g = shells();
    ExportSettingsDialog dialog(g);
    auto* show = dialog.findChild<QComboBox*>(QStringLiteral("exportSolidView"));
    auto* normal = dialog.findChild<QLineEdit*>(QStringLiteral("exportNormal"));
    ASSERT_TRUE(show && normal);
    EXPECT_FALSE(normal->isEnabled()) << "the object view has no normal";
    show->setCurrentIndex(1);
    EXPECT_TRUE(normal->isEnabled());
    normal->setFocus();
    QTest::keyClicks(normal, QStringLiteral("1, 0, 1"));
    QTest::keyClick(normal, Qt::Key_Return);
    const std::optional<SolidExport> solid = dialog.solidExport();
    ASSERT_TRUE(solid && !solid->objectView);
    ASSERT_TRUE(solid->slice.normal.has_value());
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 0, 1));
    EXPECT_NEAR(glm::length(*solid->slice.normal - n), 0.0, 1e-12);
    EXPECT_NEAR(solid->slice.value, 0.5 * (600 * n.x + 600 * n.z), 0.01) << "through the block's middle";
    // The image's aspect is the turned plane's: the block's width along its tilted axis.
    const glm::dvec2 extent = slicePlane(3, solid->slice, g.size).extent(g.size);
    const QSize size = dialog.pixels();
    ASSERT_GT(size.width(), 0);
    EXPECT_NEAR(double(size.height()) / size.width(), extent.y / extent.x, 2.0 / size.width());

    QWidget window;
    DesignExport exporter(&window);
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("turned.png"));
    QSignalSpy finished(&exporter, &DesignExport::finished);
    const QSize pixels(85, 60);
    ASSERT_TRUE(
        exporter.exportTo(g, {}, file, pixels, QStringLiteral("none"), std::nullopt, solid, 8, false));
    MARBLER_WAIT(finished.size() == 1, 60000);
    ASSERT_TRUE(finished.front().at(1).toBool()) << finished.front().at(2).toString().toStdString();
    // The file on disk is the renderer's section at that normal, not the axis section.
    RenderSettings settings;
    settings.width = pixels.width();
    settings.height = pixels.height();
    settings.slice = solid->slice;
    const QImage written(file);
    ASSERT_EQ(written.size(), pixels);
    // Pixel by pixel (the file's colour space tag is no part of what the person sees).
    const auto differing = [&](const Image& expected) {
        int count = 0;
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < expected.width; ++x) {
                const std::uint8_t* e = expected.row(y) + 3 * x;
                count += written.pixel(x, y) != qRgb(e[0], e[1], e[2]);
            }
        return count;
    };
    EXPECT_EQ(differing(CpuRenderer(g).render(settings)), 0);
    settings.slice = Slice{2, solid->slice.value};
    EXPECT_GT(differing(CpuRenderer(g).render(settings)), 0) << "not the axis section";
}

TEST(TurnedSectionLargeViewTest, TheLargeViewShowsASectionTurnedToATypedNormal) {
    const Genome g = shells();
    RenderService service(RenderService::Backend::Cpu);
    DesignDialog dialog(g, &service, QStringLiteral("sphere"));
    dialog.resize(640, 720);
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    ASSERT_TRUE(test::activate(&dialog));
    auto* controls = dialog.findChild<QWidget*>(QStringLiteral("sectionControls"));
    ASSERT_NE(controls, nullptr);
    EXPECT_FALSE(controls->isVisible()) << "the object first";
    EXPECT_FALSE(dialog.section().has_value());

    // S: the cross-section across z through the middle, its controls below the view.
    QTest::keyClick(&dialog, Qt::Key_S);
    ASSERT_TRUE(dialog.section().has_value());
    EXPECT_TRUE(controls->isVisible());
    EXPECT_EQ(dialog.section()->axis, 2);
    EXPECT_DOUBLE_EQ(dialog.section()->value, 300.0);

    // A typed normal turns it; the view shows the renderer's section at that normal.
    auto* normal = controls->findChild<QLineEdit*>(QStringLiteral("sliceNormal"));
    ASSERT_NE(normal, nullptr);
    normal->setFocus();
    QTest::keyClicks(normal, QStringLiteral("1, 1, 0"));
    QTest::keyClick(normal, Qt::Key_Return);
    ASSERT_TRUE(dialog.section().has_value());
    ASSERT_TRUE(dialog.section()->normal.has_value());
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 0));
    EXPECT_NEAR(glm::length(*dialog.section()->normal - n), 0.0, 1e-12);
    MARBLER_WAIT(dialog.imageIsFinal(), 60000);
    const QImage shown = dialog.image();
    ASSERT_FALSE(shown.isNull());
    RenderSettings settings;
    settings.width = shown.width();
    settings.height = shown.height();
    settings.aa = "rgss";
    settings.slice = *dialog.section();
    const QImage expected = toQImage(CpuRenderer(g).render(settings));
    EXPECT_EQ(shown, expected.convertToFormat(shown.format())) << "the renderer's turned section";
    settings.slice = Slice{2, 300.0};
    EXPECT_NE(shown, toQImage(CpuRenderer(g).render(settings)).convertToFormat(shown.format()))
        << "not the section across z";

    // S again: the object, the controls gone; and back to the section last shown.
    QTest::keyClick(&dialog, Qt::Key_S);
    EXPECT_FALSE(dialog.section().has_value());
    EXPECT_FALSE(controls->isVisible());
    QTest::keyClick(&dialog, Qt::Key_S);
    ASSERT_TRUE(dialog.section().has_value());
    ASSERT_TRUE(dialog.section()->normal.has_value());
    EXPECT_NEAR(glm::length(*dialog.section()->normal - n), 0.0, 1e-12);
}

/// Drags the handle of `slider` by `pixels` to the right with the mouse, as a user does.
void dragSlider(QSlider* slider, int pixels) {
    QStyleOptionSlider option;
    option.initFrom(slider);
    option.orientation = slider->orientation();
    option.minimum = slider->minimum();
    option.maximum = slider->maximum();
    option.sliderPosition = option.sliderValue = slider->value();
    option.subControls = QStyle::SC_SliderHandle;
    const QPoint from =
        slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
    const QPoint to = from + QPoint(pixels, 0);
    QTest::mousePress(slider, Qt::LeftButton, {}, from);
    QTest::mouseMove(slider, (from + to) / 2);
    QTest::mouseMove(slider, to);
    QTest::mouseRelease(slider, Qt::LeftButton, {}, to);
}

TEST_F(TurnedEditorTest, ALineOnASectionTurnedByItsHandlesIsTurnedByItsDirectionHandle) {
    // Issue 23: the section turned by dragging its handles (not a typed normal), a line drawn on
    // it, and the line turned in the section by its direction handle, all with the mouse.
    open(shells());
    auto* tilt = mEditor->findChild<QSlider*>(QStringLiteral("sliceTilt"));
    auto* turn = mEditor->findChild<QSlider*>(QStringLiteral("sliceTurn"));
    ASSERT_NE(tilt, nullptr);
    ASSERT_NE(turn, nullptr);
    dragSlider(tilt, tilt->width() / 3);
    dragSlider(turn, turn->width() / 4);
    ASSERT_GT(tilt->value(), 5) << "the tilt handle moved under the mouse";
    ASSERT_GT(turn->value(), 5) << "the turn handle moved under the mouse";
    const Slice slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value()) << "the dragged handles turned the section";
    const glm::dvec3 n = *slice.normal;
    EXPECT_NEAR(std::acos(std::abs(n.z)) * 180.0 / std::numbers::pi, tilt->value(), 1e-6)
        << "tilted from z by the tilt handle's angle";
    auto* shownNormal = mEditor->findChild<QLineEdit*>(QStringLiteral("sliceNormal"));
    ASSERT_NE(shownNormal, nullptr);
    EXPECT_FALSE(shownNormal->text().isEmpty()) << "the normal box says the handles' normal";

    auto* line = mEditor->findChild<QAction*>(QStringLiteral("tool-line"));
    ASSERT_NE(line, nullptr);
    line->trigger();
    glm::dvec3 middle, along;
    sectionMiddle(middle, along);
    drag(middle, middle + 90.0 * along);
    const Genome drawn = mEditor->document()->design();
    const Operation made = drawn.operations.back();
    ASSERT_EQ(made.tool, Tool::Line);
    EXPECT_NEAR(glm::dot(made.center, n), slice.value, 1e-6) << "on the turned section";
    EXPECT_NEAR(glm::dot(made.direction, along), 1.0, 0.02) << "along the drag";
    const QImage before = shownSection(drawn);
    const std::string drawnText = serializeGenome(drawn);

    // Selected, the line shows a direction handle an arm out the way it moves ink.
    mEditor->selectStep(mEditor->document()->stepCount() - 1);
    EditorCanvas* canvas = mEditor->canvas();
    const QPointF centre = canvas->toWidget(made.center);
    QPointF handle;
    for (const auto& [kind, point] : canvas->handlePoints())
        if (kind == EditorCanvas::Handle::Direction) handle = point;
    ASSERT_FALSE(handle.isNull()) << "a solid's line has a direction handle";
    const QPointF alongWidget = canvas->toWidget(made.center + along) - centre;
    const QPointF arm = handle - centre;
    EXPECT_NEAR(std::hypot(arm.x(), arm.y()), 70.0, 1.0);
    EXPECT_NEAR((arm.x() * alongWidget.x() + arm.y() * alongWidget.y()) /
                    (std::hypot(arm.x(), arm.y()) * std::hypot(alongWidget.x(), alongWidget.y())),
                1.0, 0.02)
        << "pointing along the line's drag";

    // Dragged a quarter turn round: the line moves ink that way, still in the section.
    const QPointF target = centre + QPointF(-arm.y(), arm.x()) * (100.0 / 70.0);
    QTest::mousePress(canvas, Qt::LeftButton, {}, handle.toPoint());
    QTest::mouseMove(canvas, ((handle + target) / 2).toPoint());
    QTest::mouseMove(canvas, target.toPoint());
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, target.toPoint());
    const Genome turnedDesign = mEditor->document()->design();
    const Operation turned = turnedDesign.operations.back();
    const glm::dvec3 expected = glm::normalize(canvas->toDesign(target) - made.center);
    EXPECT_NEAR(glm::dot(turned.direction, expected), 1.0, 0.02) << "along the handle's drag";
    EXPECT_NEAR(glm::dot(turned.direction, n), 0.0, 1e-9) << "in the section";
    EXPECT_NEAR(glm::dot(turned.normal, n), 0.0, 1e-9) << "its normal in the section too";
    EXPECT_NEAR(glm::dot(turned.direction, turned.normal), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(turned.direction), 1.0, 1e-12);
    EXPECT_EQ(turned.center, made.center);
    EXPECT_EQ(turned.alpha, made.alpha);
    EXPECT_NO_THROW(validateGenome(turnedDesign, "line turned by its handle"));
    // What the person sees is the renderer's section of the turned line, not the drawn one.
    EXPECT_GT(changed(before, shownSection(turnedDesign)), 0.005);

    mEditor->document()->undoStack()->undo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), drawnText)
        << "the handle's edit undoes exactly";
}

TEST_F(TurnedEditorTest, ACircleOnASectionTurnedByMouseLeansItsAxisByItsHandle) {
    // Issue 23's "Done when": circles about any axis by mouse on a section at any angle. The
    // section turned by dragging its handles, a circle dragged on it (about the section's
    // normal), then its axis leant by dragging its axis handle: every step with the mouse.
    open(shells());
    auto* tilt = mEditor->findChild<QSlider*>(QStringLiteral("sliceTilt"));
    auto* turn = mEditor->findChild<QSlider*>(QStringLiteral("sliceTurn"));
    ASSERT_NE(tilt, nullptr);
    ASSERT_NE(turn, nullptr);
    dragSlider(tilt, tilt->width() / 4);
    dragSlider(turn, turn->width() / 2);
    const Slice slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value()) << "the dragged handles turned the section";
    const glm::dvec3 n = *slice.normal;

    auto* circle = mEditor->findChild<QAction*>(QStringLiteral("tool-circle"));
    ASSERT_NE(circle, nullptr);
    circle->trigger();
    glm::dvec3 middle, along;
    sectionMiddle(middle, along);
    drag(middle, middle + 110.0 * along);
    const Operation made = mEditor->document()->design().operations.back();
    ASSERT_EQ(made.tool, Tool::Circle);
    const double pixel = 2.0 / mEditor->canvas()->view().scale();
    EXPECT_NEAR(glm::dot(made.center, n), slice.value, 1e-6) << "on the turned section";
    EXPECT_NEAR(made.radius, 110.0, pixel);
    EXPECT_NEAR(glm::length(made.axis - n), 0.0, 1e-12) << "about the section's normal";
    const std::string madeText = serializeGenome(mEditor->document()->design());
    const QImage before = shownSection(mEditor->document()->design());

    // The axis handle dragged half an arm further out, across the section's first axis: the
    // axis leans that way by 30 degrees (sin = half), keeping its side of the section.
    mEditor->selectStep(mEditor->document()->stepCount() - 1);
    EditorCanvas* canvas = mEditor->canvas();
    QPointF axisHandle;
    for (const auto& [kind, point] : canvas->handlePoints())
        if (kind == EditorCanvas::Handle::Axis) axisHandle = point;
    ASSERT_FALSE(axisHandle.isNull()) << "a solid's circle has an axis handle";
    const QPointF centre = canvas->toWidget(made.center);
    const glm::dvec3 across = glm::normalize(glm::cross(n, along));
    const QPointF acrossWidget = canvas->toWidget(made.center + across) - centre;
    const QPointF target = centre + 70.0 * acrossWidget / std::hypot(acrossWidget.x(), acrossWidget.y());
    QTest::mousePress(canvas, Qt::LeftButton, {}, axisHandle.toPoint());
    QTest::mouseMove(canvas, ((axisHandle + target) / 2).toPoint());
    QTest::mouseMove(canvas, target.toPoint());
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, target.toPoint());
    const Genome leant = mEditor->document()->design();
    const Operation turned = leant.operations.back();
    EXPECT_NEAR(glm::dot(turned.axis, n), std::sqrt(0.75), 0.03) << "30 degrees from the normal";
    EXPECT_GT(glm::dot(turned.axis, across), 0.4) << "leaning the drag's way";
    EXPECT_NEAR(glm::length(turned.axis), 1.0, 1e-12);
    EXPECT_EQ(turned.center, made.center);
    EXPECT_NO_THROW(validateGenome(leant, "circle leant by its handle"));
    EXPECT_GT(changed(before, shownSection(leant)), 0.005) << "the section shows the leant circle";
    mEditor->document()->undoStack()->undo();
    EXPECT_EQ(serializeGenome(mEditor->document()->design()), madeText);
}

TEST_F(TurnedEditorTest, DraggingTheSectionsPlaneInTheObjectViewsCornerTurnsIt) {
    // Issue 23: the section turned by dragging a handle on the view, not only the panel's
    // sliders or a typed normal: the block and plane in the object view's corner, dragged right,
    // turn the normal about y, dragged down about x, through the same point of the middle.
    open(shells());
    auto* view = mEditor->findChild<SolidObjectView*>(QStringLiteral("objectView"));
    ASSERT_NE(view, nullptr);
    ASSERT_TRUE(view->isVisible());
    const Slice was = mEditor->canvas()->slice();
    ASSERT_FALSE(was.normal.has_value());
    const ViewAngle angle = view->angle();
    const glm::dvec3 size = mEditor->document()->design().size;
    const SlicePlane before = slicePlane(3, was, size);
    const glm::dvec3 middle = 0.5 * size;
    const glm::dvec3 kept = middle - (glm::dot(before.normal(), middle) - before.value) * before.normal();
    const QImage shownBefore = shownSection(mEditor->document()->design());

    const QPoint press = view->sliceInset().center().toPoint();
    auto dragBy = [&](QPoint by) {
        QTest::mousePress(view, Qt::LeftButton, {}, press);
        QTest::mouseMove(view, press + by / 2);
        QTest::mouseMove(view, press + by);
        QTest::mouseRelease(view, Qt::LeftButton, {}, press + by);
    };
    dragBy(QPoint(40, 0));
    Slice slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value()) << "the drag turned the section";
    const double a = 40 * 0.01;
    EXPECT_NEAR(glm::length(*slice.normal - glm::dvec3(std::sin(a), 0.0, std::cos(a))), 0.0, 1e-9)
        << "about y, its tip to the right";
    EXPECT_NEAR(slice.value, glm::dot(*slice.normal, kept), 1e-6) << "through the same point";
    auto* tilt = mEditor->findChild<QSlider*>(QStringLiteral("sliceTilt"));
    ASSERT_NE(tilt, nullptr);
    EXPECT_EQ(tilt->value(), int(std::lround(a * 180.0 / std::numbers::pi))) << "the panel shows the tilt";
    auto* normalBox = mEditor->findChild<QLineEdit*>(QStringLiteral("sliceNormal"));
    ASSERT_NE(normalBox, nullptr);
    EXPECT_FALSE(normalBox->text().isEmpty());
    EXPECT_EQ(view->angle().yaw, angle.yaw) << "the object did not turn";
    EXPECT_EQ(view->angle().pitch, angle.pitch);

    // Down: about x, the tip down (y falls).
    const glm::dvec3 n0 = *slice.normal;
    dragBy(QPoint(0, 30));
    slice = mEditor->canvas()->slice();
    ASSERT_TRUE(slice.normal.has_value());
    const double b = 30 * 0.01;
    const glm::dvec3 expected(n0.x, n0.y * std::cos(b) - n0.z * std::sin(b),
                              n0.y * std::sin(b) + n0.z * std::cos(b));
    EXPECT_NEAR(glm::length(*slice.normal - expected), 0.0, 1e-9);
    EXPECT_LT(slice.normal->y, 0.0);

    // The canvas shows the renderer's section at the new plane, and it differs.
    const QImage shownAfter = shownSection(mEditor->document()->design());
    EXPECT_GT(changed(shownBefore, shownAfter), 0.01);

    // A drag elsewhere on the view turns the object and leaves the section.
    const QPoint middleOfView(view->width() / 2, view->height() / 3);
    QTest::mousePress(view, Qt::LeftButton, {}, middleOfView);
    QTest::mouseMove(view, middleOfView + QPoint(20, 0));
    QTest::mouseMove(view, middleOfView + QPoint(40, 0));
    QTest::mouseRelease(view, Qt::LeftButton, {}, middleOfView + QPoint(40, 0));
    EXPECT_NE(view->angle().yaw, angle.yaw) << "the object turned";
    EXPECT_EQ(*mEditor->canvas()->slice().normal, *slice.normal) << "the section stayed";
}

TEST_F(TurnedEditorTest, ASolidWavesDirectionHandleTurnsTheWayItShiftsInk) {
    // Issue 23: a wave's handle is its shift (`normal`, the way its drag went), and turning it
    // turns the wave's `direction` with it, both in the section, square to each other.
    open(shells());
    auto* wave = mEditor->findChild<QAction*>(QStringLiteral("tool-wave"));
    ASSERT_NE(wave, nullptr);
    wave->trigger();
    glm::dvec3 middle, along;
    sectionMiddle(middle, along);
    drag(middle, middle + 80.0 * along);
    const Operation made = mEditor->document()->design().operations.back();
    ASSERT_EQ(made.tool, Tool::Wave);
    EXPECT_NEAR(glm::dot(made.normal, along), 1.0, 0.02) << "the shift along the drag";
    mEditor->selectStep(mEditor->document()->stepCount() - 1);
    EditorCanvas* canvas = mEditor->canvas();
    const QPointF centre = canvas->toWidget(made.center);
    QPointF handle;
    for (const auto& [kind, point] : canvas->handlePoints())
        if (kind == EditorCanvas::Handle::Direction) handle = point;
    ASSERT_FALSE(handle.isNull()) << "a solid's wave has a direction handle";
    const QPointF alongWidget = canvas->toWidget(made.center + along) - centre;
    const QPointF arm = handle - centre;
    EXPECT_NEAR((arm.x() * alongWidget.x() + arm.y() * alongWidget.y()) /
                    (std::hypot(arm.x(), arm.y()) * std::hypot(alongWidget.x(), alongWidget.y())),
                1.0, 0.02)
        << "pointing the way the wave shifts ink";
    // Turned by 45 degrees.
    const QPointF target = centre + QPointF(arm.x() - arm.y(), arm.y() + arm.x());
    QTest::mousePress(canvas, Qt::LeftButton, {}, handle.toPoint());
    QTest::mouseMove(canvas, ((handle + target) / 2).toPoint());
    QTest::mouseMove(canvas, target.toPoint());
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, target.toPoint());
    const Genome turnedDesign = mEditor->document()->design();
    const Operation turned = turnedDesign.operations.back();
    const glm::dvec3 n = slicePlane(3, canvas->slice(), turnedDesign.size).normal();
    const glm::dvec3 expected = glm::normalize(canvas->toDesign(target) - made.center);
    EXPECT_NEAR(glm::dot(turned.normal, expected), 1.0, 0.02) << "the shift along the handle's drag";
    EXPECT_NEAR(glm::dot(turned.normal, n), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(turned.direction, n), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(turned.direction, turned.normal), 0.0, 1e-12);
    EXPECT_NO_THROW(validateGenome(turnedDesign, "wave turned by its handle"));
}

} // namespace turned_section_test
