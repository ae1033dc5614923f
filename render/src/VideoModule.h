#pragma once
/// Internal to render/: the interface of the video module marbler-video.so (render/video), the one
/// part of Marbler that sees FFmpeg. render/src/Video.cpp loads it on first use and adds what
/// every format shares (the extension check, the temporary file and its rename).

#include "marbler/Video.h"

#include <memory>
#include <string>

namespace marbler::detail {

/// What a video writer writes: `file` is the path to create (a temporary name; the caller
/// renames it), `extension` the lower-case format extension with its dot (".gif", ".webp",
/// ".mp4", ".webm"), `displayName` the name the user gave, for messages.
struct VideoTarget {
    std::string file;
    std::string extension;
    std::string displayName;
    int width = 0, height = 0;
    double fps = 25.0;
};

class VideoModule {
public:
    virtual ~VideoModule() = default;
    /// A writer whose finish() completes `target.file` (and renames nothing). Throws
    /// RuntimeFailure when the encoder is missing or the file cannot be created.
    virtual std::unique_ptr<VideoWriter> openWriter(const VideoTarget& target) = 0;
    /// A reader of `file`; `name` is how messages name it. Throws InputError when it is not a video.
    virtual std::unique_ptr<VideoReader> openReader(const std::string& file, const std::string& name) = 0;
    /// The encoders each format uses here, e.g. "mp4: libx264 (H.264); webm: libvpx-vp9 (VP9); ...",
    /// with "missing" for those this FFmpeg lacks, and FFmpeg's versions (for `marbler doctor`).
    virtual std::string describe() const = 0;
};

/// The module, loaded on first call. Throws RuntimeFailure when it cannot be loaded.
VideoModule& videoModule();

/// File name and entry point of the module.
inline constexpr const char* VideoModuleFile = "marbler-video.so";
inline constexpr const char* VideoModuleEntry = "marbler_video_module";

} // namespace marbler::detail
