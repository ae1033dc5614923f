// "Bake onto object…" in the large view: offered for solid designs only, it writes the object
// the design is shown on as glTF binary with the baked texture, and reports a bad format.

#include "shared/BakeObject.h"
#include "TestUtil.h"
#include "WaitFor.h"
#include "marbler/GenomeIO.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/RenderService.h"
#include "shared/SavedFiles.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

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
    }
    QTemporaryDir mFiles;
    QStringList mErrors;
};

TEST_F(BakeObjectTest, TheLargeViewOffersItForSolidDesignsOnly) {
    RenderService service(RenderService::Backend::Cpu);
    DesignDialog solid(test::loadExample("slate-block.marble.json"), &service, QStringLiteral("cube"));
    DesignDialog flat(test::loadExample("five-stones.marble.json"), &service, QStringLiteral("cube"));
    EXPECT_NE(solid.findChild<QPushButton*>(QStringLiteral("bakeObject")), nullptr);
    EXPECT_EQ(flat.findChild<QPushButton*>(QStringLiteral("bakeObject")), nullptr);
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
    button->click();
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
    button->click();
    ASSERT_EQ(mErrors.size(), 1);
    EXPECT_TRUE(mErrors.front().contains(QStringLiteral("cube.fbx")));
    EXPECT_TRUE(written.isEmpty());
    EXPECT_TRUE(QDir(mFiles.path()).isEmpty());
}

} // namespace
} // namespace marbler::ui
