// Video and animated-image files (marbler/Video.h): the formats by extension, the temporary file
// renamed on finish; FFmpeg itself is in the module marbler-video.so, loaded on first use.

#include "VideoModule.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/ImageFormats.h"
#include "marbler/Modules.h"
#include "marbler/Sampling.h"
#include "marbler/SourceDecoder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <system_error>

namespace marbler {
namespace fs = std::filesystem;

namespace detail {

VideoModule& videoModule() {
    static VideoModule* module = [] {
        auto entry = reinterpret_cast<VideoModule* (*)()>(moduleEntry(VideoModuleFile, VideoModuleEntry));
        return entry();
    }();
    return *module;
}

} // namespace detail

namespace {

/// The largest side and the most frames a second a writer accepts.
constexpr int MaxVideoSide = 16384;
constexpr double MaxVideoFps = 1000.0;

/// The module's writer on a temporary name beside the target (an AtomicFile), renamed over the
/// target by finish(); destroyed unfinished, it leaves nothing behind.
class AtomicVideoWriter final : public VideoWriter {
public:
    AtomicVideoWriter(const fs::path& file, int width, int height, double fps)
        : mFile(file) {
        detail::VideoTarget target{
            mFile.temporary().string(), lowerExtension(file), file.string(), width, height, fps};
        mWriter = detail::videoModule().openWriter(target);
    }

    ~AtomicVideoWriter() override {
        mWriter.reset(); // closes the file before the AtomicFile removes it
    }

    void addFrame(const std::uint8_t* rgb, std::size_t stride) override {
        if (!mWriter) throw RuntimeFailure("'" + mFile.target().string() + "': a frame added after finish()");
        mWriter->addFrame(rgb, stride);
    }

    void finish() override {
        if (!mWriter) throw RuntimeFailure("'" + mFile.target().string() + "': finished twice");
        mWriter->finish();
        mWriter.reset();
        mFile.commit();
    }

private:
    AtomicFile mFile; // before mWriter: destroyed after it, so the writer closes the file first
    std::unique_ptr<VideoWriter> mWriter;
};

} // namespace

bool isVideoFile(const fs::path& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".gif" || extension == ".webp" || extension == ".mp4" || extension == ".webm";
}

std::unique_ptr<VideoWriter> openVideoWriter(const fs::path& path, int width, int height, double fps) {
    if (!isVideoFile(path))
        throw InputError("'" + path.string() +
                         "': not a video format Marbler writes (use .gif, .webp, .mp4 or .webm)");
    if (width < 1 || height < 1 || width > MaxVideoSide || height > MaxVideoSide)
        throw InputError("'" + path.string() + "': a video of " + std::to_string(width) + " x " +
                         std::to_string(height) + " pixels (each side from 1 to " +
                         std::to_string(MaxVideoSide) + ")");
    if (!(fps > 0.0) || !(fps <= MaxVideoFps))
        throw InputError("'" + path.string() + "': a frame rate of " + std::to_string(fps) +
                         " (it must be above 0 and at most " + std::to_string(static_cast<int>(MaxVideoFps)) +
                         ")");
    return std::make_unique<AtomicVideoWriter>(path, width, height, fps);
}

std::unique_ptr<VideoReader> openVideoReader(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw InputError("'" + path.string() + "': no such file");
    return detail::videoModule().openReader(path.string(), "'" + path.string() + "'");
}

} // namespace marbler
