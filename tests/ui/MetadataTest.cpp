// Designs that travel: the window opens PNG and TIFF images that carry genomes (File ▸ Open,
// drops on the window and on cells) and refuses plain ones; its exports carry their genome; and
// designs go to and come from the clipboard as genome text (Edit ▸ Copy / Paste design, the
// large view's Copy genome).
// Runs in ui_workbench_test, whose main() sets up the application and private settings.

#include "TestUtil.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/RenderToFile.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/RenderService.h"
#include "workbench/DesignCell.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QDropEvent>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;
using marbler::test::dropFiles;

namespace {

std::vector<std::string> gridText(const PopulationModel& model) {
    std::vector<std::string> result;
    for (int i = 0; i < CellCount; ++i)
        result.push_back(model.cell(i) ? serializeGenome(*model.cell(i)) : "");
    return result;
}

class MetadataTest : public test::WindowTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(mFiles.isValid());
        WindowTest::SetUp();
        setOpenChooser(
            [](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> { return OpenChoice::Replace; });
        setErrorHandler([this](QWidget*, const QString& title, const QString& message) {
            mErrors << title + QStringLiteral(": ") + message;
        });
    }
    void TearDown() override {
        setErrorHandler({});
        setOpenChooser({});
        WindowTest::TearDown();
    }
    QString file(const QString& name) const { return mFiles.filePath(name); }
    /// An image of `genome` written as renders write it, carrying the genome.
    QString imageOf(const Genome& genome, const QString& name) {
        RenderSettings s;
        s.width = 48;
        s.height = 48;
        renderToFile(genome, s, file(name).toStdString());
        return file(name);
    }
    void showActive() {
        mWindow->show();
        ASSERT_TRUE(test::activate(mWindow.get()));
    }
    QString status() const { return mWindow->statusBar()->currentMessage(); }

    QTemporaryDir mFiles;
    QStringList mErrors;
};

TEST_F(MetadataTest, ImagesWithAGenomeOpenLikeGenomeFiles) {
    const Genome stones = test::loadExample("five-stones.marble.json");
    const Genome flame = test::loadExample("flame-comb-vortex.marble.json");
    const QString png = imageOf(stones, QStringLiteral("stones.png"));
    const QString tif = imageOf(flame, QStringLiteral("flame.tif"));

    // File ▸ Open (and the command line, which opens through the same call).
    model().setSelected(4, true);
    ASSERT_TRUE(mWindow->openFiles({png}));
    ASSERT_NE(model().cell(4), nullptr);
    EXPECT_EQ(serializeGenome(*model().cell(4)), serializeGenome(stones));

    // Dropped on a cell, and on the window.
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(2), {tif});
    ASSERT_NE(model().cell(2), nullptr);
    EXPECT_EQ(serializeGenome(*model().cell(2)), serializeGenome(flame));
    model().clearSelection();
    model().setSelected(8, true);
    dropFiles(mWindow.get(), {png});
    ASSERT_NE(model().cell(8), nullptr);
    EXPECT_EQ(serializeGenome(*model().cell(8)), serializeGenome(stones));
    EXPECT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("\n")).toStdString();
}

// A plain image is no design: it is offered to Marble a picture (issue 29); declined, nothing
// changes and nothing is reported as an error (SmallThingsTest.cpp: accepted).
TEST_F(MetadataTest, APlainImageIsOfferedToMarbleAndDecliningChangesNothing) {
    RenderSettings s;
    s.width = s.height = 32;
    const Image pixels = CpuRenderer(test::loadExample("five-stones.marble.json")).render(s);
    writeImage(pixels, file(QStringLiteral("plain.png")).toStdString());
    const auto before = gridText(model());
    const std::size_t generations = model().history().size();
    QStringList offered;
    setPictureOffer([&offered](QWidget*, const QString& picture) {
        offered << picture;
        return false;
    });

    EXPECT_FALSE(mWindow->openFiles({file(QStringLiteral("plain.png"))}));
    EXPECT_EQ(offered, QStringList{file(QStringLiteral("plain.png"))});
    EXPECT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("\n")).toStdString();
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("plain.png")));
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(5), {file(QStringLiteral("plain.png"))});
    EXPECT_EQ(offered.size(), 2);
    EXPECT_TRUE(mErrors.isEmpty());
    EXPECT_EQ(gridText(model()), before);
    EXPECT_EQ(model().history().size(), generations);
    setPictureOffer({});
}

TEST_F(MetadataTest, ExportedImagesCarryTheDesign) {
    DesignDialog* dialog = mWindow->openDesign(3);
    ASSERT_NE(dialog, nullptr);
    for (const QString& name : {QStringLiteral("export.png"), QStringLiteral("export.tif")}) {
        QSignalSpy finished(dialog, &DesignDialog::exportFinished);
        ASSERT_TRUE(dialog->exportTo(file(name), QSize(64, 64), QStringLiteral("none")));
        MARBLER_WAIT_EQ(finished.size(), 1, 120000);
        ASSERT_TRUE(finished.front().at(1).toBool()) << finished.front().at(2).toString().toStdString();
        EXPECT_EQ(serializeGenome(loadDesign(file(name).toStdString())), serializeGenome(dialog->genome()))
            << name.toStdString();
    }
    dialog->close();
}

TEST_F(MetadataTest, CopyAndPasteADesignWithTheKeys) {
    // Ctrl+C and Ctrl+V belong to these two actions alone.
    EXPECT_EQ(mWindow->copyDesignAction()->shortcut(), QKeySequence(QKeySequence::Copy));
    EXPECT_EQ(mWindow->pasteDesignAction()->shortcut(), QKeySequence(QKeySequence::Paste));
    for (QAction* action : mWindow->findChildren<QAction*>()) {
        if (action == mWindow->copyDesignAction() || action == mWindow->pasteDesignAction()) continue;
        for (const QKeySequence& key : action->shortcuts()) {
            EXPECT_NE(key, QKeySequence(QKeySequence::Copy)) << action->text().toStdString();
            EXPECT_NE(key, QKeySequence(QKeySequence::Paste)) << action->text().toStdString();
        }
    }

    showActive();
    const std::string copied = serializeGenome(*model().cell(3));
    model().setSelected(1, true); // the focused cell wins over the selection
    mWindow->cell(3)->setFocus();
    MARBLER_WAIT(mWindow->cell(3)->hasFocus(), 5000);
    QApplication::clipboard()->clear();
    QTest::keyClick(mWindow->cell(3), Qt::Key_C, Qt::ControlModifier);
    const QMimeData* mime = QApplication::clipboard()->mimeData();
    ASSERT_NE(mime, nullptr);
    EXPECT_EQ(mime->text().toStdString(), copied);
    EXPECT_EQ(mime->data(QString::fromLatin1(GenomeMimeType)).toStdString(), copied);
    EXPECT_TRUE(status().startsWith(QStringLiteral("Copied "))) << status().toStdString();

    // Pasted over the selected cell, as File ▸ Open places a file: a new generation.
    ASSERT_NE(serializeGenome(*model().cell(1)), copied);
    const std::size_t generations = model().history().size();
    QTest::keyClick(mWindow->cell(3), Qt::Key_V, Qt::ControlModifier);
    ASSERT_NE(model().cell(1), nullptr);
    EXPECT_EQ(serializeGenome(*model().cell(1)), copied);
    EXPECT_EQ(model().history().size(), generations + 1);
    EXPECT_TRUE(mErrors.isEmpty()) << mErrors.join(QStringLiteral("\n")).toStdString();
}

TEST_F(MetadataTest, PastedTextFromElsewhereAndCopiedFilesWork) {
    // Genome text typed or copied in another program: plain text only.
    const Genome flame = test::loadExample("flame-comb-vortex.marble.json");
    QApplication::clipboard()->setText(QString::fromStdString(serializeGenome(flame)));
    model().setSelected(0, true);
    ASSERT_TRUE(mWindow->pasteDesign());
    EXPECT_EQ(serializeGenome(*model().cell(0)), serializeGenome(flame));

    // Files copied in a file manager open as files, images with a genome among them.
    const Genome stones = test::loadExample("five-stones.marble.json");
    auto* mime = new QMimeData;
    mime->setUrls({QUrl::fromLocalFile(imageOf(stones, QStringLiteral("copied.png")))});
    mime->setText(file(QStringLiteral("copied.png")));
    QApplication::clipboard()->setMimeData(mime);
    model().clearSelection();
    model().setSelected(5, true);
    ASSERT_TRUE(mWindow->pasteDesign());
    EXPECT_EQ(serializeGenome(*model().cell(5)), serializeGenome(stones));
}

TEST_F(MetadataTest, BadClipboardTextIsSaidOnTheStatusBarAndChangesNothing) {
    const auto before = gridText(model());
    const std::size_t generations = model().history().size();

    QApplication::clipboard()->setText(QStringLiteral("a shopping list, not a design"));
    EXPECT_FALSE(mWindow->pasteDesign());
    EXPECT_TRUE(status().startsWith(QStringLiteral(
        "Nothing pasted: the clipboard holds no Marbler design (clipboard: line 1, column 1: JSON")))
        << status().toStdString();

    // A genome that breaks a rule names its place.
    std::string bad = serializeGenome(test::loadExample("five-stones.marble.json"));
    bad.replace(bad.find("\"radius\": "), 10, "\"radius\": -");
    QApplication::clipboard()->setText(QString::fromStdString(bad));
    EXPECT_FALSE(mWindow->pasteDesign());
    EXPECT_TRUE(status().contains(QStringLiteral("clipboard: initial[0].radius: must be > 0")))
        << status().toStdString();

    QApplication::clipboard()->clear();
    EXPECT_FALSE(mWindow->pasteDesign());
    EXPECT_TRUE(status().startsWith(QStringLiteral("Nothing pasted"))) << status().toStdString();

    EXPECT_TRUE(mErrors.isEmpty()) << "a status line, not a message box";
    EXPECT_EQ(gridText(model()), before);
    EXPECT_EQ(model().history().size(), generations);
}

TEST_F(MetadataTest, TheLargeViewCopiesItsGenome) {
    DesignDialog* dialog = mWindow->openDesign(6);
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    auto* copy = dialog->findChild<QPushButton*>(QStringLiteral("copyGenome"));
    ASSERT_NE(copy, nullptr);
    auto* copyAction = dialog->findChild<QAction*>(QStringLiteral("copyGenomeAction"));
    ASSERT_NE(copyAction, nullptr);
    EXPECT_EQ(copyAction->shortcut(), QKeySequence(QKeySequence::Copy));
    QApplication::clipboard()->clear();
    ASSERT_TRUE(test::activate(dialog));
    QTest::keyClick(dialog, Qt::Key_C, Qt::ControlModifier);
    EXPECT_EQ(QApplication::clipboard()->text().toStdString(), serializeGenome(dialog->genome()));
    EXPECT_TRUE(status().startsWith(QStringLiteral("Copied "))) << status().toStdString();
    dialog->close();

    // And back into the grid.
    model().setSelected(2, true);
    ASSERT_TRUE(mWindow->pasteDesign());
    EXPECT_EQ(serializeGenome(*model().cell(2)), serializeGenome(*model().cell(6)));
}

} // namespace
