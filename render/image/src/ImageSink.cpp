// The image formats written without OpenImageIO: PNG (libpng), TIFF (libtiff) and binary PPM. They
// are the everyday formats of Marbler's renders, and these libraries load in a millisecond
// where OpenImageIO's dependencies take a third of a second (see ImageSink.h).

#include "ImageSink.h"

#include "SrgbProfile.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/GenomeImage.h"
#include "marbler/Image.h"
#include "marbler/ImageFormats.h"
#include "marbler/Modules.h"

#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace marbler::detail {
namespace {

/// A FILE* that is closed when it goes out of scope unless released.
struct File {
    std::FILE* handle = nullptr;
    ~File() {
        if (handle) std::fclose(handle);
    }
};

/// `error` is the errno of the failed write, when one is known: a full disk is said in plain
/// words whatever the library's own message (writeFailureMessage).
[[noreturn]] void failWrite(const SinkTarget& target, const std::string& reason, int error = 0) {
    if (error == ENOSPC || error == EDQUOT)
        throw RuntimeFailure(writeFailureMessage(target.displayName, error));
    throw RuntimeFailure("cannot write '" + target.displayName + "': " + reason);
}

// --- PNG --------------------------------------------------------------------------------------

/// libpng reports errors by longjmp; every libpng call is made inside a function with no C++
/// objects to unwind (pngCall), and the message is kept for the exception thrown afterwards.
struct PngState {
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = {};
    ~PngState() {
        if (png) png_destroy_write_struct(&png, info ? &info : nullptr);
    }
};

void pngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<PngState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

template <typename Body> bool pngCall(PngState& state, Body body) {
    if (setjmp(png_jmpbuf(state.png))) return false;
    body();
    return true;
}

class PngSink final : public ImageSink {
public:
    explicit PngSink(const SinkTarget& target)
        : mTarget(target) {
        mFile.handle = std::fopen(target.file.c_str(), "wb");
        if (!mFile.handle) failWrite(target, std::strerror(errno));
        mState.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &mState, pngError, pngWarning);
        if (!mState.png) failWrite(target, "out of memory");
        mState.info = png_create_info_struct(mState.png);
        if (!mState.info) failWrite(target, "out of memory");
        const int width = target.width, height = target.height;
        const std::optional<double> dpi = target.options.dpi;
        std::FILE* handle = mFile.handle;
        png_text texts[2]{};
        texts[0].compression = PNG_TEXT_COMPRESSION_NONE;
        texts[0].key = const_cast<char*>("Software");
        texts[0].text = const_cast<char*>("Marbler");
        // The genome travels with the image (GenomeImage.h): UTF-8 in an iTXt chunk, before
        // the image data so a reader finds it without decoding a pixel.
        const std::string& genome = target.options.genome;
        const int textCount = genome.empty() ? 1 : 2;
        texts[1].compression =
            genome.size() > PngCompressAbove ? PNG_ITXT_COMPRESSION_zTXt : PNG_ITXT_COMPRESSION_NONE;
        texts[1].key = const_cast<char*>(PngGenomeKeyword);
        texts[1].text = const_cast<char*>(genome.c_str());
        texts[1].lang = const_cast<char*>("");
        texts[1].lang_key = const_cast<char*>("");
        bool ok = pngCall(mState, [&] {
            png_init_io(mState.png, handle);
            // Marbled designs are large areas of flat colour: a fast deflate level with the
            // "up" and "sub" filters keeps files small at several times the default's speed.
            png_set_compression_level(mState.png, 3);
            png_set_filter(mState.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB | PNG_FILTER_UP);
            png_set_IHDR(mState.png, mState.info, png_uint_32(width), png_uint_32(height), 8,
                         PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                         PNG_FILTER_TYPE_BASE);
            // The sRGB profile (SrgbProfile.h) in an iCCP chunk, which layout and print software
            // reads where it may ignore the sRGB chunk (PNG allows one of the two).
            const std::vector<unsigned char>& icc = srgbIccProfile();
            png_set_iCCP(mState.png, mState.info, SrgbIccProfileName, PNG_COMPRESSION_TYPE_BASE, icc.data(),
                         png_uint_32(icc.size()));
            if (dpi) {
                auto perMetre = png_uint_32(std::lround(*dpi / 0.0254));
                png_set_pHYs(mState.png, mState.info, perMetre, perMetre, PNG_RESOLUTION_METER);
            }
            png_set_text(mState.png, mState.info, texts, textCount);
            png_write_info(mState.png, mState.info);
        });
        if (!ok) failWrite(target, mState.message, errno);
    }

    bool linearFloat() const override { return false; }

    void writeRows(int y0, int y1, const void* rows) override {
        const auto* bytes = static_cast<const png_byte*>(rows);
        const std::size_t stride = std::size_t(mTarget.width) * 3;
        bool ok = true;
        for (int y = y0; y < y1 && ok; ++y) {
            png_bytep row = const_cast<png_bytep>(bytes + std::size_t(y - y0) * stride);
            ok = pngCall(mState, [&] { png_write_row(mState.png, row); });
        }
        if (!ok) failWrite(mTarget, mState.message, errno);
    }

    void finish() override {
        if (!pngCall(mState, [&] { png_write_end(mState.png, nullptr); }))
            failWrite(mTarget, mState.message, errno);
        std::FILE* handle = std::exchange(mFile.handle, nullptr);
        if (std::fflush(handle) != 0 || std::ferror(handle)) {
            const int error = errno;
            std::fclose(handle);
            failWrite(mTarget, std::strerror(error), error);
        }
        if (std::fclose(handle) != 0) failWrite(mTarget, std::strerror(errno), errno);
    }

private:
    SinkTarget mTarget;
    File mFile;
    PngState mState;
};

// --- TIFF -------------------------------------------------------------------------------------

/// libtiff reports errors through a process-wide handler; the last message of each thread is
/// kept for the exception.
thread_local std::string tiffMessage;

void tiffError(const char* module, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    tiffMessage = module && *module ? std::string(module) + ": " + text : text;
}

class TiffSink final : public ImageSink {
public:
    explicit TiffSink(const SinkTarget& target)
        : mTarget(target)
        , mDeep(target.options.bitsPerSample == 16) {
        if (target.options.bitsPerSample != 8 && target.options.bitsPerSample != 16)
            throw InputError("'" + target.displayName + "': a TIFF holds 8 or 16 bits a sample (got " +
                             std::to_string(target.options.bitsPerSample) + ")");
        static std::once_flag handlers;
        std::call_once(handlers, [] {
            TIFFSetErrorHandler(tiffError);
            TIFFSetWarningHandler(nullptr);
        });
        tiffMessage.clear();
        mTiff = TIFFOpen(target.file.c_str(), "w");
        if (!mTiff) {
            const int error = errno;
            failWrite(target, tiffMessage.empty() ? std::strerror(error) : tiffMessage, error);
        }
        TIFFSetField(mTiff, TIFFTAG_IMAGEWIDTH, std::uint32_t(target.width));
        TIFFSetField(mTiff, TIFFTAG_IMAGELENGTH, std::uint32_t(target.height));
        TIFFSetField(mTiff, TIFFTAG_SAMPLESPERPIXEL, 3);
        TIFFSetField(mTiff, TIFFTAG_BITSPERSAMPLE, mDeep ? 16 : 8);
        TIFFSetField(mTiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
        TIFFSetField(mTiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(mTiff, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
        // Deflate with the horizontal predictor at a fast level: lossless and print-shop safe.
        TIFFSetField(mTiff, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
        TIFFSetField(mTiff, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
        TIFFSetField(mTiff, TIFFTAG_ZIPQUALITY, 3);
        TIFFSetField(mTiff, TIFFTAG_ROWSPERSTRIP, std::uint32_t(RowsPerStrip));
        TIFFSetField(mTiff, TIFFTAG_SOFTWARE, "Marbler");
        const std::vector<unsigned char>& icc = srgbIccProfile();
        TIFFSetField(mTiff, TIFFTAG_ICCPROFILE, std::uint32_t(icc.size()), icc.data());
        // The genome travels with the image, in the XMP packet (GenomeImage.h).
        if (!target.options.genome.empty()) {
            const std::string packet = genomeXmpPacket(target.options.genome);
            TIFFSetField(mTiff, TIFFTAG_XMLPACKET, std::uint32_t(packet.size()), packet.data());
        }
        if (target.options.dpi) {
            TIFFSetField(mTiff, TIFFTAG_XRESOLUTION, float(*target.options.dpi));
            TIFFSetField(mTiff, TIFFTAG_YRESOLUTION, float(*target.options.dpi));
            TIFFSetField(mTiff, TIFFTAG_RESOLUTIONUNIT, RESUNIT_INCH);
        }
        mPending.reserve(std::size_t(RowsPerStrip) * std::size_t(target.width) * 3 * (mDeep ? 2 : 1));
    }

    ~TiffSink() override {
        if (mTiff) TIFFClose(mTiff);
    }

    /// A 16-bit file takes the linear average itself, so its extra bits are real, not an
    /// 8-bit value scaled up.
    bool linearFloat() const override { return mDeep; }

    /// Rows are gathered into whole strips, each encoded with one call.
    void writeRows(int y0, int y1, const void* rows) override {
        const std::size_t stride = std::size_t(mTarget.width) * 3 * (mDeep ? 2 : 1);
        std::vector<std::uint16_t> deep;
        const unsigned char* bytes = static_cast<const unsigned char*>(rows);
        if (mDeep) {
            const auto* linear = static_cast<const float*>(rows);
            deep.resize(std::size_t(y1 - y0) * std::size_t(mTarget.width) * 3);
            for (std::size_t k = 0; k < deep.size(); ++k)
                deep[k] = std::uint16_t(
                    std::lround(linearToSrgb(std::clamp(double(linear[k]), 0.0, 1.0)) * 65535.0));
            bytes = reinterpret_cast<const unsigned char*>(deep.data());
        }
        for (int y = y0; y < y1; ++y) {
            mPending.insert(mPending.end(), bytes + std::size_t(y - y0) * stride,
                            bytes + std::size_t(y - y0 + 1) * stride);
            if (mPending.size() == std::size_t(RowsPerStrip) * stride) flushStrip();
        }
    }

    void finish() override {
        if (!mPending.empty()) flushStrip();
        tiffMessage.clear();
        TIFF* tiff = std::exchange(mTiff, nullptr);
        if (!TIFFFlush(tiff)) {
            const int error = errno;
            TIFFClose(tiff);
            failWrite(mTarget, tiffMessage.empty() ? "write failed" : tiffMessage, error);
        }
        TIFFClose(tiff);
    }

private:
    static constexpr int RowsPerStrip = 64;

    void flushStrip() {
        tiffMessage.clear();
        if (TIFFWriteEncodedStrip(mTiff, mStrip++, mPending.data(), tmsize_t(mPending.size())) < 0)
            failWrite(mTarget, tiffMessage.empty() ? "write failed" : tiffMessage, errno);
        mPending.clear();
    }

    SinkTarget mTarget;
    bool mDeep = false; ///< 16 bits a sample
    TIFF* mTiff = nullptr;
    std::uint32_t mStrip = 0;
    std::vector<unsigned char> mPending;
};

// --- PPM --------------------------------------------------------------------------------------

/// Binary PPM (P6): uncompressed, for pipelines and comparisons.
class PpmSink final : public ImageSink {
public:
    explicit PpmSink(const SinkTarget& target)
        : mTarget(target) {
        mFile.handle = std::fopen(target.file.c_str(), "wb");
        if (!mFile.handle) failWrite(target, std::strerror(errno));
        if (std::fprintf(mFile.handle, "P6\n%d %d\n255\n", target.width, target.height) < 0)
            failWrite(target, std::strerror(errno), errno);
    }

    bool linearFloat() const override { return false; }

    void writeRows(int y0, int y1, const void* rows) override {
        const std::size_t count = std::size_t(y1 - y0) * std::size_t(mTarget.width) * 3;
        if (std::fwrite(rows, 1, count, mFile.handle) != count)
            failWrite(mTarget, std::strerror(errno), errno);
    }

    void finish() override {
        std::FILE* handle = std::exchange(mFile.handle, nullptr);
        bool flushed = std::fflush(handle) == 0 && !std::ferror(handle);
        int error = errno;
        if (std::fclose(handle) != 0 || !flushed) {
            const int why = flushed ? errno : error;
            failWrite(mTarget, std::strerror(why), why);
        }
    }

private:
    SinkTarget mTarget;
    File mFile;
};

} // namespace

ImageIoModule& imageIoModule() {
    static ImageIoModule* module = [] {
        auto entry =
            reinterpret_cast<ImageIoModule* (*)()>(moduleEntry(ImageIoModuleFile, ImageIoModuleEntry));
        return entry();
    }();
    return *module;
}

std::unique_ptr<ImageSink> openBuiltinSink(const SinkTarget& target) {
    const std::string& ext = target.extension;
    if (ext == ".png") return std::make_unique<PngSink>(target);
    if (ext == ".tif" || ext == ".tiff") return std::make_unique<TiffSink>(target);
    if (ext == ".ppm") return std::make_unique<PpmSink>(target);
    return nullptr;
}

} // namespace marbler::detail
