// What a bred design changed from its parent, in words (ChangeSummary.h): said in its cell's
// tooltip and in the lineage.

#include "UiTestSupport.h"
#include "marbler/ChangeSummary.h"
#include "workbench/DesignCell.h"

#include <QTreeWidget>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

class ChangeTest : public test::WindowTest {};

TEST_F(ChangeTest, BredCellsAndTheLineageSayWhatChanged) {
    model().setSteering(false); // alteration's own children and the one wildcard cell
    const Genome parent = *model().cell(4);
    EXPECT_TRUE(lineageOf(parent).change.isEmpty()) << "a random design was not bred";
    EXPECT_FALSE(mWindow->cell(4)->toolTip().contains(QStringLiteral("Changed:")));
    model().setSelected(4, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    QTreeWidgetItem* designs = mWindow->lineageTree()->topLevelItem(0);
    int bred = 0, wildcards = 0;
    for (int i = 0; i < CellCount; ++i) {
        SCOPED_TRACE("design " + std::to_string(i + 1));
        const Genome* g = model().cell(i);
        ASSERT_NE(g, nullptr);
        if (lineageOf(*g).op.isEmpty()) continue; // the parent
        if (lineageOf(*g).op == QStringLiteral("wildcard")) {
            // A fresh design, not a change of the parent: it says nothing changed.
            ++wildcards;
            EXPECT_TRUE(lineageOf(*g).change.isEmpty());
            EXPECT_FALSE(mWindow->cell(i)->toolTip().contains(QStringLiteral("Changed:")));
            continue;
        }
        ++bred;
        const QString change = QString::fromStdString(describeChange(parent, *g));
        EXPECT_EQ(lineageOf(*g).change, change);
        EXPECT_NE(change, QStringLiteral("no visible change"));
        EXPECT_TRUE(mWindow->cell(i)->toolTip().startsWith(QStringLiteral("Changed: ") + change))
            << mWindow->cell(i)->toolTip().toStdString();
        EXPECT_EQ(designs->child(i)->toolTip(1), QStringLiteral("Changed: ") + change);
    }
    EXPECT_EQ(wildcards, model().wildcardCell() ? 1 : 0);
    EXPECT_EQ(bred + wildcards, CellCount - 1);
}

/// Swap gives two results; the cells after them are gentle variations of those, and their
/// tooltips say what changed from the swap each varies (named by its number, as the captions
/// are), not the whole difference from the home parent.
TEST_F(ChangeTest, AVariedCellSaysWhatChangedFromTheDesignItVaries) {
    model().setSelected(0, true);
    model().setSelected(1, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Swap));
    int varied = 0;
    for (int i = 0; i < CellCount; ++i) {
        SCOPED_TRACE("design " + std::to_string(i + 1));
        const Genome* g = model().cell(i);
        ASSERT_NE(g, nullptr);
        if (!g->meta.toJson().contains("lineage") || !g->meta.toJson()["lineage"].contains("variation"))
            continue;
        ++varied;
        const std::string of = g->meta.toJson()["lineage"]["variation"]["of"].get<std::string>();
        int source = -1;
        for (int k = 0; k < CellCount; ++k)
            if (k != i && model().cell(k) && genomeId(*model().cell(k)) == of) source = k;
        ASSERT_GE(source, 0) << "the varied design is in the grid";
        const QString expected = QStringLiteral("a variation of #%1: %2")
                                     .arg(source + 1)
                                     .arg(QString::fromStdString(describeChange(*model().cell(source), *g)));
        EXPECT_EQ(lineageOf(*g).change.toStdString(), expected.toStdString());
        EXPECT_TRUE(mWindow->cell(i)->toolTip().startsWith(QStringLiteral("Changed: ") + expected))
            << mWindow->cell(i)->toolTip().toStdString();
        EXPECT_TRUE(designCaption(*model().cell(source)).contains(QStringLiteral("#%1)").arg(source + 1)))
            << "the number names the cell: " << designCaption(*model().cell(source)).toStdString();
    }
    EXPECT_GE(varied, 4) << "seven offspring of two swaps";
}

} // namespace
