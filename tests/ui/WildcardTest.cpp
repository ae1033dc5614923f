// The wildcard cell (PopulationModel::setWildcardCell, Breed ▸ Wildcard cell): one offspring
// cell of each generation a fresh design of the parents' family, marked in the lineage.

#include "UiTestSupport.h"
#include "marbler/Families.h"
#include "marbler/GenomeIO.h"

#include <QAction>
#include <QSettings>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

class WildcardTest : public test::WindowTest {
protected:
    WildcardTest()
        : test::WindowTest(false) {}
    QAction* toggle() const { return mWindow->findChild<QAction*>(QStringLiteral("wildcardAction")); }
};

TEST_F(WildcardTest, TheLastOffspringCellIsAFreshDesignOfTheParentsFamily) {
    ASSERT_NE(toggle(), nullptr);
    EXPECT_TRUE(toggle()->isCheckable());
    EXPECT_TRUE(toggle()->isChecked()) << "on by default";
    mWindow->setPopulationFamily(QStringLiteral("nonpareil"));
    mWindow->newRandomPopulation(2);
    model().setSteering(false); // alteration's own children beside the wildcard
    model().clearSelection();
    model().setSelected(0, true);
    const std::string parentId = genomeId(*model().cell(0));
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    for (int i = 1; i < CellCount - 1; ++i)
        EXPECT_EQ(lineageOf(*model().cell(i)).op, QStringLiteral("alter")) << i;
    const Genome& wild = *model().cell(CellCount - 1);
    const LineageInfo info = lineageOf(wild);
    EXPECT_EQ(info.op, QStringLiteral("wildcard"));
    EXPECT_EQ(info.madeBy(), QStringLiteral("Wildcard"));
    EXPECT_EQ(info.family, QStringLiteral("nonpareil"));
    EXPECT_EQ(info.generation, 2);
    EXPECT_TRUE(info.parents.isEmpty()) << "a wildcard descends from no one";
    EXPECT_NO_THROW(validateGenome(wild, "wildcard"));
    EXPECT_NE(genomeId(wild), parentId);
    // Not an alteration of the parent: a nonpareil drawn from a seed of its own.
    const Genome drawn =
        familyGenome(*findFamily("nonpareil"), wild.meta.toJson()["lineage"]["seed"].get<std::uint64_t>());
    EXPECT_EQ(genomeId(drawn), genomeId(wild));
}

TEST_F(WildcardTest, TheToggleIsRememberedAndTurnsItOff) {
    mWindow->setPopulationFamily(QStringLiteral("peacock"));
    mWindow->newRandomPopulation(2);
    model().setSteering(false); // alteration's own children in every cell
    toggle()->setChecked(false);
    EXPECT_FALSE(model().wildcardCell());
    EXPECT_EQ(QSettings().value(QStringLiteral("breed/wildcard")).toBool(), false);
    model().clearSelection();
    model().setSelected(4, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    for (int i = 0; i < CellCount; ++i) {
        if (i == 4) continue; // the parent
        EXPECT_EQ(lineageOf(*model().cell(i)).op, QStringLiteral("alter")) << i;
    }
    toggle()->setChecked(true);
    EXPECT_TRUE(model().wildcardCell());
    EXPECT_EQ(QSettings().value(QStringLiteral("breed/wildcard")).toBool(), true);
}

TEST_F(WildcardTest, OffItAlsoKeepsSteeringsFreshDesignsOut) {
    // Steering shows fresh designs beside the pick's variations; a person who turned the
    // wildcard off wants variations of the pick only.
    mWindow->newRandomPopulation(2);
    ASSERT_TRUE(model().steering());
    const auto freshCells = [&] {
        int fresh = 0;
        for (int i = 1; i < CellCount; ++i)
            fresh += lineageOf(*model().cell(i)).op == QStringLiteral("wildcard");
        return fresh;
    };
    model().clearSelection();
    model().setSelected(0, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    EXPECT_GE(freshCells(), 3) << "the wildcard, and steering's fresh designs";
    toggle()->setChecked(false);
    model().clearSelection();
    model().setSelected(0, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    EXPECT_EQ(freshCells(), 0);
    toggle()->setChecked(true);
}

TEST(WildcardModel, WithoutAFamilyAFreeDesignSeededByTheGeneration) {
    const auto breedFromFree = [](std::uint64_t sessionSeed) {
        PopulationModel model;
        model.setSessionSeed(sessionSeed);
        model.newRandomPopulation(3); // mixed: one cell is drawn by the free generator
        int free = -1;
        for (int i = 0; i < CellCount; ++i)
            if (!model.cell(i)->meta.toJson().contains("family")) free = i;
        EXPECT_GE(free, 0);
        model.setSelected(free, true);
        model.apply(GeneticOperator::Reinit, 0.5);
        int last = CellCount - 1;
        if (last == free) --last;
        return *model.cell(last);
    };
    const Genome wild = breedFromFree(7);
    EXPECT_EQ(lineageOf(wild).op, QStringLiteral("wildcard"));
    EXPECT_FALSE(wild.meta.toJson().contains("family"));
    EXPECT_EQ(wild.dimension, 3);
    EXPECT_NO_THROW(validateGenome(wild, "wildcard"));
    // The same session breeds the same wildcard; another session another one.
    EXPECT_EQ(serializeGenome(breedFromFree(7)), serializeGenome(wild));
    EXPECT_NE(genomeId(breedFromFree(8)), genomeId(wild));
}

} // namespace
