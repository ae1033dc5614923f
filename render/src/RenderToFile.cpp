#include "marbler/RenderToFile.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <cmath>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

namespace marbler {
namespace fs = std::filesystem;
namespace {

/// Writes strips on a thread of its own while the caller renders the next one. At most one
/// write is in flight; wait() returns when it is done and rethrows what it threw.
class StripWriter {
public:
    explicit StripWriter(ImageFileWriter& out)
        : mOut(out) {}
    ~StripWriter() {
        if (mThread.joinable()) mThread.join();
    }
    void write(int y0, int y1, const void* rows) {
        wait();
        mThread = std::thread([this, y0, y1, rows] {
            try {
                mOut.writeRows(y0, y1, rows);
            } catch (...) {
                mError = std::current_exception();
            }
        });
    }
    void wait() {
        if (mThread.joinable()) mThread.join();
        if (mError) std::rethrow_exception(std::exchange(mError, nullptr));
    }

private:
    ImageFileWriter& mOut;
    std::thread mThread;
    std::exception_ptr mError;
};

} // namespace

void renderToFile(const Genome& genome, const RenderSettings& settings, const fs::path& file,
                  const ExportOptions& options, const RenderControl* control) {
    checkRenderSettings(genome, settings);
    if (options.dpi && !(*options.dpi > 0.0 && std::isfinite(*options.dpi)))
        throw InputError("dpi must be a positive number");
    CpuRenderer renderer(genome);
    // The image carries the design it shows (GenomeImage.h).
    ExportOptions withGenome = options;
    if (withGenome.genome.empty()) withGenome.genome = serializeGenome(genome);
    ImageFileWriter out(file, settings.width, settings.height, withGenome);
    const bool linear = out.linearFloat();
    const int rows = ImageFileWriter::stripRows(settings.width, settings.height);
    const std::size_t stripValues = std::size_t(rows) * std::size_t(settings.width) * 3;
    // Two strip buffers: one being written while the other is rendered.
    std::vector<std::uint8_t> bytes[2];
    std::vector<float> floats[2];
    for (int b = 0; b < 2; ++b) {
        if (linear)
            floats[b].resize(stripValues);
        else
            bytes[b].resize(stripValues);
    }
    StripWriter writer(out);
    int buffer = 0;
    for (int y0 = 0; y0 < settings.height; y0 += rows, buffer ^= 1) {
        int y1 = std::min(settings.height, y0 + rows);
        RenderControl strip;
        if (control) {
            strip.cancel = control->cancel;
            if (control->progress)
                strip.progress = [&, y0, y1](double f) {
                    control->progress((y0 + f * (y1 - y0)) / settings.height);
                };
        }
        const void* data;
        if (linear) {
            renderer.renderRowsLinear(settings, y0, y1, floats[buffer].data(), &strip);
            data = floats[buffer].data();
        } else {
            renderer.renderRows(settings, y0, y1, bytes[buffer].data(), &strip);
            data = bytes[buffer].data();
        }
        if (control && control->cancelled()) break;
        writer.write(y0, y1, data);
    }
    writer.wait();
    if (control && control->cancelled()) throw Cancelled();
    out.commit();
}

} // namespace marbler
