// History is a tree (issue 12, "nothing is ever lost"): breeding after going back starts a
// branch and keeps the old one, Back/Forward/goTo move through branches, the session file keeps
// the tree (and still reads version 1 lines), and the lineage dock shows the tree with
// thumbnails rendered off the GUI thread.

#include "UiTestSupport.h"
#include "WaitFor.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "shared/RenderService.h"
#include "workbench/DesignCell.h"
#include "workbench/LineagePanel.h"
#include "workbench/PopulationModel.h"
#include "workbench/Session.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMainWindow>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <set>

using namespace marbler;
using namespace marbler::ui;

namespace {

/// The genomes of the grid as text, for exact comparisons of whole generations.
std::vector<std::string> snapshot(const PopulationModel& model) {
    std::vector<std::string> result;
    for (int i = 0; i < CellCount; ++i)
        result.push_back(model.cell(i) ? serializeGenome(*model.cell(i)) : "");
    return result;
}

/// Everything the history holds, tree links included, as text.
std::vector<std::string> treeSnapshot(const std::vector<Generation>& history) {
    std::vector<std::string> result;
    for (const Generation& g : history) {
        std::string text = std::to_string(g.parent) + "|" + std::to_string(g.number) + "|" +
                           std::to_string(g.branch) + "|" + g.description.toStdString() + "|";
        for (int i = 0; i < CellCount; ++i) {
            text += g.selected[std::size_t(i)] ? "S" : "-";
            text +=
                g.cells[std::size_t(i)] ? serializeGenome(*g.cells[std::size_t(i)]) : std::string("(empty)");
        }
        result.push_back(text);
    }
    return result;
}

/// Whether an icon shows more than one colour (a blank placeholder is one).
bool iconHasDetail(const QIcon& icon, QRect area = {}) {
    const QImage image = icon.pixmap(QSize(44, 44)).toImage();
    if (area.isNull()) area = image.rect();
    std::set<QRgb> colours;
    for (int y = area.top(); y <= area.bottom(); ++y)
        for (int x = area.left(); x <= area.right(); ++x)
            colours.insert(image.pixel(x, y));
    return colours.size() > 1;
}

/// Waits, handling events, until the condition holds; false when it did not within the time.
/// (QTRY_COMPARE would only return from the test body on failure, which gtest counts as passed.)
bool waitFor(const std::function<bool()>& condition, int timeoutMs = 5000) {
    return QTest::qWaitFor(condition, timeoutMs);
}

/// The lineage item of a generation (not one of its designs), or nullptr.
QTreeWidgetItem* generationItem(QTreeWidget* tree, int generation) {
    for (QTreeWidgetItemIterator it(tree); *it; ++it) {
        const QVariant g = (*it)->data(0, WorkbenchWindow::LineageGenerationRole);
        if (g.isValid() && g.toInt() == generation &&
            !(*it)->data(0, WorkbenchWindow::LineageCellRole).isValid())
            return *it;
    }
    return nullptr;
}

/// A point on an item's icon and name inside the viewport (rows can be wider than the view).
QPoint itemPoint(QTreeWidget* tree, QTreeWidgetItem* item) {
    const QRect rect = tree->visualItemRect(item);
    return {std::clamp(rect.left() + 60, 1, tree->viewport()->width() - 1), rect.center().y()};
}

/// Double-clicks an item the way a platform does: press, release, press, double-click,
/// release (QTest::mouseDClick alone sends only the double-click event to a widget).
void doubleClickItem(QTreeWidget* tree, QTreeWidgetItem* item) {
    tree->scrollToItem(item);
    const QPoint at = itemPoint(tree, item);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, at);
    QTest::mousePress(tree->viewport(), Qt::LeftButton, {}, at);
    QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, at);
    QTest::mouseRelease(tree->viewport(), Qt::LeftButton, {}, at);
}

/// The texts of column 0 of an item's children.
QStringList childTexts(const QTreeWidgetItem* item) {
    QStringList texts;
    for (int i = 0; i < item->childCount(); ++i)
        texts << item->child(i)->text(0);
    return texts;
}

class HistoryTreeTest : public test::WindowTest {
protected:
    /// Breeds from one selected cell of the current generation.
    void breed(int parentCell, GeneticOperator op) {
        model().clearSelection();
        model().setSelected(parentCell, true);
        ASSERT_TRUE(mWindow->applyOperator(op));
    }
    /// Generation indices 0..4: 0 -> 1 -> 2 on branch 1, 1 -> 3 (branch 2), 0 -> 4 (branch 3);
    /// `grids` gets each one's designs. Ends at generation 4.
    void makeThreeBranches(std::vector<std::vector<std::string>>& grids) {
        grids.push_back(snapshot(model()));
        breed(1, GeneticOperator::Alter);
        grids.push_back(snapshot(model()));
        breed(2, GeneticOperator::Reinit);
        grids.push_back(snapshot(model()));
        model().goBack();
        breed(5, GeneticOperator::Reinit);
        grids.push_back(snapshot(model()));
        model().goTo(0);
        breed(7, GeneticOperator::Alter);
        grids.push_back(snapshot(model()));
        ASSERT_EQ(model().history().size(), 5u);
    }
};

TEST_F(HistoryTreeTest, BreedingAfterBackKeepsTheOldBranch) {
    const auto first = snapshot(model());
    breed(1, GeneticOperator::Alter);
    const auto altered = snapshot(model());
    mWindow->backAction()->trigger();
    ASSERT_EQ(snapshot(model()), first);
    breed(1, GeneticOperator::Alter); // the same parent and operator again

    const auto& history = model().history();
    ASSERT_EQ(history.size(), 3u) << "the first branch is kept";
    EXPECT_EQ(model().currentIndex(), 2);
    EXPECT_EQ(history[1].parent, 0);
    EXPECT_EQ(history[2].parent, 0);
    EXPECT_EQ(history[1].number, 2);
    EXPECT_EQ(history[2].number, 2);
    EXPECT_EQ(history[1].branch, 1);
    EXPECT_EQ(history[2].branch, 2);
    EXPECT_NE(snapshot(model()), altered) << "breeding again from a generation draws anew";
    for (int i = 0; i < CellCount; ++i) {
        ASSERT_TRUE(history[1].cells[std::size_t(i)]);
        EXPECT_EQ(serializeGenome(*history[1].cells[std::size_t(i)]), altered[std::size_t(i)]);
    }

    // One vocabulary: "Generation 2 (branch 2)"; its children record generation 2, "(g2 #K)".
    EXPECT_EQ(model().generationLabel(1), QStringLiteral("2"));
    EXPECT_EQ(model().generationLabel(2), QStringLiteral("2 (branch 2)"));
    EXPECT_TRUE(mWindow->statusBar()->currentMessage().contains(QStringLiteral("eneration 2 (branch 2)")))
        << mWindow->statusBar()->currentMessage().toStdString();
    for (int i = 0; i < CellCount; ++i) {
        if (i == 1) continue; // the parent
        EXPECT_EQ(lineageOf(*model().cell(i)).generation, 2);
        EXPECT_TRUE(mWindow->cell(i)->caption().contains(QStringLiteral("(g2 #%1)").arg(i + 1)))
            << mWindow->cell(i)->caption().toStdString();
    }
    // The old branch is still reachable.
    model().goTo(1);
    EXPECT_EQ(snapshot(model()), altered);
}

TEST_F(HistoryTreeTest, BackForwardAndGoToAcrossBranchesRestoreExactDesigns) {
    std::vector<std::vector<std::string>> grids;
    makeThreeBranches(grids);
    PopulationModel& m = model();
    const auto& history = m.history();
    EXPECT_EQ((std::vector<int>{history[0].parent, history[1].parent, history[2].parent, history[3].parent,
                                history[4].parent}),
              (std::vector<int>{-1, 0, 1, 1, 0}));
    EXPECT_EQ(m.children(0), (std::vector<int>{1, 4}));
    EXPECT_EQ(m.children(1), (std::vector<int>{2, 3}));
    EXPECT_EQ(m.generationLabel(3), QStringLiteral("3 (branch 2)"));
    EXPECT_EQ(m.generationLabel(4), QStringLiteral("2 (branch 3)"));
    for (std::size_t k = 0; k < grids.size(); ++k)
        for (std::size_t j = 0; j < k; ++j)
            ASSERT_NE(grids[k], grids[j]) << k << " and " << j;

    QAction* back = mWindow->backAction();
    QAction* forward = mWindow->forwardAction();
    EXPECT_FALSE(forward->isEnabled()) << "generation 4 has no child";
    back->trigger();
    EXPECT_EQ(m.currentIndex(), 0);
    EXPECT_EQ(snapshot(m), grids[0]);
    EXPECT_FALSE(back->isEnabled()) << "the root";
    forward->trigger();
    EXPECT_EQ(m.currentIndex(), 4) << "forward returns to the child last visited";
    EXPECT_EQ(snapshot(m), grids[4]);

    m.goTo(2);
    EXPECT_EQ(snapshot(m), grids[2]);
    back->trigger();
    EXPECT_EQ(snapshot(m), grids[1]);
    forward->trigger();
    EXPECT_EQ(m.currentIndex(), 2);
    m.goTo(3);
    EXPECT_EQ(snapshot(m), grids[3]);
    back->trigger();
    back->trigger();
    EXPECT_EQ(m.currentIndex(), 0);
    forward->trigger();
    EXPECT_EQ(m.currentIndex(), 1) << "goTo(3) went through generation 1";
    forward->trigger();
    EXPECT_EQ(m.currentIndex(), 3) << "and then to 3, not the older 2";
    EXPECT_EQ(snapshot(m), grids[3]);
    EXPECT_FALSE(forward->isEnabled());
    EXPECT_TRUE(back->isEnabled());
}

TEST_F(HistoryTreeTest, SessionRoundTripKeepsTheTree) {
    std::vector<std::vector<std::string>> grids;
    makeThreeBranches(grids);
    model().goTo(3);
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    const QString file = sessionFilePath(folder.path());
    model().setSessionFile(file); // writes at once

    QFile in(file);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    const QByteArray text = in.readAll();
    EXPECT_TRUE(text.contains("\"version\":3")) << text.left(200).toStdString();
    // Version 3: each generation in a file of its own, naming its parent.
    QFile third(generationFile(generationsFolder(file), 3));
    ASSERT_TRUE(third.open(QIODevice::ReadOnly));
    EXPECT_TRUE(third.readAll().contains("\"parent\":1"));

    const SavedSession saved = loadSession(file);
    EXPECT_EQ(treeSnapshot(saved.history), treeSnapshot(model().history()));
    EXPECT_EQ(saved.current, 3);
    PopulationModel resumed;
    resumed.restoreSession(saved);
    EXPECT_EQ(treeSnapshot(resumed.history()), treeSnapshot(model().history()));
    EXPECT_EQ(snapshot(resumed), grids[3]);
    EXPECT_EQ(resumed.generationLabel(3), QStringLiteral("3 (branch 2)"));
    EXPECT_EQ(resumed.nextBreedSeed(), model().nextBreedSeed());
    resumed.goBack();
    resumed.goBack();
    resumed.goForward();
    resumed.goForward();
    EXPECT_EQ(resumed.currentIndex(), 3) << "after a resume Forward retraces the way to the saved generation";
    EXPECT_EQ(snapshot(resumed), grids[3]);
}

/// A session document with the given generations' extra members (each "" or `"parent":N,`).
std::string sessionText(int version, const std::vector<std::string>& parents, int current = 0) {
    const std::string cells =
        "[" + serializeGenome(randomGenome(3, 2)) + ",null,null,null,null,null,null,null,null]";
    std::string text = R"({"format":"marbler-session","version":)" + std::to_string(version) +
                       R"(,"seed":5,"dimension":2,"current":)" + std::to_string(current) +
                       R"(,"generations":[)";
    for (std::size_t k = 0; k < parents.size(); ++k) {
        if (k > 0) text += ',';
        text += "{" + parents[k] + R"("description":"g)" + std::to_string(k) + R"(","cells":)" + cells + "}";
    }
    return text + "]}";
}

TEST(HistorySessionTest, VersionOneSessionStillLoadsAsALine) {
    const SavedSession s = parseSession(sessionText(1, {"", "", ""}, 2), "old.json");
    ASSERT_EQ(s.history.size(), 3u);
    EXPECT_EQ(s.history[0].parent, -1);
    EXPECT_EQ(s.history[1].parent, 0);
    EXPECT_EQ(s.history[2].parent, 1);
    EXPECT_EQ(s.history[2].number, 3);
    EXPECT_EQ(s.history[2].branch, 1);
    PopulationModel model;
    model.restoreSession(s);
    EXPECT_EQ(model.generationLabel(2), QStringLiteral("3"));
    model.goBack();
    EXPECT_EQ(model.currentIndex(), 1);
    EXPECT_EQ(model.current().description, QStringLiteral("g1"));
    model.goForward();
    EXPECT_EQ(model.currentIndex(), 2);
}

TEST(HistorySessionTest, BadParentsAreNamedWhereTheyAre) {
    const auto fails = [](const std::string& text) {
        try {
            parseSession(text, "s.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", R"("parent":0,)", R"("parent":0,)"})), "(no error)");
    const std::string later = "s.json: generations[1].parent: must name an earlier generation (0 to 0), or "
                              "be -1 for a generation that "
                              "grows from none";
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", R"("parent":5,)"})), later);
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", R"("parent":1,)"})), later) << "itself: a cycle";
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", R"("parent":-2,)"})), later);
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", R"("parent":"0",)"})), later);
    EXPECT_EQ(fails(sessionText(2, {R"("parent":-1,)", ""})), later) << "version 2 names every parent";
    EXPECT_EQ(
        fails(sessionText(2, {R"("parent":-1,)", R"("parent":0,)", R"("parent":2,)"})),
        "s.json: generations[2].parent: must name an earlier generation (0 to 1), or be -1 for a generation "
        "that grows from none");
    EXPECT_EQ(fails(sessionText(2, {R"("parent":0,)"})),
              "s.json: generations[0].parent: must be -1: the first generation grows from none");
    EXPECT_EQ(fails(sessionText(4, {R"("parent":-1,)"})),
              "s.json: version: only version 1, 2 and 3 sessions are read");
    // Version 3 keeps its generations in files of their own: its head is read from the file.
    EXPECT_EQ(fails(sessionText(3, {R"("parent":-1,)"})),
              "s.json: generations: a version 3 session keeps its generations in a folder beside it: open "
              "the file, not its text");
    // A second root is a new start: its own branch.
    const SavedSession s =
        parseSession(sessionText(2, {R"("parent":-1,)", R"("parent":0,)", R"("parent":-1,)"}), "s");
    EXPECT_EQ(s.history[2].number, 1);
    EXPECT_EQ(s.history[2].branch, 2);
}

TEST_F(HistoryTreeTest, LineageShowsBranchesAndDoubleClickGoesBack) {
    std::vector<std::vector<std::string>> grids;
    makeThreeBranches(grids);
    QTreeWidget* tree = mWindow->lineageTree();
    QTreeWidgetItem* generations = tree->topLevelItem(1);
    ASSERT_EQ(generations->text(0), QStringLiteral("Generations"));
    // Each branch follows the generation it grew from, its generations nested inside it.
    EXPECT_EQ(childTexts(generations),
              (QStringList{QStringLiteral("Generation 1"), QStringLiteral("Branch 3"),
                           QStringLiteral("Generation 2"), QStringLiteral("Branch 2"),
                           QStringLiteral("Generation 3")}));
    EXPECT_EQ(generations->child(1)->text(1), QStringLiteral("from generation 1"));
    EXPECT_EQ(childTexts(generations->child(1)), QStringList{QStringLiteral("Generation 2 (branch 3)")});
    EXPECT_EQ(childTexts(generations->child(3)), QStringList{QStringLiteral("Generation 3 (branch 2)")});
    QTreeWidgetItem* current = generationItem(tree, 4);
    ASSERT_NE(current, nullptr);
    EXPECT_TRUE(current->font(0).bold()) << "the current generation is marked";
    EXPECT_FALSE(generationItem(tree, 2)->font(0).bold());

    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    QTreeWidgetItem* target = generationItem(tree, 2);
    doubleClickItem(tree, target);
    ASSERT_TRUE(waitFor([&] { return model().currentIndex() == 2; })) << "at " << model().currentIndex();
    EXPECT_EQ(snapshot(model()), grids[2]);
    EXPECT_EQ(model().history().size(), 5u) << "going to a generation makes none";
    EXPECT_TRUE(generationItem(tree, 2)->font(0).bold());
}

TEST_F(HistoryTreeTest, LineageDesignsSelectAndComeBack) {
    std::vector<std::vector<std::string>> grids;
    makeThreeBranches(grids);
    model().clearSelection();
    QTreeWidget* tree = mWindow->lineageTree();
    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    const auto designItem = [&](int generation, int cell) -> QTreeWidgetItem* {
        QTreeWidgetItem* item = generationItem(tree, generation);
        if (!item) return nullptr;
        item->setExpanded(true); // designs are listed when a generation is first opened
        for (int i = 0; i < item->childCount(); ++i)
            if (item->child(i)->data(0, WorkbenchWindow::LineageCellRole).toInt() == cell)
                return item->child(i);
        return nullptr;
    };

    // Double-click a design of another generation: it comes back into the grid as a new
    // generation grown from the current one, so Back undoes it.
    QTreeWidgetItem* design = designItem(3, 4);
    ASSERT_NE(design, nullptr);
    EXPECT_EQ(design->text(0).left(10), QStringLiteral("Design 5: "));
    doubleClickItem(tree, design);
    ASSERT_TRUE(waitFor([&] { return model().history().size() == 6u; })) << "no new generation";
    EXPECT_EQ(model().currentIndex(), 5);
    EXPECT_EQ(model().current().parent, 4);
    EXPECT_TRUE(model().current().parentCells.empty()) << "put in, not bred";
    EXPECT_EQ(model().current().description,
              QStringLiteral("Brought back design 5 of generation 3 (branch 2)"));
    EXPECT_EQ(serializeGenome(*model().cell(0)), grids[3][4])
        << "into the first cell, nothing being selected";
    for (int i = 1; i < CellCount; ++i)
        EXPECT_EQ(serializeGenome(*model().cell(i)), grids[4][std::size_t(i)]);
    mWindow->backAction()->trigger();
    EXPECT_EQ(snapshot(model()), grids[4]);

    // Click a design of another generation: that generation comes back, the design selected.
    design = designItem(1, 6);
    ASSERT_NE(design, nullptr);
    tree->scrollToItem(design);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, itemPoint(tree, design));
    ASSERT_TRUE(waitFor([&] { return model().currentIndex() == 1; })) << "at " << model().currentIndex();
    // Cell 6 joins the parent selected when generation 1 was left (branch 2 was bred from it).
    EXPECT_EQ(model().selectedCells(), (std::vector<int>{5, 6}));
    EXPECT_EQ(snapshot(model()), grids[1]);
    // And one of the current generation is selected in place.
    design = designItem(1, 2);
    ASSERT_NE(design, nullptr);
    tree->scrollToItem(design);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, itemPoint(tree, design));
    ASSERT_TRUE(waitFor([&] { return model().selectedCells() == std::vector<int>{2, 5, 6}; }));
    EXPECT_EQ(model().currentIndex(), 1);
    EXPECT_EQ(model().history().size(), 6u);
}

TEST_F(HistoryTreeTest, LineageThumbnailsArriveForWhatIsInView) {
    std::vector<std::vector<std::string>> grids;
    makeThreeBranches(grids);
    model().goTo(2);
    QTreeWidget* tree = mWindow->lineageTree();
    QTreeWidgetItem* branch3 = tree->topLevelItem(1)->child(1);
    ASSERT_EQ(branch3->text(0), QStringLiteral("Branch 3"));
    branch3->setExpanded(false); // generation 4's own designs are out of view
    const QIcon blankMosaic = generationItem(tree, 2)->icon(0);
    EXPECT_FALSE(iconHasDetail(blankMosaic, QRect(0, 0, 14, 14)))
        << "nothing is rendered before the window shows";

    mWindow->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(mWindow.get()));
    tree->scrollToItem(generationItem(tree, 2));
    // The current generation in view: its nine thumbnails arrive.
    const auto& cells = model().history()[2].cells;
    for (const auto& cell : cells)
        ASSERT_TRUE(waitFor([&] { return mWindow->hasLineageThumbnail(*cell); }, 60000));
    ASSERT_TRUE(waitFor([&] { return mService->idle(); }, 60000));
    QTreeWidgetItem* item = generationItem(tree, 2);
    ASSERT_NE(item, nullptr);
    EXPECT_TRUE(iconHasDetail(item->icon(0), QRect(0, 0, 14, 14))) << "the mosaic's first tile";
    EXPECT_TRUE(iconHasDetail(item->icon(0), QRect(30, 30, 14, 14))) << "the mosaic's last tile";
    ASSERT_EQ(tree->topLevelItem(0)->childCount(), CellCount);
    EXPECT_TRUE(iconHasDetail(tree->topLevelItem(0)->child(0)->icon(0)))
        << "a current design's own thumbnail";

    // Generation 4's children (all but its parent cell 7) were not rendered while folded away.
    const auto& hidden = model().history()[4].cells;
    for (int i = 0; i < CellCount; ++i) {
        if (i != 7) {
            EXPECT_FALSE(mWindow->hasLineageThumbnail(*hidden[std::size_t(i)])) << "cell " << i;
        }
    }
    tree->topLevelItem(1)->child(1)->setExpanded(true);
    tree->scrollToItem(generationItem(tree, 4));
    for (int i = 0; i < CellCount; ++i)
        ASSERT_TRUE(waitFor([&] { return mWindow->hasLineageThumbnail(*hidden[std::size_t(i)]); }, 60000));
    EXPECT_TRUE(iconHasDetail(generationItem(tree, 4)->icon(0), QRect(15, 0, 14, 14)));
}

// The lineage is an object of its own (LineagePanel.h): given a model, a render service and a
// window to sit in, it shows the generations and renders the thumbnails in view, no workbench
// window needed.
TEST(LineagePanelTest, ShowsTheTreeAndItsThumbnailsOnItsOwn) {
    RenderService service(RenderService::Backend::Cpu);
    QMainWindow window;
    PopulationModel model;
    model.setSessionSeed(42);
    LineagePanel panel(&window, &model, &service, [] { return QStringLiteral("vase"); });
    window.addDockWidget(Qt::RightDockWidgetArea, panel.dock());
    model.newRandomPopulation(2);
    panel.update();

    QTreeWidget* tree = panel.tree();
    EXPECT_EQ(panel.dock()->objectName(), QStringLiteral("lineageDock"));
    ASSERT_EQ(tree->topLevelItemCount(), 2);
    EXPECT_EQ(tree->topLevelItem(0)->text(0), QStringLiteral("Current designs"));
    EXPECT_EQ(tree->topLevelItem(0)->childCount(), CellCount);
    EXPECT_EQ(tree->topLevelItem(1)->text(0), QStringLiteral("Generations"));
    ASSERT_EQ(tree->topLevelItem(1)->childCount(), 1);
    EXPECT_EQ(tree->topLevelItem(1)->child(0)->text(0), QStringLiteral("Generation 1"));
    EXPECT_FALSE(iconHasDetail(tree->topLevelItem(0)->child(0)->icon(0))) << "a blank before it renders";

    window.resize(900, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    ASSERT_TRUE(waitFor([&] { return panel.hasThumbnail(*model.cell(0)); }, 60000));
    EXPECT_TRUE(iconHasDetail(tree->topLevelItem(0)->child(0)->icon(0))) << "the design's thumbnail";
    ASSERT_TRUE(waitFor([&] { return service.idle(); }, 60000));
}

} // namespace
