#pragma once
/// Marbler's optional modules: shared objects loaded on first use, so that a command pays only
/// for the libraries it needs. OpenImageIO alone pulls in some 260 libraries (OpenCV, GDAL,
/// FFmpeg, ...) whose loading costs far more than most renders; Qt and assimp are needed only by
/// the window and the GL back end. The `marbler` executable links none of them; the formats and
/// features that need them load `marbler-imageio.so` or `marbler-window.so` when first used.

#include <string>

namespace marbler {

/// The entry point of a module (a C function returning its interface object), looked up in the
/// module file `fileName` (e.g. "marbler-imageio.so"). Modules are searched in, in order: the
/// folder named by the environment variable MARBLER_MODULE_DIR; the executable's own folder;
/// `../lib/marbler` beside it (an installed layout); and the build tree's module folder. A
/// module stays loaded for the life of the process, and is loaded once however many threads
/// ask. Throws RuntimeFailure saying what is missing and where it was looked for.
void* moduleEntry(const std::string& fileName, const std::string& entryName);

/// Whether a module file (e.g. "marbler-imageio.so") is loaded in this process, by whichever
/// copy of this library loaded it (each module links its own); never loads it.
bool moduleLoaded(const std::string& fileName);

/// The folder the module would be loaded from, or why none is found (for `marbler doctor`).
std::string moduleLocation(const std::string& fileName);

} // namespace marbler
