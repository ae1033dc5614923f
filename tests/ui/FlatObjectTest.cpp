// Flat designs on objects in the window, and mesh files in the breeding window (issue 23): the
// render service draws objects on the CPU where there is no GL, the grid's object box offers
// flat designs an object and every population a mesh file, remembered with the session, and
// the large view and the editor's preview show a flat design on its object.

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "editor/EditorWindow.h"
#include "editor/SolidObjectView.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Generator.h"
#include "marbler/ObjectView.h"
#include "marbler/gl/GlRenderer.h"
#include "marbler/gl/Meshes.h"
#include "shared/DesignDialog.h"
#include "shared/MeshChooser.h"
#include "shared/RenderService.h"
#include "shared/ViewController.h"
#include "workbench/DesignCell.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace marbler {
namespace flat_object_test {

using ui::loadSession;
using ui::RenderRequest;
using ui::RenderService;
using ui::toQImage;
using ui::ViewAngle;
using ui::viewAngleOf;

/// The object view the service should make for a final pass of `genome` on `mesh` at the size
/// of `shown`, from the design's own angle.
QImage expectedObject(const Genome& genome, const MeshData& mesh, const QImage& shown, ViewAngle angle) {
    MeshSettings settings;
    settings.width = shown.width();
    settings.height = shown.height();
    settings.yaw = angle.yaw;
    settings.pitch = angle.pitch;
    settings.supersample = 3;
    return toQImage(renderObjectOnCpu(genome, mesh, settings));
}

/// Whether a pixel is the object view's background (MeshSettings::clearColor).
bool isBackground(const QImage& image, int x, int y) {
    const Color clear = MeshSettings{}.clearColor;
    const QColor c = image.pixelColor(x, y);
    return c.red() == clear.r && c.green() == clear.g && c.blue() == clear.b;
}

bool cornersAreBackground(const QImage& image) {
    const int w = image.width() - 1, h = image.height() - 1;
    return isBackground(image, 0, 0) && isBackground(image, w, 0) && isBackground(image, 0, h) &&
           isBackground(image, w, h);
}

/// A unit square in the x-y plane with texture coordinates: a small OBJ as a user would make.
void writeQuadObj(const QString& file) {
    QFile out(file);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Text));
    out.write("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
              "vn 0 0 1\n"
              "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n");
}

/// The object box's entry whose data is `data` (a name, a path, "" for flat), or -1.
int entryOf(QComboBox* box, const QString& data) {
    return box->findData(data);
}

/// Picks entry `index` of a combo box as the user does (activated follows the choice).
void pick(QComboBox* box, int index) {
    ASSERT_GE(index, 0);
    box->setCurrentIndex(index);
    emit box->activated(index);
}

/// Picks "Mesh file…" with `file` answered by the (replaced) file dialog.
void pickMeshFile(QComboBox* box, const QString& file) {
    ui::setMeshFileChooser([file](QWidget*) { return file; });
    pick(box, box->findText(QStringLiteral("Mesh file…")));
    ui::setMeshFileChooser({});
}

// ---- The render service without GL ----

TEST(FlatObjectServiceTest, WithoutGlSolidsAndFlatDesignsAreDrawnOnTheirObjectOnTheCpu) {
    RenderService service(RenderService::Backend::Cpu);
    const Genome solid = randomGenome(7, 3);
    const Genome flat = randomGenome(8, 2);
    QImage images[2];
    QObject::connect(&service, &RenderService::rendered,
                     [&](std::uint64_t key, const QImage& image, bool final) {
                         if (final) images[key - 1] = image;
                     });
    RenderRequest a;
    a.genome = solid;
    a.size = QSize(96, 80);
    a.mesh = QStringLiteral("torus");
    a.yaw = -40.0;
    a.pitch = 25.0;
    RenderRequest b;
    b.genome = flat;
    b.size = QSize(90, 90);
    b.mesh = QStringLiteral("cushion");
    b.flatOnObject = true;
    const std::uint64_t key = service.newKeys(2);
    ASSERT_EQ(key, 1u);
    service.request(key, a);
    service.request(key + 1, b);
    MARBLER_WAIT(!images[0].isNull() && !images[1].isNull(), 120000);

    // The object itself, not a cross-section: the CPU's object path, exactly.
    EXPECT_EQ(images[0], expectedObject(solid, builtinMesh("torus"), images[0], ViewAngle{-40.0, 25.0}));
    EXPECT_EQ(images[1], expectedObject(flat, builtinMesh("cushion"), images[1], ViewAngle{}));
    EXPECT_TRUE(cornersAreBackground(images[0]));
    EXPECT_TRUE(cornersAreBackground(images[1]));
}

TEST(FlatObjectServiceTest, AMeshFileThatCannotBeShownFailsItsRequestAndSaysWhy) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString broken = dir.filePath(QStringLiteral("broken.obj"));
    {
        QFile out(broken);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("this is not a mesh\n");
    }
    RenderService service(RenderService::Backend::Cpu);
    QSignalSpy unreadable(&service, &RenderService::meshUnreadable);
    QSignalSpy failed(&service, &RenderService::failed);
    RenderRequest r;
    r.genome = randomGenome(3, 2);
    r.size = QSize(64, 64);
    r.mesh = broken;
    r.flatOnObject = true;
    service.request(service.newKey(), r);
    MARBLER_WAIT(failed.size() == 1, 60000);
    ASSERT_GE(unreadable.size(), 1);
    EXPECT_EQ(unreadable.front().at(0).toString(), broken);
    EXPECT_TRUE(unreadable.front().at(1).toString().contains(broken)) << "the message names the file";
    EXPECT_TRUE(failed.front().at(1).toString().contains(broken));
}

TEST(FlatObjectServiceTest, OnGlAFlatDesignOnAnObjectIsShownWhereGlCannotDrawIt) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    RenderService service(gl::BackendPreference::Gpu);
    MARBLER_WAIT(!service.backendName().isEmpty(), 60000);
    ASSERT_TRUE(service.usesGl()) << service.backendReason().toStdString();
    const Genome flat = randomGenome(9, 2);
    QImage image;
    QString failure;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage& shown, bool final) {
        if (final) image = shown;
    });
    QObject::connect(&service, &RenderService::failed,
                     [&](std::uint64_t, const QString& message) { failure = message; });
    RenderRequest r;
    r.genome = flat;
    r.size = QSize(100, 90);
    r.mesh = QStringLiteral("book");
    r.flatOnObject = true;
    service.request(service.newKey(), r);
    MARBLER_WAIT(!image.isNull() || !failure.isEmpty(), 120000);
    ASSERT_TRUE(failure.isEmpty()) << failure.toStdString();
    // The CPU's object where GL refuses flat designs; GL's own up to its float rounding where
    // it draws them.
    const QImage expected = expectedObject(flat, builtinMesh("book"), image, ViewAngle{});
    ASSERT_EQ(image.size(), expected.size());
    double difference = 0.0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor a = image.pixelColor(x, y), b = expected.pixelColor(x, y);
            difference +=
                std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
        }
    EXPECT_LT(difference / (3.0 * image.width() * image.height()), 1.0) << "mean difference per channel";
    EXPECT_TRUE(cornersAreBackground(image));
}

// ---- The grid ----

class FlatObjectTest : public test::WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        mWindow->resize(700, 620); // small cells: nine objects on the CPU
        mWindow->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    }
    void waitForGrid() { MARBLER_WAIT(mWindow->renderingDone(), 240000); }
};

TEST_F(FlatObjectTest, AFlatPopulationShownOnTheBookShowsItsCellsOnTheBook) {
    QComboBox* box = mWindow->objectBox();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->currentText(), QStringLiteral("Flat")) << "flat designs start flat";
    EXPECT_EQ(mWindow->flatMesh(), QString());
    waitForGrid();
    const QImage flatImage = mWindow->cell(4)->image();
    ASSERT_FALSE(flatImage.isNull());
    EXPECT_FALSE(cornersAreBackground(flatImage)) << "a flat design fills its image";

    pick(box, entryOf(box, QStringLiteral("book")));
    EXPECT_EQ(mWindow->flatMesh(), QStringLiteral("book"));
    EXPECT_EQ(model().flatMesh(), QStringLiteral("book"));
    waitForGrid();
    for (int i : {0, 4, 8}) {
        const Genome& g = *model().cell(i);
        const QImage shown = mWindow->cell(i)->image();
        ASSERT_FALSE(shown.isNull()) << "cell " << i;
        EXPECT_TRUE(cornersAreBackground(shown))
            << "cell " << i << ": the object's background in the corners";
        EXPECT_EQ(shown, expectedObject(g, builtinMesh("book"), shown, viewAngleOf(g)))
            << "cell " << i << ": the design on the book";
        const QImage flat = toQImage(CpuRenderer(g).render([&] {
            RenderSettings s;
            s.width = shown.width();
            s.height = shown.height();
            return s;
        }()));
        EXPECT_NE(shown, flat) << "cell " << i;
    }
    // The cells turn as solids' do.
    emit mWindow->cell(4)->orbitDragged(4, QPoint(20, 0), true);
    EXPECT_EQ(viewAngleOf(*model().cell(4)), (ViewAngle{40.0, 20.0}));
    waitForGrid();
    const QImage turned = mWindow->cell(4)->image();
    EXPECT_EQ(turned, expectedObject(*model().cell(4), builtinMesh("book"), turned, ViewAngle{40.0, 20.0}));

    // Flat again: the flat render.
    pick(box, entryOf(box, QString()));
    EXPECT_EQ(mWindow->flatMesh(), QString());
    waitForGrid();
    EXPECT_FALSE(cornersAreBackground(mWindow->cell(0)->image()));
}

TEST_F(FlatObjectTest, TheObjectOfAFlatPopulationSurvivesASessionReopen) {
    QTemporaryDir sessionDir;
    ASSERT_TRUE(sessionDir.isValid());
    const QString sessionFile = ui::sessionFilePath(sessionDir.path());
    model().setSessionFile(sessionFile);
    pick(mWindow->objectBox(), entryOf(mWindow->objectBox(), QStringLiteral("cloth")));
    EXPECT_EQ(loadSession(sessionFile).flatMesh, QStringLiteral("cloth")) << "written with the session";
    EXPECT_EQ(loadSession(sessionFile).mesh, model().mesh()) << "the solids' object kept apart";

    ui::WorkbenchWindow reopened(mService.get());
    reopened.resumeSession(loadSession(sessionFile));
    EXPECT_EQ(reopened.flatMesh(), QStringLiteral("cloth"));
    EXPECT_EQ(reopened.objectBox()->currentText(), QStringLiteral("cloth")) << "what the box shows";

    // A solid population's box offers no "Flat", and keeps the flat population's object apart.
    reopened.newRandomPopulation(3);
    EXPECT_EQ(entryOf(reopened.objectBox(), QString()), -1);
    EXPECT_EQ(reopened.objectBox()->currentText(), reopened.mesh());
    EXPECT_EQ(reopened.flatMesh(), QStringLiteral("cloth"));
}

TEST_F(FlatObjectTest, AMeshFileChosenInTheObjectBoxShowsTheDesignsAndIsKept) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString obj = dir.filePath(QStringLiteral("quad.obj"));
    writeQuadObj(obj);
    const QString sessionFile = ui::sessionFilePath(dir.path());
    model().setSessionFile(sessionFile);

    pickMeshFile(mWindow->objectBox(), obj);
    EXPECT_EQ(mWindow->flatMesh(), obj);
    EXPECT_EQ(mWindow->objectBox()->currentText(), QStringLiteral("quad.obj")) << "named by the file";
    EXPECT_EQ(loadSession(sessionFile).flatMesh, obj) << "the path kept with the session";
    waitForGrid();
    const MeshData quad = gl::loadMesh(obj.toStdString());
    for (int i : {1, 7}) {
        const Genome& g = *model().cell(i);
        const QImage shown = mWindow->cell(i)->image();
        ASSERT_FALSE(shown.isNull());
        EXPECT_EQ(shown, expectedObject(g, quad, shown, viewAngleOf(g))) << "cell " << i;
        EXPECT_TRUE(cornersAreBackground(shown));
        EXPECT_FALSE(isBackground(shown, shown.width() / 2, shown.height() / 2)) << "the quad in the middle";
    }

    // Reopened, the file is shown again.
    ui::WorkbenchWindow reopened(mService.get());
    reopened.resumeSession(loadSession(sessionFile));
    EXPECT_EQ(reopened.flatMesh(), obj);
    EXPECT_EQ(reopened.objectBox()->currentData().toString(), obj);
}

TEST_F(FlatObjectTest, ABrokenMeshFileGivesAMessageAndKeepsTheSession) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString sessionFile = ui::sessionFilePath(dir.path());
    model().setSessionFile(sessionFile);
    waitForGrid();
    const std::size_t generations = model().history().size();
    std::vector<Genome> cells;
    for (int i = 0; i < 9; ++i)
        cells.push_back(*model().cell(i));
    test::ErrorCapture errors;

    // A file that is not there: refused at once, nothing changes.
    const QString missing = dir.filePath(QStringLiteral("gone.obj"));
    pickMeshFile(mWindow->objectBox(), missing);
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(missing)) << errors.messages.front().toStdString();
    EXPECT_EQ(mWindow->flatMesh(), QString());
    EXPECT_EQ(mWindow->objectBox()->currentText(), QStringLiteral("Flat"));

    // A file that is no mesh: the render service finds out, the window says so and shows the
    // designs on a built-in object instead.
    const QString broken = dir.filePath(QStringLiteral("broken.obj"));
    {
        QFile out(broken);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("v 1 2\nf 9 9 9 9\nnonsense\n");
    }
    pickMeshFile(mWindow->objectBox(), broken);
    MARBLER_WAIT(errors.messages.size() == 2, 60000);
    EXPECT_TRUE(errors.messages.back().contains(broken)) << errors.messages.back().toStdString();
    EXPECT_EQ(mWindow->flatMesh(), QString::fromLatin1(DefaultMesh)) << "a built-in instead";
    EXPECT_EQ(mWindow->objectBox()->currentText(), QString::fromLatin1(DefaultMesh));
    waitForGrid();
    EXPECT_EQ(errors.messages.size(), 2) << "one message, not one per cell";
    const QImage shown = mWindow->cell(0)->image();
    EXPECT_EQ(shown, expectedObject(*model().cell(0), builtinMesh(DefaultMesh), shown,
                                    viewAngleOf(*model().cell(0))));

    // The session is the same one, with the built-in.
    EXPECT_EQ(model().history().size(), generations);
    for (int i = 0; i < 9; ++i)
        EXPECT_EQ(*model().cell(i), cells[std::size_t(i)]) << "cell " << i;
    const ui::SavedSession saved = loadSession(sessionFile);
    EXPECT_EQ(saved.history.size(), generations);
    EXPECT_EQ(saved.flatMesh, QString::fromLatin1(DefaultMesh));
}

TEST_F(FlatObjectTest, ASessionWhoseMeshFileIsGoneSaysSoAndShowsABuiltIn) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString obj = dir.filePath(QStringLiteral("quad.obj"));
    writeQuadObj(obj);
    const QString sessionFile = ui::sessionFilePath(dir.path());
    model().setSessionFile(sessionFile);
    pickMeshFile(mWindow->objectBox(), obj);
    ASSERT_EQ(loadSession(sessionFile).flatMesh, obj);
    ASSERT_TRUE(QFile::remove(obj));

    test::ErrorCapture errors;
    ui::WorkbenchWindow reopened(mService.get());
    reopened.resize(700, 620);
    reopened.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&reopened));
    reopened.resumeSession(loadSession(sessionFile));
    MARBLER_WAIT(errors.messages.size() >= 1, 60000);
    EXPECT_TRUE(errors.messages.front().contains(obj)) << errors.messages.front().toStdString();
    EXPECT_EQ(reopened.flatMesh(), QString::fromLatin1(DefaultMesh));
    MARBLER_WAIT(reopened.renderingDone(), 240000);
    EXPECT_TRUE(cornersAreBackground(reopened.cell(2)->image()));
}

// ---- The large view and the editor ----

TEST_F(FlatObjectTest, TheLargeViewShowsAFlatDesignOnTheObjectAndTurnsIt) {
    mWindow->setFlatMesh(QStringLiteral("book"));
    ui::DesignDialog* dialog = mWindow->openDesign(3);
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    const Genome& g = *model().cell(3);
    const QImage first = dialog->image();
    EXPECT_EQ(first, expectedObject(g, builtinMesh("book"), first, viewAngleOf(g)));
    EXPECT_TRUE(cornersAreBackground(first));

    QWidget* canvas = dialog->canvas();
    const QPoint from = canvas->rect().center();
    QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(canvas, from + QPoint(-60, 10));
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, from + QPoint(-60, 10));
    const ViewAngle turned{0.0, 25.0}; // half a degree a pixel
    EXPECT_EQ(dialog->viewAngle(), turned);
    EXPECT_EQ(viewAngleOf(*model().cell(3)), turned) << "given back to its cell";
    MARBLER_WAIT(dialog->imageIsFinal(), 120000);
    EXPECT_EQ(dialog->image(), expectedObject(g, builtinMesh("book"), dialog->image(), turned));
    dialog->close();
}

class FlatObjectEditorTest : public test::EditorTest {};

TEST_F(FlatObjectEditorTest, TheEditorShowsAFlatDesignOnAnObjectBesideTheCanvasAfterEachEdit) {
    ui::EditorWindow* editor = open(randomGenome(11, 2));
    auto* view = editor->findChild<ui::SolidObjectView*>(QStringLiteral("objectView"));
    ASSERT_NE(view, nullptr);
    EXPECT_FALSE(view->isVisible()) << "on demand";
    QAction* show = editor->findChild<QAction*>(QStringLiteral("showOnObject"));
    ASSERT_NE(show, nullptr);
    show->trigger();
    EXPECT_TRUE(view->isVisible());
    ASSERT_NE(view->objectBox(), nullptr);
    EXPECT_EQ(view->objectBox()->currentText(), QStringLiteral("book"));
    MARBLER_WAIT(!view->image().isNull() && mService->idle(), 120000);
    const Genome first = editor->document()->design();
    EXPECT_EQ(view->image(), expectedObject(first, builtinMesh("book"), view->image(), view->angle()));

    // After an edit the preview shows the new design.
    const QImage before = view->image();
    Genome changed = first;
    changed.palette.front() = Color{250, 20, 20};
    ASSERT_NE(changed.palette.front(), first.palette.front());
    editor->document()->replaceDesign(changed, QStringLiteral("Recolour"));
    MARBLER_WAIT(mService->idle() && view->image() != before, 120000);
    EXPECT_EQ(view->image(), expectedObject(changed, builtinMesh("book"), view->image(), view->angle()));

    // Another object, turned by a drag.
    pick(view->objectBox(), view->objectBox()->findData(QStringLiteral("cushion")));
    const QPoint from = view->rect().center();
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(view, from + QPoint(30, 0));
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, from + QPoint(30, 0));
    EXPECT_EQ(view->angle(), (ViewAngle{45.0, 20.0}));
    MARBLER_WAIT(mService->idle(), 120000);
    EXPECT_EQ(view->image(), expectedObject(changed, builtinMesh("cushion"), view->image(), view->angle()));
    editor->close();
}

} // namespace flat_object_test
} // namespace marbler
