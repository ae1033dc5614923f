#pragma once
/// Internal to render/image: which image formats a genome's `source` may be, told by the file's
/// first bytes alone (never by its name or a data URL's MIME type), so that a stranger's file
/// reaches one well-worn decoder or none. The allow-list: PNG, JPEG, TIFF, OpenEXR and WebP.

#include <cstddef>
#include <cstdint>
#include <string>

namespace marbler::detail {

/// What a source's first bytes say it is.
struct SourceFormat {
    /// OpenImageIO's name of the one reader allowed to decode it ("png", "jpeg", "tiff",
    /// "openexr", "webp"); empty when the format is not allowed.
    std::string reader;
    /// What it is, for messages: "a PNG image", "a Photoshop file", "a file of an unknown kind".
    std::string description;
};

/// The bytes looked at: enough for every signature recognised (DICOM's is at offset 128).
inline constexpr std::size_t SourceSniffBytes = 136;

/// Tells the format from the first `size` bytes of a source (fewer than SourceSniffBytes when
/// the file is shorter).
SourceFormat sniffSourceFormat(const unsigned char* bytes, std::size_t size);

/// The most of an OpenEXR file's head read to check its header (checkExrHeader).
inline constexpr std::size_t ExrHeaderBytes = std::size_t(1) << 20;

/// Checks an OpenEXR header's attributes against the file's size before OpenEXR reads it:
/// OpenEXR 3.1 allocates whatever size an attribute declares (up to 2 GiB) before finding the
/// file shorter. `head` holds the file's first `size` bytes (at most ExrHeaderBytes),
/// `fileSize` its whole length. Returns "" when the header is sound, else what is wrong.
std::string checkExrHeader(const unsigned char* head, std::size_t size, std::uint64_t fileSize);

/// The refusal's text for a format that is not allowed: "a Photoshop file: sources must be
/// PNG, JPEG, TIFF, EXR or WebP".
std::string refusedSourceFormat(const SourceFormat& format);

} // namespace marbler::detail
