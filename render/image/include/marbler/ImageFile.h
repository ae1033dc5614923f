#pragma once
/// Image files written whole or row by row, atomically: a temporary file beside the target is
/// renamed over it only when complete, so a failure or a cancel leaves nothing behind. PNG,
/// TIFF and PPM are written here; every other format through OpenImageIO's module.

#include "marbler/Image.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace marbler {

namespace detail {
class ImageSink;
}

/// Output options of a render to a file.
struct ExportOptions {
    std::optional<double> dpi; ///< written into the file's resolution when set
    /// The genome the image shows, as canonical genome JSON (serializeGenome), carried in the
    /// file's metadata by PNG and TIFF (marbler/GenomeImage.h says where); empty: none.
    /// renderToFile fills it from the genome it renders when left empty.
    std::string genome;
    /// Bits a sample of a TIFF: 8, or 16 (sRGB encoded from the linear average, for print work
    /// that grades the image further). Other formats have a depth of their own (EXR: half float).
    int bitsPerSample = 8;
};

/// Writes an in-memory image atomically (format by extension). The image knows no genome, so
/// the caller puts the design's into `options.genome` for PNG and TIFF to carry it. Throws
/// InputError for an unknown extension, RuntimeFailure for I/O failures.
void writeImage(const Image& image, const std::filesystem::path& file, const ExportOptions& options = {});

/// An image file being written in strips of rows, top to bottom (format by extension), to a
/// temporary name beside `file`; commit() renames it over `file`, and destroyed uncommitted it
/// leaves nothing behind. Throws InputError for an unknown extension, RuntimeFailure for I/O.
class ImageFileWriter {
public:
    ImageFileWriter(const std::filesystem::path& file, int width, int height, const ExportOptions& options);
    ~ImageFileWriter();
    ImageFileWriter(const ImageFileWriter&) = delete;
    ImageFileWriter& operator=(const ImageFileWriter&) = delete;

    /// Whether the file takes linear-light floats (EXR) rather than 8-bit sRGB rows.
    bool linearFloat() const;
    /// Rows [y0, y1): (y1 - y0) * width * 3 values, bytes or floats as linearFloat() says.
    void writeRows(int y0, int y1, const void* rows);
    /// Completes the file and renames it over the target.
    void commit();

    /// Rows in a strip: several strips an image, so writing one overlaps making the next, and at
    /// most about two megapixels a strip, so memory stays bounded at poster sizes.
    static int stripRows(int width, int height);

private:
    struct Impl;
    std::unique_ptr<Impl> mImpl;
};

} // namespace marbler
