#pragma once
/// Image formats: how a file names its format, and where Marbler's formats come from (for
/// `marbler doctor`).

#include <filesystem>
#include <optional>
#include <string>

namespace marbler {

/// A file's extension in lower case with its dot (".png"), which is how every writer and
/// reader picks a format; "" when there is none.
std::string lowerExtension(const std::filesystem::path& file);

/// The formats written without OpenImageIO, with their libraries' versions, e.g.
/// "PNG (libpng 1.6.39), TIFF (libtiff 4.5.0), PPM".
std::string builtinImageFormats();

/// OpenImageIO's version, loading its module (marbler-imageio.so) if need be. Throws
/// RuntimeFailure when the module cannot be loaded.
std::string openImageIoVersion();

/// OpenImageIO's version when its module is already loaded in this process (by an export or a
/// source image), else nullopt: asking never loads it, since loading costs more than most
/// renders (the window's About box says "not loaded" instead).
std::optional<std::string> loadedOpenImageIoVersion();

} // namespace marbler
