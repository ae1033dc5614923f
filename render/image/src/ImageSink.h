#pragma once
/// Internal to render/: where image files are written and read. PNG, TIFF and PPM are written
/// here directly with libpng and libtiff (small libraries that load in a millisecond); every
/// other format, and the decoding of source images, goes through OpenImageIO in the module
/// marbler-imageio.so (render/image/imageio), loaded on first use because OpenImageIO's own
/// dependencies take longer to load than most renders take to run.

#include "ImageData.h"
#include "marbler/ImageFile.h"

#include <cstddef>
#include <memory>
#include <string>

namespace marbler::detail {

/// An image file being written row by row. Rows arrive top to bottom, either as 8-bit sRGB
/// RGB or, when linearFloat(), as linear-light RGB floats. Throws RuntimeFailure on I/O errors.
class ImageSink {
public:
    virtual ~ImageSink() = default;
    virtual bool linearFloat() const = 0;
    /// Rows [y0, y1): (y1 - y0) * width * 3 values of the sink's type.
    virtual void writeRows(int y0, int y1, const void* rows) = 0;
    /// Completes and closes the file.
    virtual void finish() = 0;
};

/// What a sink writes: `file` is the path to create (a temporary name; the caller renames it),
/// `extension` the lower-case format extension with its dot, `displayName` the name the user
/// gave, for messages.
struct SinkTarget {
    std::string file;
    std::string extension;
    std::string displayName;
    int width = 0, height = 0;
    ExportOptions options;
};

/// The writers built into render/ (PNG, TIFF, PPM); nullptr for any other extension.
std::unique_ptr<ImageSink> openBuiltinSink(const SinkTarget& target);

/// The interface of marbler-imageio.so (OpenImageIO).
class ImageIoModule {
public:
    virtual ~ImageIoModule() = default;
    /// A writer for any format OpenImageIO knows. Throws InputError for an unknown extension,
    /// RuntimeFailure when the file cannot be created.
    virtual std::unique_ptr<ImageSink> openSink(const SinkTarget& target) = 0;
    /// Decodes an image file, or `size` bytes of one, into linear RGB with OpenImageIO's one
    /// reader named `reader` (SourceFormat.h: never a guess from a name, never another
    /// reader). The size in the header is checked before any pixel is decoded. `name` is how
    /// messages name it. Throws InputError when it cannot be decoded or is too large.
    virtual LinearRaster readFile(const std::string& file, const std::string& reader,
                                  const std::string& name) = 0;
    virtual LinearRaster readMemory(const unsigned char* data, std::size_t size, const std::string& reader,
                                    const std::string& name) = 0;
    /// OpenImageIO's version, e.g. "2.4.7".
    virtual std::string version() const = 0;
};

/// The module, loaded on first call. Throws RuntimeFailure when it cannot be loaded.
ImageIoModule& imageIoModule();

/// File name and entry point of the module.
inline constexpr const char* ImageIoModuleFile = "marbler-imageio.so";
inline constexpr const char* ImageIoModuleEntry = "marbler_imageio_module";

} // namespace marbler::detail
