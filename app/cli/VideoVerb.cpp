// `marbler video`: every frame of a video marbled, the frame as the genome's source image
// (spec/cli.md); written as PNG frames or as a video at the input's frame rate.

#include "cli/Cli.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFile.h"
#include "marbler/SourceDecoder.h"
#include "marbler/Video.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace marbler::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* VideoHelp = R"(usage: marbler video GENOME IN -o OUT [options]

Marbles every frame of the video IN: each frame is the source image of the flat (2D) genome
GENOME (a genome file or a PNG or TIFF image Marbler wrote), rendered as `marbler render` would
render the genome with that frame as its `source`. IN is any video FFmpeg reads. OUT is a folder
of PNG frames (frame-0000.png, frame-0001.png, ..., each carrying the genome) or a video file:
.mp4 (H.264), .webm (VP9), .gif or .webp (animated), at IN's frame rate. Nothing is left behind
unless every frame is written; exit status 0 success, 2 bad usage or bad input, 1 any other
failure.

options:
  -o, --output OUT          the folder or video file to write (required)
  --width W                 width in pixels (default: IN's width); the height keeps the
                            design's aspect
  --aa MODE                 antialiasing: none (default), rgss, quincunx, grid2..grid8,
                            checker4, rooks8; samples are averaged in linear light
  --threads N               worker threads (default: every core)
  --progress                show progress on stderr even when it is not a terminal
  --quiet                   no progress line
  -h, --help                this text
)";

/// Where the frames go: PNG files in a folder, or a video file. Until commit() nothing written
/// stays: a folder this run made is removed, frames this run wrote are removed, a video's
/// temporary is dropped.
class FrameOutput {
public:
    FrameOutput(const fs::path& out, int width, int height, double fps)
        : mOut(out) {
        if (isVideoFile(out)) {
            mVideo = openVideoWriter(out, width, height, fps);
            return;
        }
        std::error_code ec;
        if (fs::exists(out, ec) && !fs::is_directory(out, ec))
            throw InputError("'" + out.string() +
                             "' is a file; OUT is a folder or a .gif, .webp, .mp4 or .webm file");
        if (!fs::exists(out, ec)) {
            if (!fs::create_directories(out, ec) || ec)
                throw RuntimeFailure("cannot create the folder '" + out.string() + "': " + ec.message());
            mMadeFolder = true;
        }
    }

    ~FrameOutput() {
        if (mCommitted) return;
        mVideo.reset();
        std::error_code ec;
        for (const fs::path& file : mWritten)
            fs::remove(file, ec);
        if (mMadeFolder) fs::remove(mOut, ec);
    }

    FrameOutput(const FrameOutput&) = delete;
    FrameOutput& operator=(const FrameOutput&) = delete;

    void add(const Image& image, const ExportOptions& options) {
        if (mVideo) {
            mVideo->addFrame(image.rgb.data(), std::size_t(image.width) * 3);
        } else {
            char name[32];
            std::snprintf(name, sizeof name, "frame-%04d.png", mCount);
            const fs::path file = mOut / name;
            writeImage(image, file, options);
            mWritten.push_back(file);
        }
        ++mCount;
    }

    void commit() {
        if (mVideo) mVideo->finish();
        mCommitted = true;
    }

private:
    fs::path mOut;
    std::unique_ptr<VideoWriter> mVideo;
    std::vector<fs::path> mWritten;
    int mCount = 0;
    bool mMadeFolder = false;
    bool mCommitted = false;
};

int video(std::span<const std::string> words) {
    Args args =
        parseArgs(words, {"o", "output", "width", "aa", "threads"}, {"quiet", "progress", "help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << VideoHelp;
        return ExitOk;
    }
    if (args.positional.size() != 2)
        throw InputError("a genome and a video are expected (got " + std::to_string(args.positional.size()) +
                         " arguments; see marbler video --help)");
    const std::optional<std::string> outArg = requiredOutput(args, "video");
    const fs::path out(*outArg);
    if (!out.extension().empty() && !isVideoFile(out) && !fs::is_directory(out))
        throw InputError("'" + out.string() + "': OUT is a folder or a .gif, .webp, .mp4 or .webm file");

    RenderSettings settings;
    settings.aa = args.get("aa").value_or("none");
    aaPattern(settings.aa);
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);
    const bool hasWidth = args.has("width");
    const int askedWidth = parseIntOption(args, "width", 0, 1, MaxImageSide);

    const std::string genomeName = args.positional[0];
    const Genome genome = loadGenomeArgument("video", genomeName);
    if (genome.dimension != 2)
        throw InputError(genomeName +
                         ": a solid (3D) genome cannot marble a video; video needs a flat (2D) one");
    const fs::path in(args.positional[1]);
    std::unique_ptr<VideoReader> reader = openVideoReader(in);

    // The design's aspect, as `render` keeps it.
    const Region region = effectiveRegion(genome, settings);
    const double aspect = (region.x1 - region.x0) / (region.y1 - region.y0);
    settings.width = hasWidth ? askedWidth : reader->width();
    const double height = std::round(settings.width / aspect);
    if (!(height >= 1.0) || height > MaxImageSide)
        throw InputError("the height for width " + std::to_string(settings.width) + " comes to " +
                         std::to_string(static_cast<long long>(std::min(height, 1e18))) + " pixels");
    settings.height = static_cast<int>(height);

    ExportOptions options;
    options.genome = serializeGenome(genome);
    ProgressLine progress(args);
    FrameOutput output(out, settings.width, settings.height, reader->fps());
    std::vector<std::uint8_t> rgb;
    int frames = 0;
    while (reader->nextFrame(rgb)) {
        LinearRaster source = linearRasterOfSrgb8(rgb.data(), reader->width(), reader->height(),
                                                  std::size_t(reader->width()) * 3);
        output.add(CpuRenderer(genome, std::move(source)).render(settings), options);
        ++frames;
        progress.show("marbling frame " + std::to_string(frames));
    }
    progress.finish();
    if (frames == 0) throw InputError("'" + in.string() + "': holds no frames");
    output.commit();
    return ExitOk;
}

} // namespace

int runVideo(std::span<const std::string> words) {
    return guarded("video", [&] { return video(words); });
}

} // namespace marbler::cli
