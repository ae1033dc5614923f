// The making of a design as a video or a folder of PNG frames (marbler/Animation.h).

#include "marbler/Animation.h"

#include "marbler/Error.h"
#include "marbler/Growth.h"
#include "marbler/Video.h"

#include <cstdio>
#include <system_error>

#include <unistd.h>

namespace marbler {
namespace {

/// A temporary folder beside OUT, removed unless committed (renamed to OUT).
class TemporaryFolder {
public:
    explicit TemporaryFolder(const std::filesystem::path& out) : mOut(out) {
        std::filesystem::path parent = out.parent_path();
        if (parent.empty()) parent = ".";
        mPath = parent / ("." + out.filename().string() + ".tmp-" + std::to_string(::getpid()));
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
        if (!std::filesystem::create_directory(mPath, ec) || ec)
            throw RuntimeFailure("cannot make the folder " + mPath.string() + ": " + ec.message());
    }
    ~TemporaryFolder() {
        if (mCommitted) return;
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    void commit() {
        std::error_code ec;
        std::filesystem::rename(mPath, mOut, ec); // replaces an empty folder at OUT
        if (ec) throw RuntimeFailure("cannot rename " + mPath.string() + " to " + mOut.string() + ": " + ec.message());
        mCommitted = true;
    }

private:
    std::filesystem::path mOut, mPath;
    bool mCommitted = false;
};

} // namespace

std::string animationFrameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", frame);
    return name;
}

void writeAnimation(const Genome& genome, const RenderSettings& settings, const std::filesystem::path& out, int frames,
                    double fps, const std::atomic<bool>* cancel,
                    const std::function<void(int frame, double within)>& progress) {
    if (frames < 2) throw InputError("an animation needs at least 2 frames (got " + std::to_string(frames) + ")");
    checkRenderSettings(genome, settings);
    const std::size_t steps = stepCount(genome);
    auto designOf = [&](int frame) { return designAtGrowth(genome, frameGrowth(steps, frame, frames)); };
    auto cancelled = [&] { return cancel && cancel->load(); };
    auto controlOf = [&](int frame) {
        RenderControl control;
        control.cancel = cancel;
        if (progress) control.progress = [&progress, frame](double f) { progress(frame, f); };
        return control;
    };
    if (isVideoFile(out)) {
        // The writer renames its temporary over OUT on finish; destroyed unfinished, it leaves nothing.
        std::unique_ptr<VideoWriter> writer = openVideoWriter(out, settings.width, settings.height, fps);
        for (int frame = 0; frame < frames; ++frame) {
            const RenderControl control = controlOf(frame);
            const Image image = CpuRenderer(designOf(frame)).render(settings, &control);
            if (cancelled()) throw Cancelled();
            writer->addFrame(image.rgb.data(), std::size_t(settings.width) * 3);
        }
        writer->finish();
        return;
    }
    TemporaryFolder folder(out);
    for (int frame = 0; frame < frames; ++frame) {
        const RenderControl control = controlOf(frame);
        // renderToFile puts the frame's own design into the PNG.
        renderToFile(designOf(frame), settings, folder.path() / animationFrameName(frame), {}, &control);
        if (cancelled()) throw Cancelled();
    }
    std::error_code ec;
    if (std::filesystem::exists(out, ec)) std::filesystem::remove(out, ec); // an empty folder, checked by the caller
    folder.commit();
}

} // namespace marbler
