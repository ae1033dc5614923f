// File ▸ Marble a picture…: nine flat designs whose bath is the picture, read from its own
// folder without asking, rendered from it, and a picture that cannot be read reported.

#include "TestUtil.h"
#include "UiTestSupport.h"
#include "WaitFor.h"
#include "shared/SourcePermissions.h"
#include "workbench/DesignCell.h"
#include "workbench/OpenPlacement.h"

#include <QAction>
#include <QColor>
#include <QImage>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

using namespace marbler;
using namespace marbler::ui;
namespace fs = std::filesystem;

namespace {

class PictureTest : public test::WindowTest {
protected:
    PictureTest()
        : test::WindowTest(false) {}

    /// A 64 x 32 picture of four coloured bands in a folder of this test's own.
    QString picture() {
        const fs::path folder = test::outputDir(
            std::string("ui-picture-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder);
        fs::create_directories(folder);
        QImage image(64, 32, QImage::Format_RGB32);
        const QColor bands[] = {QColor(200, 30, 40), QColor(30, 160, 60), QColor(40, 60, 200),
                                QColor(230, 200, 40)};
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                image.setPixelColor(x, y, bands[x / 16]);
        const QString file = QString::fromStdString((folder / "bands.png").string());
        EXPECT_TRUE(image.save(file));
        return file;
    }
};

TEST_F(PictureTest, NineDesignsMarbleThePictureFromItsOwnFolder) {
    int asked = 0;
    setExternalSourceAsker([&](QWidget*, const QString&, const QString&) {
        ++asked;
        return false;
    });
    const QString file = picture();
    mWindow->resize(600, 500);
    mWindow->show();
    QSignalSpy finished(mWindow.get(), &WorkbenchWindow::renderingFinished);
    const std::vector<int> cells = mWindow->marblePicture(file);
    ASSERT_EQ(cells.size(), std::size_t(CellCount));
    for (int c : cells) {
        const Genome* design = model().cell(c);
        ASSERT_NE(design, nullptr);
        ASSERT_TRUE(design->source.has_value());
        EXPECT_EQ(design->source->image, "bands.png");
        EXPECT_EQ(fs::path(design->baseDirectory), fs::path(file.toStdString()).parent_path());
        EXPECT_DOUBLE_EQ(design->size.y, 500.0) << "the picture's 2:1 shape";
        EXPECT_TRUE(std::any_of(design->operations.begin(), design->operations.end(),
                                [](const Operation& op) { return op.tool == Tool::Flow; }));
    }
    EXPECT_NE(*model().cell(0), *model().cell(1)) << "nine different designs";
    while (!mWindow->renderingDone() || finished.isEmpty())
        ASSERT_TRUE(finished.wait(120000));
    EXPECT_EQ(asked, 0) << "a picture in the design's own folder needs no permission";
    // The cells show the picture carried by the flow: its saturated bands, not the pale bath.
    const QImage plain = mWindow->cell(0)->image();
    ASSERT_FALSE(plain.isNull());
    int bandColoured = 0;
    for (int y = 0; y < plain.height(); y += 4)
        for (int x = 0; x < plain.width(); x += 4) {
            const QColor c = plain.pixelColor(x, y);
            if (std::max({c.red(), c.green(), c.blue()}) - std::min({c.red(), c.green(), c.blue()}) > 100)
                ++bandColoured;
        }
    EXPECT_GT(bandColoured, (plain.width() / 4) * (plain.height() / 4) / 2)
        << "the picture's colours fill the bath";
    setExternalSourceAsker({});
}

TEST_F(PictureTest, APictureThatCannotBeReadIsReportedAndChangesNothing) {
    test::ErrorCapture errors;
    const fs::path folder = test::outputDir("ui-picture-broken");
    fs::create_directories(folder);
    const fs::path broken = folder / "broken.png";
    {
        std::FILE* f = std::fopen(broken.c_str(), "wb");
        std::fputs("not a picture", f);
        std::fclose(f);
    }
    EXPECT_TRUE(mWindow->marblePicture(QString::fromStdString(broken.string())).empty());
    EXPECT_TRUE(mWindow->marblePicture(QString::fromStdString((folder / "missing.png").string())).empty());
    ASSERT_EQ(errors.messages.size(), 2);
    EXPECT_TRUE(errors.messages[0].contains(QStringLiteral("broken.png")))
        << errors.messages[0].toStdString();
    EXPECT_TRUE(errors.messages[1].contains(QStringLiteral("no such file")))
        << errors.messages[1].toStdString();
    for (int c = 0; c < CellCount; ++c)
        EXPECT_EQ(model().cell(c), nullptr);
}

TEST_F(PictureTest, TheFileMenuOffersIt) {
    auto* action = mWindow->findChild<QAction*>(QStringLiteral("marblePictureAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_FALSE(action->shortcut().isEmpty());
    EXPECT_FALSE(action->statusTip().isEmpty());
}

/// Marbling a picture over a grid: all nine designs come in as a generation of their own (the
/// grid before one generation back, even with a parent selected, and without a question whose
/// words would not match), each under a name of its own, and no cell shows the previous
/// design's image under a new name while the new one renders.
TEST_F(PictureTest, NineNamedDesignsReplaceTheGridWithoutStaleImages) {
    int asked = 0;
    setOpenChooser([&](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> {
        ++asked;
        return OpenChoice::NewGeneration;
    });
    const QString file = picture();
    mWindow->resize(600, 500);
    mWindow->show();
    mWindow->newRandomPopulation(2);
    MARBLER_WAIT(mWindow->renderingDone(), 120000);
    for (int c = 0; c < CellCount; ++c)
        ASSERT_FALSE(mWindow->cell(c)->image().isNull()) << c;
    model().setSelected(4, true);
    const int before = model().currentIndex();

    const std::vector<int> cells = mWindow->marblePicture(file);
    EXPECT_EQ(asked, 0) << "nine new designs are a new generation, as a new random population is";
    ASSERT_EQ(cells.size(), std::size_t(CellCount)) << "all nine placed";
    EXPECT_EQ(model().current().parent, before);
    std::set<QString> names;
    for (int c = 0; c < CellCount; ++c) {
        const Genome* design = model().cell(c);
        ASSERT_NE(design, nullptr) << c;
        ASSERT_TRUE(design->source.has_value()) << c;
        // What the person sees: the caption under the cell, and no old picture in it.
        names.insert(mWindow->cell(c)->caption());
        EXPECT_TRUE(mWindow->cell(c)->image().isNull())
            << "cell " << c << " shows the previous design's image";
        EXPECT_FALSE(model().isSelected(c)) << c;
    }
    EXPECT_EQ(names.size(), std::size_t(CellCount)) << "nine distinct names";
    EXPECT_TRUE(names.count(QStringLiteral("bands marbled 1")));
    EXPECT_TRUE(names.count(QStringLiteral("bands marbled 9")));
    MARBLER_WAIT(mWindow->renderingDone(), 120000);
    for (int c = 0; c < CellCount; ++c)
        EXPECT_FALSE(mWindow->cell(c)->image().isNull()) << c;
    // Back returns to the grid as it was, its images from the cache at once.
    mWindow->backAction()->trigger();
    EXPECT_EQ(model().currentIndex(), before);
    for (int c = 0; c < CellCount; ++c)
        EXPECT_FALSE(mWindow->cell(c)->image().isNull()) << c;
    setOpenChooser({});
}

} // namespace
