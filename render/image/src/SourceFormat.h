#pragma once
/// Internal to render/image: which image formats a genome's `source` may be, told by the file's
/// first bytes alone (never by its name or a data URL's MIME type), so that a stranger's file
/// reaches one well-worn decoder or none. The allow-list: PNG, JPEG, TIFF, OpenEXR and WebP.

#include <cstddef>
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

/// The refusal's text for a format that is not allowed: "a Photoshop file: sources must be
/// PNG, JPEG, TIFF, EXR or WebP".
std::string refusedSourceFormat(const SourceFormat& format);

} // namespace marbler::detail
