// `marbler svg`: vector output of a flat design (spec/cli.md); the tracing is in render
// (marbler/Vector.h).

#include "cli/Cli.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "marbler/Vector.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>

namespace marbler::cli {
namespace {

constexpr const char* SvgHelp = R"(usage: marbler svg GENOME -o OUT.svg [--tolerance T] [--simplify] [--stats]

Writes a flat (2D) design as an SVG file: the background as a full rectangle, then every ink
as a filled path, oldest first, so later inks cover earlier ones (a drop inside a drop makes a
ring, a spray covers what lies beneath). Each path is the circle its drop or spray laid,
carried forward through every later step; its vertices lie on the true boundary, and a vertex
is added wherever two neighbours would be more than T design units apart. Where the outline
is straight, vertices within T/100 of their neighbours' chord are dropped (chords stay <= T
unless --simplify). The viewBox is the design space in design units. Solid (3D) genomes and
genomes with a source image cannot be drawn as vectors (render them as rasters). Nothing is
written unless the whole file is; exit status 0 success, 2 bad usage or bad input, 1 any
other failure.

options:
  -o, --output OUT.svg   the SVG file to write (required)
  --tolerance T          the largest distance between neighbouring vertices, in design
                         units (default 1; larger gives smaller files); at most 4,000,000
                         vertices in all, more is bad input (give a larger T)
  --simplify             where the outline is straight (every vertex within T/100 of the
                         chord) let chords span up to 16 T, waiving the spacing above
                         there: some 4 to 8 times fewer vertices
  --stats                print outlines, vertices (and those dropped as straight), bytes
                         and seconds on stdout
  -h, --help             this text
)";

int svg(std::span<const std::string> words) {
    Args args = parseArgs(words, {"o", "output", "tolerance"}, {"simplify", "stats", "help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << SvgHelp;
        return ExitOk;
    }
    oneGenomeArgument(args, "svg");
    const std::optional<std::string> output = requiredOutput(args, "svg", "OUT.svg");
    const std::filesystem::path outFile(*output);
    if (lowerExtension(outFile) != ".svg")
        throw InputError(*output + ": the output of marbler svg must end in .svg");
    VectorOptions options;
    options.tolerance = parseDoubleOption(args, "tolerance", 1.0);
    if (!(options.tolerance > 0.0))
        throw InputError("--tolerance: must be a positive number of design units (got " +
                         *args.get("tolerance") + ")");
    // Straight runs may span up to 16 T: about 4 x fewer vertices at T = 1 on the examples.
    if (args.has("simplify")) options.straightChord = 16.0;

    const std::string genomeName = args.positional[0];
    Genome genome = loadGenomeArgument("svg", genomeName);

    const auto start = std::chrono::steady_clock::now();
    VectorDesign design;
    try {
        design = traceDesign(genome, options);
    } catch (const InputError& e) {
        throw InputError(genomeName + ": " + e.what());
    }
    const std::string text = toSvg(design, decimalsFor(options.tolerance));
    writeFileAtomically(outFile, text);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (design.gapsAtDepthCap > 0) {
        // A stylus strong enough to drag ink (c = 15 |alpha| p / (16 reach) >= 1) gathers the
        // outlines on its track into its tip, finer than any refinement reaches.
        const bool dragging =
            std::any_of(genome.operations.begin(), genome.operations.end(), [](const Operation& op) {
                const double pressure =
                    op.pressure.empty() ? 1.0 : *std::max_element(op.pressure.begin(), op.pressure.end());
                return op.tool == Tool::Stylus &&
                       15.0 * std::abs(op.alpha) * pressure / (16.0 * op.reach) >= 1.0;
            });
        std::cerr
            << "marbler svg: warning: " << genomeName << ": " << design.gapsAtDepthCap
            << " gaps stay wider than the tolerance where an outline runs through the centre of a later "
               "drop (the drop covers them)"
            << (dragging ? " or where a stylus drags ink into its tip (the ink there is finer than the "
                           "tolerance)"
                         : "")
            << "\n";
    }
    if (args.has("stats"))
        std::cout << "outlines " << design.outlines.size() << " vertices " << design.vertexCount
                  << " dropped-as-straight " << design.droppedAsStraight << " bytes " << text.size()
                  << " seconds " << seconds << '\n';
    return ExitOk;
}

} // namespace

int runSvg(std::span<const std::string> words) {
    return guarded("svg", [&] { return svg(words); });
}

} // namespace marbler::cli
