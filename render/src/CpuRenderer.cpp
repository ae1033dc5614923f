#include "marbler/CpuRenderer.h"

#include "Kernel.h"
#include "SprayGrid.h"
#include "marbler/Error.h"
#include "marbler/SourceDecoder.h"
#include "marbler/Threads.h"
#include "marbler/Tools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>

namespace marbler {

struct CpuRenderer::Impl {
    int dimension = 2;
    glm::dvec3 size{1000.0};
    std::vector<PreparedOp> reversed; ///< operations in the order the colour rule visits them
    std::vector<glm::dvec3> paletteLinear;
    glm::dvec3 backgroundLinear{0.0};
    /// encodeSrgb8 of paletteLinear and backgroundLinear.
    std::vector<std::array<std::uint8_t, 3>> paletteSrgb8;
    std::array<std::uint8_t, 3> backgroundSrgb8{};
    std::optional<LinearRaster> source;
    double bleed = 0.0; ///< the genome's soft ink edges (0: hard)
    /// A wrapping bath's many sprays, binned (SprayGrid.h); null for other designs.
    std::shared_ptr<const kernel::SprayGrid> sprayGrid;
    /// The genome's dimension and size only: what the sampling functions read.
    Genome shape;

    /// The source image at a design point, bilinear between pixel centres in linear light,
    /// clamped to the edge pixels inside the design space; the background outside it.
    glm::dvec3 sourceAt(double x, double y) const {
        if (!(x >= 0.0 && x <= size.x && y >= 0.0 && y <= size.y)) return backgroundLinear;
        const LinearRaster& img = *source;
        double u = x * img.width / size.x - 0.5, v = y * img.height / size.y - 0.5;
        double fu = std::floor(u), fv = std::floor(v);
        double tu = u - fu, tv = v - fv;
        auto clampIndex = [](double i, int n) { return static_cast<int>(std::clamp(i, 0.0, double(n - 1))); };
        int i0 = clampIndex(fu, img.width), i1 = clampIndex(fu + 1.0, img.width);
        int j0 = clampIndex(fv, img.height), j1 = clampIndex(fv + 1.0, img.height);
        auto at = [&](int i, int j) {
            const float* p = img.rgb.data() + (std::size_t(j) * std::size_t(img.width) + std::size_t(i)) * 3;
            return glm::dvec3(p[0], p[1], p[2]);
        };
        glm::dvec3 top = at(i0, j0) * (1.0 - tu) + at(i1, j0) * tu;
        glm::dvec3 bottom = at(i0, j1) * (1.0 - tu) + at(i1, j1) * tu;
        return top * (1.0 - tv) + bottom * tv;
    }

    /// The samples of one tile, traced: colors[k] is sample k's palette index (-1: none); with a
    /// source image, whereX[k], whereY[k] is where a sample without ink mapped back to.
    struct Traced {
        const int* colors;
        const double* whereX;
        const double* whereY;
        /// Under bleed (else null): per sample the weight of what lies beneath its inks, and
        /// the linear colour they add (kernel::Bleed).
        const double* weight = nullptr;
        const double* rgb = nullptr;
    };

    /// The linear colour a traced sample shows: its ink, else the source image where it mapped
    /// back to, else the background; under bleed, the inks it met over that.
    glm::dvec3 linearAt(const Traced& t, int k) const {
        const int c = t.colors[k];
        if (t.weight) {
            const double* inks = t.rgb + 3 * std::size_t(k);
            glm::dvec3 sum(inks[0], inks[1], inks[2]);
            const double w = t.weight[k];
            if (w > 0.0) sum += w * (source ? sourceAt(t.whereX[k], t.whereY[k]) : backgroundLinear);
            return sum;
        }
        return c >= 0   ? paletteLinear[std::size_t(c)]
               : source ? sourceAt(t.whereX[k], t.whereY[k])
                        : backgroundLinear;
    }

    /// The kernel's bleed record for a tile's outputs, or null when the genome has no bleed.
    std::optional<kernel::Bleed> bleedFor(double* weight, double* rgb) const {
        if (!(bleed > 0.0)) return std::nullopt;
        return kernel::Bleed{bleed, paletteLinear.data(), weight, rgb};
    }

    /// Traces rows [y0, y1) on every requested core, one tile at a time: a run of pixels of one
    /// row with all their samples, pixel by pixel, left to right. Each worker gets its own
    /// shader from `makeShader()`; `shade(row, i0, pixels, traced)` turns a traced tile into
    /// pixels i0 .. i0 + pixels - 1 of the row.
    /// With `hardEdges`, a genome's bleed is not applied: colors[k] follows the hard rule.
    template <typename MakeShader>
    void traceRows(const RenderSettings& settings, int y0, int y1, const RenderControl* control,
                   const MakeShader& makeShader, bool hardEdges = false) const;

    /// Renders rows [y0, y1) in linear light; `emit(row, linearRgb)` receives each finished row
    /// (width * 3 doubles, the weighted average of its samples) from the worker that made it.
    template <typename Emit>
    void renderLinear(const RenderSettings& settings, int y0, int y1, const RenderControl* control,
                      const Emit& emit) const;
};

namespace {

void checkRows(const RenderSettings& settings, int y0, int y1) {
    if (y0 < 0 || y1 > settings.height || y0 > y1)
        throw InputError("rows " + std::to_string(y0) + ".." + std::to_string(y1) +
                         " are outside the raster of " + std::to_string(settings.height) + " rows");
}

} // namespace

template <typename MakeShader>
void CpuRenderer::Impl::traceRows(const RenderSettings& settings, int y0, int y1,
                                  const RenderControl* control, const MakeShader& makeShader,
                                  bool hardEdges) const {
    const AaPattern pattern = aaPattern(settings.aa);
    const SampleFrame frame = sampleFrame(shape, settings);
    const int width = settings.width;
    const int samples = static_cast<int>(pattern.offsets.size());
    const int pixelsPerTile = std::max(1, kernel::TileSize / samples);
    const int rows = y1 - y0;
    if (rows <= 0) return;

    RowLoop rowLoop(y0, y1, settings.threads, control);
    auto worker = [&] {
        auto tile = std::make_unique<kernel::Tile>();
        std::vector<int> colors(kernel::TileSize);
        std::vector<double> whereX(kernel::TileSize), whereY(kernel::TileSize);
        std::vector<double> weight(bleed > 0.0 && !hardEdges ? kernel::TileSize : 0), rgb(weight.size() * 3);
        const std::optional<kernel::Bleed> layers =
            hardEdges ? std::nullopt : bleedFor(weight.data(), rgb.data());
        const Traced traced{colors.data(), whereX.data(), whereY.data(), layers ? weight.data() : nullptr,
                            layers ? rgb.data() : nullptr};
        std::vector<glm::dvec3> rowPart(static_cast<std::size_t>(samples));
        auto shade = makeShader();
        for (int j; rowLoop.next(j);) {
            // frame.at(i, j, ox, oy) component by component, in the same order of
            // operations (so the same bits), with the row's part computed once per sample.
            for (int s = 0; s < samples; ++s) {
                const double b = (double(j) + 0.5) + pattern.offsets[s].y;
                rowPart[s] = b * frame.dv;
            }
            for (int i0 = 0; i0 < width; i0 += pixelsPerTile) {
                const int pixels = std::min(pixelsPerTile, width - i0);
                for (int s = 0; s < samples; ++s) {
                    // One sample of every pixel at a time: a plain strided loop.
                    const double ox = pattern.offsets[s].x;
                    const glm::dvec3 rp = rowPart[s];
                    for (int p = 0, n = s; p < pixels; ++p, n += samples) {
                        const double a = (double(i0 + p) + 0.5) + ox;
                        tile->x[n] = (frame.origin.x + a * frame.du.x) + rp.x;
                        tile->y[n] = (frame.origin.y + a * frame.du.y) + rp.y;
                        // 2D kernels never read z.
                        if (dimension == 3) tile->z[n] = (frame.origin.z + a * frame.du.z) + rp.z;
                    }
                }
                const int n = pixels * samples;
                for (int k = 0; k < n; ++k)
                    tile->id[k] = k;
                if (sprayGrid) {
                    // The operations before the sprays in the kernel, the sprays by their grid.
                    kernel::traceTile(reversed.data(), sprayGrid->first, dimension, *tile, n, colors.data(),
                                      whereX.data(), whereY.data(), layers ? &*layers : nullptr);
                    kernel::traceSprays(*sprayGrid, n, colors.data(), whereX.data(), whereY.data(),
                                        layers ? &*layers : nullptr);
                } else {
                    kernel::traceTile(reversed.data(), reversed.size(), dimension, *tile, n, colors.data(),
                                      source ? whereX.data() : nullptr, whereY.data(),
                                      layers ? &*layers : nullptr);
                }
                shade(j, i0, pixels, traced);
            }
            rowLoop.done();
        }
    };
    rowLoop.run(worker);
}

template <typename Emit>
void CpuRenderer::Impl::renderLinear(const RenderSettings& settings, int y0, int y1,
                                     const RenderControl* control, const Emit& emit) const {
    const AaPattern pattern = aaPattern(settings.aa);
    const int samples = static_cast<int>(pattern.offsets.size());
    const int width = settings.width;
    traceRows(settings, y0, y1, control, [&] {
        // A worker traces each of its rows whole, left to right, into its own row buffer.
        return [&, line = std::vector<double>(std::size_t(width) * 3)](int j, int i0, int pixels,
                                                                       const Traced& traced) mutable {
            for (int p = 0, k = 0; p < pixels; ++p) {
                glm::dvec3 sum(0.0);
                for (int s = 0; s < samples; ++s, ++k)
                    sum += pattern.weights[s] * linearAt(traced, k);
                double* out = line.data() + std::size_t(i0 + p) * 3;
                out[0] = sum.x;
                out[1] = sum.y;
                out[2] = sum.z;
            }
            if (i0 + pixels == width) emit(j, line.data());
        };
    });
}

CpuRenderer::CpuRenderer(const Genome& genome)
    : mImpl(std::make_unique<Impl>()) {
    mImpl->dimension = genome.dimension;
    mImpl->size = genome.size;
    mImpl->shape.dimension = genome.dimension;
    mImpl->shape.size = genome.size;
    mImpl->reversed = prepare(genome);
    std::reverse(mImpl->reversed.begin(), mImpl->reversed.end());
    for (const PreparedOp& op : mImpl->reversed)
        if (op.color >= static_cast<int>(genome.palette.size()))
            throw InputError("colour index " + std::to_string(op.color) + " is outside the palette of " +
                             std::to_string(genome.palette.size()) + " inks");
    for (Color c : genome.palette)
        mImpl->paletteLinear.push_back(linearOf(c));
    mImpl->backgroundLinear = linearOf(genome.background);
    auto encode = [](const glm::dvec3& v) {
        return std::array<std::uint8_t, 3>{encodeSrgb8(v.x), encodeSrgb8(v.y), encodeSrgb8(v.z)};
    };
    for (const glm::dvec3& v : mImpl->paletteLinear)
        mImpl->paletteSrgb8.push_back(encode(v));
    mImpl->backgroundSrgb8 = encode(mImpl->backgroundLinear);
    if (genome.source && genome.dimension == 2) mImpl->source = decodeSourceImage(genome);
    mImpl->bleed = genome.bleed;
    mImpl->sprayGrid = kernel::makeSprayGrid(mImpl->reversed, genome.bleed);
}

namespace {

Genome withoutSource(Genome genome) {
    genome.source.reset();
    return genome;
}

} // namespace

CpuRenderer::CpuRenderer(const Genome& genome, LinearRaster source)
    : CpuRenderer(withoutSource(genome)) {
    if (source.width < 1 || source.height < 1 ||
        source.rgb.size() != std::size_t(source.width) * std::size_t(source.height) * 3)
        throw InputError("a source image of " + std::to_string(source.width) + " x " +
                         std::to_string(source.height) + " pixels with " + std::to_string(source.rgb.size()) +
                         " values");
    if (genome.dimension == 2) mImpl->source = std::move(source);
}

CpuRenderer::~CpuRenderer() = default;
CpuRenderer::CpuRenderer(CpuRenderer&&) noexcept = default;
CpuRenderer& CpuRenderer::operator=(CpuRenderer&&) noexcept = default;

Image CpuRenderer::render(const RenderSettings& settings, const RenderControl* control) const {
    checkRenderSettings(mImpl->shape, settings);
    Image image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.resize(std::size_t(settings.width) * std::size_t(settings.height) * 3);
    renderRows(settings, 0, settings.height, image.rgb.data(), control);
    return image;
}

void CpuRenderer::renderRows(const RenderSettings& settings, int y0, int y1, std::uint8_t* rgb,
                             const RenderControl* control) const {
    checkRenderSettings(mImpl->shape, settings);
    checkRows(settings, y0, y1);
    const std::size_t stride = std::size_t(settings.width) * 3;
    const AaPattern pattern = aaPattern(settings.aa);
    if (pattern.offsets.size() == 1 && pattern.weights[0] == 1.0 && !(mImpl->bleed > 0.0)) {
        // One sample of weight 1 is its own average (0 + 1 x is x, bit for bit), so an ink's or
        // the background's 8-bit code comes from a table made once instead of being averaged
        // and encoded per pixel (not under bleed, whose samples blend inks).
        const Impl& impl = *mImpl;
        impl.traceRows(settings, y0, y1, control, [&] {
            return [&](int j, int i0, int pixels, const Impl::Traced& traced) {
                std::uint8_t* out = rgb + std::size_t(j - y0) * stride + std::size_t(i0) * 3;
                for (int p = 0; p < pixels; ++p, out += 3) {
                    const int c = traced.colors[p];
                    if (c >= 0 || !impl.source) {
                        const std::uint8_t* code =
                            c >= 0 ? impl.paletteSrgb8[std::size_t(c)].data() : impl.backgroundSrgb8.data();
                        out[0] = code[0];
                        out[1] = code[1];
                        out[2] = code[2];
                    } else {
                        const glm::dvec3 lin = impl.sourceAt(traced.whereX[p], traced.whereY[p]);
                        out[0] = encodeSrgb8(lin.x);
                        out[1] = encodeSrgb8(lin.y);
                        out[2] = encodeSrgb8(lin.z);
                    }
                }
            };
        });
        return;
    }
    mImpl->renderLinear(settings, y0, y1, control, [&](int j, const double* line) {
        std::uint8_t* out = rgb + std::size_t(j - y0) * stride;
        // Neighbouring pixels mostly share their colour: encode a channel again only when it
        // changes (NaN never equals itself, so the first pixel is always encoded).
        double last[3] = {std::nan(""), std::nan(""), std::nan("")};
        std::uint8_t code[3] = {0, 0, 0};
        for (std::size_t k = 0; k < stride; k += 3)
            for (std::size_t c = 0; c < 3; ++c) {
                const double v = line[k + c];
                if (!(v == last[c])) {
                    last[c] = v;
                    code[c] = encodeSrgb8(v);
                }
                out[k + c] = code[c];
            }
    });
}

void CpuRenderer::renderRowsCoverage(const RenderSettings& settings, int y0, int y1, float* coverage,
                                     const RenderControl* control) const {
    checkRenderSettings(mImpl->shape, settings);
    checkRows(settings, y0, y1);
    const AaPattern pattern = aaPattern(settings.aa);
    const int samples = static_cast<int>(pattern.offsets.size());
    const std::size_t channels = mImpl->paletteLinear.size() + 1;
    const std::size_t stride = std::size_t(settings.width) * channels;
    std::fill(coverage, coverage + std::size_t(y1 - y0) * stride, 0.0f);
    mImpl->traceRows(
        settings, y0, y1, control,
        [&] {
            return [&](int j, int i0, int pixels, const Impl::Traced& traced) {
                float* out = coverage + std::size_t(j - y0) * stride + std::size_t(i0) * channels;
                for (int p = 0, k = 0; p < pixels; ++p, out += channels)
                    for (int s = 0; s < samples; ++s, ++k)
                        out[std::size_t(traced.colors[k] + 1)] += static_cast<float>(pattern.weights[s]);
            };
        },
        true);
}

void CpuRenderer::renderRowsLinear(const RenderSettings& settings, int y0, int y1, float* rgb,
                                   const RenderControl* control) const {
    checkRenderSettings(mImpl->shape, settings);
    checkRows(settings, y0, y1);
    const std::size_t stride = std::size_t(settings.width) * 3;
    mImpl->renderLinear(settings, y0, y1, control, [&](int j, const double* line) {
        float* out = rgb + std::size_t(j - y0) * stride;
        for (std::size_t k = 0; k < stride; ++k)
            out[k] = static_cast<float>(line[k]);
    });
}

CpuKernelInfo cpuKernel() {
    kernel::Choice choice = kernel::activeChoice();
    return {kernel::variantName(choice.variant), choice.reason};
}

std::vector<std::string> cpuKernelsSupported() {
    std::vector<std::string> names;
    for (kernel::Variant v : kernel::supportedVariants())
        names.emplace_back(kernel::variantName(v));
    return names;
}

void setCpuKernelForTesting(const std::string& name) {
    if (name.empty()) {
        kernel::setActiveChoice(kernel::chooseVariant(std::getenv("MARBLER_KERNEL")));
        return;
    }
    std::optional<kernel::Variant> v = kernel::variantNamed(name);
    if (!v) throw InputError("'" + name + "' is not a CPU kernel variant (avx512, avx2, baseline)");
    if (!kernel::cpuRuns(*v)) throw InputError("this CPU cannot run the " + name + " kernel");
    kernel::setActiveChoice({*v, "set for testing"});
}

int CpuRenderer::colorIndexAt(const glm::dvec3& p) const {
    auto tile = std::make_unique<kernel::Tile>();
    tile->x[0] = p.x;
    tile->y[0] = p.y;
    tile->z[0] = mImpl->dimension == 3 ? p.z : 0.0;
    tile->id[0] = 0;
    int color = -1;
    kernel::traceTile(mImpl->reversed.data(), mImpl->reversed.size(), mImpl->dimension, *tile, 1, &color,
                      nullptr, nullptr);
    return color;
}

namespace {

/// The first `n` points of a tile from caller's arrays; `z` null for 2D (the kernel reads none).
void loadTile(kernel::Tile& tile, const double* x, const double* y, const double* z, int n) {
    for (int k = 0; k < n; ++k) {
        tile.x[k] = x[k];
        tile.y[k] = y[k];
        tile.z[k] = z ? z[k] : 0.0;
        tile.id[k] = k;
    }
}

} // namespace

void CpuRenderer::colorIndicesAt(const double* x, const double* y, const double* z, std::size_t count,
                                 int* colors) const {
    auto tile = std::make_unique<kernel::Tile>();
    const bool solid = mImpl->dimension == 3;
    for (std::size_t first = 0; first < count; first += kernel::TileSize) {
        const int n = static_cast<int>(std::min<std::size_t>(kernel::TileSize, count - first));
        loadTile(*tile, x + first, y + first, solid ? z + first : nullptr, n);
        kernel::traceTile(mImpl->reversed.data(), mImpl->reversed.size(), mImpl->dimension, *tile, n,
                          colors + first, nullptr, nullptr);
    }
}

void CpuRenderer::linearColorsAt(const double* x, const double* y, const double* z, std::size_t count,
                                 double* rgb) const {
    const Impl& impl = *mImpl;
    auto tile = std::make_unique<kernel::Tile>();
    const bool solid = impl.dimension == 3;
    std::vector<int> colors(kernel::TileSize);
    std::vector<double> whereX(kernel::TileSize), whereY(kernel::TileSize);
    std::vector<double> weight(kernel::TileSize), inks(std::size_t(kernel::TileSize) * 3);
    const std::optional<kernel::Bleed> layers = impl.bleedFor(weight.data(), inks.data());
    const Impl::Traced traced{colors.data(), whereX.data(), whereY.data(), layers ? weight.data() : nullptr,
                              layers ? inks.data() : nullptr};
    for (std::size_t first = 0; first < count; first += kernel::TileSize) {
        const int n = static_cast<int>(std::min<std::size_t>(kernel::TileSize, count - first));
        loadTile(*tile, x + first, y + first, solid ? z + first : nullptr, n);
        kernel::traceTile(impl.reversed.data(), impl.reversed.size(), impl.dimension, *tile, n, colors.data(),
                          impl.source ? whereX.data() : nullptr, whereY.data(), layers ? &*layers : nullptr);
        for (int k = 0; k < n; ++k) {
            const glm::dvec3 c = impl.linearAt(traced, k);
            double* out = rgb + 3 * (first + std::size_t(k));
            out[0] = c.x;
            out[1] = c.y;
            out[2] = c.z;
        }
    }
}

} // namespace marbler
