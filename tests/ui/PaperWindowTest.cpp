// File ▸ New marbled paper: the generator of `marbler paper` as a starting point in the window.

#include "UiTestSupport.h"
#include "marbler/GenomeIO.h"
#include "marbler/Paper.h"
#include "workbench/OpenPlacement.h"
#include "workbench/PaperDialog.h"
#include "workbench/PopulationModel.h"
#include "workbench/WorkbenchWindow.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>

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
        // File ▸ New marbled paper asks first (PaperDialog.h); answered with what it offers.
        setPaperChooser([this](QWidget*, const PaperChoice& start) -> std::optional<PaperChoice> {
            offered = start;
            if (answer) return answer(start);
            return start;
        });
    }
    void TearDown() override {
        setPaperChooser({});
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
    std::optional<PaperChoice> offered;
    std::function<std::optional<PaperChoice>(const PaperChoice&)> answer;
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

// Issue 29: the window made only the default A4 paper; now it asks for the sheet, the inks, the
// passes, pastel and the seed, as `marbler paper` takes them, and remembers the answer.
TEST_F(PaperWindowTest, NewPaperAsksForSizeColoursAndPastelAndRemembersThem) {
    QAction* action = mWindow->findChild<QAction*>(QStringLiteral("newPaperAction"));
    ASSERT_NE(action, nullptr);
    PaperChoice chosen;
    chosen.options.width = 300.0;
    chosen.options.height = 300.0;
    chosen.options.colors = 3;
    chosen.options.passes = 1;
    chosen.options.pastel = true;
    chosen.seed = 77;
    answer = [&](const PaperChoice&) { return chosen; };
    action->trigger();
    ASSERT_TRUE(offered.has_value()) << "the window asked";
    ASSERT_EQ(paperCells().size(), 1u);
    const int cell = paperCells().front();
    EXPECT_EQ(serializeGenome(*model().cell(cell)), serializeGenome(paperGenome(77, chosen.options)))
        << "the paper of marbler paper --size 300x300mm --colors 3 --passes 1 --pastel --seed 77";
    EXPECT_EQ(model().cell(cell)->size.x, 300.0);

    // Asked again, the last answer is offered (with a seed of its own); cancel makes nothing.
    answer = [](const PaperChoice&) { return std::nullopt; };
    const std::size_t generations = model().history().size();
    action->trigger();
    ASSERT_TRUE(offered.has_value());
    EXPECT_EQ(offered->options.width, 300.0);
    EXPECT_EQ(offered->options.colors, 3);
    EXPECT_EQ(offered->options.passes, 1);
    EXPECT_TRUE(offered->options.pastel);
    EXPECT_EQ(model().history().size(), generations);
}

TEST_F(PaperWindowTest, ThePaperDialogSaysWhatItWillMake) {
    PaperChoice start;
    start.seed = 5;
    PaperDialog dialog(start);
    auto* sheet = dialog.findChild<QComboBox*>(QStringLiteral("paperSheet"));
    auto* width = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("paperWidth"));
    auto* colors = dialog.findChild<QSpinBox*>(QStringLiteral("paperColors"));
    auto* pastel = dialog.findChild<QCheckBox*>(QStringLiteral("paperPastel"));
    auto* seed = dialog.findChild<QLineEdit*>(QStringLiteral("paperSeed"));
    ASSERT_TRUE(sheet && width && colors && pastel && seed);
    EXPECT_TRUE(sheet->currentText().startsWith(QStringLiteral("A4"))) << "the default sheet";
    EXPECT_FALSE(width->isEnabled()) << "a named sheet has its size";
    EXPECT_EQ(seed->text(), QStringLiteral("5"));
    sheet->setCurrentIndex(sheet->count() - 1); // Custom size
    EXPECT_TRUE(width->isEnabled());
    width->setValue(420.0);
    colors->setValue(2);
    pastel->setChecked(true);
    seed->setText(QStringLiteral("123"));
    const PaperChoice made = dialog.choice();
    EXPECT_EQ(made.options.width, 420.0);
    EXPECT_EQ(made.options.height, 297.0);
    EXPECT_EQ(made.options.colors, 2);
    EXPECT_TRUE(made.options.pastel);
    EXPECT_EQ(made.seed, 123u);
    for (QWidget* field :
         {static_cast<QWidget*>(sheet), static_cast<QWidget*>(colors), static_cast<QWidget*>(pastel)})
        EXPECT_FALSE(field->toolTip().isEmpty());
}

} // namespace
