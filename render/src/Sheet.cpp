#include "marbler/Sheet.h"
#include "marbler/ImageFile.h"

#include "marbler/Error.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace marbler {

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
    const std::int64_t width = std::int64_t(layout.columns) * (layout.cellWidth + layout.gap) + layout.gap;
    const std::int64_t height = std::int64_t(layout.rows) * (layout.cellHeight + layout.gap) + layout.gap;
    if (width > MaxImageSide || height > MaxImageSide || width * height > MaxImagePixels)
        throw InputError("a sheet of " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels is too large");
    layout.width = static_cast<int>(width);
    layout.height = static_cast<int>(height);
    return layout;
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
    if (control && control->progress) control->progress(1.0);
    return sheet;
}

void writeSheet(const std::vector<Genome>& designs, const SheetSettings& settings,
                const std::filesystem::path& file, const RenderControl* control) {
    writeImage(renderSheet(designs, settings, control), file);
}

} // namespace marbler
