// Breeding that steers in the window (issue 26; Steer.h, Breed ▸ Steer by my picks, Less like
// this): the status line says why the children were chosen, and the marks show on the cells.

#include "UiTestSupport.h"
#include "marbler/Operators.h"
#include "workbench/DesignCell.h"

#include <QAction>
#include <QLabel>
#include <QSettings>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

class SteerUiTest : public test::WindowTest {
protected:
    SteerUiTest()
        : test::WindowTest(false) {}
    QAction* steer() const { return mWindow->findChild<QAction*>(QStringLiteral("steerAction")); }
    QAction* lessLike() const { return mWindow->findChild<QAction*>(QStringLiteral("lessLikeAction")); }
    QString statusLine() const {
        return mWindow->findChild<QLabel*>(QStringLiteral("generationLabel"))->text();
    }
    /// Picks one cell and breeds with Alter, as a click on the cell and Ctrl+1 do.
    void pickAndAlter(int cell) {
        model().clearSelection();
        model().setSelected(cell, true);
        ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    }
};

TEST_F(SteerUiTest, TheStatusLineSaysWhyTheChildrenWereChosen) {
    ASSERT_NE(steer(), nullptr);
    EXPECT_TRUE(steer()->isCheckable());
    EXPECT_TRUE(steer()->isChecked()) << "on by default";
    mWindow->setPopulationFamily(QStringLiteral("zebra"));
    mWindow->newRandomPopulation(2);
    pickAndAlter(0);
    // The first pick already steers.
    EXPECT_TRUE(statusLine().contains(QStringLiteral("more like your last pick")))
        << statusLine().toStdString();
    pickAndAlter(3);
    EXPECT_TRUE(statusLine().contains(QStringLiteral("more like your last 2 picks")))
        << statusLine().toStdString();
    // The children say where they come from (the ranked ones carry their rank).
    int ranked = 0;
    for (int i = 0; i < CellCount; ++i)
        ranked += model().cell(i)->meta.toJson()["lineage"].contains("steered");
    EXPECT_GE(ranked, CellCount - 2);
    // Going back shows the generation before, with its own reason; back to the first, none.
    model().goBack();
    EXPECT_TRUE(statusLine().contains(QStringLiteral("more like your last pick")))
        << statusLine().toStdString();
    model().goBack();
    EXPECT_FALSE(statusLine().contains(QStringLiteral("more like"))) << statusLine().toStdString();
    model().goForward();
    model().goForward();
    EXPECT_TRUE(statusLine().contains(QStringLiteral("more like your last 2 picks")))
        << statusLine().toStdString();
}

TEST_F(SteerUiTest, OnUntilTurnedOff) {
    // Measured to beat plain breeding and random search (docs/performance.md): on by default.
    QSettings().remove(QStringLiteral("breed/steer"));
    WorkbenchWindow fresh(mService.get());
    QAction* action = fresh.findChild<QAction*>(QStringLiteral("steerAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isChecked());
    EXPECT_TRUE(fresh.model()->steering());
}

TEST_F(SteerUiTest, TurnedOffItBreedsAsBeforeAndIsRemembered) {
    mWindow->setPopulationFamily(QStringLiteral("zebra"));
    mWindow->newRandomPopulation(2);
    steer()->setChecked(false);
    EXPECT_FALSE(model().steering());
    EXPECT_EQ(QSettings().value(QStringLiteral("breed/steer")).toBool(), false);
    pickAndAlter(0);
    pickAndAlter(2);
    EXPECT_FALSE(statusLine().contains(QStringLiteral("more like"))) << statusLine().toStdString();
    for (int i = 0; i < CellCount; ++i)
        EXPECT_FALSE(model().cell(i)->meta.toJson()["lineage"].contains("steered")) << i;
    steer()->setChecked(true);
    EXPECT_TRUE(model().steering());
}

TEST_F(SteerUiTest, LessLikeThisMarksTheSelectedDesignsAndLetsThemGo) {
    ASSERT_NE(lessLike(), nullptr);
    EXPECT_EQ(lessLike()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_X));
    mWindow->setPopulationFamily(QStringLiteral("zebra"));
    mWindow->newRandomPopulation(2);
    model().clearSelection();
    model().setSelected(1, true);
    model().setSelected(5, true);
    lessLike()->trigger();
    EXPECT_TRUE(model().isDisliked(1));
    EXPECT_TRUE(model().isDisliked(5));
    EXPECT_FALSE(model().isSelected(5)) << "a design marked less like this is no parent";
    EXPECT_TRUE(mWindow->cell(5)->caption().contains(QStringLiteral("less like this")))
        << mWindow->cell(5)->caption().toStdString();
    EXPECT_FALSE(mWindow->cell(0)->caption().contains(QStringLiteral("less like this")));
    // The steering sees it as passed over, marked.
    model().setSelected(0, true);
    const std::vector<PickRound> rounds = model().pickRounds();
    ASSERT_EQ(rounds.size(), 1u);
    EXPECT_EQ(rounds.back().picked.size(), 1u);
    EXPECT_EQ(rounds.back().disliked.size(), 2u);
    EXPECT_EQ(rounds.back().passed.size(), 6u);
    // Again on the same designs: unmarked.
    model().clearSelection();
    model().setSelected(1, true);
    model().setSelected(5, true);
    lessLike()->trigger();
    EXPECT_FALSE(model().isDisliked(1));
    EXPECT_FALSE(mWindow->cell(5)->caption().contains(QStringLiteral("less like this")));
}

TEST(SteerModel, SteeredGenerationsAreReproducibleFromTheSessionSeed) {
    const auto session = [](std::uint64_t seed) {
        PopulationModel model;
        model.setSessionSeed(seed);
        model.setSteering(true);
        model.newRandomPopulation(2, "zebra");
        for (int cell : {0, 4, 7}) {
            model.clearSelection();
            model.setSelected(cell, true);
            model.apply(GeneticOperator::Alter, 0.5);
        }
        std::vector<std::string> ids;
        for (int i = 0; i < CellCount; ++i)
            ids.push_back(genomeId(*model.cell(i)));
        EXPECT_FALSE(model.steerExplanation().isEmpty());
        return ids;
    };
    const auto a = session(21);
    EXPECT_EQ(a, session(21));
    EXPECT_NE(a, session(22));
}

TEST_F(SteerUiTest, MoreLikeThisBreedsFromThatDesignAlone) {
    // A design's right-click "More like this": the next generation is bred from it alone, though
    // other designs were selected, and it keeps its cell.
    mWindow->setPopulationFamily(QStringLiteral("zebra"));
    mWindow->newRandomPopulation(2);
    model().clearSelection();
    model().setSelected(0, true);
    model().setSelected(3, true);
    const std::string liked = genomeId(*model().cell(5));
    const int before = model().currentIndex();
    mWindow->moreLikeThis(5);
    ASSERT_NE(model().currentIndex(), before) << "a generation was bred";
    EXPECT_EQ(model().selectedCells(), std::vector<int>{5});
    EXPECT_EQ(genomeId(*model().cell(5)), liked);
    int fromIt = 0;
    for (int i = 0; i < CellCount; ++i) {
        if (i == 5) continue;
        const auto lineage = model().cell(i)->meta.toJson()["lineage"];
        EXPECT_FALSE(lineage.contains("parents") && lineage["parents"].size() != 1) << lineage.dump();
        fromIt += lineage.contains("parents") && lineage["parents"][0] == liked;
    }
    EXPECT_GE(fromIt, 3) << "the variations are of the design liked";
}

} // namespace
