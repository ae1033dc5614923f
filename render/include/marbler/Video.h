#pragma once
/// Video and animated-image files: writing the frames of `marbler animate` and `marbler video`,
/// reading the frames `marbler video` marbles. FFmpeg's libraries do the work inside the module
/// `marbler-video.so` (Modules.h), loaded on first use, so no other command pays for them.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace marbler {

/// Writes frames to a video or animated image, the format chosen by the file's extension:
/// `.gif` (one 256-colour palette made from every frame, ordered dithering; the frames are held
/// until finish() makes it), `.webp` (animated, lossy at quality 90), `.mp4` (H.264, 4:2:0: an
/// odd width or height is encoded one pixel larger, the last column or row repeated) or `.webm`
/// (VP9). Frame k is shown at k / fps seconds exactly (GIF, which counts hundredths, keeps the
/// rate on average).
class VideoWriter {
public:
    virtual ~VideoWriter() = default;
    /// One frame of the writer's width x height, 8-bit sRGB RGB, rows top first, `stride` bytes
    /// apart. Throws RuntimeFailure.
    virtual void addFrame(const std::uint8_t* rgb, std::size_t stride) = 0;
    /// Flushes and closes the file. Until then nothing exists at the path: the file is written
    /// beside it under a temporary name and renamed here. Throws RuntimeFailure.
    virtual void finish() = 0;
};

/// Whether the extension of `path` (any case) names a format VideoWriter writes.
bool isVideoFile(const std::filesystem::path& path);

/// Opens a writer of `width` x `height` frames at `fps` frames a second (loads the video module
/// on first use). Throws InputError for an extension it does not write, RuntimeFailure when the
/// module or an encoder is missing or the file cannot be opened.
std::unique_ptr<VideoWriter> openVideoWriter(const std::filesystem::path& path, int width, int height,
                                             double fps);

/// Reads the frames of a video (any format FFmpeg reads), one at a time.
class VideoReader {
public:
    virtual ~VideoReader() = default;
    virtual int width() const = 0;
    virtual int height() const = 0;
    /// Frames a second, as the file says (its average frame rate).
    virtual double fps() const = 0;
    /// The next frame as width x height 8-bit sRGB RGB, rows top first and packed; false at the
    /// end. Throws RuntimeFailure on a decoding error.
    virtual bool nextFrame(std::vector<std::uint8_t>& rgb) = 0;
};

/// Opens a video for reading. Throws InputError when the file is not a video FFmpeg reads,
/// RuntimeFailure when the module is missing.
std::unique_ptr<VideoReader> openVideoReader(const std::filesystem::path& path);

} // namespace marbler
