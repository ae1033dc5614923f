// Sheets of designs (marbler/Sheet.h): the layout, each cell exactly the CPU renderer's image
// of its design, the gaps the sheet's colour, progress over the whole sheet, and the file.

#include "RenderTestUtil.h"
#include "TestUtil.h"

#include "marbler/Colourways.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeImage.h"
#include "marbler/Sheet.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <mutex>

namespace marbler {
namespace {

std::vector<Genome> colourwaySet(int count) {
    const Genome design = randomGenome(21, 2);
    ColourwayRequest request;
    request.parents = {design};
    request.seed = 4;
    request.count = count - 1;
    std::vector<Genome> out{design};
    for (Genome& g : colourways(request))
        out.push_back(std::move(g));
    return out;
}

/// Whether a cell of the sheet holds exactly `image`.
bool cellEquals(const Image& sheet, int x, int y, const Image& image) {
    for (int row = 0; row < image.height; ++row)
        if (std::memcmp(sheet.row(y + row) + std::size_t(x) * 3, image.row(row),
                        std::size_t(image.width) * 3) != 0)
            return false;
    return true;
}

TEST(Sheet, EachCellIsARenderOfItsDesignWithTheGapAround) {
    const auto designs = colourwaySet(8); // two full rows and two of a third
    SheetSettings settings;
    settings.cellWidth = 48;
    settings.cellHeight = 40;
    settings.gap = 5;
    settings.paper = {0x12, 0x34, 0x56};
    settings.aa = "rgss";
    const SheetLayout layout = sheetLayout(designs, settings);
    EXPECT_EQ(layout.columns, 3);
    EXPECT_EQ(layout.rows, 3);
    EXPECT_EQ(layout.width, 3 * 48 + 4 * 5);
    EXPECT_EQ(layout.height, 3 * 40 + 4 * 5);
    const Image sheet = renderSheet(designs, settings);
    ASSERT_EQ(sheet.width, layout.width);
    ASSERT_EQ(sheet.height, layout.height);
    std::vector<bool> inCell(std::size_t(sheet.width) * std::size_t(sheet.height), false);
    for (int i = 0; i < int(designs.size()); ++i) {
        RenderSettings cell = sheetCellSettings(designs[std::size_t(i)], layout, settings);
        const Image image = CpuRenderer(designs[std::size_t(i)]).render(cell);
        EXPECT_TRUE(cellEquals(sheet, layout.cellX(i), layout.cellY(i), image)) << "cell " << i;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 48; ++x)
                inCell[std::size_t(layout.cellY(i) + y) * std::size_t(sheet.width) +
                       std::size_t(layout.cellX(i) + x)] = true;
    }
    // The cells differ (colourways), and everything outside them is the sheet's colour.
    const Image first = CpuRenderer(designs[0]).render(sheetCellSettings(designs[0], layout, settings));
    EXPECT_FALSE(cellEquals(sheet, layout.cellX(1), layout.cellY(1), first));
    int paper = 0;
    for (int y = 0; y < sheet.height; ++y)
        for (int x = 0; x < sheet.width; ++x) {
            if (inCell[std::size_t(y) * std::size_t(sheet.width) + std::size_t(x)]) continue;
            const std::uint8_t* p = sheet.row(y) + std::size_t(x) * 3;
            EXPECT_TRUE(p[0] == 0x12 && p[1] == 0x34 && p[2] == 0x56) << x << "," << y;
            ++paper;
        }
    EXPECT_EQ(paper, sheet.width * sheet.height - 8 * 48 * 40);
}

TEST(Sheet, CellHeightFollowsTheDesignAndSolidsAreSliced) {
    Genome wide = randomGenome(3, 2);
    wide.size = {1000.0, 500.0, 1000.0};
    SheetSettings settings;
    settings.cellWidth = 60;
    EXPECT_EQ(sheetLayout({wide}, settings).cellHeight, 30);
    EXPECT_EQ(sheetLayout({wide}, settings).columns, 1);

    const Genome solid = randomGenome(3, 3);
    settings.cellWidth = 20;
    settings.gap = 2;
    const Image sheet = renderSheet({solid, solid}, settings);
    RenderSettings cell;
    cell.width = cell.height = 20;
    cell.slice = Slice{2, solid.size.z / 2.0};
    const Image image = CpuRenderer(solid).render(cell);
    EXPECT_TRUE(cellEquals(sheet, 2, 2, image));
    EXPECT_TRUE(cellEquals(sheet, 24, 2, image));
}

TEST(Sheet, ReportsProgressAndIsCancelled) {
    const auto designs = colourwaySet(3);
    SheetSettings settings;
    settings.cellWidth = 32;
    std::vector<double> seen;
    std::mutex lock;
    RenderControl control;
    control.progress = [&](double f) {
        std::lock_guard guard(lock);
        seen.push_back(f);
    };
    renderSheet(designs, settings, &control);
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    for (double f : seen)
        EXPECT_TRUE(f >= 0.0 && f <= 1.0);
    EXPECT_TRUE(std::any_of(seen.begin(), seen.end(), [](double f) { return f > 0.4 && f < 0.9; }));

    std::atomic<bool> cancel{true};
    RenderControl cancelled;
    cancelled.cancel = &cancel;
    EXPECT_THROW(renderSheet(designs, settings, &cancelled), Cancelled);
}

TEST(Sheet, RefusesBadLayouts) {
    SheetSettings settings;
    EXPECT_THROW(sheetLayout({}, settings), InputError);
    const auto designs = colourwaySet(2);
    settings.columns = 0;
    EXPECT_THROW(sheetLayout(designs, settings), InputError);
    settings.columns = 3;
    settings.gap = -1;
    EXPECT_THROW(sheetLayout(designs, settings), InputError);
    settings.gap = 0;
    settings.cellWidth = 70000;
    EXPECT_THROW(sheetLayout(designs, settings), InputError);
}

TEST(Sheet, WritesPngAndTiffWithoutAGenome) {
    const auto designs = colourwaySet(4);
    SheetSettings settings;
    settings.cellWidth = 30;
    settings.gap = 3;
    const Image sheet = renderSheet(designs, settings);
    const auto dir = test::outputDir("sheet");
    for (const char* name : {"sheet.png", "sheet.tiff"}) {
        writeSheet(designs, settings, dir / name);
        const Image back = test::readImage8(dir / name);
        ASSERT_EQ(back.width, sheet.width);
        ASSERT_EQ(back.height, sheet.height);
        EXPECT_EQ(back.rgb, sheet.rgb) << name;
        const ImageKind kind = std::string(name).ends_with("png") ? ImageKind::Png : ImageKind::Tiff;
        EXPECT_FALSE(readGenomeText(dir / name, kind, name).has_value()) << name;
    }
}

// Issue 29: a colourway sheet says what each design is: its name under it and, optionally, its
// inks as chips with their hex values.
TEST(Sheet, LabelsNameEachDesignAndChipsShowItsInks) {
    const auto designs = colourwaySet(5);
    SheetSettings settings;
    settings.cellWidth = 140;
    settings.gap = 6;
    settings.paper = {0xff, 0xff, 0xff};
    const SheetLayout plain = sheetLayout(designs, settings);
    EXPECT_TRUE(sheetTexts(designs, plain, settings).empty()) << "no labels unless asked";

    settings.labels = true;
    const SheetLayout named = sheetLayout(designs, settings);
    EXPECT_GT(named.labelHeight, 0);
    EXPECT_EQ(named.height, plain.height + named.rows * named.labelHeight);
    const std::vector<SheetText> names = sheetTexts(designs, named, settings);
    ASSERT_EQ(names.size(), designs.size());
    for (std::size_t i = 0; i < designs.size(); ++i) {
        EXPECT_EQ(names[i].text, *designs[i].meta.name);
        // Under its cell, inside the sheet, not over the next row.
        EXPECT_EQ(names[i].x, named.cellX(int(i)));
        EXPECT_GE(names[i].y, named.cellY(int(i)) + named.cellHeight);
        EXPECT_LE(names[i].y + names[i].height, named.cellY(int(i)) + named.cellHeight + named.labelHeight);
    }
    EXPECT_TRUE(sheetChips(designs, named, settings).empty());

    settings.chips = true;
    const SheetLayout chipped = sheetLayout(designs, settings);
    const std::vector<SheetText> texts = sheetTexts(designs, chipped, settings);
    const std::vector<SheetChip> chips = sheetChips(designs, chipped, settings);
    std::size_t inks = 0;
    for (const Genome& g : designs)
        inks += g.palette.size();
    ASSERT_EQ(chips.size(), inks) << "every ink has a chip at this width";
    ASSERT_EQ(texts.size(), designs.size() + inks);
    EXPECT_EQ(texts[1].text, toHex(designs[0].palette[0]));
    // The chips are painted in their inks' colours, where the plain sheet has its paper.
    const Image sheet = renderSheet(designs, settings);
    ASSERT_EQ(sheet.height, chipped.height);
    for (const SheetChip& chip : chips) {
        const std::uint8_t* p = sheet.row(chip.y + chip.side / 2) + std::size_t(chip.x + chip.side / 2) * 3;
        EXPECT_EQ(Color(p[0], p[1], p[2]), chip.color);
    }
    // The cells are the same renders as before, moved down by the rows' labels.
    const Image plainSheet = [&] {
        SheetSettings s = settings;
        s.labels = s.chips = false;
        return renderSheet(designs, s);
    }();
    const int last = int(designs.size()) - 1;
    for (int row = 0; row < chipped.cellHeight; ++row)
        EXPECT_EQ(std::memcmp(sheet.row(chipped.cellY(last) + row) + std::size_t(chipped.cellX(last)) * 3,
                              plainSheet.row(plain.cellY(last) + row) + std::size_t(plain.cellX(last)) * 3,
                              std::size_t(chipped.cellWidth) * 3),
                  0);
}

} // namespace
} // namespace marbler
