#pragma once
/// A render streamed into an image file: the CPU renderer makes strips of rows on every core
/// while the previous strip is written (marbler/ImageFile.h), so a poster never sits whole in
/// memory, and the file carries the design it shows (GenomeImage.h).

#include "marbler/CpuRenderer.h"
#include "marbler/ImageFile.h"

#include <filesystem>

namespace marbler {

/// Renders in strips of rows and writes them progressively to `file` (format by extension:
/// PNG, TIFF, EXR, JPEG, ...), atomically: a temporary file is renamed over `file` only when
/// complete; on failure or cancel nothing is left behind. Throws InputError, RuntimeFailure,
/// Cancelled.
void renderToFile(const Genome& genome, const RenderSettings& settings, const std::filesystem::path& file,
                  const ExportOptions& options = {}, const RenderControl* control = nullptr);

} // namespace marbler
