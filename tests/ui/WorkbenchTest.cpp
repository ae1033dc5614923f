// The workbench window: selection, operators, generations, favourites, bad files, and the
// render service (CPU always, GL when a context can be made).

#include "TestUtil.h"

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Mesh.h"
#include "marbler/Sampling.h"
#include "marbler/gl/GlRenderer.h"
#include "shared/DesignDialog.h"
#include "shared/ErrorReport.h"
#include "shared/RenderService.h"
#include "shared/StartDialog.h"
#include "workbench/DesignCell.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/SessionStore.h"
#include "workbench/Workbench.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QLabel>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QUrl>

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

using namespace marbler;
using namespace marbler::ui;
using marbler::test::dropFiles;
using marbler::test::ErrorCapture;

namespace {

/// The genomes of the grid as text, for exact comparisons of whole generations.
std::vector<std::string> snapshot(const PopulationModel& model) {
    std::vector<std::string> result;
    for (int i = 0; i < CellCount; ++i)
        result.push_back(model.cell(i) ? serializeGenome(*model.cell(i)) : "");
    return result;
}

class WorkbenchTest : public test::WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        // Opening over designs asks where they go; these tests answer "replace" without a
        // modal dialog (tests/ui/HelpTest.cpp tests the question itself).
        setOpenChooser(
            [](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> { return OpenChoice::Replace; });
    }
    void TearDown() override {
        setOpenChooser({});
        WindowTest::TearDown();
    }
};

TEST_F(WorkbenchTest, FirstRandomPopulationIsGenerationOne) {
    ASSERT_EQ(model().history().size(), 1u);
    EXPECT_EQ(model().currentIndex(), 0);
    EXPECT_FALSE(model().isEmptyWorkbench());
    EXPECT_FALSE(model().canGoBack());
    EXPECT_FALSE(mWindow->backAction()->isEnabled());
    EXPECT_FALSE(mWindow->forwardAction()->isEnabled());
    QTreeWidget* tree = mWindow->lineageTree();
    ASSERT_EQ(tree->topLevelItemCount(), 2);
    ASSERT_EQ(tree->topLevelItem(1)->childCount(), 1);
    EXPECT_EQ(tree->topLevelItem(1)->child(0)->text(0), QStringLiteral("Generation 1"));
    EXPECT_EQ(tree->topLevelItem(1)->child(0)->text(1), QStringLiteral("New random population"));
}

TEST(PopulationModelTest, OpenedDesignsAreGenerationOne) {
    PopulationModel model;
    EXPECT_TRUE(model.isEmptyWorkbench());
    EXPECT_FALSE(model.canGoBack());
    const auto used =
        model.placeDesigns({randomGenome(3, 2), randomGenome(4, 2)}, QStringLiteral("Opened two"));
    EXPECT_EQ(used, (std::vector<int>{0, 1}));
    EXPECT_FALSE(model.isEmptyWorkbench());
    ASSERT_EQ(model.history().size(), 1u);
    EXPECT_EQ(model.current().number, 1);
    EXPECT_EQ(model.current().parent, -1);
    EXPECT_EQ(model.current().description, QStringLiteral("Opened two"));
    EXPECT_FALSE(model.canGoBack());
    // A second change is generation 2, and back returns to the opened designs, never to an
    // empty grid.
    model.newRandomPopulation(3);
    ASSERT_EQ(model.history().size(), 2u);
    model.goBack();
    EXPECT_NE(model.cell(0), nullptr);
    EXPECT_EQ(model.cell(2), nullptr);
    EXPECT_FALSE(model.canGoBack());
}

TEST_F(WorkbenchTest, RandomPopulationFillsNineValidCells) {
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_NE(model().cell(i), nullptr) << "cell " << i;
        EXPECT_EQ(model().cell(i)->dimension, 2);
        EXPECT_NO_THROW(validateGenome(*model().cell(i), "cell"));
    }
    EXPECT_EQ(model().selectedCount(), 0);
}

TEST_F(WorkbenchTest, ClickSelectsAndClickAgainDeselects) {
    DesignCell* cell = mWindow->cell(4);
    QTest::mouseClick(cell, Qt::LeftButton);
    EXPECT_TRUE(model().isSelected(4));
    EXPECT_TRUE(cell->isSelectedParent());
    EXPECT_EQ(model().selectedCells(), std::vector<int>{4});
    QTest::mouseClick(cell, Qt::LeftButton);
    EXPECT_FALSE(model().isSelected(4));
    EXPECT_FALSE(cell->isSelectedParent());
}

TEST_F(WorkbenchTest, SpaceTogglesSelection) {
    QTest::keyClick(mWindow->cell(2), Qt::Key_Space);
    EXPECT_TRUE(model().isSelected(2));
    QTest::keyClick(mWindow->cell(2), Qt::Key_Space);
    EXPECT_FALSE(model().isSelected(2));
}

TEST_F(WorkbenchTest, OperatorButtonsFollowParentCount) {
    auto enabled = [&](GeneticOperator op) { return mWindow->operatorAction(op)->isEnabled(); };
    using Op = GeneticOperator;
    EXPECT_FALSE(enabled(Op::Alter) || enabled(Op::Recombine) || enabled(Op::Swap) || enabled(Op::Reinit));

    QTest::mouseClick(mWindow->cell(0), Qt::LeftButton);
    EXPECT_TRUE(enabled(Op::Alter));
    EXPECT_TRUE(enabled(Op::Reinit));
    EXPECT_FALSE(enabled(Op::Recombine));
    EXPECT_FALSE(enabled(Op::Swap));

    QTest::mouseClick(mWindow->cell(1), Qt::LeftButton);
    EXPECT_FALSE(enabled(Op::Alter));
    EXPECT_FALSE(enabled(Op::Reinit));
    EXPECT_TRUE(enabled(Op::Recombine));
    EXPECT_TRUE(enabled(Op::Swap));

    QTest::mouseClick(mWindow->cell(2), Qt::LeftButton);
    EXPECT_TRUE(enabled(Op::Recombine));
    EXPECT_FALSE(enabled(Op::Swap));
    EXPECT_FALSE(enabled(Op::Alter));
}

TEST_F(WorkbenchTest, OperatorKeepsParentsAndFillsNineCells) {
    model().setSteering(false); // the operator's own children (steering mixes in others: SteerUiTest)
    model().setSelected(0, true);
    model().setSelected(4, true);
    const auto before = snapshot(model());
    const std::string idA = genomeId(*model().cell(0)), idB = genomeId(*model().cell(4));
    mWindow->operatorAction(GeneticOperator::Recombine)->trigger();

    const auto after = snapshot(model());
    EXPECT_EQ(after[0], before[0]);
    EXPECT_EQ(after[4], before[4]);
    EXPECT_TRUE(model().isSelected(0) && model().isSelected(4)) << "parents stay selected";
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_NE(model().cell(i), nullptr);
        EXPECT_NO_THROW(validateGenome(*model().cell(i), "cell"));
        if (i == 0 || i == 4) continue;
        EXPECT_NE(after[std::size_t(i)], before[std::size_t(i)]) << "cell " << i << " holds offspring";
        const LineageInfo info = lineageOf(*model().cell(i));
        if (i == CellCount - 1) { // the wildcard cell (WildcardTest.cpp)
            EXPECT_EQ(info.op, QStringLiteral("wildcard"));
            continue;
        }
        EXPECT_EQ(info.op, QStringLiteral("recombine"));
        EXPECT_TRUE(info.parents.contains(QString::fromStdString(idA)) ||
                    info.parents.contains(QString::fromStdString(idB)));
    }
    EXPECT_EQ(model().history().size(), 2u) << "the random population is generation 1, the offspring 2";
}

TEST_F(WorkbenchTest, BreedingIsReproducibleFromTheSessionSeed) {
    model().setSelected(3, true);
    mWindow->applyOperator(GeneticOperator::Alter);
    const auto first = snapshot(model());

    RenderService service(RenderService::Backend::Cpu);
    WorkbenchWindow other(&service);
    other.model()->setSessionSeed(42);
    other.newRandomPopulation(2);
    other.model()->setSelected(3, true);
    other.applyOperator(GeneticOperator::Alter);
    EXPECT_EQ(snapshot(*other.model()), first);
}

TEST_F(WorkbenchTest, BreedingLeavesTheWindowDrawingButTakesNoClicks) {
    // A generation is bred off the GUI thread (from long stylus strokes it takes seconds): the
    // window's own events go on meanwhile, but a click on a cell is not taken until it is done.
    model().setSelected(3, true);
    bool breeding = true, ranDuring = false, clickTaken = true;
    QTimer::singleShot(0, mWindow.get(), [&] {
        ranDuring = breeding;
        QTest::mouseClick(mWindow->cell(5), Qt::LeftButton);
        clickTaken = model().isSelected(5);
    });
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    breeding = false;
    EXPECT_TRUE(ranDuring) << "the GUI thread waited for the children";
    EXPECT_FALSE(clickTaken) << "a click landed while the generation was being bred";
    EXPECT_EQ(model().history().size(), 2u);
    EXPECT_EQ(model().selectedCells(), std::vector<int>{3});
    // Afterwards the window takes clicks again.
    QTest::mouseClick(mWindow->cell(5), Qt::LeftButton);
    EXPECT_TRUE(model().isSelected(5));
}

TEST_F(WorkbenchTest, BackAndForwardRestoreGenerationsExactly) {
    const auto gen0 = snapshot(model());
    model().setSelected(1, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    const auto gen1 = snapshot(model());
    model().clearSelection();
    model().setSelected(5, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Reinit));
    const auto gen2 = snapshot(model());
    ASSERT_NE(gen1, gen0);
    ASSERT_NE(gen2, gen1);

    EXPECT_FALSE(mWindow->forwardAction()->isEnabled());
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen1);
    EXPECT_TRUE(model().isSelected(5)) << "a generation keeps the selection it was left with";
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen0);
    EXPECT_FALSE(mWindow->backAction()->isEnabled()) << "generation 1 is the first";
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen0);
    mWindow->forwardAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen1);
    mWindow->forwardAction()->trigger();
    EXPECT_EQ(snapshot(model()), gen2);
    EXPECT_FALSE(mWindow->forwardAction()->isEnabled());
    EXPECT_TRUE(mWindow->backAction()->isEnabled());
}

TEST_F(WorkbenchTest, UndoShortcutsAreCtrlZAndCtrlShiftZ) {
    EXPECT_EQ(mWindow->backAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_Z));
    EXPECT_EQ(mWindow->forwardAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z));
}

TEST_F(WorkbenchTest, SavedFavouriteLoadsAgain) {
    ASSERT_TRUE(mWindow->keepFavourite(6));
    ASSERT_EQ(model().favourites().size(), 1u);
    const QString file = model().favourites().front().file;
    EXPECT_TRUE(QFileInfo::exists(file));
    EXPECT_TRUE(file.startsWith(mFavourites.path()));

    // A new session (a new model reading the same folder) finds it again.
    PopulationModel reread;
    EXPECT_TRUE(reread.setFavouritesFolder(mFavourites.path()).isEmpty());
    ASSERT_EQ(reread.favourites().size(), 1u);
    EXPECT_EQ(reread.favourites().front().genome, *model().cell(6));

    // Brought back into the grid, it becomes a new generation.
    model().setSelected(0, true);
    mWindow->restoreFavourite(0);
    EXPECT_EQ(*model().cell(0), reread.favourites().front().genome);
    mWindow->backAction()->trigger();
    EXPECT_NE(serializeGenome(*model().cell(0)), serializeGenome(reread.favourites().front().genome));
}

TEST_F(WorkbenchTest, OpenFileLoadsIntoSelectedCell) {
    const QString file =
        QString::fromStdString((test::dataDir() / "examples" / "five-stones.marble.json").string());
    model().setSelected(7, true);
    ASSERT_TRUE(mWindow->openFiles({file}));
    EXPECT_EQ(*model().cell(7), loadGenome(file.toStdString()));
}

TEST_F(WorkbenchTest, BadFileShowsErrorAndKeepsPopulation) {
    ErrorCapture errors;
    const auto before = snapshot(model());
    const std::size_t generations = model().history().size();
    const QString bad =
        QString::fromStdString((test::dataDir() / "ui" / "negative-radius.marble.json").string());

    EXPECT_FALSE(mWindow->openFiles({bad}));
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(QStringLiteral("negative-radius.marble.json")));
    EXPECT_TRUE(errors.messages.front().contains(QStringLiteral("radius")))
        << errors.messages.front().toStdString();
    EXPECT_EQ(snapshot(model()), before);
    EXPECT_EQ(model().history().size(), generations);

    // The same file dropped onto a cell (a drop site is registered once the window exists).
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(3), {bad});
    EXPECT_EQ(errors.messages.size(), 2);
    EXPECT_EQ(snapshot(model()), before);
    EXPECT_EQ(model().history().size(), generations);
}

TEST_F(WorkbenchTest, DroppedGoodFileReplacesThatCell) {
    const QString file =
        QString::fromStdString((test::dataDir() / "examples" / "slate-block.marble.json").string());
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    dropFiles(mWindow->cell(8), {file});
    ASSERT_NE(model().cell(8), nullptr);
    EXPECT_EQ(*model().cell(8), loadGenome(file.toStdString()));
}

TEST_F(WorkbenchTest, LocksAreStoredInTheGenome) {
    Locks locks;
    locks.palette = true;
    model().setCellLocks(2, locks);
    EXPECT_EQ(locksOf(*model().cell(2)), locks);
}

TEST_F(WorkbenchTest, LineageListsEveryCellAndGeneration) {
    model().setSelected(0, true);
    mWindow->applyOperator(GeneticOperator::Alter);
    QTreeWidget* tree = mWindow->lineageTree();
    ASSERT_EQ(tree->topLevelItemCount(), 2);
    EXPECT_EQ(tree->topLevelItem(0)->childCount(), CellCount);
    EXPECT_EQ(tree->topLevelItem(1)->childCount(), int(model().history().size()));
    EXPECT_EQ(tree->topLevelItem(1)->childCount(), 2);
}

TEST_F(WorkbenchTest, EmptyWorkbenchListsNoGeneration) {
    RenderService service(RenderService::Backend::Cpu);
    WorkbenchWindow window(&service);
    EXPECT_TRUE(window.model()->isEmptyWorkbench());
    EXPECT_FALSE(window.backAction()->isEnabled());
    ASSERT_EQ(window.lineageTree()->topLevelItemCount(), 2);
    EXPECT_EQ(window.lineageTree()->topLevelItem(1)->childCount(), 0);
}

// Every child is worth a cell (issue 12).

/// The designs of the grid, compared without meta.
std::set<std::string> distinctDesigns(const PopulationModel& model) {
    std::set<std::string> ids;
    for (int i = 0; i < CellCount; ++i)
        if (model.cell(i)) ids.insert(genomeId(*model.cell(i)));
    return ids;
}

TEST_F(WorkbenchTest, EveryOperatorFillsTheGridWithDistinctDesigns) {
    ASSERT_EQ(distinctDesigns(model()).size(), std::size_t(CellCount));
    for (GeneticOperator op : {GeneticOperator::Alter, GeneticOperator::Recombine, GeneticOperator::Swap,
                               GeneticOperator::Reinit}) {
        const int most = maxParents(op) == 0 ? CellCount - 1 : maxParents(op);
        for (int parents = minParents(op); parents <= most; ++parents) {
            SCOPED_TRACE(std::string(operatorName(op)) + " of " + std::to_string(parents) + " parents");
            model().clearSelection();
            for (int i = 0; i < parents; ++i)
                model().setSelected(i, true);
            ASSERT_TRUE(mWindow->applyOperator(op));
            EXPECT_EQ(distinctDesigns(model()).size(), std::size_t(CellCount))
                << "two cells hold the same design";
            model().goBack();
        }
    }
    // Swap twice in a row: the grid's swaps and their variations stay distinct too.
    model().clearSelection();
    model().setSelected(2, true);
    model().setSelected(6, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Swap));
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Swap));
    EXPECT_EQ(distinctDesigns(model()).size(), std::size_t(CellCount));
    // The lineage says which children are variations.
    int varied = 0;
    for (int i = 0; i < mWindow->lineageTree()->topLevelItem(0)->childCount(); ++i)
        varied += mWindow->lineageTree()->topLevelItem(0)->child(i)->text(1) == QStringLiteral("Swap, varied")
                      ? 1
                      : 0;
    EXPECT_EQ(varied, CellCount - 2 - 2 - 1) << "two parents, two swaps, a wildcard, the rest varied";
}

TEST(PopulationModelTest, EveryNewRandomPopulationIsNew) {
    PopulationModel model;
    model.setSessionSeed(42);
    model.newRandomPopulation(2);
    std::set<std::string> seen = distinctDesigns(model);
    ASSERT_EQ(seen.size(), std::size_t(CellCount));
    for (int round = 0; round < 3; ++round) {
        model.newRandomPopulation(2);
        for (const std::string& id : distinctDesigns(model))
            EXPECT_TRUE(seen.insert(id).second) << "round " << round;
    }
    // Back to the first and new again: new against the grid it replaces as well.
    model.goTo(0);
    const std::set<std::string> first = distinctDesigns(model);
    model.newRandomPopulation(2);
    for (const std::string& id : distinctDesigns(model))
        EXPECT_EQ(first.count(id), 0u);
    EXPECT_EQ(distinctDesigns(model).size(), std::size_t(CellCount));
}

// One vocabulary: the window's words and numbers agree everywhere.

TEST_F(WorkbenchTest, GenerationsAndOperatorsAreNamedAlikeEverywhere) {
    model().setSteering(false); // the operator's own children (steering mixes in others: SteerUiTest)
    model().setSelected(4, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Reinit));
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("eneration 2")))
        << mWindow->statusBar()->currentMessage().toStdString();
    QTreeWidget* tree = mWindow->lineageTree();
    QTreeWidgetItem* designs = tree->topLevelItem(0);
    QTreeWidgetItem* generations = tree->topLevelItem(1);
    ASSERT_EQ(generations->childCount(), 2);
    EXPECT_EQ(generations->child(0)->text(0), QStringLiteral("Generation 1"));
    EXPECT_EQ(generations->child(1)->text(0), QStringLiteral("Generation 2"));
    EXPECT_EQ(generations->child(1)->text(2), QStringLiteral("design 5"));
    for (int i = 0; i < CellCount; ++i) {
        SCOPED_TRACE("design " + std::to_string(i + 1));
        const QString caption = mWindow->cell(i)->caption();
        const QString row =
            designs->child(i)->text(0) + designs->child(i)->text(1) + designs->child(i)->text(3);
        EXPECT_FALSE(caption.contains(QStringLiteral("reinit")) || row.contains(QStringLiteral("reinit")));
        EXPECT_TRUE(designs->child(i)->text(0).startsWith(QStringLiteral("Design %1: ").arg(i + 1)));
        if (i == 4) continue; // the parent, from generation 1
        // A child of generation 2 in design 7 is called "(g2 #7)", as the status bar counts.
        EXPECT_TRUE(caption.contains(QStringLiteral("(g2 #%1)").arg(i + 1))) << caption.toStdString();
        // The last offspring cell is the wildcard (WildcardTest.cpp), and says so.
        const QString madeBy =
            i == CellCount - 1 ? QStringLiteral("Wildcard") : QStringLiteral("Change initial state");
        EXPECT_TRUE(caption.contains(madeBy)) << caption.toStdString();
        EXPECT_EQ(designs->child(i)->text(1), madeBy);
        EXPECT_EQ(designs->child(i)->text(3), QStringLiteral("2"));
        EXPECT_EQ(lineageOf(*model().cell(i)).generation, 2);
    }
}

TEST_F(WorkbenchTest, LockMarkerIsDrawnNotAnEmoji) {
    mWindow->show();
    DesignCell* cell = mWindow->cell(2);
    cell->setImage(QImage()); // a plain cell, so only the marker differs
    const QImage before = cell->grab().toImage();
    EXPECT_TRUE(cell->lockMarkerRect().isEmpty());
    Locks locks;
    locks.initial = true;
    model().setCellLocks(2, locks);
    EXPECT_TRUE(cell->isLocked());
    const QRect marker = cell->lockMarkerRect();
    ASSERT_FALSE(marker.isEmpty());
    for (QChar ch : cell->caption())
        EXPECT_FALSE(ch.isSurrogate()) << "no emoji (or other astral character) in the caption";
    const QImage after = cell->grab().toImage();
    const qreal dpr = after.devicePixelRatio();
    int changed = 0;
    for (int y = marker.top(); y <= marker.bottom(); ++y)
        for (int x = marker.left(); x <= marker.right(); ++x)
            changed +=
                after.pixel(int(x * dpr), int(y * dpr)) != before.pixel(int(x * dpr), int(y * dpr)) ? 1 : 0;
    EXPECT_GT(changed, marker.width() * marker.height() / 5) << "a padlock is drawn where the marker goes";
    model().setCellLocks(2, Locks{});
    EXPECT_FALSE(cell->isLocked());
}

TEST_F(WorkbenchTest, ShrinkingTheWindowKeepsDocksAndCellsUsable) {
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    mWindow->resize(200, 150);
    QTest::qWait(50);
    for (QDockWidget* dock : mWindow->findChildren<QDockWidget*>()) {
        if (!dock->isVisible()) continue;
        EXPECT_GE(dock->widget()->width(), 170) << dock->objectName().toStdString();
        EXPECT_GE(dock->widget()->height(), 120) << dock->objectName().toStdString();
    }
    for (int i = 0; i < CellCount; ++i) {
        EXPECT_GE(mWindow->cell(i)->width(), 110) << i;
        EXPECT_GE(mWindow->cell(i)->height(), 110) << i;
    }
}

// The large view of a design: save and export.

TEST_F(WorkbenchTest, LargeDesignSavesGenomeAtomically) {
    ErrorCapture errors;
    DesignDialog* dialog = mWindow->openDesign(3);
    ASSERT_NE(dialog, nullptr);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("kept.marble.json"));
    ASSERT_TRUE(dialog->saveTo(file));
    EXPECT_EQ(loadGenome(file.toStdString()), *model().cell(3));
    // Saving again replaces the file whole; no temporary is left beside it.
    ASSERT_TRUE(dialog->saveTo(file));
    EXPECT_EQ(loadGenome(file.toStdString()), *model().cell(3));
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
              QStringList{QStringLiteral("kept.marble.json")});
    // A folder that does not exist is reported, and nothing is written.
    EXPECT_FALSE(dialog->saveTo(dir.filePath(QStringLiteral("no/such/folder/x.marble.json"))));
    EXPECT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.isEmpty() ||
                errors.messages.front().startsWith(QStringLiteral("Cannot save the design")));
}

TEST_F(WorkbenchTest, LargeDesignExportsImageAtTheChosenSize) {
    ErrorCapture errors;
    DesignDialog* dialog = mWindow->openDesign(1);
    ASSERT_NE(dialog, nullptr);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("export.png"));
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    ASSERT_TRUE(dialog->exportTo(file, QSize(96, 60), QStringLiteral("none"), 150.0));
    EXPECT_TRUE(dialog->isExporting());
    EXPECT_FALSE(dialog->exportTo(file, QSize(8, 8))) << "one export at a time";
    MARBLER_WAIT_EQ(finished.size(), 1, 120000);
    EXPECT_EQ(finished.front().at(0).toString(), file);
    EXPECT_TRUE(finished.front().at(1).toBool()) << finished.front().at(2).toString().toStdString();
    EXPECT_FALSE(dialog->isExporting());
    EXPECT_TRUE(errors.messages.isEmpty());
    QImageReader reader(file);
    EXPECT_EQ(reader.size(), QSize(96, 60));
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
              QStringList{QStringLiteral("export.png")})
        << "no temporary file remains";
}

TEST_F(WorkbenchTest, CancelledExportLeavesNoFile) {
    ErrorCapture errors;
    DesignDialog* dialog = mWindow->openDesign(2);
    ASSERT_NE(dialog, nullptr);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    ASSERT_TRUE(dialog->exportTo(dir.filePath(QStringLiteral("big.png")), QSize(6000, 6000),
                                 QStringLiteral("grid4")));
    dialog->cancelExport();
    MARBLER_WAIT_EQ(finished.size(), 1, 120000);
    EXPECT_FALSE(finished.front().at(1).toBool());
    EXPECT_TRUE(finished.front().at(2).toString().isEmpty()) << "a cancel is no failure";
    EXPECT_TRUE(errors.messages.isEmpty());
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

// The export settings: units, the size check, focus order, and no stale progress box.

TEST_F(WorkbenchTest, ExportUnitChangeConvertsTheWidth) {
    ExportSettingsDialog dialog(*model().cell(0));
    dialog.setDpi(300);
    ASSERT_EQ(dialog.unit(), QStringLiteral("pixels"));
    EXPECT_EQ(dialog.pixels().width(), 2048);
    // 2048 px became 2048 in (614,400 px): the value must be converted, the pixels kept.
    dialog.setUnit(QStringLiteral("inches"));
    EXPECT_NEAR(dialog.widthValue(), 2048.0 / 300.0, 1e-3);
    EXPECT_EQ(dialog.pixels().width(), 2048);
    dialog.setUnit(QStringLiteral("cm"));
    EXPECT_NEAR(dialog.widthValue(), 2048.0 / 300.0 * 2.54, 1e-3);
    EXPECT_EQ(dialog.pixels().width(), 2048);
    dialog.setUnit(QStringLiteral("mm"));
    EXPECT_NEAR(dialog.widthValue(), 2048.0 / 300.0 * 25.4, 1e-3);
    dialog.setUnit(QStringLiteral("pixels"));
    EXPECT_DOUBLE_EQ(dialog.widthValue(), 2048.0);
    EXPECT_EQ(dialog.pixels().width(), 2048);
    // A print size: 100 mm at 300 dpi, then the same print at 600 dpi.
    dialog.setUnit(QStringLiteral("mm"));
    dialog.setWidthValue(100.0);
    EXPECT_EQ(dialog.pixels().width(), 1181);
    dialog.setDpi(600);
    EXPECT_DOUBLE_EQ(dialog.widthValue(), 100.0);
    EXPECT_EQ(dialog.pixels().width(), 2362);
    EXPECT_EQ(dialog.dpi(), 600.0);
    // In pixels the dpi only labels the file: the pixels stay.
    dialog.setUnit(QStringLiteral("pixels"));
    dialog.setDpi(150);
    EXPECT_EQ(dialog.pixels().width(), 2362);
}

TEST_F(WorkbenchTest, ExportRefusesSizesBeyondTheRenderersLimits) {
    EXPECT_TRUE(exportSizeProblem(QSize(2048, 2048)).isEmpty());
    EXPECT_TRUE(exportSizeProblem(QSize(MaxImageSide, 1000)).isEmpty());
    EXPECT_FALSE(exportSizeProblem(QSize(MaxImageSide + 1, 10)).isEmpty());
    EXPECT_FALSE(exportSizeProblem(QSize(50000, 50000)).isEmpty()) << "2.5 gigapixels";
    EXPECT_TRUE(exportSizeProblem(QSize(614400, 614400)).contains(QStringLiteral("at most")));

    ExportSettingsDialog settings(*model().cell(0));
    settings.setDpi(300);
    settings.setUnit(QStringLiteral("inches"));
    settings.setWidthValue(2048.0); // 614,400 px a side
    auto* ok = settings.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    EXPECT_FALSE(ok->isEnabled());
    EXPECT_TRUE(settings.findChild<QLabel*>(QStringLiteral("exportPixels"))
                    ->text()
                    .contains(QStringLiteral("at most")));
    settings.setWidthValue(10.0);
    EXPECT_TRUE(ok->isEnabled());

    ErrorCapture errors;
    DesignDialog* dialog = mWindow->openDesign(0);
    ASSERT_NE(dialog, nullptr);
    QTemporaryDir dir;
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    EXPECT_FALSE(dialog->exportTo(dir.filePath(QStringLiteral("huge.png")), QSize(614400, 614400)));
    EXPECT_FALSE(dialog->isExporting()) << "refused before any work starts";
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().contains(QStringLiteral("614")));
    EXPECT_TRUE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    dialog->close();
}

TEST_F(WorkbenchTest, ExportSettingsTabOrderReachesEveryField) {
    ExportSettingsDialog dialog(*model().cell(0));
    dialog.show();
    ASSERT_TRUE(test::activate(&dialog));
    QWidget* width = dialog.findChild<QWidget*>(QStringLiteral("exportWidth"));
    width->setFocus(Qt::TabFocusReason);
    MARBLER_WAIT(width->hasFocus(), 5000);
    QStringList reached;
    for (int i = 0; i < 8; ++i) {
        for (QWidget* w = QApplication::focusWidget(); w; w = w->parentWidget())
            if (!w->objectName().isEmpty()) {
                if (!reached.contains(w->objectName())) reached << w->objectName();
                break;
            }
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
    }
    for (const char* field : {"exportWidth", "exportUnit", "exportDpi", "exportAa"})
        EXPECT_TRUE(reached.contains(QString::fromLatin1(field)))
            << field << " is not reached: " << reached.join(',').toStdString();
    EXPECT_EQ(reached.mid(0, 4), (QStringList{QStringLiteral("exportWidth"), QStringLiteral("exportUnit"),
                                              QStringLiteral("exportDpi"), QStringLiteral("exportAa")}));
}

TEST_F(WorkbenchTest, ExportErrorIsNeverCoveredByAStaleProgressBox) {
    DesignDialog* dialog = mWindow->openDesign(1);
    ASSERT_NE(dialog, nullptr);
    bool progressVisibleAtError = false;
    int errorCount = 0;
    setErrorHandler([&](QWidget*, const QString&, const QString&) {
        ++errorCount;
        for (QProgressDialog* box : dialog->findChildren<QProgressDialog*>())
            progressVisibleAtError = progressVisibleAtError || box->isVisible();
    });
    QTemporaryDir dir;
    QSignalSpy finished(dialog, &DesignDialog::exportFinished);
    ASSERT_TRUE(dialog->exportTo(dir.filePath(QStringLiteral("no/such/folder/x.png")), QSize(64, 64),
                                 QStringLiteral("none")));
    // As after a long export: the progress box is up when the failure arrives.
    auto* box = dialog->findChild<QProgressDialog*>(QStringLiteral("exportProgress"));
    ASSERT_NE(box, nullptr);
    box->show();
    MARBLER_WAIT_EQ(finished.size(), 1, 60000);
    setErrorHandler({});
    EXPECT_EQ(errorCount, 1);
    EXPECT_FALSE(finished.front().at(2).toString().isEmpty());
    EXPECT_FALSE(progressVisibleAtError) << "the progress box covered the error";
    QTest::qWait(400); // past the box's minimum duration: it must not come back
    for (QProgressDialog* b : dialog->findChildren<QProgressDialog*>())
        EXPECT_FALSE(b->isVisible());
    dialog->close();
}

// Keyboard use of the grid.

TEST_F(WorkbenchTest, ArrowsMoveFocusSpaceSelectsEnterOpens) {
    mWindow->show();
    ASSERT_TRUE(test::activate(mWindow.get()));
    mWindow->cell(4)->setFocus(Qt::TabFocusReason);
    MARBLER_WAIT(mWindow->cell(4)->hasFocus(), 5000);
    const auto press = [](int key) { QTest::keyClick(QApplication::focusWidget(), Qt::Key(key)); };
    press(Qt::Key_Right);
    EXPECT_TRUE(mWindow->cell(5)->hasFocus());
    press(Qt::Key_Right); // the edge stops it
    EXPECT_TRUE(mWindow->cell(5)->hasFocus());
    press(Qt::Key_Down);
    EXPECT_TRUE(mWindow->cell(8)->hasFocus());
    press(Qt::Key_Left);
    press(Qt::Key_Left);
    EXPECT_TRUE(mWindow->cell(6)->hasFocus());
    press(Qt::Key_Up);
    EXPECT_TRUE(mWindow->cell(3)->hasFocus());

    press(Qt::Key_Space);
    EXPECT_EQ(model().selectedCells(), std::vector<int>{3});

    // Enter opens the design large; the dialog is not modal, so the test just closes it.
    QSignalSpy opened(mWindow.get(), &WorkbenchWindow::designOpened);
    press(Qt::Key_Return);
    ASSERT_EQ(opened.size(), 1);
    auto* dialog = opened.front().at(0).value<DesignDialog*>();
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->genome(), *model().cell(3));
    EXPECT_FALSE(dialog->isModal());
    dialog->close();
    EXPECT_EQ(model().selectedCells(), std::vector<int>{3}) << "opening does not change the selection";
}

// The start choice.

class StartChoiceTest : public ::testing::Test {
protected:
    void SetUp() override {
        QSettings().remove(QStringLiteral("start"));
        QSettings().remove(QStringLiteral("population"));
        QSettings().remove(QStringLiteral("view"));
        setStartChooser([this](QWidget*, const StartChoice& defaults) -> std::optional<StartChoice> {
            ++asked;
            lastDefaults = defaults;
            return answer;
        });
    }
    void TearDown() override { setStartChooser({}); }

    int asked = 0;
    StartChoice lastDefaults;
    std::optional<StartChoice> answer;
    RenderService service{RenderService::Backend::Cpu};
};

TEST_F(StartChoiceTest, SolidChoiceBreedsSolidGenomesOnTheChosenObject) {
    answer = StartChoice{3, QStringLiteral("torus")};
    WorkbenchWindow window(&service);
    startSession(window, {});
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(lastDefaults, StartChoice{}) << "flat on a vase the first time";
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_NE(window.model()->cell(i), nullptr);
        EXPECT_EQ(window.model()->cell(i)->dimension, 3);
    }
    EXPECT_EQ(window.mesh(), QStringLiteral("torus"));
    EXPECT_EQ(window.model()->history().size(), 1u);
    EXPECT_FALSE(window.backAction()->isEnabled());
    // Breeding keeps to solids.
    window.model()->setSelected(0, true);
    ASSERT_TRUE(window.applyOperator(GeneticOperator::Alter));
    for (int i = 0; i < CellCount; ++i)
        EXPECT_EQ(window.model()->cell(i)->dimension, 3);

    // The next start offers the last choice.
    WorkbenchWindow next(&service);
    answer.reset(); // the question closed: the defaults apply
    startSession(next, {});
    EXPECT_EQ(lastDefaults, (StartChoice{3, QStringLiteral("torus")}));
    EXPECT_EQ(next.model()->cell(0)->dimension, 3);
}

TEST_F(StartChoiceTest, FlatChoiceBreedsFlatGenomes) {
    answer = StartChoice{2, QStringLiteral("vase")};
    WorkbenchWindow window(&service);
    startSession(window, {});
    EXPECT_EQ(asked, 1);
    for (int i = 0; i < CellCount; ++i)
        EXPECT_EQ(window.model()->cell(i)->dimension, 2);
}

TEST_F(StartChoiceTest, ForcedDimensionFilesAndDontAskSkipTheQuestion) {
    answer = StartChoice{2, QStringLiteral("vase")};
    {
        WorkbenchWindow window(&service);
        StartOptions options;
        options.dimension = 3; // --solid or MARBLER_SOLID=1
        startSession(window, options);
        EXPECT_EQ(window.model()->cell(4)->dimension, 3);
    }
    {
        WorkbenchWindow window(&service);
        StartOptions options;
        options.ask = false; // screenshots, MARBLER_NO_START_DIALOG=1
        startSession(window, options);
        EXPECT_EQ(window.model()->cell(4)->dimension, 3) << "as last time";
    }
    {
        const std::string file = (test::dataDir() / "examples" / "five-stones.marble.json").string();
        WorkbenchWindow window(&service);
        StartOptions options;
        options.files = {file};
        startSession(window, options);
        EXPECT_EQ(*window.model()->cell(0), loadGenome(file));
        EXPECT_EQ(window.model()->history().size(), 1u) << "the opened file is generation 1";
        EXPECT_FALSE(window.backAction()->isEnabled());
    }
    EXPECT_EQ(asked, 0);
    // "Don't ask again": the last choice is used without a question.
    rememberStartChoice({3, QStringLiteral("cube")}, false);
    WorkbenchWindow window(&service);
    startSession(window, {});
    EXPECT_EQ(asked, 0);
    EXPECT_EQ(window.model()->cell(0)->dimension, 3);
    EXPECT_EQ(window.mesh(), QStringLiteral("cube"));
}

TEST_F(StartChoiceTest, StartDialogOffersBothKindsAndRemembersNotAsking) {
    StartDialog dialog(StartChoice{3, QStringLiteral("sphere")});
    EXPECT_TRUE(dialog.solidButton()->isDefault());
    EXPECT_FALSE(dialog.flatButton()->isDefault());
    EXPECT_EQ(dialog.meshBox()->currentText(), QStringLiteral("sphere"));
    EXPECT_FALSE(dialog.dontAskAgain());
    dialog.meshBox()->setCurrentText(QStringLiteral("teapot"));
    dialog.dontAskBox()->setChecked(true);
    dialog.solidButton()->click();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.choice(), (StartChoice{3, QStringLiteral("teapot")}));
    EXPECT_TRUE(dialog.dontAskAgain());

    StartDialog flat(StartChoice{});
    EXPECT_TRUE(flat.flatButton()->isDefault());
    flat.flatButton()->click();
    EXPECT_EQ(flat.choice().dimension, 2);

    EXPECT_TRUE(askStartChoice());
    rememberStartChoice(dialog.choice(), !dialog.dontAskAgain());
    EXPECT_FALSE(askStartChoice());
    EXPECT_EQ(lastStartChoice(), (StartChoice{3, QStringLiteral("teapot")}));
}

TEST_F(StartChoiceTest, TheObjectBoxListsEveryBuiltInObjectDefaultFirst) {
    // One list of built-in objects (Mesh.h): the start dialog offers exactly those `--mesh` takes.
    StartDialog dialog(StartChoice{3});
    QStringList offered;
    for (int i = 0; i < dialog.meshBox()->count(); ++i)
        offered << dialog.meshBox()->itemText(i);
    QStringList builtin;
    for (const std::string& name : builtinMeshNames())
        builtin << QString::fromStdString(name);
    EXPECT_EQ(offered.join(", ").toStdString(), builtin.join(", ").toStdString());
    EXPECT_EQ(offered.value(0).toStdString(), DefaultMesh);
    EXPECT_EQ(dialog.meshBox()->currentText().toStdString(), DefaultMesh);
}

// The session: autosaved after every change, offered and resumed at the next start.

/// Everything a session's history holds, as text, for exact comparisons.
std::vector<std::string> historySnapshot(const PopulationModel& model) {
    std::vector<std::string> result;
    for (const Generation& g : model.history()) {
        std::string text = std::to_string(g.parent) + "|" + std::to_string(g.number) + "|" +
                           std::to_string(g.branch) + "|" + g.description.toStdString() + "|";
        for (int p : g.parentCells)
            text += std::to_string(p) + ",";
        text += "|";
        for (int i = 0; i < CellCount; ++i) {
            text += g.selected[std::size_t(i)] ? "S" : "-";
            text +=
                g.cells[std::size_t(i)] ? serializeGenome(*g.cells[std::size_t(i)]) : std::string("(empty)");
        }
        result.push_back(text);
    }
    return result;
}

/// Every entry of a folder, hidden ones (a temporary file of an atomic write) included.
QStringList folderEntries(const QString& folder) {
    QStringList entries =
        QDir(folder).entryList(QDir::Files | QDir::Dirs | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
    // A session's generations folder (Session.h, version 3) goes with its file: no entry of its own.
    entries.removeIf([&](const QString& name) {
        return name.endsWith(QStringLiteral(".generations")) &&
               QFileInfo(QDir(folder).filePath(name)).isDir();
    });
    return entries;
}

class SessionTest : public StartChoiceTest {
protected:
    void SetUp() override {
        StartChoiceTest::SetUp();
        ASSERT_TRUE(mFavourites.isValid());
        ASSERT_TRUE(mSession.isValid());
        qputenv("MARBLER_FAVOURITES_DIR", mFavourites.path().toLocal8Bit());
        options.sessionFolder = mSession.path().toStdString();
    }
    void TearDown() override {
        qunsetenv("MARBLER_FAVOURITES_DIR");
        StartChoiceTest::TearDown();
    }
    /// The folder the kept sessions are in.
    QString sessionsFolder() const { return SessionStore(mSession.path()).folder(); }
    /// The last session's file: the kept session changed most recently.
    QString sessionFile() const {
        const auto kept = SessionStore(mSession.path()).list();
        return kept.empty() ? QString() : kept.front().file;
    }

    QTemporaryDir mFavourites;
    QTemporaryDir mSession;
    StartOptions options;
};

TEST_F(SessionTest, ResumeBringsBackGenerationsCurrentSeedAndHistory) {
    answer = StartChoice{2, QStringLiteral("vase")};
    std::vector<std::string> before;
    std::vector<std::string> grid;
    std::uint64_t seed = 0, nextSeed = 0;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        EXPECT_EQ(lastDefaults.resumeGeneration, 0) << "nothing to resume the first time";
        PopulationModel& m = *window.model();
        m.setSelected(0, true);
        ASSERT_TRUE(window.applyOperator(GeneticOperator::Alter));
        m.clearSelection();
        m.setSelected(1, true);
        m.setSelected(2, true);
        ASSERT_TRUE(window.applyOperator(GeneticOperator::Recombine));
        m.goBack(); // generation 2 of 3: forward history to bring back too
        m.setCellLocks(5, Locks{true, false, true});
        ASSERT_EQ(m.history().size(), 3u);
        ASSERT_EQ(m.currentIndex(), 1);
        before = historySnapshot(m);
        grid = snapshot(m);
        seed = m.sessionSeed();
        nextSeed = m.nextBreedSeed();
    } // the window and its model are gone, as after a crash or a close

    WorkbenchWindow window(&service);
    answer.reset(); // the question closed: its default, resuming, applies
    startSession(window, options);
    EXPECT_EQ(asked, 2);
    EXPECT_TRUE(lastDefaults.resume) << "resuming is the default choice";
    EXPECT_EQ(lastDefaults.resumeGeneration, 2);
    EXPECT_EQ(lastDefaults.resumeDimension, 2);
    PopulationModel& m = *window.model();
    EXPECT_EQ(historySnapshot(m), before);
    EXPECT_EQ(snapshot(m), grid);
    EXPECT_EQ(m.currentIndex(), 1);
    EXPECT_EQ(m.sessionSeed(), seed);
    EXPECT_EQ(m.nextBreedSeed(), nextSeed) << "breeding goes on as it would have";
    EXPECT_EQ(locksOf(*m.cell(5)), (Locks{true, false, true}));
    EXPECT_TRUE(window.backAction()->isEnabled());
    EXPECT_TRUE(window.forwardAction()->isEnabled());
    m.goForward();
    EXPECT_EQ(m.currentIndex(), 2);
    EXPECT_EQ(m.current().description, QStringLiteral("Recombine of 2 parents"));
    m.goTo(0);
    EXPECT_EQ(m.current().description, QStringLiteral("New random population"));
    EXPECT_EQ(folderEntries(sessionsFolder()), QStringList{QFileInfo(m.sessionFile()).fileName()})
        << "resuming keeps one session file";
}

TEST_F(SessionTest, SolidSessionResumesItsKindAndObject) {
    answer = StartChoice{3, QStringLiteral("torus")};
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        ASSERT_EQ(window.model()->cell(0)->dimension, 3);
        window.setMesh(QStringLiteral("teapot")); // changing the object is saved too
    }
    rememberStartChoice({2, QStringLiteral("cube")}, true); // what the settings say now
    answer = StartChoice{2, QStringLiteral("cube"), true};
    WorkbenchWindow window(&service);
    startSession(window, options);
    EXPECT_EQ(lastDefaults.resumeGeneration, 1);
    EXPECT_EQ(lastDefaults.resumeDimension, 3);
    EXPECT_EQ(window.model()->cell(4)->dimension, 3);
    EXPECT_EQ(window.mesh(), QStringLiteral("teapot"));
    EXPECT_EQ(window.model()->populationDimension(), 3);
}

TEST_F(SessionTest, NotResumingKeepsTheOldSession) {
    answer = StartChoice{2, QStringLiteral("vase")};
    std::vector<std::string> first;
    QString firstFile;
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
        first = snapshot(*window.model());
        firstFile = window.model()->sessionFile();
    }
    answer = StartChoice{3, QStringLiteral("vase")}; // "breed solid" instead of resuming
    WorkbenchWindow window(&service);
    startSession(window, options);
    EXPECT_EQ(window.model()->cell(0)->dimension, 3);
    EXPECT_NE(window.model()->sessionFile(), firstFile) << "a new session has a file of its own";
    EXPECT_EQ(folderEntries(sessionsFolder()).size(), 2)
        << folderEntries(sessionsFolder()).join(' ').toStdString();
    const SavedSession previous = loadSession(firstFile);
    ASSERT_EQ(previous.history.size(), 1u);
    EXPECT_EQ(serializeGenome(*previous.history[0].cells[0]), first[0]);
    EXPECT_EQ(loadSession(window.model()->sessionFile()).dimension, 3);

    // A forced kind (--solid, --flat) starts a new session without offering the old one.
    const int askedBefore = asked;
    WorkbenchWindow forced(&service);
    StartOptions flat = options;
    flat.dimension = 2;
    startSession(forced, flat);
    EXPECT_EQ(asked, askedBefore);
    EXPECT_EQ(forced.model()->cell(0)->dimension, 2);
    EXPECT_EQ(SessionStore(mSession.path()).list().size(), 3u) << "every session is kept";
}

TEST_F(SessionTest, EveryChangeIsSavedAtomically) {
    answer = StartChoice{2, QStringLiteral("vase")};
    ErrorCapture errors;
    WorkbenchWindow window(&service);
    PopulationModel& m = *window.model();
    // Saved state equals the model: generations, current, seed.
    const auto expectSaved = [&](const char* after) {
        ASSERT_EQ(m.sessionFile(), sessionFile()) << after << ": the session being bred is the last one";
        const SavedSession saved = loadSession(sessionFile());
        PopulationModel copy;
        copy.restoreSession(saved);
        EXPECT_EQ(historySnapshot(copy), historySnapshot(m)) << after;
        EXPECT_EQ(saved.current, m.currentIndex()) << after;
        EXPECT_EQ(saved.seed, m.sessionSeed()) << after;
        EXPECT_EQ(folderEntries(sessionsFolder()), QStringList{QFileInfo(sessionFile()).fileName()})
            << after << ": no temporary file is left behind";
    };
    startSession(window, options);
    expectSaved("the first population");
    m.setSelected(3, true);
    ASSERT_TRUE(window.applyOperator(GeneticOperator::Alter));
    expectSaved("an operator");
    m.goBack();
    expectSaved("back");
    m.goForward();
    expectSaved("forward");
    m.goBack();
    m.clearSelection();
    m.setSelected(6, true);
    ASSERT_TRUE(window.applyOperator(GeneticOperator::Reinit));
    EXPECT_EQ(m.history().size(), 3u);
    expectSaved("breeding after going back (a new branch beside the old one)");
    window.newRandomPopulation(2);
    expectSaved("a new random population");
    const QString design =
        QString::fromStdString((test::dataDir() / "examples" / "five-stones.marble.json").string());
    ASSERT_TRUE(window.openFiles({design}, 2));
    expectSaved("an opened file");
    dropFiles(window.cell(7), {design});
    EXPECT_EQ(*m.cell(7), loadGenome(design.toStdString()));
    expectSaved("a dropped file");
    m.setCellLocks(1, Locks{false, true, false});
    expectSaved("locks");
    EXPECT_EQ(locksOf(*loadSession(sessionFile()).history[std::size_t(m.currentIndex())].cells[1]),
              (Locks{false, true, false}));
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("\n")).toStdString();
}

TEST_F(SessionTest, CorruptSessionIsReportedKeptAsBadAndAFreshOneStarts) {
    answer = StartChoice{2, QStringLiteral("vase")};
    {
        WorkbenchWindow window(&service);
        startSession(window, options);
    }
    // Half a session, as a crash in a non-atomic writer would leave it.
    const QString damaged = sessionFile();
    QFile file(damaged);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray whole = file.readAll();
    file.close();
    const QByteArray half = whole.left(whole.size() / 2);
    {
        QFile out(damaged);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(half);
    }
    ErrorCapture errors;
    const int askedBefore = asked;
    lastDefaults = {};
    WorkbenchWindow window(&service);
    startSession(window, options);
    ASSERT_EQ(errors.messages.size(), 1) << "reported once";
    EXPECT_TRUE(errors.messages.front().startsWith(QStringLiteral("Cannot resume the last session")));
    EXPECT_TRUE(errors.messages.front().contains(QFileInfo(damaged).fileName() + QStringLiteral(".bad")))
        << errors.messages.front().toStdString();
    EXPECT_EQ(asked, askedBefore + 1);
    EXPECT_EQ(lastDefaults.resumeGeneration, 0) << "nothing to resume offered";
    EXPECT_TRUE(lastDefaults.otherSessions.isEmpty()) << "a session moved aside is not listed";
    EXPECT_EQ(window.model()->history().size(), 1u) << "a fresh session";
    QFile bad(damaged + QStringLiteral(".bad"));
    ASSERT_TRUE(bad.open(QIODevice::ReadOnly)) << "the bad file is kept aside";
    EXPECT_EQ(bad.readAll(), half);
    EXPECT_FALSE(QFileInfo::exists(damaged));
    EXPECT_EQ(window.model()->sessionFile(), sessionFile());
    EXPECT_NO_THROW(loadSession(sessionFile())) << "the fresh session is saved";

    // Valid JSON holding a broken design: also kept aside (beside the first), named.
    const QString fresh = sessionFile();
    // The designs are in the generation files beside the session's head (Session.h, version 3).
    const std::string cells = generationFile(generationsFolder(fresh), 0).toStdString();
    std::string broken = test::readFile(cells);
    const auto pos = broken.find("\"format\":\"marbler-genome\",\"version\":1,\"dimension\":2");
    ASSERT_NE(pos, std::string::npos) << broken.substr(0, 400);
    broken.replace(pos, 51, "\"format\":\"marbler-genome\",\"version\":1,\"dimension\":7");
    test::writeFile(cells, broken);
    EXPECT_THROW(loadSession(fresh), InputError);
    WorkbenchWindow again(&service);
    startSession(again, options);
    ASSERT_EQ(errors.messages.size(), 2);
    EXPECT_TRUE(errors.messages.back().contains(QFileInfo(fresh).fileName() + QStringLiteral(".bad")));
    EXPECT_TRUE(QFileInfo::exists(fresh + QStringLiteral(".bad")));
    EXPECT_TRUE(QFileInfo::exists(damaged + QStringLiteral(".bad")));
    EXPECT_EQ(again.model()->history().size(), 1u);

    // keepBadSession never overwrites an earlier .bad of the same name.
    test::writeFile(fresh.toStdString(), "{");
    EXPECT_EQ(keepBadSession(fresh), fresh + QStringLiteral(".2.bad"));
}

TEST_F(SessionTest, BadSessionDocumentsThrowInputErrors) {
    const auto fails = [](const std::string& text) {
        try {
            parseSession(text, "s.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(fails(""), "(no error)");
    EXPECT_NE(fails("[]"), "(no error)");
    EXPECT_NE(fails(R"({"format":"marbler-session","version":1})"), "(no error)");
    const std::string genome = serializeGenome(randomGenome(3, 2));
    const std::string cells = "[" + genome + ",null,null,null,null,null,null,null,null]";
    const std::string good = R"({"format":"marbler-session","version":1,"seed":5,"dimension":2,"current":0,)"
                             R"("generations":[{"cells":)" +
                             cells + "}]}";
    EXPECT_EQ(fails(good), "(no error)");
    const SavedSession s = parseSession(good, "s.json");
    EXPECT_EQ(s.seed, 5u);
    EXPECT_EQ(*s.history[0].cells[0], randomGenome(3, 2));
    std::string outOfRange = good;
    outOfRange.replace(outOfRange.find("\"current\":0"), 11, "\"current\":1");
    EXPECT_EQ(fails(outOfRange), "s.json: current: must name one of the generations");
    std::string noDesigns = R"({"format":"marbler-session","version":1,"seed":5,"dimension":2,"current":0,)"
                            R"("generations":[{"cells":[null,null,null,null,null,null,null,null,null]}]})";
    EXPECT_EQ(fails(noDesigns), "s.json: generations[0].cells: a generation holds at least one design");
}

TEST_F(SessionTest, SaveFailureIsReportedOnce) {
    ErrorCapture errors;
    // A file where the session folder should be: the folder cannot be made.
    const QString blocker = mSession.filePath(QStringLiteral("blocker"));
    QFile f(blocker);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.close();
    options.sessionFolder = (blocker + QStringLiteral("/session")).toStdString();
    answer = StartChoice{2, QStringLiteral("vase")};
    WorkbenchWindow window(&service);
    startSession(window, options);
    window.model()->setSelected(0, true);
    ASSERT_TRUE(window.applyOperator(GeneticOperator::Alter));
    ASSERT_EQ(errors.messages.size(), 1);
    EXPECT_TRUE(errors.messages.front().startsWith(QStringLiteral("Cannot save the session")));
    EXPECT_EQ(window.model()->history().size(), 2u) << "breeding goes on";
}

TEST_F(SessionTest, SessionFolderComesFromTheEnvironmentInTests) {
    qputenv("MARBLER_SESSION_DIR", mSession.path().toLocal8Bit());
    EXPECT_EQ(defaultSessionFolder(), mSession.path());
    qunsetenv("MARBLER_SESSION_DIR");
    EXPECT_TRUE(defaultSessionFolder().endsWith(QStringLiteral("/session")));
}

TEST_F(StartChoiceTest, StartDialogOffersToResumeASavedSession) {
    StartChoice offer{2, QStringLiteral("vase"), true, 4, 3};
    StartDialog dialog(offer);
    ASSERT_NE(dialog.resumeButton(), nullptr);
    EXPECT_TRUE(dialog.resumeButton()->isDefault());
    EXPECT_FALSE(dialog.flatButton()->isDefault());
    EXPECT_TRUE(dialog.resumeButton()->text().contains(QStringLiteral("generation 4, solid")))
        << dialog.resumeButton()->text().toStdString();
    dialog.resumeButton()->click();
    EXPECT_TRUE(dialog.choice().resume);

    StartDialog flat(offer);
    flat.flatButton()->click();
    EXPECT_FALSE(flat.choice().resume);
    EXPECT_EQ(flat.choice().dimension, 2);

    StartDialog none(StartChoice{});
    EXPECT_EQ(none.resumeButton(), nullptr);
}

// The window's command line.

TEST(WorkbenchArgsTest, HiddenOptionsAndFiles) {
    const std::vector<std::string> words{
        "a.marble.json", "--seed",   "17", "--screenshot=shot.png", "--solid", "-platform",
        "offscreen",     "-reverse", "--", "--odd-name.json"};
    const WorkbenchArgs args = parseWorkbenchArgs(words);
    EXPECT_EQ(args.error, "");
    EXPECT_EQ(args.files, (std::vector<std::string>{"a.marble.json", "--odd-name.json"}));
    EXPECT_EQ(args.seed, 17ULL);
    EXPECT_EQ(args.screenshot, "shot.png");
    EXPECT_EQ(args.dimension, 3);
    EXPECT_FALSE(args.help);
    EXPECT_EQ(parseWorkbenchArgs(std::vector<std::string>{"--flat"}).dimension, 2);
    EXPECT_TRUE(parseWorkbenchArgs(std::vector<std::string>{"x.json", "-h"}).help);
}

TEST(WorkbenchArgsTest, BadOptionsAreNamedOnOneLine) {
    const auto error = [](std::vector<std::string> words) { return parseWorkbenchArgs(words).error; };
    EXPECT_EQ(error({"a.json", "--bogus"}), "marbler: unknown option --bogus (see marbler --help)");
    EXPECT_EQ(error({"-seed", "3"}), "marbler: unknown option -seed (see marbler --help)");
    EXPECT_EQ(error({"--seed", "x3"}), "marbler: --seed needs a whole number, not 'x3'");
    EXPECT_EQ(error({"--screenshot"}), "marbler: --screenshot needs a value");
    EXPECT_EQ(error({"--solid=yes"}), "marbler: unknown option --solid=yes (see marbler --help)");
    for (const std::string& e : {error({"--bogus"}), error({"--seed"})})
        EXPECT_EQ(e.find('\n'), std::string::npos);
}

TEST_F(WorkbenchTest, WindowRendersEveryCellOnTheCpu) {
    mWindow->resize(600, 500);
    mWindow->show();
    QSignalSpy finished(mWindow.get(), &WorkbenchWindow::renderingFinished);
    // Resizing restarts renders after a debounce; wait until all nine have final images.
    while (!mWindow->renderingDone() || finished.isEmpty())
        ASSERT_TRUE(finished.wait(120000));
    for (int i = 0; i < CellCount; ++i)
        EXPECT_FALSE(mWindow->cell(i)->image().isNull()) << "cell " << i;
}

// The render service on its own.

TEST(RenderServiceTest, GuiThreadRunsWhileALargeRenderIsInFlight) {
    RenderService service(RenderService::Backend::Cpu);
    RenderRequest request;
    request.genome = randomGenome(9, 2);
    request.size = QSize(2048, 2048);
    request.aa = QStringLiteral("grid4");
    bool finalArrived = false;
    int previews = 0;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage&, bool final) {
        if (final)
            finalArrived = true;
        else
            ++previews;
    });
    service.request(3, request);

    // Work queued on the GUI thread after the request: a posted call and a repeating timer.
    bool postedRan = false, finalBeforePosted = false;
    QMetaObject::invokeMethod(
        &service,
        [&] {
            postedRan = true;
            finalBeforePosted = finalArrived;
        },
        Qt::QueuedConnection);
    int ticks = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] { ++ticks; });
    timer.start(0);
    MARBLER_WAIT(postedRan && ticks >= 50 && previews >= 1, 120000);
    EXPECT_FALSE(finalBeforePosted);
    EXPECT_FALSE(finalArrived) << "the large final pass is still rendering while the GUI thread runs";
    EXPECT_FALSE(service.idle());
    // Cancelling stops the in-flight render; the service goes idle and closes promptly.
    QSignalSpy idle(&service, &RenderService::becameIdle);
    service.cancel(3);
    EXPECT_EQ(idle.size(), 1);
    EXPECT_TRUE(service.idle());
}

TEST(RenderServiceTest, NewerRequestSupersedesOlder) {
    RenderService service(RenderService::Backend::Cpu);
    const Genome a = randomGenome(1, 2), b = randomGenome(2, 2);
    QSignalSpy idle(&service, &RenderService::becameIdle);
    QImage finalImage;
    int finals = 0;
    QObject::connect(&service, &RenderService::rendered,
                     [&](std::uint64_t key, const QImage& image, bool final) {
                         EXPECT_EQ(key, 7u);
                         if (final) {
                             finalImage = image;
                             ++finals;
                         }
                     });
    RenderRequest first;
    first.genome = a;
    first.size = QSize(64, 64);
    service.request(7, first);
    RenderRequest second = first;
    second.genome = b;
    service.request(7, second);
    ASSERT_TRUE(idle.wait(120000));
    EXPECT_EQ(finals, 1);
    RenderSettings settings;
    settings.width = settings.height = 64;
    settings.aa = "rgss";
    EXPECT_EQ(finalImage, toQImage(CpuRenderer(b).render(settings)));
}

TEST(RenderServiceTest, GlRendersSolidOnAnObject) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    // Asked for explicitly: on a software rasteriser the automatic choice is the CPU.
    const QByteArray forced = qgetenv("MARBLER_RENDERER");
    qunsetenv("MARBLER_RENDERER");
    RenderService service(gl::BackendPreference::Gpu);
    if (!forced.isEmpty()) qputenv("MARBLER_RENDERER", forced);
    QSignalSpy ready(&service, &RenderService::backendReady);
    ASSERT_TRUE(ready.wait(60000));
    EXPECT_TRUE(service.usesGl());
    EXPECT_TRUE(service.backendName().startsWith(QStringLiteral("OpenGL")))
        << service.backendName().toStdString();
    QSignalSpy idle(&service, &RenderService::becameIdle);
    QImage finalImage;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage& image, bool final) {
        if (final) finalImage = image;
    });
    RenderRequest request;
    request.genome = randomGenome(5, 3);
    request.size = QSize(96, 80);
    service.request(1, request);
    ASSERT_TRUE(idle.wait(120000));
    ASSERT_FALSE(finalImage.isNull());
    EXPECT_EQ(finalImage.size(), QSize(96, 80));
    // Not all one colour: the object and its marbling are there.
    const QRgb corner = finalImage.pixel(0, 0);
    bool varied = false;
    for (int y = 0; y < finalImage.height() && !varied; ++y)
        for (int x = 0; x < finalImage.width() && !varied; ++x)
            varied = finalImage.pixel(x, y) != corner;
    EXPECT_TRUE(varied);
}

/// Unsets MARBLER_RENDERER for a test's lifetime (a developer's shell may set it).
struct NoRendererOverride {
    QByteArray saved = qgetenv("MARBLER_RENDERER");
    NoRendererOverride() { qunsetenv("MARBLER_RENDERER"); }
    ~NoRendererOverride() {
        if (!saved.isEmpty()) qputenv("MARBLER_RENDERER", saved);
    }
};

/// Mean channel difference and the share of channels off by more than 24 between two renders
/// that differ by float rounding at ink edges only.
void expectCloseImages(const QImage& actualImage, const QImage& expectedImage) {
    const QImage actual = actualImage.convertToFormat(QImage::Format_RGB888);
    const QImage expected = expectedImage.convertToFormat(QImage::Format_RGB888);
    ASSERT_EQ(actual.size(), expected.size());
    double sum = 0.0;
    std::size_t far = 0, channels = 0;
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width() * 3; ++x, ++channels) {
            const int diff = std::abs(int(actual.constScanLine(y)[x]) - int(expected.constScanLine(y)[x]));
            sum += diff;
            if (diff > 24) ++far;
        }
    const double mean = sum / double(channels);
    EXPECT_TRUE(mean < 0.6 && far * 200 < channels)
        << "mean difference " << mean << ", " << far << " of " << channels << " channels off by more than 24";
}

TEST(RenderServiceTest, CpuChoiceShowsSolidsOnTheirObjectLikeGl) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    NoRendererOverride noOverride;
    RenderService service(gl::BackendPreference::Cpu);
    QSignalSpy ready(&service, &RenderService::backendReady);
    ASSERT_TRUE(ready.wait(60000));
    EXPECT_FALSE(service.usesGl());
    EXPECT_TRUE(service.backendName().startsWith(QStringLiteral("CPU")))
        << service.backendName().toStdString();
    QSignalSpy idle(&service, &RenderService::becameIdle);
    QImage preview, finalImage;
    QObject::connect(&service, &RenderService::rendered, [&](std::uint64_t, const QImage& image, bool final) {
        (final ? finalImage : preview) = image;
    });
    RenderRequest request;
    request.genome = randomGenome(5, 3);
    request.size = QSize(96, 80);
    request.mesh = QStringLiteral("torus");
    request.yaw = 50.0;
    service.request(1, request);
    ASSERT_TRUE(idle.wait(120000));
    ASSERT_FALSE(finalImage.isNull());
    EXPECT_EQ(preview.size(), QSize(48, 40)) << "the preview is the object at half size, not a slice";
    gl::GlRenderer renderer;
    gl::MeshSettings mesh;
    mesh.width = 96;
    mesh.height = 80;
    mesh.mesh = "torus";
    mesh.yaw = 50.0;
    mesh.pitch = request.pitch;
    mesh.supersample = 3;
    expectCloseImages(finalImage, toQImage(renderer.renderMesh(request.genome, mesh)));
}

TEST(RenderServiceTest, EnvironmentOverridesThePreference) {
    NoRendererOverride noOverride;
    qputenv("MARBLER_RENDERER", "cpu");
    RenderService service(gl::BackendPreference::Gpu);
    QSignalSpy ready(&service, &RenderService::backendReady);
    ASSERT_TRUE(ready.wait(60000));
    EXPECT_EQ(service.preference(), gl::BackendPreference::Gpu);
    EXPECT_FALSE(service.usesGl());
    EXPECT_TRUE(service.backendName().startsWith(QStringLiteral("CPU")))
        << service.backendName().toStdString();
    EXPECT_TRUE(service.backendReason().contains(QStringLiteral("CPU renderer was asked for")))
        << service.backendReason().toStdString();
    // The window's menu shows what the environment forces, and cannot change it.
    WorkbenchWindow window(&service);
    EXPECT_TRUE(window.rendererAction(gl::BackendPreference::Cpu)->isChecked());
    EXPECT_FALSE(window.rendererAction(gl::BackendPreference::Gpu)->isEnabled());
    EXPECT_TRUE(window.rendererAction(gl::BackendPreference::Gpu)
                    ->toolTip()
                    .contains(QStringLiteral("MARBLER_RENDERER")));
}

TEST_F(WorkbenchTest, AboutNamesTheBackEndNotTheStatusBar) {
    // The status bar speaks of the task at hand; which renderer draws, and why, is in About.
    EXPECT_EQ(mWindow->findChild<QLabel*>(QStringLiteral("backendLabel")), nullptr);
    if (mService->backendName().isEmpty()) {
        QSignalSpy ready(mService.get(), &RenderService::backendReady);
        ASSERT_TRUE(ready.wait(60000));
    }
    const QString renderer = mWindow->rendererDescription();
    EXPECT_TRUE(renderer.startsWith(QStringLiteral("Rendering on the CPU ("))) << renderer.toStdString();
    EXPECT_TRUE(renderer.contains(QStringLiteral("threads"))) << renderer.toStdString();
    EXPECT_TRUE(renderer.contains(mService->backendReason())) << renderer.toStdString();
    EXPECT_FALSE(mService->backendReason().isEmpty());
    QDialog* about = mWindow->showAbout();
    ASSERT_NE(about, nullptr);
    auto* text = about->findChild<QLabel*>(QStringLiteral("aboutText"));
    ASSERT_NE(text, nullptr);
    EXPECT_TRUE(text->text().contains(renderer.toHtmlEscaped())) << text->text().toStdString();
    about->close();
}

TEST(WorkbenchRenderer, SettingSwitchesTheBackEndAndRendersAgain) {
    std::string reason;
    if (!gl::GlRenderer::available(&reason)) {
        if (qEnvironmentVariableIntValue("MARBLER_REQUIRE_GL") == 1) FAIL() << "no GL: " << reason;
        GTEST_SKIP() << "no OpenGL context here: " << reason;
    }
    NoRendererOverride noOverride;
    QTemporaryDir favourites;
    qputenv("MARBLER_FAVOURITES_DIR", favourites.path().toLocal8Bit());
    QSettings().setValue(QStringLiteral("view/renderer"), QStringLiteral("auto"));
    RenderService service;
    EXPECT_EQ(service.preference(), gl::BackendPreference::Auto);
    WorkbenchWindow window(&service);
    QSignalSpy ready(&service, &RenderService::backendReady);
    if (service.backendName().isEmpty()) {
        ASSERT_TRUE(ready.wait(60000));
    }
    window.model()->setSessionSeed(3);
    window.newRandomPopulation(2);
    QSignalSpy finished(&window, &WorkbenchWindow::renderingFinished);
    while (!window.renderingDone())
        ASSERT_TRUE(finished.wait(120000));

    // Automatic: the GPU only where OpenGL is hardware.
    const gl::GlProbe probe = gl::probeGl();
    EXPECT_EQ(service.usesGl(), !probe.software);
    EXPECT_TRUE(window.rendererAction(gl::BackendPreference::Auto)->isChecked());
    if (probe.software) {
        const QString renderer = window.rendererDescription();
        EXPECT_TRUE(renderer.contains(QStringLiteral("on the CPU"))) << renderer.toStdString();
        EXPECT_TRUE(renderer.contains(QStringLiteral("software rasteriser"))) << renderer.toStdString();
    }

    // GPU, then CPU: each is remembered, named in About (and on the status bar for a moment),
    // and renders the grid again.
    for (gl::BackendPreference preference : {gl::BackendPreference::Gpu, gl::BackendPreference::Cpu}) {
        const QImage before = window.cell(0)->image();
        ready.clear();
        finished.clear();
        window.rendererAction(preference)->trigger();
        ASSERT_TRUE(ready.wait(60000));
        EXPECT_EQ(QSettings().value(QStringLiteral("view/renderer")).toString().toStdString(),
                  gl::backendPreferenceName(preference));
        EXPECT_EQ(service.usesGl(), preference == gl::BackendPreference::Gpu);
        const QString expected = preference == gl::BackendPreference::Gpu
                                     ? QStringLiteral("Rendering with OpenGL")
                                     : QStringLiteral("Rendering on the CPU");
        EXPECT_TRUE(window.rendererDescription().startsWith(expected))
            << window.rendererDescription().toStdString();
        EXPECT_TRUE(window.statusBar()->currentMessage().startsWith(expected))
            << window.statusBar()->currentMessage().toStdString();
        while (!window.renderingDone() || finished.isEmpty())
            ASSERT_TRUE(finished.wait(120000));
        EXPECT_FALSE(window.cell(0)->image().isNull());
        EXPECT_EQ(window.cell(0)->image().size(), before.size());
    }
    EXPECT_EQ(RenderService::storedPreference(), gl::BackendPreference::Cpu);
    QSettings().remove(QStringLiteral("view/renderer"));
    qunsetenv("MARBLER_FAVOURITES_DIR");
}

// Issue 27, the workbench's items.

/// Every control of the tool bars is in sight at the default window size and on a 1,366-pixel
/// screen: none hides behind a bar's ›› (the family box, New random and the object box did).
TEST_F(WorkbenchTest, EveryToolBarControlIsInSightAtTheDefaultWidth) {
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    for (const int width : {1180, 1366 - 16}) {
        mWindow->resize(width, 860);
        MARBLER_WAIT(mWindow->width() == width, 5000);
        QApplication::processEvents();
        const auto bars = mWindow->findChildren<QToolBar*>();
        ASSERT_GE(bars.size(), 1);
        for (QToolBar* bar : bars) {
            if (!bar->isVisible()) continue;
            auto* extension = bar->findChild<QToolButton*>(QStringLiteral("qt_toolbar_ext_button"));
            ASSERT_NE(extension, nullptr);
            EXPECT_FALSE(extension->isVisible())
                << bar->objectName().toStdString() << " overflows at " << width;
            for (QAction* action : bar->actions()) {
                QWidget* widget = bar->widgetForAction(action);
                ASSERT_NE(widget, nullptr);
                EXPECT_TRUE(widget->isVisible()) << bar->objectName().toStdString() << ": "
                                                 << action->text().toStdString() << " hidden at " << width;
                EXPECT_TRUE(bar->rect().contains(widget->geometry()))
                    << bar->objectName().toStdString() << ": " << action->text().toStdString()
                    << " cut off at " << width;
            }
        }
        auto* family = mWindow->findChild<QComboBox*>(QStringLiteral("familyCombo"));
        ASSERT_NE(family, nullptr);
        EXPECT_TRUE(family->isVisible()) << width;
    }
}

/// Twenty fast clicks on Alter while the generation it bred is still rendering make one more
/// generation once the grid has caught up, not twenty that keep arriving for seconds.
TEST_F(WorkbenchTest, FastOperatorClicksWaitForTheRendersAndCoalesce) {
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    MARBLER_WAIT(mWindow->renderingDone(), 120000);
    model().setSelected(4, true);
    const std::size_t before = model().history().size();
    QAction* alter = mWindow->operatorAction(GeneticOperator::Alter);
    for (int k = 0; k < 20; ++k)
        alter->trigger();
    EXPECT_EQ(model().history().size(), before + 1) << "the first click breeds at once";
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("Alter follows")))
        << mWindow->statusBar()->currentMessage().toStdString();
    // The last click waiting is made once the first generation has rendered, and nothing after.
    MARBLER_WAIT(model().history().size() == before + 2, 120000);
    MARBLER_WAIT(mWindow->renderingDone(), 120000);
    QApplication::processEvents();
    EXPECT_EQ(model().history().size(), before + 2);
    EXPECT_TRUE(model().isSelected(4)) << "the parent stays selected";

    // A click waiting when the user goes back is dropped: it was meant for the grid left.
    alter->trigger();
    ASSERT_EQ(model().history().size(), before + 3);
    alter->trigger();
    mWindow->backAction()->trigger();
    MARBLER_WAIT(mWindow->renderingDone(), 120000);
    QApplication::processEvents();
    EXPECT_EQ(model().history().size(), before + 3);
}

/// A solid design brought back from the lineage into a flat grid starts a generation of its own,
/// as an opened one does; it never sits among flat designs.
TEST_F(WorkbenchTest, ADesignOfTheOtherKindBroughtBackStartsItsOwnGeneration) {
    mWindow->newRandomPopulation(3);
    const int solid = model().currentIndex();
    const Genome solidDesign = *model().cell(2);
    mWindow->newRandomPopulation(2);
    const int flat = model().currentIndex();
    ASSERT_EQ(model().populationDimension(), 2);
    mWindow->bringBackDesign(solid, 2);
    EXPECT_EQ(model().current().parent, flat) << "the flat grid is one generation back";
    int designs = 0;
    for (int c = 0; c < CellCount; ++c)
        if (const Genome* g = model().cell(c)) {
            ++designs;
            EXPECT_EQ(g->dimension, 3) << "cell " << c;
            EXPECT_EQ(genomeId(*g), genomeId(solidDesign));
        }
    EXPECT_EQ(designs, 1);
    QComboBox* kind = nullptr;
    for (QComboBox* box : mWindow->findChildren<QComboBox*>())
        if (box->findData(3) >= 0 && box->findData(2) >= 0) kind = box;
    ASSERT_NE(kind, nullptr);
    EXPECT_EQ(kind->currentData().toInt(), 3) << "the kind box follows the grid";
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("generation of their own")))
        << mWindow->statusBar()->currentMessage().toStdString();
    // A flat one brought back into the flat grid goes on as before: into the grid.
    mWindow->backAction()->trigger();
    ASSERT_EQ(model().currentIndex(), flat);
    mWindow->bringBackDesign(0, 0);
    for (int c = 0; c < CellCount; ++c)
        EXPECT_EQ(model().cell(c)->dimension, 2) << c;
}

/// The question before opened designs replace others says what its Replace does: nine designs
/// over a grid with one parent replace all nine, not "the selected cells".
TEST(OpenPlacementWording, ReplaceSaysWhatItReplaces) {
    OpenQuestion nine;
    for (int c = 0; c < CellCount; ++c) {
        nine.names << QStringLiteral("p%1").arg(c);
        nine.replaced.push_back(c);
    }
    nine.parents = {4};
    EXPECT_EQ(OpenPlacementDialog(nine).replaceButton()->text(), QStringLiteral("&Replace all nine designs"));
    OpenQuestion selected{{QStringLiteral("a"), QStringLiteral("b")}, {0, 4}, {0, 4}};
    EXPECT_EQ(OpenPlacementDialog(selected).replaceButton()->text(),
              QStringLiteral("&Replace the selected cells"));
    OpenQuestion mixed{{QStringLiteral("a"), QStringLiteral("b")}, {0, 1}, {0}};
    EXPECT_EQ(OpenPlacementDialog(mixed).replaceButton()->text(), QStringLiteral("&Replace designs 1 and 2"));
}

} // namespace
