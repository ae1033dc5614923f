// Smaller things issue 29 saw in the window: a cancelled export said nothing and the large view's
// title turned into the last message; Show in folder did nothing without a file manager.

#include "TestUtil.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/GenomeIO.h"
#include "shared/DesignDialog.h"
#include "shared/SavedFiles.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace small_things_test {

class SmallThingsTest : public test::WindowTest {};

TEST_F(SmallThingsTest, ACancelledExportSaysSoAndTheLargeViewKeepsItsTitle) {
    test::ErrorCapture errors;
    DesignDialog* dialog = mWindow->openDesign(2);
    ASSERT_NE(dialog, nullptr);
    const QString title = dialog->windowTitle();
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    ASSERT_TRUE(dialog->exportTo(dir.filePath(QStringLiteral("big.png")), QSize(6000, 6000),
                                 QStringLiteral("grid4")));
    dialog->cancelExport();
    MARBLER_WAIT_EQ(finished.size(), 1, 120000);
    ASSERT_FALSE(finished.front().at(1).toBool());
    const QString said = mWindow->statusBar()->currentMessage();
    EXPECT_TRUE(said.contains(QStringLiteral("cancelled"))) << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("big.png"))) << said.toStdString();
    EXPECT_TRUE(errors.messages.isEmpty());

    // A written export: the window's note says where; the large view still names its design.
    const QString small = dir.filePath(QStringLiteral("small.png"));
    ASSERT_TRUE(dialog->exportTo(small, QSize(32, 20), QStringLiteral("none")));
    MARBLER_WAIT_EQ(finished.size(), 2, 120000);
    ASSERT_TRUE(finished.back().at(1).toBool());
    EXPECT_EQ(dialog->windowTitle(), title);
    EXPECT_EQ(mWindow->savedFileNotice()->file(), QFileInfo(small).absoluteFilePath());
    dialog->close();
}

TEST_F(SmallThingsTest, ShowInFolderWithoutAFileManagerSaysSoAndCopiesThePath) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("sheet.png"));
    int asked = 0;
    setUrlOpener([&asked](const QUrl&) {
        ++asked;
        return false; // no file manager answers
    });
    SavedFileNotice* notice = mWindow->savedFileNotice();
    notice->showFile(file);
    QApplication::clipboard()->clear();
    notice->showInFolderButton()->click();
    setUrlOpener({});
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(QApplication::clipboard()->text(),
              QDir::toNativeSeparators(QFileInfo(file).absoluteFilePath()));
    const QString said = notice->pathLabel()->text();
    EXPECT_TRUE(said.contains(QStringLiteral("No file manager"))) << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("clipboard"))) << said.toStdString();
    EXPECT_TRUE(notice->isVisibleTo(mWindow.get()));
}

TEST_F(SmallThingsTest, TheKindBoxFollowsTheGridThroughBackAndForward) {
    auto* kind = mWindow->findChild<QComboBox*>(QStringLiteral("kindCombo"));
    ASSERT_NE(kind, nullptr);
    ASSERT_EQ(model().populationDimension(), 2);
    EXPECT_EQ(kind->currentData().toInt(), 2);
    mWindow->newRandomPopulation(3);
    ASSERT_EQ(model().populationDimension(), 3);
    EXPECT_EQ(kind->currentData().toInt(), 3);
    EXPECT_EQ(kind->currentText(), QStringLiteral("Solid designs"));
    // Back to the flat grid: the box no longer says "Solid designs" over it.
    mWindow->backAction()->trigger();
    ASSERT_EQ(model().populationDimension(), 2);
    EXPECT_EQ(kind->currentData().toInt(), 2) << kind->currentText().toStdString();
    mWindow->forwardAction()->trigger();
    ASSERT_EQ(model().populationDimension(), 3);
    EXPECT_EQ(kind->currentData().toInt(), 3);
    // A kind chosen over a grid stays chosen: New random makes it.
    kind->setCurrentIndex(kind->findData(2));
    EXPECT_EQ(kind->currentData().toInt(), 2);
    mWindow->newRandomPopulation(kind->currentData().toInt());
    EXPECT_EQ(model().populationDimension(), 2);
}

TEST_F(SmallThingsTest, NewRandomTurnsColourwaysOff) {
    model().clearSelection();
    model().setSelected(0, true);
    mWindow->setColourwaysMode(true);
    ASSERT_TRUE(mWindow->colourwaysMode());
    ASSERT_TRUE(mWindow->colourwaysAction()->isChecked());
    mWindow->newRandomPopulation(2);
    EXPECT_FALSE(mWindow->colourwaysMode());
    EXPECT_FALSE(mWindow->colourwaysAction()->isChecked()) << "the tool bar's button is up";
}

TEST_F(SmallThingsTest, ADroppedPhotoIsOfferedToMarbleAPicture) {
    test::ErrorCapture errors;
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // A plain photo: pixels and nothing of Marbler.
    QImage photo(64, 48, QImage::Format_RGB32);
    for (int y = 0; y < photo.height(); ++y)
        for (int x = 0; x < photo.width(); ++x)
            photo.setPixel(x, y, qRgb(4 * x, 5 * y, 128));
    const QString file = dir.filePath(QStringLiteral("harbour.png"));
    ASSERT_TRUE(photo.save(file));
    QStringList offered;
    setPictureOffer([&offered](QWidget*, const QString& picture) {
        offered << picture;
        return true;
    });
    const std::size_t generations = model().history().size();
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    test::dropFiles(mWindow.get(), {file});
    setPictureOffer({});
    EXPECT_EQ(offered, QStringList{file});
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("\n")).toStdString();
    ASSERT_EQ(model().history().size(), generations + 1);
    EXPECT_TRUE(model().current().description.contains(QStringLiteral("harbour.png")))
        << model().current().description.toStdString();
    int marbled = 0;
    for (int i = 0; i < CellCount; ++i)
        if (const Genome* g = model().cell(i);
            g && g->source && g->source->image.find("harbour.png") != std::string::npos)
            ++marbled;
    EXPECT_EQ(marbled, CellCount) << "nine designs whose bath is the photo";
}

TEST_F(SmallThingsTest, FlatAndSolidDroppedTogetherBothOpen) {
    test::ErrorCapture errors;
    setOpenChooser(
        [](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> { return OpenChoice::Replace; });
    const QString flat = QString::fromStdString(test::examplePath("five-stones.marble.json"));
    const QString solid = QString::fromStdString(test::examplePath("slate-block.marble.json"));
    const Genome flatDesign = loadGenome(flat.toStdString());
    const Genome solidDesign = loadGenome(solid.toStdString());
    ASSERT_EQ(flatDesign.dimension, 2);
    ASSERT_EQ(solidDesign.dimension, 3);
    const std::size_t generations = model().history().size();
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    test::dropFiles(mWindow.get(), {solid, flat});
    setOpenChooser({});
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("\n")).toStdString();
    // The solid one is a generation of its own, shown now; the flat one went into the flat grid,
    // one generation back.
    ASSERT_EQ(model().history().size(), generations + 2);
    EXPECT_EQ(model().populationDimension(), 3);
    auto holds = [this](const Genome& design) {
        for (int i = 0; i < CellCount; ++i)
            if (model().cell(i) && serializeGenome(*model().cell(i)) == serializeGenome(design)) return true;
        return false;
    };
    EXPECT_TRUE(holds(solidDesign));
    const QString said = mWindow->statusBar()->currentMessage();
    EXPECT_TRUE(said.contains(QStringLiteral("slate-block")) && said.contains(QStringLiteral("five-stones")))
        << said.toStdString();
    mWindow->backAction()->trigger();
    EXPECT_EQ(model().populationDimension(), 2);
    EXPECT_TRUE(holds(flatDesign));
}

} // namespace small_things_test
