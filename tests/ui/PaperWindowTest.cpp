// File ▸ New marbled paper: the generator of `marbler paper` as a starting point in the window.

#include "UiTestSupport.h"
#include "marbler/GenomeIO.h"
#include "marbler/Paper.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

class PaperWindowTest : public test::WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        // Placing over designs asks where they go; answered without a modal dialog.
        setOpenChooser(
            [](QWidget*, const OpenQuestion&) -> std::optional<OpenChoice> { return OpenChoice::Replace; });
    }
    void TearDown() override {
        setOpenChooser({});
        WindowTest::TearDown();
    }
    /// The cells holding a paper of this generator (either recipe; the window makes the default).
    std::vector<int> paperCells() {
        std::vector<int> cells;
        for (int i = 0; i < CellCount; ++i) {
            if (!model().cell(i)) continue;
            const std::string generator = model().cell(i)->meta.toJson().value("generator", std::string());
            if (generator == PaperGeneratorVersion || generator == PaperPostGeneratorVersion)
                cells.push_back(i);
        }
        return cells;
    }
};

TEST_F(PaperWindowTest, NewPaperPutsTheCommandLinesPaperIntoTheGridAsANewGeneration) {
    ASSERT_EQ(model().history().size(), 1u);
    ASSERT_TRUE(paperCells().empty());
    const std::vector<int> used = mWindow->newPaper(9);
    ASSERT_EQ(used.size(), 1u);
    ASSERT_NE(model().cell(used[0]), nullptr);
    // The same genome as `marbler paper --seed 9` with its defaults (A4, 5 colours, 3 passes).
    EXPECT_EQ(serializeGenome(*model().cell(used[0])), serializeGenome(paperGenome(9, PaperOptions{})));
    EXPECT_EQ(model().history().size(), 2u);
    EXPECT_TRUE(model().history().back().description.contains(QStringLiteral("seed 9")))
        << model().history().back().description.toStdString();
    // Back undoes it.
    model().goBack();
    EXPECT_TRUE(paperCells().empty());
}

TEST_F(PaperWindowTest, TheFileMenuOffersIt) {
    QAction* action = mWindow->findChild<QAction*>(QStringLiteral("newPaperAction"));
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isEnabled());
    action->trigger();
    EXPECT_EQ(paperCells().size(), 1u);
}

} // namespace
