#pragma once
/// The CPU renderer: the colour rule of genome-format.md evaluated backward per sample, over
/// tiles of points in structure-of-arrays form, one operation at a time, on every core.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"
#include "marbler/SourceDecoder.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace marbler {

/// Progress and cancellation of long work. Both optional; `progress` receives a fraction in
/// [0, 1] and may be called from worker threads.
struct RenderControl {
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;
    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

/// A genome prepared for rendering (operations in ready form, the source image decoded).
/// Immutable once built, so one instance may render from many threads.
class CpuRenderer {
public:
    /// Throws InputError when the genome's source image cannot be loaded.
    explicit CpuRenderer(const Genome& genome);
    /// Renders a 2D genome with `source` as its source image instead of the one its `source`
    /// names (which is not read): a frame of a video, decoded in memory. Throws InputError
    /// when the raster is empty or its pixels do not match its size.
    CpuRenderer(const Genome& genome, LinearRaster source);
    ~CpuRenderer();
    CpuRenderer(CpuRenderer&&) noexcept;
    CpuRenderer& operator=(CpuRenderer&&) noexcept;

    /// Renders the whole raster. Throws InputError for bad settings (checkRenderSettings),
    /// Cancelled when cancelled.
    Image render(const RenderSettings& settings, const RenderControl* control = nullptr) const;

    /// Renders rows [y0, y1) of the raster into `rgb` ((y1 - y0) * width * 3 bytes).
    void renderRows(const RenderSettings& settings, int y0, int y1, std::uint8_t* rgb,
                    const RenderControl* control = nullptr) const;

    /// As renderRows, in linear light: `rgb` receives (y1 - y0) * width * 3 floats, the
    /// weighted average of the samples before 8-bit encoding (for HDR output such as EXR).
    void renderRowsLinear(const RenderSettings& settings, int y0, int y1, float* rgb,
                          const RenderControl* control = nullptr) const;

    /// What each pixel of rows [y0, y1) is made of (separations, marbler/Separations.h): for
    /// each pixel, palette size + 1 floats, the summed weights of its samples that show the
    /// background (or source image) first, then each ink in palette order; they add up to 1.
    /// The hard colour rule: a genome's `bleed` is not applied.
    void renderRowsCoverage(const RenderSettings& settings, int y0, int y1, float* coverage,
                            const RenderControl* control = nullptr) const;

    /// The palette index seen at one design point (-1: background or source), by the vector
    /// kernel; for tests and picking.
    int colorIndexAt(const glm::dvec3& p) const;

    /// The palette indices seen at `count` design points (z is ignored in 2D), by the vector
    /// kernel: colors[k] for (x[k], y[k], z[k]), -1 for the background or source. For callers
    /// that find their own sample points (an object's surface, shaded by the GL back end on the
    /// CPU). Safe to call from many threads at once.
    /// Both follow the hard colour rule: a genome's `bleed` is not applied (see linearColorsAt).
    void colorIndicesAt(const double* x, const double* y, const double* z, std::size_t count,
                        int* colors) const;

    /// The linear colours seen at `count` design points (z is ignored in 2D): rgb[3k .. 3k+2]
    /// for (x[k], y[k], z[k]), the ink, source or background, with the soft edges of a genome's
    /// `bleed` composited in linear light. Safe to call from many threads at once.
    void linearColorsAt(const double* x, const double* y, const double* z, std::size_t count,
                        double* rgb) const;

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

/// The variant of the CPU renderer's vector kernel in use ("avx512", "avx2" or "baseline") and
/// why: "best this CPU runs", "MARBLER_KERNEL=avx2", or why MARBLER_KERNEL was not followed.
struct CpuKernelInfo {
    std::string name;
    std::string reason;
};
/// The kernel variant this process renders with. The environment variable MARBLER_KERNEL
/// (auto, avx512, avx2, baseline; read on first use) picks one; a name that is unknown or
/// that this CPU cannot run falls back to the best it runs, with the reason saying so.
CpuKernelInfo cpuKernel();
/// The kernel variants this CPU runs, best first.
std::vector<std::string> cpuKernelsSupported();
/// Makes every later render in this process use the variant `name` (for tests); "" goes back to
/// what MARBLER_KERNEL picks, read again. Throws InputError for a name that is not a variant or
/// that this CPU cannot run.
void setCpuKernelForTesting(const std::string& name);

} // namespace marbler
