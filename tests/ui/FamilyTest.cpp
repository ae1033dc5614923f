// New populations of the craft's pattern families (Families.h): a mixed first population, one
// family chosen in the tool bar and remembered, and the family kept through breeding and shown
// in the lineage.

#include "UiTestSupport.h"
#include "marbler/Families.h"

#include <QComboBox>
#include <QSettings>

#include <gtest/gtest.h>

#include <set>

using namespace marbler;
using namespace marbler::ui;

namespace {

class FamilyTest : public test::WindowTest {
protected:
    FamilyTest()
        : test::WindowTest(false) {}
    QComboBox* combo() const { return mWindow->findChild<QComboBox*>(QStringLiteral("familyCombo")); }
    std::set<std::string> familiesInGrid() {
        std::set<std::string> found;
        for (int c = 0; c < CellCount; ++c)
            if (const Genome* g = model().cell(c))
                found.insert(g->meta.toJson().value("family", std::string("(free)")));
        return found;
    }
};

TEST_F(FamilyTest, AMixedPopulationShowsADifferentFamilyInEveryCell) {
    mWindow->setPopulationFamily(QString());
    mWindow->newRandomPopulation(2);
    EXPECT_EQ(familiesInGrid().size(), std::size_t(CellCount))
        << "nine cells, nine families (one may be free)";
    for (const std::string& family : familiesInGrid()) {
        if (family == "(free)") continue;
        EXPECT_EQ(findFamily(family)->dimension, 2) << family;
    }
    // Solid: three families and the free generator, each more than once.
    mWindow->newRandomPopulation(3);
    std::set<std::string> solid = familiesInGrid();
    EXPECT_GE(solid.size(), 3u);
    for (const std::string& family : solid) {
        if (family == "(free)") continue;
        EXPECT_EQ(findFamily(family)->dimension, 3) << family;
    }
}

TEST_F(FamilyTest, OneFamilyChosenInTheToolBarAndRemembered) {
    QComboBox* families = combo();
    ASSERT_NE(families, nullptr);
    mWindow->newRandomPopulation(2); // the kind box now says flat
    int flat = 0;
    for (const Family& f : allFamilies())
        flat += f.dimension == 2;
    EXPECT_EQ(families->count(), flat + 1) << "Mixed families and every flat family";
    mWindow->setPopulationFamily(QStringLiteral("peacock"));
    EXPECT_EQ(mWindow->populationFamily(), QStringLiteral("peacock"));
    EXPECT_FALSE(families->itemData(families->currentIndex(), Qt::ToolTipRole).toString().isEmpty());
    mWindow->newRandomPopulation(2);
    EXPECT_EQ(familiesInGrid(), std::set<std::string>{"peacock"});
    EXPECT_TRUE(model().current().description.contains(QStringLiteral("peacock")));
    EXPECT_EQ(QSettings().value(QStringLiteral("population/family")).toString(), QStringLiteral("peacock"));
    // Children keep their family, and the lineage says it.
    model().toggleSelected(0);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    EXPECT_EQ(familiesInGrid(), std::set<std::string>{"peacock"});
    EXPECT_EQ(lineageOf(*model().cell(1)).family, QStringLiteral("peacock"));
    // Solid designs list only the solid families; a flat family is not kept for them.
    mWindow->newRandomPopulation(3);
    EXPECT_EQ(mWindow->populationFamily(), QString()) << "peacock is flat: the solid list starts mixed";
    for (int i = 1; i < families->count(); ++i)
        EXPECT_EQ(findFamily(families->itemData(i).toString().toStdString())->dimension, 3);
}

} // namespace
