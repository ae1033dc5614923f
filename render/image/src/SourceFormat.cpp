#include "SourceFormat.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace marbler::detail {
namespace {
using namespace std::string_view_literals;

bool startsWith(const unsigned char* bytes, std::size_t size, std::string_view magic, std::size_t at = 0) {
    return size >= at + magic.size() && std::memcmp(bytes + at, magic.data(), magic.size()) == 0;
}

/// A signature at the start of a file and what it is.
struct Signature {
    std::string_view magic;
    std::size_t at;
    const char* reader; ///< the allowed reader, or nullptr
    const char* description;
};

// Allowed first, then the formats OpenImageIO (or a program beside it) would also read, named
// so that a refusal says what the file is. Order matters only where one signature begins with
// another's (none here).
constexpr std::array Signatures{
    Signature{"\x89PNG\r\n\x1a\n"sv, 0, "png", "a PNG image"},
    Signature{"\xff\xd8\xff"sv, 0, "jpeg", "a JPEG image"},
    Signature{"II*\0"sv, 0, "tiff", "a TIFF image"},
    Signature{"MM\0*"sv, 0, "tiff", "a TIFF image"},
    Signature{"II+\0"sv, 0, "tiff", "a BigTIFF image"},
    Signature{"MM\0+"sv, 0, "tiff", "a BigTIFF image"},
    Signature{"v/1\x01"sv, 0, "openexr", "an OpenEXR image"},
    Signature{"8BPS"sv, 0, nullptr, "a Photoshop file"},
    Signature{"SDPX"sv, 0, nullptr, "a DPX file"},
    Signature{"XPDS"sv, 0, nullptr, "a DPX file"},
    Signature{"\x80\x2a\x5f\xd7"sv, 0, nullptr, "a Cineon file"},
    Signature{"\xd7\x5f\x2a\x80"sv, 0, nullptr, "a Cineon file"},
    Signature{"GIF87a"sv, 0, nullptr, "a GIF image"},
    Signature{"GIF89a"sv, 0, nullptr, "a GIF image"},
    Signature{"BM"sv, 0, nullptr, "a BMP image"},
    Signature{"DDS "sv, 0, nullptr, "a DirectDraw Surface (DDS) file"},
    Signature{"SIMPLE  ="sv, 0, nullptr, "a FITS file"},
    Signature{"DICM"sv, 128, nullptr, "a DICOM file"},
    Signature{"\0\0\0\x0cjP  \r\n\x87\n"sv, 0, nullptr, "a JPEG 2000 image"},
    Signature{"\xff\x4f\xff\x51"sv, 0, nullptr, "a JPEG 2000 codestream"},
    Signature{"#?RADIANCE"sv, 0, nullptr, "a Radiance HDR image"},
    Signature{"#?RGBE"sv, 0, nullptr, "a Radiance HDR image"},
    Signature{"Ptex"sv, 0, nullptr, "a Ptex file"},
    Signature{"\x01\xda"sv, 0, nullptr, "an SGI image"},
    Signature{"\x53\x80\xf6\x34"sv, 0, nullptr, "a Softimage PIC image"},
    Signature{"\0\0\x01\0"sv, 0, nullptr, "a Windows icon"},
    Signature{"\x1a\x45\xdf\xa3"sv, 0, nullptr, "a Matroska or WebM video"},
    Signature{"%PDF"sv, 0, nullptr, "a PDF document"},
    Signature{"PK\x03\x04"sv, 0, nullptr, "a ZIP archive"},
    Signature{"\x1f\x8b"sv, 0, nullptr, "a gzip archive"},
    Signature{"<"sv, 0, nullptr, "an SVG or other XML or HTML file"},
    Signature{"{"sv, 0, nullptr, "a JSON file"},
};

/// A name read from a file, fit for a one-line message: printable ASCII kept, anything else '?'.
std::string printable(const std::string& name) {
    std::string out;
    for (char c : name.substr(0, 64))
        out += c >= 0x20 && c < 0x7f ? c : '?';
    return out;
}

} // namespace

SourceFormat sniffSourceFormat(const unsigned char* bytes, std::size_t size) {
    // RIFF containers: WebP is allowed, the rest (AVI, WAV) are not.
    if (startsWith(bytes, size, "RIFF")) {
        if (startsWith(bytes, size, "WEBP", 8)) return {"webp", "a WebP image"};
        if (startsWith(bytes, size, "AVI ", 8)) return {"", "an AVI video"};
        return {"", "a RIFF file that is not a WebP image"};
    }
    // ISO base media files: HEIF, AVIF and the video containers.
    if (startsWith(bytes, size, "ftyp", 4)) {
        for (std::string_view brand : {"heic"sv, "heix"sv, "hevc"sv, "mif1"sv, "msf1"sv})
            if (startsWith(bytes, size, brand, 8)) return {"", "a HEIF image"};
        if (startsWith(bytes, size, "avif", 8) || startsWith(bytes, size, "avis", 8))
            return {"", "an AVIF image"};
        return {"", "an MP4 or QuickTime file"};
    }
    if (size >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7') return {"", "a Netpbm image"};
    if (startsWith(bytes, size, "FORM") &&
        (startsWith(bytes, size, "ILBM", 8) || startsWith(bytes, size, "RGB8", 8) ||
         startsWith(bytes, size, "RGBN", 8) || startsWith(bytes, size, "CIMG", 8)))
        return {"", "an IFF image"};
    for (const Signature& s : Signatures)
        if (startsWith(bytes, size, s.magic, s.at)) return {s.reader ? s.reader : "", s.description};
    if (size == 0) return {"", "an empty file"};
    char first[3 * 8 + 1] = {};
    std::size_t shown = size < 8 ? size : 8;
    for (std::size_t i = 0; i < shown; ++i)
        std::snprintf(first + 3 * i, 4, i + 1 < shown ? "%02X " : "%02X", bytes[i]);
    return {"", std::string("a file of an unknown kind (it begins ") + first + ")"};
}

std::string checkExrHeader(const unsigned char* head, std::size_t size, std::uint64_t fileSize) {
    if (size < 8) return "a damaged OpenEXR image (too short)";
    const bool multipart = (head[5] & 0x10) != 0; // version field bit 12
    std::size_t at = 8;
    // A null-terminated name of at most 255 characters; "" at the end of a header.
    auto name = [&](std::string& out) {
        out.clear();
        while (at < size && head[at] != 0 && out.size() <= 255)
            out += char(head[at++]);
        if (at >= size || out.size() > 255) return false;
        ++at;
        return true;
    };
    for (int part = 0;; ++part) {
        std::string attribute, type;
        int attributes = 0;
        for (;;) {
            if (!name(attribute)) return "an OpenEXR header that does not end within 1 MiB";
            if (attribute.empty()) break;
            if (!name(type) || at + 4 > size) return "an OpenEXR header that does not end within 1 MiB";
            const std::uint32_t length = std::uint32_t(head[at]) | std::uint32_t(head[at + 1]) << 8 |
                                         std::uint32_t(head[at + 2]) << 16 |
                                         std::uint32_t(head[at + 3]) << 24;
            at += 4;
            if (length > 0x7fffffffu || at + std::uint64_t(length) > fileSize)
                return "a damaged OpenEXR image: its attribute '" + printable(attribute) + "' says " +
                       std::to_string(length) + " bytes, more than the file holds";
            if (at + length > size) return "an OpenEXR header that does not end within 1 MiB";
            at += length;
            ++attributes;
        }
        // A single-part file has one header; a multi-part one ends its list with an empty header.
        if (!multipart || attributes == 0) return "";
        if (part > 1000) return "an OpenEXR file of more than 1,000 parts";
    }
}

std::string refusedSourceFormat(const SourceFormat& format) {
    return format.description + ": sources must be PNG, JPEG, TIFF, EXR or WebP";
}

} // namespace marbler::detail
