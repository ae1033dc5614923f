#pragma once
/// A sheet of designs in one image, as a textile designer shows a design's colourways: the
/// designs in a grid, row by row, each in a cell of one size, with a gap of the sheet's colour
/// between the cells and around them. Each cell is exactly the CPU renderer's image of its
/// design at the cell's size (a solid design: its slice z = size.z / 2).

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <filesystem>
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
};

/// The layout of a sheet of `count` designs: its size and where cell i's top left corner is.
struct SheetLayout {
    int width = 0, height = 0, cellWidth = 0, cellHeight = 0, columns = 0, rows = 0, gap = 0;
    int cellX(int i) const { return gap + (i % columns) * (cellWidth + gap); }
    int cellY(int i) const { return gap + (i / columns) * (cellHeight + gap); }
};
/// Throws InputError for no design, columns or sizes below 1, a negative gap, or a sheet
/// beyond the renderer's limits.
SheetLayout sheetLayout(const std::vector<Genome>& designs, const SheetSettings& settings);

/// The cell settings a design of the sheet is rendered with.
RenderSettings sheetCellSettings(const Genome& design, const SheetLayout& layout,
                                 const SheetSettings& settings);

/// Renders the sheet: the designs one after another, each on every core. Progress runs over
/// the whole sheet. Throws InputError (a design's source image), Cancelled.
Image renderSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                  const RenderControl* control = nullptr);

/// Renders the sheet and writes it atomically (writeImage: PNG, TIFF, ...). The file carries no
/// genome: a sheet is not the image of one design, so opening it as a design would mislead.
void writeSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                const std::filesystem::path& file, const RenderControl* control = nullptr);

} // namespace marbler
