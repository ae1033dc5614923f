#include "marbler/Sheet.h"
#include "marbler/ImageFile.h"

#include "marbler/Error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace marbler {

namespace {

/// The width of an ink's chip and its hex value ("#rrggbb" at the label's size), a space after.
int chipStep(int lineHeight) {
    return lineHeight * 9 / 2;
}

} // namespace

SheetLayout sheetLayout(const std::vector<Genome>& designs, const SheetSettings& settings) {
    if (designs.empty()) throw InputError("a sheet needs at least one design");
    if (settings.columns < 1)
        throw InputError("a sheet needs at least one column (got " + std::to_string(settings.columns) + ")");
    if (settings.cellWidth < 1 || settings.cellHeight < 0)
        throw InputError("a sheet's cells need a size of at least 1 pixel");
    if (settings.gap < 0)
        throw InputError("a sheet's gap cannot be negative (got " + std::to_string(settings.gap) + ")");
    SheetLayout layout;
    layout.gap = settings.gap;
    layout.cellWidth = settings.cellWidth;
    const Genome& first = designs.front();
    layout.cellHeight =
        settings.cellHeight > 0
            ? settings.cellHeight
            : std::max(1, static_cast<int>(std::lround(settings.cellWidth * first.size.y / first.size.x)));
    const int count = static_cast<int>(designs.size());
    layout.columns = std::min(settings.columns, count);
    layout.rows = (count + layout.columns - 1) / layout.columns;
    if (settings.labels) {
        // Legible at any cell size, never more than a cell's tenth.
        layout.lineHeight = std::clamp(layout.cellWidth / 14, 12, 64);
        int lines = 1;
        if (settings.chips) {
            // Every ink of every design: as many lines of chips as the largest palette needs.
            std::size_t inks = 1;
            for (const Genome& g : designs)
                inks = std::max(inks, g.palette.size());
            layout.chipsPerLine = std::max(1, layout.cellWidth / chipStep(layout.lineHeight));
            lines += static_cast<int>((inks + std::size_t(layout.chipsPerLine) - 1) /
                                      std::size_t(layout.chipsPerLine));
        }
        layout.labelHeight = layout.lineHeight * lines + layout.lineHeight / 3;
    }
    const std::int64_t width = std::int64_t(layout.columns) * (layout.cellWidth + layout.gap) + layout.gap;
    const std::int64_t height =
        std::int64_t(layout.rows) * (layout.cellHeight + layout.labelHeight + layout.gap) + layout.gap;
    if (width > MaxImageSide || height > MaxImageSide || width * height > MaxImagePixels)
        throw InputError("a sheet of " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels is too large");
    layout.width = static_cast<int>(width);
    layout.height = static_cast<int>(height);
    return layout;
}

namespace {

/// Where design i's inks go: a chip and its hex value each, in lines under the name.
template <typename Each> void eachChip(const Genome& design, const SheetLayout& layout, int i, Each each) {
    const int line = layout.lineHeight;
    const int side = std::max(4, line * 3 / 4);
    const int step = chipStep(line);
    const int x0 = layout.cellX(i), y0 = layout.cellY(i) + layout.cellHeight + line + line / 3;
    for (std::size_t k = 0; k < design.palette.size(); ++k) {
        const int column = static_cast<int>(k) % layout.chipsPerLine,
                  row = static_cast<int>(k) / layout.chipsPerLine;
        each(k, x0 + column * step, y0 + row * line, side, step);
    }
}

} // namespace

std::vector<SheetText> sheetTexts(const std::vector<Genome>& designs, const SheetLayout& layout,
                                  const SheetSettings& settings) {
    std::vector<SheetText> texts;
    if (!settings.labels || layout.lineHeight == 0) return texts;
    for (std::size_t i = 0; i < designs.size(); ++i) {
        const Genome& design = designs[i];
        const int cell = static_cast<int>(i);
        std::string name = design.meta.name && !design.meta.name->empty() ? *design.meta.name : "";
        if (name.empty()) name = design.meta.id ? design.meta.id->substr(0, 8) : "untitled";
        texts.push_back({layout.cellX(cell), layout.cellY(cell) + layout.cellHeight + layout.lineHeight / 6,
                         layout.cellWidth, layout.lineHeight, name});
        if (!settings.chips || layout.chipsPerLine == 0) continue;
        eachChip(design, layout, cell, [&](std::size_t k, int x, int y, int side, int step) {
            const int textX = x + side + layout.lineHeight / 4;
            texts.push_back({textX, y, step - (textX - x), layout.lineHeight, toHex(design.palette[k])});
        });
    }
    return texts;
}

std::vector<SheetChip> sheetChips(const std::vector<Genome>& designs, const SheetLayout& layout,
                                  const SheetSettings& settings) {
    std::vector<SheetChip> chips;
    if (!settings.labels || !settings.chips || layout.chipsPerLine == 0) return chips;
    for (std::size_t i = 0; i < designs.size(); ++i)
        eachChip(designs[i], layout, static_cast<int>(i), [&](std::size_t k, int x, int y, int side, int) {
            chips.push_back({x, y + (layout.lineHeight - side) / 2, side, designs[i].palette[k]});
        });
    return chips;
}

RenderSettings sheetCellSettings(const Genome& design, const SheetLayout& layout,
                                 const SheetSettings& settings) {
    RenderSettings render;
    render.width = layout.cellWidth;
    render.height = layout.cellHeight;
    render.aa = settings.aa;
    render.threads = settings.threads;
    if (design.dimension == 3) render.slice = Slice{2, design.size.z / 2.0};
    return render;
}

Image renderSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                  const RenderControl* control) {
    const SheetLayout layout = sheetLayout(designs, settings);
    Image sheet;
    sheet.width = layout.width;
    sheet.height = layout.height;
    sheet.rgb.resize(std::size_t(sheet.width) * std::size_t(sheet.height) * 3);
    for (std::size_t p = 0; p < sheet.rgb.size(); p += 3) {
        sheet.rgb[p] = settings.paper.r;
        sheet.rgb[p + 1] = settings.paper.g;
        sheet.rgb[p + 2] = settings.paper.b;
    }
    const double count = static_cast<double>(designs.size());
    for (std::size_t i = 0; i < designs.size(); ++i) {
        // Each cell's progress is a share of the whole sheet's.
        RenderControl cell;
        if (control) {
            cell.cancel = control->cancel;
            if (control->progress)
                cell.progress = [control, i, count](double f) {
                    control->progress((static_cast<double>(i) + f) / count);
                };
        }
        const Genome& design = designs[i];
        const Image image = CpuRenderer(design).render(sheetCellSettings(design, layout, settings), &cell);
        const int x = layout.cellX(static_cast<int>(i)), y = layout.cellY(static_cast<int>(i));
        for (int row = 0; row < image.height; ++row)
            std::memcpy(sheet.row(y + row) + std::size_t(x) * 3, image.row(row),
                        std::size_t(image.width) * 3);
    }
    for (const SheetChip& chip : sheetChips(designs, layout, settings))
        for (int row = chip.y; row < chip.y + chip.side && row < sheet.height; ++row)
            for (int col = chip.x; col < chip.x + chip.side && col < sheet.width; ++col) {
                std::uint8_t* p = sheet.row(row) + std::size_t(col) * 3;
                p[0] = chip.color.r;
                p[1] = chip.color.g;
                p[2] = chip.color.b;
            }
    if (control && control->progress) control->progress(1.0);
    return sheet;
}

void writeSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                const std::filesystem::path& file, const RenderControl* control) {
    writeImage(renderSheet(designs, settings, control), file);
}

} // namespace marbler
