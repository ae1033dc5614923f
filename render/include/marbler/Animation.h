#pragma once
/// The making of a design as an animation (genome-format.md, "The making of a design"): the frames
/// of `marbler animate` and of the editor's Export animation, written by one function.

#include "marbler/CpuRenderer.h"
#include "marbler/Genome.h"

#include <atomic>
#include <filesystem>
#include <functional>

namespace marbler {

/// The name of PNG frame `frame` in a frames folder: frame-0000.png, frame-0001.png, ...
std::string animationFrameName(int frame);

/// Renders `frames` frames (at least 2) of the making of `genome` at `settings` (width and
/// height set; a slice for a solid) and writes them to `out`: a video or animated image when its
/// extension is one VideoWriter writes (isVideoFile), shown at `fps` frames a second, else a
/// folder of PNG frames (animationFrameName), each carrying the partial design it shows. Frame f
/// shows designAtGrowth(genome, frameGrowth(steps, f, frames)): frame 0 the bare bath, the last
/// the whole design. Nothing is left at `out` unless every frame is written: a video replaces a
/// file there, a folder replaces only an empty folder (the caller checks). `progress(frame,
/// within)` is called from the rendering threads; `cancel` stops between and within frames.
/// Throws InputError, RuntimeFailure, Cancelled.
void writeAnimation(const Genome& genome, const RenderSettings& settings, const std::filesystem::path& out,
                    int frames, double fps, const std::atomic<bool>* cancel = nullptr,
                    const std::function<void(int frame, double within)>& progress = {});

} // namespace marbler
