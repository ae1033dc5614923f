// marbler-imageio.so: the one file of Marbler that sees OpenImageIO. Loaded on first use by
// render/image (ImageFile.cpp, SourceDecoder.cpp) for the formats it does not write itself
// (EXR, JPEG, ...) and to decode source images.

#include "ImageSink.h"
#include "SrgbProfile.h"
#include "marbler/Error.h"
#include "marbler/OneLine.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace marbler::detail {
namespace {

/// The largest source accepted: 32,768 pixels on a side and 64 megapixels (8192 x 8192) in
/// all. Checked against the header before any pixel is decoded, so a hostile file that claims a
/// huge size cannot make the loader allocate gigabytes; decoding then needs the raster (12
/// bytes a pixel, 768 MiB at most) and the reader's own buffer of the image's native pixels.
constexpr std::int64_t MaxSourceSide = 32768;
constexpr std::int64_t MaxSourcePixels = std::int64_t(1) << 26;

bool isLinearColorSpace(const OIIO::ImageSpec& spec) {
    std::string space = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(space.begin(), space.end(), space.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return space == "linear" || space == "scene_linear" || space == "lin_srgb";
}

LinearRaster readRaster(OIIO::ImageInput& in, const std::string& name) {
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.width < 1 || spec.height < 1 || spec.depth > 1 || spec.nchannels < 1)
        throw InputError("source image " + name + ": unsupported size " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height));
    if (spec.width > MaxSourceSide || spec.height > MaxSourceSide ||
        std::int64_t(spec.width) * spec.height > MaxSourcePixels)
        throw InputError("source image " + name + ": " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height) + " pixels is too large (sources may have at most " +
                         std::to_string(MaxSourceSide) + " pixels on a side and " +
                         std::to_string(MaxSourcePixels >> 20) + " megapixels in all)");
    LinearRaster raster;
    raster.width = spec.width;
    raster.height = spec.height;
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
    raster.rgb.resize(count * 3);
    // Decoded straight into the raster: RGB as it is; a grey image (with or without alpha) into
    // the red of each pixel, then repeated. Alpha and further channels are not read.
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    const OIIO::stride_t pixelStride = OIIO::stride_t(3 * sizeof(float));
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raster.rgb.data(), pixelStride))
        throw InputError("source image " + name + ": " + oneLine(in.geterror()));
    const bool linear = isLinearColorSpace(spec);
    for (std::size_t p = 0; p < count; ++p) {
        float* px = raster.rgb.data() + p * 3;
        if (channels == 1) px[1] = px[2] = px[0];
        if (!linear)
            for (int c = 0; c < 3; ++c)
                px[c] = static_cast<float>(srgbToLinear(std::clamp(double(px[c]), 0.0, 1.0)));
    }
    return raster;
}

/// Bytes in memory read by OpenImageIO's readers. OpenImageIO 2.4's own IOMemReader copies from
/// any offset it is asked for, a negative one included (an OpenEXR line offset table can ask
/// for one: found by fuzz_source, a heap read before the buffer); this one reads nothing
/// outside the bytes.
class BoundedMemReader final : public OIIO::Filesystem::IOProxy {
public:
    BoundedMemReader(const unsigned char* data, std::size_t size)
        : IOProxy("", Read)
        , mData(data)
        , mSize(size) {}
    const char* proxytype() const override { return "memreader"; }
    std::size_t read(void* buf, std::size_t size) override {
        const std::size_t got = pread(buf, size, m_pos);
        m_pos += std::int64_t(got);
        return got;
    }
    std::size_t pread(void* buf, std::size_t size, std::int64_t offset) override {
        if (offset < 0 || std::uint64_t(offset) >= mSize) return 0;
        size = std::min(size, mSize - std::size_t(offset));
        std::memcpy(buf, mData + offset, size);
        return size;
    }
    std::size_t size() const override { return mSize; }

private:
    const unsigned char* mData;
    std::size_t mSize;
};

/// OpenImageIO's reader named `reader`, and only it: ImageInput::open(file) would pick one by
/// the file's name and then try every format it knows.
std::unique_ptr<OIIO::ImageInput> createReader(const std::string& reader, const std::string& name) {
    auto in = OIIO::ImageInput::create(reader);
    if (!in)
        throw InputError("source image " + name + ": this OpenImageIO has no " + reader +
                         " reader: " + oneLine(OIIO::geterror()));
    return in;
}

/// An OpenImageIO writer. OpenImageIO 2.4 writes a JPEG's density with the unit byte 0 (aspect
/// ratio only) even when asked for inches; finish() sets the JFIF unit to 1 (dots per inch) so
/// the dpi means something.
class OiioSink final : public ImageSink {
public:
    explicit OiioSink(const SinkTarget& target)
        : mTarget(target) {
        mOut = OIIO::ImageOutput::create(target.displayName);
        if (!mOut) {
            OIIO::geterror(); // clear the library's message; ours says it better
            throw InputError("'" + target.displayName + "': unknown image format '" + target.extension +
                             "' (use .png, .tif, .exr or .jpg)");
        }
        const std::string& ext = target.extension;
        mFloat = ext == ".exr" || ext == ".hdr";
        mJpegDpi = target.options.dpi && (ext == ".jpg" || ext == ".jpeg");
        OIIO::ImageSpec spec(target.width, target.height, 3,
                             mFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:ColorSpace", mFloat ? "Linear" : "sRGB");
        spec.attribute("Software", "Marbler");
        if (ext == ".jpg" || ext == ".jpeg") {
            spec.attribute("Compression", "jpeg:95");
            const std::vector<unsigned char>& icc = srgbIccProfile();
            spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, int(icc.size())), icc.data());
        }
        if (target.options.dpi) {
            spec.attribute("XResolution", static_cast<float>(*target.options.dpi));
            spec.attribute("YResolution", static_cast<float>(*target.options.dpi));
            spec.attribute("ResolutionUnit", "inch");
        }
        if (!mOut->open(target.file, spec)) fail(oneLine(mOut->geterror()));
        mOpen = true;
    }
    ~OiioSink() override {
        if (mOpen) mOut->close();
    }

    bool linearFloat() const override { return mFloat; }

    void writeRows(int y0, int y1, const void* rows) override {
        if (!mOut->write_scanlines(y0, y1, 0, mFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8, rows))
            fail(oneLine(mOut->geterror()));
    }

    void finish() override {
        mOpen = false;
        if (!mOut->close()) fail(oneLine(mOut->geterror()));
        if (mJpegDpi) markJfifDensityInInches();
    }

private:
    [[noreturn]] void fail(const std::string& reason) {
        throw RuntimeFailure("cannot write '" + mTarget.displayName + "': " + reason);
    }

    void markJfifDensityInInches() {
        std::FILE* f = std::fopen(mTarget.file.c_str(), "r+b");
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

    SinkTarget mTarget;
    std::unique_ptr<OIIO::ImageOutput> mOut;
    bool mFloat = false;
    bool mJpegDpi = false;
    bool mOpen = false;
};

class OiioModule final : public ImageIoModule {
public:
    std::unique_ptr<ImageSink> openSink(const SinkTarget& target) override {
        return std::make_unique<OiioSink>(target);
    }

    LinearRaster readFile(const std::string& file, const std::string& reader,
                          const std::string& name) override {
        auto in = createReader(reader, name);
        OIIO::ImageSpec spec;
        if (!in->open(file, spec))
            throw InputError("source image " + name + ": cannot load: " + oneLine(in->geterror()));
        LinearRaster raster = readRaster(*in, name);
        in->close();
        return raster;
    }

    LinearRaster readMemory(const unsigned char* data, std::size_t size, const std::string& reader,
                            const std::string& name) override {
        auto in = createReader(reader, name);
        if (!in->supports("ioproxy"))
            throw InputError("source image " + name + ": a " + reader +
                             " image cannot be read from a data URL; save it as a file beside the genome");
        BoundedMemReader memory(data, size);
        if (!in->set_ioproxy(&memory))
            throw InputError("source image " + name + ": cannot decode: " + oneLine(in->geterror()));
        OIIO::ImageSpec spec;
        if (!in->open("source." + reader, spec))
            throw InputError("source image " + name + ": cannot decode: " + oneLine(in->geterror()));
        LinearRaster raster = readRaster(*in, name);
        in->close();
        return raster;
    }

    std::string version() const override { return OIIO_VERSION_STRING; }
};

} // namespace
} // namespace marbler::detail

extern "C" __attribute__((visibility("default"))) marbler::detail::ImageIoModule* marbler_imageio_module() {
    static marbler::detail::OiioModule module;
    return &module;
}
