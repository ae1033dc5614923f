// Image input and output: the one file of Marbler that sees OpenImageIO.

#include "ImageData.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <unistd.h>

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

namespace {

/// Rasters larger than this (64 megapixels, 8192 x 8192) are refused as sources, so a hostile
/// file that claims a huge size cannot make the loader allocate gigabytes of float pixels.
constexpr std::int64_t MaxSourcePixels = std::int64_t(1) << 26;
/// Channels decoded at most (RGBA); extra channels are not read.
constexpr int MaxSourceChannels = 4;

bool isLinearColorSpace(const OIIO::ImageSpec& spec) {
    std::string space = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(space.begin(), space.end(), space.begin(), [](unsigned char c) { return std::tolower(c); });
    return space == "linear" || space == "scene_linear" || space == "lin_srgb";
}

LinearRaster readRaster(OIIO::ImageInput& in, const std::string& name) {
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 ||
        std::int64_t(spec.width) * spec.height > MaxSourcePixels)
        throw InputError("source image " + name + ": unsupported size " + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height));
    const int channels = std::min(spec.nchannels, MaxSourceChannels);
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw InputError("source image " + name + ": " + in.geterror());
    LinearRaster raster;
    raster.width = spec.width;
    raster.height = spec.height;
    raster.rgb.resize(std::size_t(spec.width) * std::size_t(spec.height) * 3);
    const bool linear = isLinearColorSpace(spec);
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
    for (std::size_t p = 0; p < count; ++p)
        for (int c = 0; c < 3; ++c) {
            // Grey and grey+alpha images repeat their one channel; alpha is ignored.
            int from = channels >= 3 ? c : 0;
            float v = pixels[p * std::size_t(channels) + std::size_t(from)];
            raster.rgb[p * 3 + std::size_t(c)] =
                linear ? v : static_cast<float>(srgbToLinear(std::clamp(double(v), 0.0, 1.0)));
        }
    return raster;
}

} // namespace

LinearRaster loadSourceImage(const SourceImage& source, const std::string& baseDirectory) {
    const std::string& text = source.image;
    if (text.rfind("data:", 0) == 0) {
        const std::string name = "(data URL)";
        std::size_t comma = text.find(',');
        if (comma == std::string::npos) throw InputError("source image " + name + ": no ',' in the data URL");
        std::string header = text.substr(5, comma - 5);
        if (header.size() < 7 || header.substr(header.size() - 7) != ";base64")
            throw InputError("source image " + name + ": only base64 data URLs are supported");
        std::string mime = header.substr(0, header.size() - 7);
        std::string extension = "png";
        if (mime == "image/jpeg" || mime == "image/jpg") extension = "jpg";
        else if (mime == "image/tiff") extension = "tif";
        else if (mime == "image/bmp") extension = "bmp";
        else if (mime == "image/x-exr") extension = "exr";
        std::vector<unsigned char> bytes;
        try {
            bytes = decodeBase64(std::string_view(text).substr(comma + 1));
        } catch (const InputError& e) {
            throw InputError("source image " + name + ": " + e.what());
        }
        OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
        auto in = OIIO::ImageInput::open("source." + extension, nullptr, &reader);
        if (!in) throw InputError("source image " + name + ": cannot decode: " + OIIO::geterror());
        LinearRaster raster = readRaster(*in, name);
        in->close();
        return raster;
    }
    fs::path file(text);
    if (file.is_relative() && !baseDirectory.empty()) file = fs::path(baseDirectory) / file;
    const std::string name = "'" + file.string() + "'";
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) throw InputError("source image " + name + ": no such file");
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw InputError("source image " + name + ": cannot load: " + OIIO::geterror());
    LinearRaster raster = readRaster(*in, name);
    in->close();
    return raster;
}

} // namespace detail

namespace {

/// Rows rendered and written at a time: bounds the memory of a poster-sized render.
constexpr int StripRows = 64;

/// An image file written in strips to a temporary name beside the target, renamed over the
/// target only by commit(); destroyed uncommitted, it leaves nothing behind.
class AtomicImageFile {
public:
    AtomicImageFile(const fs::path& file, int width, int height, const ExportOptions& options) : mFile(file) {
        std::string extension = file.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        mOut = OIIO::ImageOutput::create(file.string());
        if (!mOut) {
            OIIO::geterror(); // clear the library's message; ours says it better
            throw InputError("'" + file.string() + "': unknown image format '" + extension +
                             "' (use .png, .tif, .exr or .jpg)");
        }
        mFloat = extension == ".exr" || extension == ".hdr";
        mJpegDpi = options.dpi && (extension == ".jpg" || extension == ".jpeg");
        OIIO::ImageSpec spec(width, height, 3, mFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", mFloat ? "Linear" : "sRGB");
        spec.attribute("Software", "Marbler");
        if (extension == ".jpg" || extension == ".jpeg") spec.attribute("Compression", "jpeg:95");
        if (options.dpi) {
            spec.attribute("XResolution", static_cast<float>(*options.dpi));
            spec.attribute("YResolution", static_cast<float>(*options.dpi));
            spec.attribute("ResolutionUnit", "inch");
        }
        static std::atomic<int> counter{0};
        fs::path folder = file.parent_path();
        mTemp = folder / ("." + file.stem().string() + ".part-" + std::to_string(::getpid()) + "-" +
                          std::to_string(counter++) + file.extension().string());
        if (!mOut->open(mTemp.string(), spec)) {
            std::string reason = mOut->geterror();
            mOut.reset();
            removeTemp();
            throw RuntimeFailure("cannot write '" + file.string() + "': " + reason);
        }
        mOpen = true;
    }

    ~AtomicImageFile() {
        if (mOpen) mOut->close();
        if (!mCommitted) removeTemp();
    }

    AtomicImageFile(const AtomicImageFile&) = delete;
    AtomicImageFile& operator=(const AtomicImageFile&) = delete;

    /// Whether the file holds linear floats (EXR) rather than 8-bit sRGB.
    bool linearFloat() const { return mFloat; }

    void writeRows(int y0, int y1, const void* data, OIIO::TypeDesc type) {
        if (!mOut->write_scanlines(y0, y1, 0, type, data)) fail(mOut->geterror());
    }

    void commit() {
        mOpen = false;
        if (!mOut->close()) fail(mOut->geterror());
        if (mJpegDpi) markJfifDensityInInches();
        std::error_code ec;
        fs::rename(mTemp, mFile, ec);
        if (ec) fail(ec.message());
        mCommitted = true;
    }

private:
    [[noreturn]] void fail(const std::string& reason) {
        throw RuntimeFailure("cannot write '" + mFile.string() + "': " + reason);
    }
    /// OpenImageIO 2.4 writes a JPEG's density with the unit byte 0 (aspect ratio only) even
    /// when asked for inches; set the JFIF unit to 1 (dots per inch) so the dpi means something.
    void markJfifDensityInInches() {
        std::FILE* f = std::fopen(mTemp.c_str(), "r+b");
        if (!f) return;
        unsigned char head[20] = {};
        std::size_t got = std::fread(head, 1, sizeof head, f);
        // SOI, APP0 marker, 2 length bytes, "JFIF\0", 2 version bytes, then the unit byte.
        if (got == sizeof head && head[0] == 0xff && head[1] == 0xd8 && head[2] == 0xff && head[3] == 0xe0 &&
            std::memcmp(head + 6, "JFIF", 5) == 0 && head[13] == 0) {
            const unsigned char inches = 1;
            std::fseek(f, 13, SEEK_SET);
            std::fwrite(&inches, 1, 1, f);
        }
        std::fclose(f);
    }

    void removeTemp() {
        std::error_code ec;
        fs::remove(mTemp, ec);
    }

    fs::path mFile, mTemp;
    std::unique_ptr<OIIO::ImageOutput> mOut;
    bool mFloat = false;
    bool mJpegDpi = false;
    bool mOpen = false;
    bool mCommitted = false;
};

} // namespace

void writeImage(const Image& image, const fs::path& file, const ExportOptions& options) {
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        throw RuntimeFailure("cannot write '" + file.string() + "': the image is empty or malformed");
    AtomicImageFile out(file, image.width, image.height, options);
    if (!out.linearFloat()) {
        out.writeRows(0, image.height, image.rgb.data(), OIIO::TypeDesc::UINT8);
    } else {
        const float* table = srgbToLinearTable();
        std::vector<float> strip;
        for (int y0 = 0; y0 < image.height; y0 += StripRows) {
            int y1 = std::min(image.height, y0 + StripRows);
            strip.resize(std::size_t(y1 - y0) * std::size_t(image.width) * 3);
            const std::uint8_t* src = image.row(y0);
            for (std::size_t k = 0; k < strip.size(); ++k) strip[k] = table[src[k]];
            out.writeRows(y0, y1, strip.data(), OIIO::TypeDesc::FLOAT);
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
    AtomicImageFile out(file, settings.width, settings.height, options);
    const std::size_t rowValues = std::size_t(settings.width) * 3;
    std::vector<std::uint8_t> bytes;
    std::vector<float> floats;
    for (int y0 = 0; y0 < settings.height; y0 += StripRows) {
        int y1 = std::min(settings.height, y0 + StripRows);
        RenderControl strip;
        if (control) {
            strip.cancel = control->cancel;
            if (control->progress)
                strip.progress = [&, y0, y1](double f) {
                    control->progress((y0 + f * (y1 - y0)) / settings.height);
                };
        }
        if (out.linearFloat()) {
            floats.resize(std::size_t(y1 - y0) * rowValues);
            renderer.renderRowsLinear(settings, y0, y1, floats.data(), &strip);
            out.writeRows(y0, y1, floats.data(), OIIO::TypeDesc::FLOAT);
        } else {
            bytes.resize(std::size_t(y1 - y0) * rowValues);
            renderer.renderRows(settings, y0, y1, bytes.data(), &strip);
            out.writeRows(y0, y1, bytes.data(), OIIO::TypeDesc::UINT8);
        }
    }
    if (control && control->cancelled()) throw Cancelled();
    out.commit();
}

} // namespace marbler
