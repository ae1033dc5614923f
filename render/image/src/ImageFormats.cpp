#include "marbler/ImageFormats.h"

#include "ImageSink.h"
#include "marbler/Modules.h"

#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cctype>

namespace marbler {

std::string lowerExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string builtinImageFormats() {
    // TIFFGetVersion() is a paragraph ("LIBTIFF, Version 4.5.0\nCopyright ..."): keep the number.
    std::string tiff = TIFFGetVersion();
    std::size_t version = tiff.find("Version ");
    tiff =
        version == std::string::npos ? "" : tiff.substr(version + 8, tiff.find('\n', version) - version - 8);
    return std::string("PNG (libpng ") + png_get_libpng_ver(nullptr) + "), TIFF (libtiff " + tiff + "), PPM";
}

std::string openImageIoVersion() {
    return detail::imageIoModule().version();
}

std::optional<std::string> loadedOpenImageIoVersion() {
    if (!moduleLoaded(detail::ImageIoModuleFile)) return std::nullopt;
    // Loaded already, so this copy's handle is a cheap dlopen of the same object.
    return detail::imageIoModule().version();
}

} // namespace marbler
