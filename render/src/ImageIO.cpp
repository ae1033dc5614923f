// Image input and output: source images, atomic image files, renders streamed to a file. The
// formats themselves live in ImageWriters.cpp (PNG, TIFF, PPM) and in the OpenImageIO module.

#include "ImageSink.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "marbler/Modules.h"
#include "marbler/SourcePath.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <thread>
#include <utility>

namespace marbler {
namespace fs = std::filesystem;

namespace detail {

std::vector<unsigned char> decodeBase64(std::string_view text) {
    auto value = [](unsigned char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+' || c == '-') return 62;
        if (c == '/' || c == '_') return 63;
        return -1;
    };
    std::vector<unsigned char> out;
    out.reserve(text.size() / 4 * 3 + 3);
    std::uint32_t buffer = 0;
    int bits = 0;
    bool padding = false;
    for (unsigned char c : text) {
        if (std::isspace(c)) continue;
        if (c == '=') {
            padding = true;
            continue;
        }
        int v = value(c);
        if (v < 0 || padding) throw InputError("bad base64 data");
        buffer = (buffer << 6) | std::uint32_t(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xffu));
        }
    }
    return out;
}

ImageIoModule& imageIoModule() {
    static ImageIoModule* module = [] {
        auto entry =
            reinterpret_cast<ImageIoModule* (*)()>(moduleEntry(ImageIoModuleFile, ImageIoModuleEntry));
        return entry();
    }();
    return *module;
}

/// Decodes a `data:image/...;base64,` URI. Throws InputError.
LinearRaster decodeDataUri(const std::string& text) {
    const std::string name = "(data URL)";
    std::size_t comma = text.find(',');
    if (comma == std::string::npos) throw InputError("source image " + name + ": no ',' in the data URL");
    std::string header = text.substr(5, comma - 5);
    if (header.size() < 7 || header.substr(header.size() - 7) != ";base64")
        throw InputError("source image " + name + ": only base64 data URLs are supported");
    std::string mime = header.substr(0, header.size() - 7);
    std::string extension = "png";
    if (mime == "image/jpeg" || mime == "image/jpg")
        extension = "jpg";
    else if (mime == "image/tiff")
        extension = "tif";
    else if (mime == "image/bmp")
        extension = "bmp";
    else if (mime == "image/x-exr")
        extension = "exr";
    std::vector<unsigned char> bytes;
    try {
        bytes = decodeBase64(std::string_view(text).substr(comma + 1));
    } catch (const InputError& e) {
        throw InputError("source image " + name + ": " + e.what());
    }
    return imageIoModule().readMemory(bytes.data(), bytes.size(), extension, name);
}

} // namespace detail

LinearRaster decodeSourceImage(const Genome& genome) {
    const std::string& text = genome.source->image;
    if (!isDataUri(text)) {
        // The rule of SourcePath.h comes first: a refused file is never opened.
        const fs::path file = sourceFileToRead(genome);
        try {
            return detail::imageIoModule().readFile(file.string(), "'" + file.string() + "'");
        } catch (const GenomeError&) {
            throw;
        } catch (const InputError& e) {
            throw GenomeError(genomeName(genome), "source.image", e.what());
        }
    }
    try {
        return detail::decodeDataUri(text);
    } catch (const InputError& e) {
        throw GenomeError(genomeName(genome), "source.image", e.what());
    }
}

namespace {

using detail::imageIoModule;
using detail::ImageSink;
using detail::openBuiltinSink;
using detail::SinkTarget;

/// Rows of a strip: several strips an image, so writing one overlaps rendering the next, and at
/// most about two megapixels a strip, so memory stays bounded at poster sizes.
int stripRows(int width, int height) {
    const int most = std::max(16, (1 << 21) / std::max(1, width));
    return std::clamp((height + 7) / 8, 16, most);
}

/// An image file written in strips to a temporary name beside the target (an AtomicFile),
/// renamed over the target only by commit(); destroyed uncommitted, it leaves nothing behind.
class AtomicImageFile {
public:
    AtomicImageFile(const fs::path& file, int width, int height, const ExportOptions& options)
        : mFile(file) {
        SinkTarget target{
            mFile.temporary().string(), lowerExtension(file), file.string(), width, height, options};
        mSink = openBuiltinSink(target);
        if (!mSink) mSink = imageIoModule().openSink(target);
    }

    ~AtomicImageFile() {
        mSink.reset(); // closes the file before the AtomicFile removes it
    }

    AtomicImageFile(const AtomicImageFile&) = delete;
    AtomicImageFile& operator=(const AtomicImageFile&) = delete;

    /// Whether the file holds linear floats (EXR) rather than 8-bit sRGB.
    bool linearFloat() const { return mSink->linearFloat(); }

    void writeRows(int y0, int y1, const void* data) { mSink->writeRows(y0, y1, data); }

    void commit() {
        mSink->finish();
        mSink.reset();
        mFile.commit();
    }

private:
    AtomicFile mFile; // before mSink: destroyed after it, so the sink closes the file first
    std::unique_ptr<ImageSink> mSink;
};

/// Writes strips on a thread of its own while the caller renders the next one. At most one
/// write is in flight; wait() returns when it is done and rethrows what it threw.
class StripWriter {
public:
    explicit StripWriter(AtomicImageFile& out)
        : mOut(out) {}
    ~StripWriter() {
        if (mThread.joinable()) mThread.join();
    }
    void write(int y0, int y1, const void* rows) {
        wait();
        mThread = std::thread([this, y0, y1, rows] {
            try {
                mOut.writeRows(y0, y1, rows);
            } catch (...) {
                mError = std::current_exception();
            }
        });
    }
    void wait() {
        if (mThread.joinable()) mThread.join();
        if (mError) std::rethrow_exception(std::exchange(mError, nullptr));
    }

private:
    AtomicImageFile& mOut;
    std::thread mThread;
    std::exception_ptr mError;
};

} // namespace

void writeImage(const Image& image, const fs::path& file, const ExportOptions& options) {
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        throw RuntimeFailure("cannot write '" + file.string() + "': the image is empty or malformed");
    AtomicImageFile out(file, image.width, image.height, options);
    if (!out.linearFloat()) {
        out.writeRows(0, image.height, image.rgb.data());
    } else {
        const float* table = srgbToLinearTable();
        const int rows = stripRows(image.width, image.height);
        std::vector<float> strip;
        for (int y0 = 0; y0 < image.height; y0 += rows) {
            int y1 = std::min(image.height, y0 + rows);
            strip.resize(std::size_t(y1 - y0) * std::size_t(image.width) * 3);
            const std::uint8_t* src = image.row(y0);
            for (std::size_t k = 0; k < strip.size(); ++k)
                strip[k] = table[src[k]];
            out.writeRows(y0, y1, strip.data());
        }
    }
    out.commit();
}

void renderToFile(const Genome& genome, const RenderSettings& settings, const fs::path& file,
                  const ExportOptions& options, const RenderControl* control) {
    checkRenderSettings(genome, settings);
    if (options.dpi && !(*options.dpi > 0.0 && std::isfinite(*options.dpi)))
        throw InputError("dpi must be a positive number");
    CpuRenderer renderer(genome);
    // The image carries the design it shows (GenomeImage.h).
    ExportOptions withGenome = options;
    if (withGenome.genome.empty()) withGenome.genome = serializeGenome(genome);
    AtomicImageFile out(file, settings.width, settings.height, withGenome);
    const bool linear = out.linearFloat();
    const int rows = stripRows(settings.width, settings.height);
    const std::size_t stripValues = std::size_t(rows) * std::size_t(settings.width) * 3;
    // Two strip buffers: one being written while the other is rendered.
    std::vector<std::uint8_t> bytes[2];
    std::vector<float> floats[2];
    for (int b = 0; b < 2; ++b) {
        if (linear)
            floats[b].resize(stripValues);
        else
            bytes[b].resize(stripValues);
    }
    StripWriter writer(out);
    int buffer = 0;
    for (int y0 = 0; y0 < settings.height; y0 += rows, buffer ^= 1) {
        int y1 = std::min(settings.height, y0 + rows);
        RenderControl strip;
        if (control) {
            strip.cancel = control->cancel;
            if (control->progress)
                strip.progress = [&, y0, y1](double f) {
                    control->progress((y0 + f * (y1 - y0)) / settings.height);
                };
        }
        const void* data;
        if (linear) {
            renderer.renderRowsLinear(settings, y0, y1, floats[buffer].data(), &strip);
            data = floats[buffer].data();
        } else {
            renderer.renderRows(settings, y0, y1, bytes[buffer].data(), &strip);
            data = bytes[buffer].data();
        }
        if (control && control->cancelled()) break;
        writer.write(y0, y1, data);
    }
    writer.wait();
    if (control && control->cancelled()) throw Cancelled();
    out.commit();
}

} // namespace marbler
