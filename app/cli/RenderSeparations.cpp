#include "cli/RenderSeparations.h"

#include "marbler/Error.h"
#include "marbler/Separations.h"

namespace marbler::cli {

bool separationsWithoutOutput(const Args& args) {
    return args.has("separations") && !args.has("o") && !args.has("output");
}

void writeRenderSeparations(const Args& args, const Genome& genome, const RenderSettings& settings,
                            const std::optional<double>& dpi) {
    for (const char* other : {"mesh", "repeat", "gpu"})
        if (args.has(other))
            throw InputError(std::string("--separations and --") + other +
                             " exclude each other (separations are of the flat render)");
    SeparationFileOptions options;
    options.maskBits = parseIntOption(args, "mask-bits", 8, 1, 8);
    if (options.maskBits != 1 && options.maskBits != 8)
        throw InputError("--mask-bits: must be 1 or 8 (got " + *args.get("mask-bits") + ")");
    options.dpi = dpi;
    const std::string folder = *args.get("separations");
    if (folder.empty()) throw InputError("--separations: give the folder to write the separations into");
    ProgressLine progress(args);
    RenderControl control;
    control.progress = [&](double f) {
        progress.show("separating " + std::to_string(static_cast<int>(f * 100.0)) + "%");
    };
    const RasterSeparations separations = renderSeparations(genome, settings, &control);
    progress.finish();
    writeSeparations(separations, folder, options);
}

} // namespace marbler::cli
