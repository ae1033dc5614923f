// The window's Colourways mode (Breed ▸ Colourways): entering it with one design picked, breeding
// only palettes while it is on, the operators it turns off, the session keeping its
// generations, and Breed ▸ Export colourway sheet… through the injectable file question.

#include "UiTestSupport.h"
#include "WaitFor.h"

#include "marbler/Colourways.h"
#include "marbler/Sheet.h"
#include "shared/SavedFiles.h"
#include "workbench/Session.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QProgressDialog>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>

#include <cstring>
#include <set>

#include <gtest/gtest.h>

using namespace marbler;
using namespace marbler::ui;

namespace {

class ColourwaysUiTest : public test::WindowTest {
protected:
    void TearDown() override {
        setSaveFileAsker({});
        test::WindowTest::TearDown();
    }
};

TEST_F(ColourwaysUiTest, EnteringWithOneDesignFillsItsColourways) {
    model().setSelected(4, true);
    const Genome design = *model().cell(4);
    const int before = model().currentIndex();
    QAction* mode = mWindow->colourwaysAction();
    ASSERT_NE(mode, nullptr);
    EXPECT_TRUE(mode->isCheckable());
    mode->trigger();
    ASSERT_TRUE(mWindow->colourwaysMode());
    EXPECT_NE(model().currentIndex(), before);
    EXPECT_TRUE(model().current().description.startsWith(QStringLiteral("Colourways of")));
    EXPECT_EQ(*model().cell(4), design);
    for (int c = 0; c < CellCount; ++c) {
        if (c == 4) continue;
        ASSERT_NE(model().cell(c), nullptr);
        EXPECT_TRUE(sameStructure(*model().cell(c), design)) << "cell " << c;
        EXPECT_NE(model().cell(c)->palette, design.palette) << "cell " << c;
        EXPECT_TRUE(paletteHasContrast(model().cell(c)->palette, model().cell(c)->background));
        EXPECT_EQ(lineageOf(*model().cell(c)).madeBy(), QStringLiteral("Colourway"));
    }
}

TEST_F(ColourwaysUiTest, BreedingInTheModeKeepsTheStructure) {
    model().setSelected(0, true);
    const Genome design = *model().cell(0);
    mWindow->setColourwaysMode(true);
    // Swap and Change initial state are off, and say why.
    for (GeneticOperator op : {GeneticOperator::Swap, GeneticOperator::Reinit}) {
        EXPECT_FALSE(mWindow->operatorAction(op)->isEnabled());
        EXPECT_TRUE(mWindow->operatorAction(op)->toolTip().contains(QStringLiteral("Colourways")));
    }
    model().clearSelection();
    model().setSelected(3, true);
    ASSERT_TRUE(mWindow->operatorAction(GeneticOperator::Alter)->isEnabled());
    mWindow->operatorAction(GeneticOperator::Alter)->trigger();
    for (int c = 0; c < CellCount; ++c)
        EXPECT_TRUE(sameStructure(*model().cell(c), design)) << "alter, cell " << c;
    model().setSelected(5, true);
    EXPECT_FALSE(mWindow->operatorAction(GeneticOperator::Swap)->isEnabled());
    ASSERT_TRUE(mWindow->operatorAction(GeneticOperator::Recombine)->isEnabled());
    EXPECT_TRUE(mWindow->applyOperator(GeneticOperator::Recombine));
    EXPECT_FALSE(mWindow->applyOperator(GeneticOperator::Swap));
    for (int c = 0; c < CellCount; ++c)
        EXPECT_TRUE(sameStructure(*model().cell(c), design)) << "recombine, cell " << c;

    // Leaving the mode: ordinary breeding, which moves the strokes.
    mWindow->setColourwaysMode(false);
    EXPECT_TRUE(mWindow->operatorAction(GeneticOperator::Swap)->isEnabled());
    model().clearSelection();
    model().setSelected(0, true);
    ASSERT_TRUE(mWindow->applyOperator(GeneticOperator::Alter));
    int moved = 0;
    for (int c = 1; c < CellCount; ++c)
        moved += model().cell(c)->operations != design.operations;
    EXPECT_GT(moved, 0);
}

TEST_F(ColourwaysUiTest, TheSessionKeepsAColourwayGeneration) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("session.json"));
    model().setSessionFile(file);
    model().setSelected(2, true);
    mWindow->setColourwaysMode(true);
    ASSERT_TRUE(model().saveSession());
    const SavedSession saved = loadSession(file);
    ASSERT_EQ(saved.history.size(), model().history().size());
    const Generation& back = saved.history[std::size_t(saved.current)];
    for (int c = 0; c < CellCount; ++c)
        EXPECT_EQ(*back.cells[std::size_t(c)], *model().cell(c)) << "cell " << c;
}

TEST_F(ColourwaysUiTest, ExportsTheSheetThroughTheFileQuestion) {
    test::ErrorCapture errors;
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("sheet.png"));
    QString offered;
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString& filter) {
        offered = suggested;
        EXPECT_TRUE(filter.contains(QStringLiteral("*.tif")));
        return file;
    });
    model().setSelected(1, true);
    mWindow->setColourwaysMode(true);
    mWindow->setSheetCellWidth(40);
    ASSERT_TRUE(mWindow->exportSheetAction()->isEnabled());
    mWindow->exportSheetAction()->trigger();
    EXPECT_TRUE(offered.endsWith(QStringLiteral("colourways.png"))) << offered.toStdString();
    MARBLER_WAIT(!mWindow->sheetExportRunning(), 60000);
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("; ")).toStdString();
    EXPECT_EQ(mWindow->savedFileNotice()->file(), file);

    std::vector<Genome> designs;
    for (int c = 0; c < CellCount; ++c)
        designs.push_back(*model().cell(c));
    SheetSettings settings;
    settings.cellWidth = 40;
    settings.gap = 4;
    settings.aa = "rgss";
    settings.labels = true; // each design named under it (issue 29)
    const Image expected = renderSheet(designs, settings);
    const SheetLayout layout = sheetLayout(designs, settings);
    QImage image(file);
    ASSERT_FALSE(image.isNull());
    image = image.convertToFormat(QImage::Format_RGB888);
    ASSERT_EQ(image.width(), expected.width);
    ASSERT_EQ(image.height(), expected.height);
    // The cells are the renderer's (the labels' text is the window's font).
    for (int c = 0; c < CellCount; ++c)
        for (int y = layout.cellY(c); y < layout.cellY(c) + layout.cellHeight; ++y)
            ASSERT_EQ(std::memcmp(image.constScanLine(y) + layout.cellX(c) * 3,
                                  expected.row(y) + std::size_t(layout.cellX(c)) * 3,
                                  std::size_t(layout.cellWidth) * 3),
                      0)
                << "cell " << c << " row " << y;

    // Cancelled by the question: nothing is started.
    setSaveFileAsker([](QWidget*, const QString&, const QString&, const QString&) { return QString(); });
    EXPECT_FALSE(mWindow->exportColourwaySheet());
}

TEST_F(ColourwaysUiTest, CancellingTheSheetLeavesNoFile) {
    test::ErrorCapture errors;
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("big"));
    mWindow->setSheetCellWidth(2000); // long enough to cancel while it renders
    ASSERT_TRUE(mWindow->exportColourwaySheet(file));
    EXPECT_TRUE(mWindow->sheetExportRunning());
    EXPECT_FALSE(mWindow->exportSheetAction()->isEnabled());
    auto* progress = mWindow->findChild<QProgressDialog*>();
    ASSERT_NE(progress, nullptr);
    // The dialog's Cancel button.
    auto* button = progress->findChild<QPushButton*>();
    ASSERT_NE(button, nullptr);
    button->click();
    MARBLER_WAIT(!mWindow->sheetExportRunning(), 60000);
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("; ")).toStdString();
    EXPECT_FALSE(QFileInfo::exists(file + QStringLiteral(".png")));
    EXPECT_TRUE(QDir(dir.path()).isEmpty());
    EXPECT_TRUE(mWindow->exportSheetAction()->isEnabled());
}

// The sheet runs as a BackgroundJob: its box still says what it does and the status bar still says
// a cancelled sheet was cancelled; closing the window meanwhile stops it, leaving no file.
TEST_F(ColourwaysUiTest, TheSheetsBoxAndMessagesStay) {
    test::ErrorCapture errors;
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("sheet.png"));
    mWindow->setSheetCellWidth(2000); // long enough to cancel while it renders
    ASSERT_TRUE(mWindow->exportColourwaySheet(file));
    auto* progress = mWindow->findChild<QProgressDialog*>();
    ASSERT_NE(progress, nullptr);
    EXPECT_EQ(progress->windowTitle(), QStringLiteral("Export colourway sheet"));
    EXPECT_EQ(progress->labelText(), QStringLiteral("Rendering the colourway sheet…"));
    // A second sheet waits for the first.
    EXPECT_FALSE(mWindow->exportColourwaySheet(dir.filePath(QStringLiteral("second.png"))));
    EXPECT_EQ(mWindow->statusBar()->currentMessage(),
              QStringLiteral("A colourway sheet is being written already"));
    emit progress->canceled(); // what the box's Cancel button says
    MARBLER_WAIT(!mWindow->sheetExportRunning(), 60000);
    EXPECT_EQ(mWindow->statusBar()->currentMessage(), QStringLiteral("Colourway sheet cancelled"));
    EXPECT_EQ(mWindow->findChild<QProgressDialog*>(), nullptr) << "the box is gone";
    EXPECT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("; ")).toStdString();

    // Closing the window while a sheet renders stops the work before the window is gone, leaving
    // no file, not even a half-written one.
    ASSERT_TRUE(mWindow->exportColourwaySheet(file));
    mWindow.reset();
    EXPECT_FALSE(QFileInfo::exists(file));
    EXPECT_TRUE(QDir(dir.path()).isEmpty())
        << QDir(dir.path()).entryList(QDir::Files).join(' ').toStdString();
}

// The colourway sheet names each design under it, offers the parent's name as its file, and on
// request shows each design's inks with their hex values.
TEST_F(ColourwaysUiTest, TheColourwaySheetIsLabelledAndNamedAfterTheParent) {
    test::ErrorCapture errors;
    QTemporaryDir dir;
    model().setSelected(1, true);
    const std::string parentName = model().cell(1)->meta.name.value_or("");
    mWindow->setColourwaysMode(true);
    MARBLER_WAIT(model().current().parentCells.size() == 1, 5000);
    // Colourways are named from their own inks, each name its own.
    std::set<std::string> names;
    for (int c = 0; c < CellCount; ++c)
        names.insert(model().cell(c)->meta.name.value_or(""));
    EXPECT_EQ(names.size(), std::size_t(CellCount));
    auto* chips = mWindow->findChild<QAction*>(QStringLiteral("sheetChipsAction"));
    ASSERT_NE(chips, nullptr);
    chips->setChecked(true);
    const QString file = QDir(dir.path()).filePath(QStringLiteral("sheet.png"));
    QString offered;
    setSaveFileAsker([&](QWidget*, const QString&, const QString& suggested, const QString&) {
        offered = suggested;
        return file;
    });
    mWindow->setSheetCellWidth(160);
    mWindow->exportSheetAction()->trigger();
    EXPECT_EQ(QFileInfo(offered).fileName(),
              QString::fromStdString(parentName) + QStringLiteral(" colourways.png"));
    MARBLER_WAIT(!mWindow->sheetExportRunning(), 60000);
    ASSERT_TRUE(errors.messages.isEmpty()) << errors.messages.join(QStringLiteral("; ")).toStdString();

    std::vector<Genome> designs;
    for (int c = 0; c < CellCount; ++c)
        designs.push_back(*model().cell(c));
    SheetSettings settings;
    settings.cellWidth = 160;
    settings.gap = std::max(4, 160 / 25);
    settings.labels = settings.chips = true;
    const SheetLayout layout = sheetLayout(designs, settings);
    QImage image(file);
    ASSERT_FALSE(image.isNull());
    image = image.convertToFormat(QImage::Format_RGB888);
    ASSERT_EQ(image.height(), layout.height);
    // Each name's box and each hex value's box has ink on the paper: the text was drawn.
    for (const SheetText& text : sheetTexts(designs, layout, settings)) {
        int dark = 0;
        for (int y = text.y; y < text.y + text.height; ++y)
            for (int x = text.x; x < text.x + text.width; ++x)
                if (qGray(image.pixel(x, y)) < 160) ++dark;
        EXPECT_GT(dark, 10) << "no text drawn for “" << text.text << "”";
    }
    // The chips show the inks.
    for (const SheetChip& chip : sheetChips(designs, layout, settings))
        EXPECT_EQ(image.pixel(chip.x + chip.side / 2, chip.y + chip.side / 2),
                  qRgb(chip.color.r, chip.color.g, chip.color.b));
    // To look at it: MARBLER_KEEP_SHEET=path keeps a copy.
    if (qEnvironmentVariableIsSet("MARBLER_KEEP_SHEET"))
        image.save(qEnvironmentVariable("MARBLER_KEEP_SHEET"));
    chips->setChecked(false); // a remembered setting: the next test starts without
}

} // namespace
