#pragma once
// `marbler render --separations DIR`: the render's inks as masks and an indexed PNG
// (marbler/Separations.h), kept out of RenderVerb.cpp but for the lines that call it.

#include "cli/Cli.h"
#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <optional>

namespace marbler::cli {

/// Whether `--separations` is given without `-o`, which it then stands in for.
bool separationsWithoutOutput(const Args& args);

/// Renders and writes the separations `--separations DIR` asks for, with `--mask-bits` and the
/// render's settings (its size and antialiasing) and resolution. Throws InputError for what
/// separations cannot take (--mesh, --repeat, --gpu, a source image, a bad --mask-bits),
/// RuntimeFailure for I/O failures.
void writeRenderSeparations(const Args& args, const Genome& genome, const RenderSettings& settings,
                            const std::optional<double>& dpi);

} // namespace marbler::cli
