// The making of a design as a video or a folder of PNG frames (marbler/Animation.h).

#include "marbler/Animation.h"

#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/Growth.h"
#include "marbler/RenderToFile.h"
#include "marbler/Video.h"

#include <cstdio>
#include <system_error>

namespace marbler {

std::string animationFrameName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04d.png", frame);
    return name;
}

void writeAnimation(const Genome& genome, const RenderSettings& settings, const std::filesystem::path& out,
                    int frames, double fps, const std::atomic<bool>* cancel,
                    const std::function<void(int frame, double within)>& progress) {
    if (frames < 2)
        throw InputError("an animation needs at least 2 frames (got " + std::to_string(frames) + ")");
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
    // The frames go to a temporary folder beside OUT, renamed to OUT when all are written.
    AtomicFile folder(out, AtomicFile::Kind::Folder);
    for (int frame = 0; frame < frames; ++frame) {
        const RenderControl control = controlOf(frame);
        // renderToFile puts the frame's own design into the PNG.
        renderToFile(designOf(frame), settings, folder.temporary() / animationFrameName(frame), {}, &control);
        if (cancelled()) throw Cancelled();
    }
    std::error_code ec;
    if (std::filesystem::exists(out, ec))
        std::filesystem::remove(out, ec); // an empty folder, checked by the caller
    folder.commit();
}

} // namespace marbler
