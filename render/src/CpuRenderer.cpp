#include "marbler/CpuRenderer.h"

#include "ImageData.h"
#include "Kernel.h"
#include "marbler/Error.h"
#include "marbler/Tools.h"

#include <algorithm>
#include <cmath>
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
    std::optional<detail::LinearRaster> source;
    /// The genome's dimension and size only: what the sampling functions read.
    Genome shape;

    /// The source image at a design point, bilinear between pixel centres in linear light,
    /// clamped to the edge pixels inside the design space; the background outside it.
    glm::dvec3 sourceAt(double x, double y) const {
        if (!(x >= 0.0 && x <= size.x && y >= 0.0 && y <= size.y)) return backgroundLinear;
        const detail::LinearRaster& img = *source;
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

    /// Renders rows [y0, y1) on every requested core; `emit(row, linearRgb)` receives each
    /// finished row (width * 3 doubles) from the worker that made it.
    template <typename Emit>
    void renderLinear(const RenderSettings& settings, int y0, int y1, const RenderControl* control,
                      const Emit& emit) const;
};

namespace {

glm::dvec3 linearOf(Color c) {
    return {srgbToLinear(c.r / 255.0), srgbToLinear(c.g / 255.0), srgbToLinear(c.b / 255.0)};
}

void checkRows(const RenderSettings& settings, int y0, int y1) {
    if (y0 < 0 || y1 > settings.height || y0 > y1)
        throw InputError("rows " + std::to_string(y0) + ".." + std::to_string(y1) + " are outside the raster of " +
                         std::to_string(settings.height) + " rows");
}

/// Reports progress from many workers through one lock, at most once per 1/1000 of the work.
class ProgressReporter {
public:
    ProgressReporter(const RenderControl* control, int total) : mControl(control), mTotal(total) {}
    void rowDone() {
        if (!mControl || !mControl->progress) return;
        std::lock_guard lock(mMutex);
        ++mDone;
        int permille = static_cast<int>(std::int64_t(mDone) * 1000 / mTotal);
        if (permille == mLastPermille && mDone != mTotal) return;
        mLastPermille = permille;
        mControl->progress(double(mDone) / mTotal);
    }

private:
    const RenderControl* mControl;
    int mTotal;
    int mDone = 0;
    int mLastPermille = -1;
    std::mutex mMutex;
};

} // namespace

template <typename Emit>
void CpuRenderer::Impl::renderLinear(const RenderSettings& settings, int y0, int y1, const RenderControl* control,
                                     const Emit& emit) const {
    const AaPattern pattern = aaPattern(settings.aa);
    const SampleFrame frame = sampleFrame(shape, settings);
    const int width = settings.width;
    const int samples = static_cast<int>(pattern.offsets.size());
    const int pixelsPerTile = std::max(1, kernel::TileSize / samples);
    const int rows = y1 - y0;
    if (rows <= 0) return;

    int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::clamp(threads, 1, rows);

    std::atomic<int> nextRow{y0};
    std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::mutex failureMutex;
    ProgressReporter progress(control, rows);

    auto worker = [&] {
        try {
            auto tile = std::make_unique<kernel::Tile>();
            std::vector<int> colors(kernel::TileSize);
            std::vector<double> whereX(kernel::TileSize), whereY(kernel::TileSize);
            std::vector<double> line(std::size_t(width) * 3);
            std::vector<glm::dvec3> rowPart(static_cast<std::size_t>(samples));
            const bool useSource = source.has_value();
            for (;;) {
                if (stop.load(std::memory_order_relaxed)) return;
                if (control && control->cancelled()) {
                    stop = true;
                    return;
                }
                int j = nextRow.fetch_add(1);
                if (j >= y1) return;
                // frame.at(i, j, ox, oy) component by component, in the same order of
                // operations (so the same bits), with the row's part computed once per sample.
                for (int s = 0; s < samples; ++s) {
                    const double b = (double(j) + 0.5) + pattern.offsets[s].y;
                    rowPart[s] = b * frame.dv;
                }
                for (int i0 = 0; i0 < width; i0 += pixelsPerTile) {
                    int pixels = std::min(pixelsPerTile, width - i0);
                    int n = 0;
                    for (int p = 0; p < pixels; ++p)
                        for (int s = 0; s < samples; ++s, ++n) {
                            const double a = (double(i0 + p) + 0.5) + pattern.offsets[s].x;
                            tile->x[n] = (frame.origin.x + a * frame.du.x) + rowPart[s].x;
                            tile->y[n] = (frame.origin.y + a * frame.du.y) + rowPart[s].y;
                            tile->z[n] = (frame.origin.z + a * frame.du.z) + rowPart[s].z;
                            tile->id[n] = n;
                        }
                    kernel::traceTile(reversed.data(), reversed.size(), dimension, *tile, n, colors.data(),
                                      useSource ? whereX.data() : nullptr, whereY.data());
                    for (int p = 0, k = 0; p < pixels; ++p) {
                        glm::dvec3 sum(0.0);
                        for (int s = 0; s < samples; ++s, ++k) {
                            int c = colors[k];
                            glm::dvec3 lin = c >= 0 ? paletteLinear[c]
                                             : useSource ? sourceAt(whereX[k], whereY[k])
                                                         : backgroundLinear;
                            sum += pattern.weights[s] * lin;
                        }
                        double* out = line.data() + std::size_t(i0 + p) * 3;
                        out[0] = sum.x;
                        out[1] = sum.y;
                        out[2] = sum.z;
                    }
                }
                emit(j, line.data());
                progress.rowDone();
            }
        } catch (...) {
            std::lock_guard lock(failureMutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
    };

    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    if (control && control->cancelled()) throw Cancelled();
}

CpuRenderer::CpuRenderer(const Genome& genome) : mImpl(std::make_unique<Impl>()) {
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
    for (Color c : genome.palette) mImpl->paletteLinear.push_back(linearOf(c));
    mImpl->backgroundLinear = linearOf(genome.background);
    if (genome.source && genome.dimension == 2)
        mImpl->source = detail::loadSourceImage(*genome.source, genome.baseDirectory);
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

void CpuRenderer::renderRowsLinear(const RenderSettings& settings, int y0, int y1, float* rgb,
                                   const RenderControl* control) const {
    checkRenderSettings(mImpl->shape, settings);
    checkRows(settings, y0, y1);
    const std::size_t stride = std::size_t(settings.width) * 3;
    mImpl->renderLinear(settings, y0, y1, control, [&](int j, const double* line) {
        float* out = rgb + std::size_t(j - y0) * stride;
        for (std::size_t k = 0; k < stride; ++k) out[k] = static_cast<float>(line[k]);
    });
}

int CpuRenderer::colorIndexAt(const glm::dvec3& p) const {
    auto tile = std::make_unique<kernel::Tile>();
    tile->x[0] = p.x;
    tile->y[0] = p.y;
    tile->z[0] = mImpl->dimension == 3 ? p.z : 0.0;
    tile->id[0] = 0;
    int color = -1;
    kernel::traceTile(mImpl->reversed.data(), mImpl->reversed.size(), mImpl->dimension, *tile, 1, &color, nullptr,
                      nullptr);
    return color;
}

} // namespace marbler
