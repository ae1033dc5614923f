// `marbler animate`: the making of a design (genome-format.md, "The making of a design") as a
// folder of PNG frames or a video (spec/cli.md).

#include "cli/Cli.h"
#include "marbler/Animation.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/Growth.h"
#include "marbler/Sampling.h"
#include "marbler/Video.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace marbler::cli {
namespace {

constexpr const char* AnimateHelp = R"(usage: marbler animate GENOME -o OUT [options]

Renders the making of a design: its steps (the entries of "initial", then of "operations") one
after another, each growing in (an ink's area, a stroke's shift). Frame f of N shows the first
k f / (N - 1) steps of the design's k, the last one in part: frame 0 is the bare bath, the last
frame the whole design, equal to `marbler render` at the same size. GENOME is a genome file or a
PNG or TIFF image Marbler wrote. Nothing is left at OUT unless every frame is written; exit
status 0 success, 2 bad usage or bad input, 1 any other failure.

OUT is a folder of PNG frames, frame-0000.png, frame-0001.png, ... (made; it may exist only as an
empty folder), or a video or animated image by its extension: .gif, .webp, .mp4 or .webm. Each
PNG frame carries the partial design it shows (not the whole one), so opening or rendering a
frame gives that frame exactly; the last frame carries the whole design.

options:
  -o, --output OUT          the folder or video file to write (required)
  --frames N                number of frames, at least 2 (default: 4 seconds at the frame rate)
  --fps F                   frames a second of a video (default 25)
  --width W                 width in pixels; alone, the height keeps the design's aspect
  --height H                height in pixels; alone, the width keeps the design's aspect
                            (default: 512 pixels on the longer side)
  --aa MODE                 antialiasing: none (default), rgss, quincunx, grid2..grid8,
                            checker4, rooks8
  --slice AXIS=VALUE        the cross-section of a solid (3D) genome to show, e.g. z=500;
                            required in 3D
  --threads N               worker threads (default: every core)
  --allow-external-source   read the genome's source image even where it lies outside the
                            genome's folder
  --progress                show progress on stderr even when it is not a terminal
  --quiet                   no progress line
  -h, --help                this text
)";

/// Set by SIGINT and SIGTERM while frames are rendered; the render stops and OUT stays untouched.
std::atomic<bool> gInterrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void onInterrupt(int) {
    gInterrupted.store(true);
}

/// Catches Ctrl-C (and SIGTERM) for its lifetime, so that the temporary output is removed.
class InterruptGuard {
public:
    InterruptGuard() {
        gInterrupted.store(false);
        mInt = std::signal(SIGINT, onInterrupt);
        mTerm = std::signal(SIGTERM, onInterrupt);
    }
    ~InterruptGuard() {
        std::signal(SIGINT, mInt);
        std::signal(SIGTERM, mTerm);
    }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void (*mInt)(int);
    void (*mTerm)(int);
};

int animateGenome(const Args& args, const std::string& genomeName, const Genome& genome,
                  RenderSettings settings, const std::filesystem::path& out, double fps, int frames,
                  int width, int height);

int animate(std::span<const std::string> words) {
    Args args =
        parseArgs(words, {"o", "output", "frames", "fps", "width", "height", "aa", "slice", "threads"},
                  {"quiet", "progress", "allow-external-source", "help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << AnimateHelp;
        return ExitOk;
    }
    oneGenomeArgument(args, "animate");
    const std::optional<std::string> output = requiredOutput(args, "animate", "OUT");
    std::filesystem::path out(*output);
    if (!out.has_filename() && out.has_parent_path())
        out = out.parent_path(); // "frames/" is the folder "frames"
    const bool video = isVideoFile(out);

    // Everything the command line can check is checked before the genome is read.
    const double fps = parseDoubleOption(args, "fps", 25.0);
    if (!(fps > 0.0) || fps > 1000.0)
        throw InputError("--fps: must be a number above 0, at most 1000 (got " + *args.get("fps") + ")");
    const int frames =
        parseIntOption(args, "frames", std::max(2, static_cast<int>(std::lround(4.0 * fps))), 2, 100000);
    RenderSettings settings;
    settings.aa = args.get("aa").value_or("none");
    aaPattern(settings.aa);
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);
    if (auto slice = args.get("slice")) settings.slice = parseSlice(*slice);
    const bool hasW = args.has("width"), hasH = args.has("height");
    int width = hasW ? parseIntOption(args, "width", 0, 1, MaxImageSide) : 0;
    int height = hasH ? parseIntOption(args, "height", 0, 1, MaxImageSide) : 0;
    // A video replaces a file at OUT, as `render` does; frames go only into a new or empty folder.
    std::error_code ec;
    if (std::filesystem::exists(out, ec)) {
        if (video ? std::filesystem::is_directory(out, ec)
                  : !std::filesystem::is_directory(out, ec) || !std::filesystem::is_empty(out, ec))
            throw InputError(out.string() +
                             ": already exists; OUT must be a new or empty folder, or a .gif, .webp, "
                             ".mp4 or .webm file");
    }

    const std::string genomeName = args.positional[0];
    Genome genome = loadGenomeArgument("animate", genomeName);
    genome.allowExternalSource = args.has("allow-external-source");
    try {
        return animateGenome(args, genomeName, genome, std::move(settings), out, fps, frames, width, height);
    } catch (const InputError& e) {
        // One line that names the file: the genome, unless the message names one already.
        std::string message = e.what();
        if (message.find('\'') != std::string::npos || message.starts_with(genomeName) ||
            message.starts_with(out.string()))
            throw;
        throw InputError(genomeName + ": " + message);
    }
}

int animateGenome(const Args& args, const std::string& genomeName, const Genome& genome,
                  RenderSettings settings, const std::filesystem::path& out, double fps, int frames,
                  int width, int height) {
    const bool hasW = args.has("width"), hasH = args.has("height");
    auto withGenome = [&](const std::string& message) { return InputError(genomeName + ": " + message); };
    if (genome.dimension == 3 && !settings.slice)
        throw withGenome("a solid (3D) genome needs --slice AXIS=VALUE (e.g. z=" +
                         std::to_string(static_cast<int>(genome.size.z / 2)) + ")");
    if (genome.dimension == 2 && settings.slice)
        throw withGenome("--slice needs a solid (3D) genome; this one is flat (2D)");

    // Pixel size: as `render`, with 512 pixels on the longer side by default.
    RenderSettings probe = settings;
    probe.width = probe.height = 1;
    checkRenderSettings(genome, probe);
    const Region region = effectiveRegion(genome, settings);
    const double aspect = (region.x1 - region.x0) / (region.y1 - region.y0);
    auto pixels = [](double value) {
        return static_cast<int>(std::clamp(std::round(value), 1.0, double(MaxImageSide)));
    };
    if (hasW && !hasH) height = pixels(width / aspect);
    if (hasH && !hasW) width = pixels(height * aspect);
    if (!hasW && !hasH) {
        width = aspect >= 1.0 ? 512 : pixels(512 * aspect);
        height = aspect >= 1.0 ? pixels(512 / aspect) : 512;
    }
    settings.width = width;
    settings.height = height;
    checkRenderSettings(genome, settings);

    ProgressLine progress(args);
    InterruptGuard interrupts;
    writeAnimation(genome, settings, out, frames, fps, &gInterrupted,
                   [&progress, frames](int frame, double within) {
                       const int percent = static_cast<int>((frame + within) / frames * 100.0);
                       progress.show("frame " + std::to_string(frame + 1) + "/" + std::to_string(frames) +
                                     " (" + std::to_string(percent) + "%)");
                   });
    progress.finish();
    return ExitOk;
}

} // namespace

int runAnimate(std::span<const std::string> words) {
    return guarded("animate", [&] {
        try {
            return animate(words);
        } catch (const Cancelled&) {
            std::cerr << "marbler animate: interrupted; nothing written\n";
            return 130;
        }
    });
}

} // namespace marbler::cli
