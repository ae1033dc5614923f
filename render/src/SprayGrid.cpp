#include "SprayGrid.h"

#include "Kernel.h"

#include <algorithm>
#include <cmath>

namespace marbler::kernel {

std::shared_ptr<const SprayGrid> makeSprayGrid(const std::vector<PreparedOp>& reversed, double bleed) {
    // The run of sprays at the end of the reversed operations (the initial drops).
    std::size_t first = reversed.size();
    while (first > 0 && reversed[first - 1].tool == Tool::Spray && reversed[first - 1].dimension == 2)
        --first;
    const std::size_t count = reversed.size() - first;
    // Below a few dozen sprays the kernel's pass over them costs no more.
    if (count < 32 || !(reversed.back().wrap.x > 0.0)) return nullptr;
    auto grid = std::make_shared<SprayGrid>();
    grid->first = first;
    grid->width = reversed.back().wrap.x;
    grid->height = reversed.back().wrap.y;
    grid->shift = reversed.back().wrapShift;
    const bool lattice = grid->shift.x > 0.0 || grid->shift.y > 0.0;
    // About four cells a spray, at most 256 a side.
    const double cell = std::sqrt(grid->width * grid->height / (4.0 * double(count)));
    grid->cols = std::clamp(static_cast<int>(std::ceil(grid->width / cell)), 1, 256);
    grid->rows = std::clamp(static_cast<int>(std::ceil(grid->height / cell)), 1, 256);
    grid->cellWidth = grid->width / grid->cols;
    grid->cellHeight = grid->height / grid->rows;
    std::vector<std::vector<std::uint32_t>> cells(std::size_t(grid->cols) * std::size_t(grid->rows));
    // Where a disc's coverage ends (r + b / 2), and a little more for the rounding of the
    // points' distances: a spray left out of a cell must cover none of its points.
    const double slack = 1e-9 * (grid->width + grid->height);
    for (std::size_t k = first; k < reversed.size(); ++k) {
        const PreparedOp& op = reversed[k];
        const auto index = static_cast<std::uint32_t>(grid->sprays.size());
        grid->sprays.push_back({op.c.x, op.c.y, op.r, op.r * op.r, op.color});
        const double reach = op.r + 0.5 * std::max(bleed, 0.0) + slack;
        auto span = [](double c, double reach, double cellSize, int cells) {
            long lo = static_cast<long>(std::floor((c - reach) / cellSize));
            long hi = static_cast<long>(std::floor((c + reach) / cellSize));
            if (hi - lo + 1 >= cells) return std::pair<long, long>{0, cells - 1};
            return std::pair<long, long>{lo, hi};
        };
        if (lattice) {
            // Half-drop or brick: every image C + i A + j B whose square of side 2 reach meets the
            // tile adds the cells it covers there (each cell once).
            auto add = [&](double x, double y) {
                if (x + reach < 0.0 || x - reach >= grid->width || y + reach < 0.0 ||
                    y - reach >= grid->height)
                    return;
                const long c0 = std::max(0L, static_cast<long>(std::floor((x - reach) / grid->cellWidth)));
                const long c1 = std::min(long(grid->cols - 1),
                                         static_cast<long>(std::floor((x + reach) / grid->cellWidth)));
                const long r0 = std::max(0L, static_cast<long>(std::floor((y - reach) / grid->cellHeight)));
                const long r1 = std::min(long(grid->rows - 1),
                                         static_cast<long>(std::floor((y + reach) / grid->cellHeight)));
                for (long r = r0; r <= r1; ++r)
                    for (long c = c0; c <= c1; ++c) {
                        auto& list = cells[std::size_t(r) * std::size_t(grid->cols) + std::size_t(c)];
                        if (list.empty() || list.back() != index) list.push_back(index);
                    }
            };
            const bool brick = grid->shift.x > 0.0;
            // Columns (half-drop) or rows (brick) i, then the images along them j.
            const double along = brick ? grid->height : grid->width,
                         across = brick ? grid->width : grid->height;
            const double ca = brick ? op.c.y : op.c.x, cb = brick ? op.c.x : op.c.y;
            const double drop = brick ? grid->shift.x : grid->shift.y;
            const long iLo = static_cast<long>(std::floor((-reach - ca) / along)) - 1;
            const long iHi = static_cast<long>(std::ceil((along + reach - ca) / along)) + 1;
            for (long i = iLo; i <= iHi; ++i) {
                const double b = cb + double(i) * drop;
                const long jLo = static_cast<long>(std::floor((-reach - b) / across)) - 1;
                const long jHi = static_cast<long>(std::ceil((across + reach - b) / across)) + 1;
                for (long j = jLo; j <= jHi; ++j) {
                    const double a = ca + double(i) * along, bj = b + double(j) * across;
                    if (brick)
                        add(bj, a);
                    else
                        add(a, bj);
                }
            }
            continue;
        }
        const auto [c0, c1] = span(op.c.x, reach, grid->cellWidth, grid->cols);
        const auto [r0, r1] = span(op.c.y, reach, grid->cellHeight, grid->rows);
        for (long r = r0; r <= r1; ++r)
            for (long c = c0; c <= c1; ++c) {
                const long col = ((c % grid->cols) + grid->cols) % grid->cols;
                const long row = ((r % grid->rows) + grid->rows) % grid->rows;
                cells[std::size_t(row) * std::size_t(grid->cols) + std::size_t(col)].push_back(index);
            }
    }
    grid->start.reserve(cells.size() + 1);
    for (const std::vector<std::uint32_t>& list : cells) {
        grid->start.push_back(static_cast<std::uint32_t>(grid->items.size()));
        grid->items.insert(grid->items.end(), list.begin(), list.end());
    }
    grid->start.push_back(static_cast<std::uint32_t>(grid->items.size()));
    return grid;
}

void traceSprays(const SprayGrid& grid, int n, int* colors, const double* whereX, const double* whereY,
                 const Bleed* bleed) {
    const double w = grid.width, h = grid.height, hw = 0.5 * w, hh = 0.5 * h;
    const bool lattice = grid.shift.x > 0.0 || grid.shift.y > 0.0;
    const glm::dvec2 size(w, h);
    for (int k = 0; k < n; ++k) {
        if (colors[k] >= 0) continue; // stopped on an ink before the sprays
        // The kernel leaves points wrapped (after a stretch, or at the start); wrapping again
        // changes no bit of a wrapped coordinate.
        double px = whereX[k] - w * std::floor(whereX[k] / w);
        double py = whereY[k] - h * std::floor(whereY[k] / h);
        if (lattice) {
            const glm::dvec2 q = wrapPoint(whereX[k], whereY[k], size, grid.shift);
            px = q.x;
            py = q.y;
        }
        const int col = std::clamp(static_cast<int>(px / grid.cellWidth), 0, grid.cols - 1);
        const int row = std::clamp(static_cast<int>(py / grid.cellHeight), 0, grid.rows - 1);
        const std::size_t cell = std::size_t(row) * std::size_t(grid.cols) + std::size_t(col);
        double weight = 1.0, red = 0.0, green = 0.0, blue = 0.0;
        if (bleed) {
            weight = bleed->weight[k];
            red = bleed->rgb[3 * k];
            green = bleed->rgb[3 * k + 1];
            blue = bleed->rgb[3 * k + 2];
        }
        for (std::uint32_t at = grid.start[cell]; at < grid.start[cell + 1]; ++at) {
            const SprayGrid::Spray& s = grid.sprays[grid.items[at]];
            double dx = px - s.cx, dy = py - s.cy;
            if (lattice) {
                const glm::dvec2 d = nearestImage(glm::dvec2(dx, dy), size, grid.shift);
                dx = d.x;
                dy = d.y;
            } else {
                dx = dx > hw ? dx - w : (dx < -hw ? dx + w : dx);
                dy = dy > hh ? dy - h : (dy < -hh ? dy + h : dy);
            }
            const double len2 = dx * dx + dy * dy;
            if (!bleed) {
                if (len2 < s.rr) {
                    colors[k] = s.color;
                    break;
                }
                continue;
            }
            // Kernel.cpp bleedInk, in its order of operations.
            const double e = std::sqrt(len2) - s.r;
            const double c = std::clamp(0.5 - e / bleed->width, 0.0, 1.0);
            const double wc = weight * c;
            const glm::dvec3& ink = bleed->palette[s.color];
            red = red + wc * ink.x;
            green = green + wc * ink.y;
            blue = blue + wc * ink.z;
            weight = weight - wc;
            if (c >= 1.0) {
                colors[k] = s.color;
                weight = 0.0;
                break;
            }
        }
        if (bleed) {
            bleed->weight[k] = weight;
            bleed->rgb[3 * k] = red;
            bleed->rgb[3 * k + 1] = green;
            bleed->rgb[3 * k + 2] = blue;
        }
    }
}

} // namespace marbler::kernel
