#include "marbler/SourceDecoder.h"

#include "ImageData.h"
#include "ImageSink.h"
#include "SourceFormat.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Image.h"
#include "marbler/SourcePath.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

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

/// Decodes a `data:image/...;base64,` URI. Throws InputError.
LinearRaster decodeDataUri(const std::string& text) {
    const std::string name = "(data URL)";
    std::size_t comma = text.find(',');
    if (comma == std::string::npos) throw InputError("source image " + name + ": no ',' in the data URL");
    std::string header = text.substr(5, comma - 5);
    if (header.size() < 7 || header.substr(header.size() - 7) != ";base64")
        throw InputError("source image " + name + ": only base64 data URLs are supported");
    std::vector<unsigned char> bytes;
    try {
        bytes = decodeBase64(std::string_view(text).substr(comma + 1));
    } catch (const InputError& e) {
        throw InputError("source image " + name + ": " + e.what());
    }
    // The MIME type is not believed: the bytes say what they are.
    const SourceFormat format = sniffSourceFormat(bytes.data(), bytes.size());
    if (format.reader.empty()) throw InputError("source image " + name + ": " + refusedSourceFormat(format));
    if (format.reader == "openexr") {
        const std::string damaged =
            checkExrHeader(bytes.data(), std::min(bytes.size(), ExrHeaderBytes), bytes.size());
        if (!damaged.empty()) throw InputError("source image " + name + ": " + damaged);
    }
    return imageIoModule().readMemory(bytes.data(), bytes.size(), format.reader, name);
}

/// Decodes a source image file with the one reader its first bytes allow. Throws InputError.
LinearRaster decodeFile(const fs::path& file) {
    const std::string name = "'" + file.string() + "'";
    unsigned char head[SourceSniffBytes] = {};
    std::size_t got = 0;
    {
        std::ifstream in(file, std::ios::binary);
        if (!in) throw InputError("source image " + name + ": cannot read: " + std::strerror(errno));
        in.read(reinterpret_cast<char*>(head), sizeof head);
        got = std::size_t(in.gcount());
    }
    const SourceFormat format = sniffSourceFormat(head, got);
    if (format.reader.empty()) throw InputError("source image " + name + ": " + refusedSourceFormat(format));
    if (format.reader == "openexr") {
        std::vector<unsigned char> exr(ExrHeaderBytes);
        std::ifstream in(file, std::ios::binary);
        in.read(reinterpret_cast<char*>(exr.data()), std::streamsize(exr.size()));
        std::error_code ec;
        const std::uint64_t size = fs::file_size(file, ec);
        const std::string damaged = checkExrHeader(exr.data(), std::size_t(in.gcount()), ec ? 0 : size);
        if (!damaged.empty()) throw InputError("source image " + name + ": " + damaged);
    }
    return imageIoModule().readFile(file.string(), format.reader, name);
}

} // namespace detail

LinearRaster decodeSourceImage(const Genome& genome) {
    const std::string& text = genome.source->image;
    if (!isDataUri(text)) {
        // The rule of SourcePath.h comes first: a refused file is never opened.
        const fs::path file = sourceFileToRead(genome);
        try {
            return detail::decodeFile(file);
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

LinearRaster linearRasterOfSrgb8(const std::uint8_t* rgb, int width, int height, std::size_t stride) {
    // As the image module decodes an 8-bit file: OpenImageIO converts a byte v to the float
    // v * (1.0f / 255), which is then sRGB-decoded in double precision.
    static const std::vector<float> table = [] {
        std::vector<float> t(256);
        for (int v = 0; v < 256; ++v)
            t[std::size_t(v)] =
                static_cast<float>(srgbToLinear(std::clamp(double(float(v) * (1.0f / 255.0f)), 0.0, 1.0)));
        return t;
    }();
    LinearRaster raster;
    raster.width = width;
    raster.height = height;
    raster.rgb.resize(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* row = rgb + std::size_t(y) * stride;
        float* out = raster.rgb.data() + std::size_t(y) * std::size_t(width) * 3;
        for (std::size_t i = 0; i < std::size_t(width) * 3; ++i)
            out[i] = table[row[i]];
    }
    return raster;
}

} // namespace marbler
