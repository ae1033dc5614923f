#pragma once
/// A sheet of designs in one image, as a textile designer shows a design's colourways: the
/// designs in a grid, row by row, each in a cell of one size, with a gap of the sheet's colour
/// between the cells and around them. Each cell is exactly the CPU renderer's image of its
/// design at the cell's size (a solid design: its slice z = size.z / 2).

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <filesystem>
#include <string>
#include <vector>

namespace marbler {

struct SheetSettings {
    int columns = 3;
    int cellWidth = 600;
    int cellHeight = 0; ///< 0: from the first design's aspect
    int gap = 24;       ///< pixels between cells and around them
    Color paper{0xff, 0xff, 0xff};
    std::string aa = "none"; ///< the cells' antialiasing (Sampling.h)
    int threads = 0;         ///< 0: every core
    /// A band under each cell for the design's name (meta.name; its short id when it has none).
    bool labels = false;
    /// With the labels, a row of the design's inks under its name: a chip of each ink with its
    /// hex value ("#6e2387") beside it.
    bool chips = false;
};

/// A line of text the sheet carries at a place of it: the renderer lays it out, the caller (the
/// window, which has fonts) draws it, left aligned and vertically centred in its box.
struct SheetText {
    int x = 0, y = 0, width = 0, height = 0;
    std::string text;
};
/// An ink's chip: a square of its colour, painted by renderSheet.
struct SheetChip {
    int x = 0, y = 0, side = 0;
    Color color;
};

/// The layout of a sheet of `count` designs: its size and where cell i's top left corner is.
struct SheetLayout {
    int width = 0, height = 0, cellWidth = 0, cellHeight = 0, columns = 0, rows = 0, gap = 0;
    int lineHeight = 0;   ///< a label line's height (0: no labels)
    int labelHeight = 0;  ///< the band under each cell: the name line, and the chips' lines
    int chipsPerLine = 0; ///< ink chips (each with its hex value) in a line (0: no chips)
    int cellX(int i) const { return gap + (i % columns) * (cellWidth + gap); }
    int cellY(int i) const { return gap + (i / columns) * (cellHeight + labelHeight + gap); }
};
/// Throws InputError for no design, columns or sizes below 1, a negative gap, or a sheet
/// beyond the renderer's limits.
SheetLayout sheetLayout(const std::vector<Genome>& designs, const SheetSettings& settings);

/// The texts of a sheet's labels, in order: each design's name, then (with chips) its inks' hex
/// values. Empty without labels.
std::vector<SheetText> sheetTexts(const std::vector<Genome>& designs, const SheetLayout& layout,
                                  const SheetSettings& settings);
/// The ink chips of a sheet (with labels and chips), each design's inks in palette order.
std::vector<SheetChip> sheetChips(const std::vector<Genome>& designs, const SheetLayout& layout,
                                  const SheetSettings& settings);

/// The cell settings a design of the sheet is rendered with.
RenderSettings sheetCellSettings(const Genome& design, const SheetLayout& layout,
                                 const SheetSettings& settings);

/// Renders the sheet: the designs one after another, each on every core, and the ink chips (the
/// labels' texts are the caller's to draw, sheetTexts). Progress runs over the whole sheet. Throws InputError
/// (a design's source image), Cancelled.
Image renderSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                  const RenderControl* control = nullptr);

/// Renders the sheet and writes it atomically (writeImage: PNG, TIFF, ...). The file carries no
/// genome: a sheet is not the image of one design, so opening it as a design would mislead.
void writeSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                const std::filesystem::path& file, const RenderControl* control = nullptr);

} // namespace marbler
