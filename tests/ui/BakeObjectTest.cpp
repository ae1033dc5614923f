// "Bake onto object…" in the large view and the editor: offered for flat and solid designs, it
// writes the object chosen (the one shown, a built-in or a mesh file) as glTF binary with the
// baked texture, the same file `marbler bake` writes, and reports a bad format.

#include "shared/BakeObject.h"
#include "TestUtil.h"
#include "WaitFor.h"
#include "editor/EditorWindow.h"
#include "marbler/Bake.h"
#include "marbler/GenomeIO.h"
#include "marbler/Mesh.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/MeshChooser.h"
#include "shared/RenderService.h"
#include "shared/SavedFiles.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMenu>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <memory>

namespace marbler::ui {
namespace {

class BakeObjectTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(mFiles.isValid());
        setErrorHandler([this](QWidget*, const QString&, const QString& message) { mErrors << message; });
    }
    void TearDown() override {
        setErrorHandler({});
        setSaveFileAsker({});
        setMeshFileChooser({});
    }
    /// Answers the save dialog with `name` in the temporary folder.
    void saveAs(const QString& name) {
        setSaveFileAsker([this, name](QWidget*, const QString&, const QString&, const QString&) {
            return mFiles.filePath(name);
        });
    }
    /// What `marbler bake GENOME --mesh MESH --texture SIZE` writes, as bytes.
    QByteArray cliBake(const QString& genome, const QString& mesh, int size) {
        const QString out = mCli.filePath(QStringLiteral("cli.glb"));
        QFile::remove(out);
        QProcess cli;
        cli.start(QStringLiteral(MARBLER_EXECUTABLE),
                  {QStringLiteral("bake"), genome, QStringLiteral("--mesh"), mesh,
                   QStringLiteral("--texture"), QString::number(size), QStringLiteral("--quiet"),
                   QStringLiteral("-o"), out});
        EXPECT_TRUE(cli.waitForFinished(300000));
        EXPECT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
        return readAll(out);
    }
    static QByteArray readAll(const QString& file) {
        QFile in(file);
        return in.open(QIODevice::ReadOnly) ? in.readAll() : QByteArray();
    }
    /// Chooses `name` in the bake menu under `parent`.
    static void choose(QObject* parent, const QString& name) {
        auto* action = parent->findChild<QAction*>(name);
        ASSERT_NE(action, nullptr) << name.toStdString();
        action->trigger();
    }
    QTemporaryDir mFiles;
    QTemporaryDir mCli;
    QStringList mErrors;
};

QString example(const char* name) {
    return QStringLiteral(MARBLER_TEST_DATA "/examples/") + QLatin1String(name);
}

TEST_F(BakeObjectTest, TheLargeViewOffersItForFlatAndSolidDesigns) {
    RenderService service(RenderService::Backend::Cpu);
    DesignDialog solid(test::loadExample("slate-block.marble.json"), &service, QStringLiteral("cube"));
    DesignDialog flat(test::loadExample("five-stones.marble.json"), &service, QStringLiteral("cube"));
    DesignDialog flatOnBook(test::loadExample("five-stones.marble.json"), &service, QStringLiteral("cube"),
                            nullptr, QStringLiteral("book"));
    for (DesignDialog* view : {&solid, &flat, &flatOnBook}) {
        auto* button = view->findChild<QPushButton*>(QStringLiteral("bakeObject"));
        ASSERT_NE(button, nullptr);
        EXPECT_NE(button->findChild<QAction*>(QStringLiteral("bakeOnto:book")), nullptr);
        EXPECT_NE(button->findChild<QAction*>(QStringLiteral("bakeOntoMeshFile")), nullptr);
    }
    // The object shown comes first: the solid's, and a flat design's only when it is on one.
    auto shown = [](DesignDialog& view) { return view.findChild<QAction*>(QStringLiteral("bakeOntoShown")); };
    ASSERT_NE(shown(solid), nullptr);
    EXPECT_TRUE(shown(solid)->text().contains(QStringLiteral("cube")));
    EXPECT_EQ(shown(flat), nullptr);
    ASSERT_NE(shown(flatOnBook), nullptr);
    EXPECT_TRUE(shown(flatOnBook)->text().contains(QStringLiteral("book")));
}

TEST_F(BakeObjectTest, TheLargeViewBakesAFlatDesignAsMarblerBakeDoes) {
    // The book has texture coordinates of its own, so the flat design follows them (FlatOnUvs);
    // the window's file is the very file `marbler bake` writes: the same UVs, the same texture.
    ASSERT_TRUE(hasUsableUvs(builtinMesh("book")));
    RenderService service(RenderService::Backend::Cpu);
    DesignDialog view(test::loadExample("five-stones.marble.json"), &service, QStringLiteral("cube"));
    QStringList written;
    QObject::connect(&view, &DesignDialog::fileSaved, [&](const QString& file) { written << file; });
    saveAs(QStringLiteral("stones on a book"));
    choose(&view, QStringLiteral("bakeOnto:book"));
    MARBLER_WAIT(!written.isEmpty() || !mErrors.isEmpty(), 300000);
    ASSERT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("; ")).toStdString();
    const QString file = mFiles.filePath(QStringLiteral("stones on a book.glb"));
    ASSERT_EQ(written, QStringList{file});
    const QByteArray baked = readAll(file);
    EXPECT_EQ(baked.left(4), QByteArray("glTF"));
    EXPECT_TRUE(baked ==
                cliBake(example("five-stones.marble.json"), QStringLiteral("book"), WindowBakeTexture))
        << "the window's bake differs from marbler bake's";
}

TEST_F(BakeObjectTest, WritesTheObjectAsGlbWithTheDesignsName) {
    QString offered;
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return mFiles.filePath(QStringLiteral("slate cube")); // typed without a format
    });
    QWidget parent;
    QStringList written;
    QPushButton* button = makeBakeButton(
        &parent, [] { return test::loadExample("slate-block.marble.json"); }, QStringLiteral("cube"),
        [&](const QString& file) { written << file; }, 256);
    // A click pops up the objects to choose from.
    auto* menu = button->findChild<QMenu*>(QStringLiteral("bakeObjectMenu"));
    ASSERT_NE(menu, nullptr);
    button->click();
    MARBLER_WAIT(menu->isVisible(), 10000);
    menu->hide();
    choose(button, QStringLiteral("bakeOntoShown"));
    MARBLER_WAIT(!written.isEmpty() || !mErrors.isEmpty(), 120000);
    ASSERT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("; ")).toStdString();
    EXPECT_TRUE(offered.endsWith(QStringLiteral(".glb"))) << offered.toStdString();
    const QString file = mFiles.filePath(QStringLiteral("slate cube.glb"));
    EXPECT_EQ(written, QStringList{file});
    QFile glb(file);
    ASSERT_TRUE(glb.open(QIODevice::ReadOnly));
    EXPECT_EQ(glb.read(4), QByteArray("glTF"));
    EXPECT_TRUE(button->isEnabled()) << "the button comes back once the bake is done";
    EXPECT_EQ(QDir(mFiles.path()).entryList(QDir::Files | QDir::Hidden),
              QStringList{QStringLiteral("slate cube.glb")});
}

TEST_F(BakeObjectTest, AnotherFormatIsReportedAndNothingWritten) {
    setSaveFileAsker([&](QWidget*, const QString&, const QString&, const QString&) {
        return mFiles.filePath(QStringLiteral("cube.fbx"));
    });
    QWidget parent;
    QStringList written;
    QPushButton* button = makeBakeButton(
        &parent, [] { return test::loadExample("slate-block.marble.json"); }, QStringLiteral("cube"),
        [&](const QString& file) { written << file; }, 256);
    choose(button, QStringLiteral("bakeOntoShown"));
    ASSERT_EQ(mErrors.size(), 1);
    EXPECT_TRUE(mErrors.front().contains(QStringLiteral("cube.fbx")));
    EXPECT_TRUE(written.isEmpty());
    EXPECT_TRUE(QDir(mFiles.path()).isEmpty());
}

TEST_F(BakeObjectTest, TheEditorBakesItsDesignAsMarblerBakeDoes) {
    RenderService service(RenderService::Backend::Cpu);
    auto* editor = new EditorWindow(test::loadExample("five-stones.marble.json"), &service, {}, nullptr, {});
    editor->setAttribute(Qt::WA_DeleteOnClose, false);
    std::unique_ptr<EditorWindow> owner(editor);
    auto* menu = editor->findChild<QMenu*>(QStringLiteral("bakeObjectMenu"));
    ASSERT_NE(menu, nullptr);
    EXPECT_TRUE(menu->menuAction()->isVisible());
    saveAs(QStringLiteral("editor book.glb"));
    choose(editor, QStringLiteral("bakeOnto:book"));
    const QString file = mFiles.filePath(QStringLiteral("editor book.glb"));
    MARBLER_WAIT(menu->isEnabled() && (QFile::exists(file) || !mErrors.isEmpty()), 300000);
    ASSERT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("; ")).toStdString();
    EXPECT_TRUE(editor->statusBar()->currentMessage().contains(QStringLiteral("editor book.glb")))
        << editor->statusBar()->currentMessage().toStdString();
    // The design the editor holds, baked by `marbler bake`.
    const QString design = mCli.filePath(QStringLiteral("editor.marble.json"));
    {
        QFile out(design);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(QByteArray::fromStdString(serializeGenome(editor->document()->renderedDesign())));
    }
    EXPECT_TRUE(readAll(file) == cliBake(design, QStringLiteral("book"), WindowBakeTexture))
        << "the editor's bake differs from marbler bake's";
}

TEST_F(BakeObjectTest, TheEditorOffersItForASolidDesignToo) {
    RenderService service(RenderService::Backend::Cpu);
    EditorWindow editor(test::loadExample("slate-block.marble.json"), &service, {}, nullptr, {});
    editor.setAttribute(Qt::WA_DeleteOnClose, false);
    auto* menu = editor.findChild<QMenu*>(QStringLiteral("bakeObjectMenu"));
    ASSERT_NE(menu, nullptr);
    EXPECT_NE(menu->findChild<QAction*>(QStringLiteral("bakeOnto:cube")), nullptr);
    EXPECT_NE(menu->findChild<QAction*>(QStringLiteral("bakeOntoMeshFile")), nullptr);
}

TEST_F(BakeObjectTest, AMeshFileChosenIsBakedOntoThroughItsOwnUvs) {
    // A square of two triangles whose texture coordinates are its own.
    const QString mesh = mCli.filePath(QStringLiteral("square.obj"));
    {
        QFile out(mesh);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                  "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    }
    setMeshFileChooser([&](QWidget*) { return mesh; });
    saveAs(QStringLiteral("square.glb"));
    QWidget parent;
    QStringList written;
    makeBakeButton(
        &parent, [] { return test::loadExample("five-stones.marble.json"); }, {},
        [&](const QString& file) { written << file; }, 256);
    choose(&parent, QStringLiteral("bakeOntoMeshFile"));
    MARBLER_WAIT(!written.isEmpty() || !mErrors.isEmpty(), 120000);
    ASSERT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("; ")).toStdString();
    EXPECT_TRUE(readAll(mFiles.filePath(QStringLiteral("square.glb"))) ==
                cliBake(example("five-stones.marble.json"), mesh, 256))
        << "the window's bake onto the mesh file differs from marbler bake's";
}

TEST_F(BakeObjectTest, AMissingMeshFileIsReportedAndNothingWritten) {
    setMeshFileChooser([&](QWidget*) { return mFiles.filePath(QStringLiteral("gone.obj")); });
    saveAs(QStringLiteral("never.glb"));
    QWidget parent;
    makeBakeButton(
        &parent, [] { return test::loadExample("five-stones.marble.json"); }, {}, {}, 256);
    choose(&parent, QStringLiteral("bakeOntoMeshFile"));
    ASSERT_EQ(mErrors.size(), 1);
    EXPECT_TRUE(mErrors.front().contains(QStringLiteral("gone.obj"))) << mErrors.front().toStdString();
    EXPECT_TRUE(QDir(mFiles.path()).isEmpty());
}

TEST_F(BakeObjectTest, CancellingTheBakeLeavesNothing) {
    saveAs(QStringLiteral("cancelled.glb"));
    QWidget parent;
    QStringList written;
    QPushButton* button = makeBakeButton(
        &parent, [] { return test::loadExample("slate-block.marble.json"); }, QStringLiteral("sphere"),
        [&](const QString& file) { written << file; }, 4096);
    choose(button, QStringLiteral("bakeOntoShown"));
    EXPECT_FALSE(button->isEnabled()) << "the button waits for the bake";
    QProgressDialog* box = nullptr;
    MARBLER_WAIT((box = parent.findChild<QProgressDialog*>(QStringLiteral("bakeProgress"))) != nullptr &&
                     box->isVisible(),
                 60000);
    ASSERT_NE(box, nullptr);
    auto* cancel = box->findChild<QPushButton*>();
    ASSERT_NE(cancel, nullptr);
    cancel->click(); // the box's Cancel button
    MARBLER_WAIT(button->isEnabled(), 60000);
    EXPECT_TRUE(button->isEnabled());
    EXPECT_TRUE(written.isEmpty());
    EXPECT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("; ")).toStdString();
    EXPECT_EQ(QDir(mFiles.path()).entryList(QDir::Files | QDir::Hidden), QStringList{});
}

} // namespace
} // namespace marbler::ui
