// `marbler svg`: vector output of a flat design (spec/cli.md); the tracing is in render
// (marbler/Vector.h).

#include "cli/Cli.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "marbler/Separations.h"
#include "marbler/Vector.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace marbler::cli {
namespace {

constexpr const char* SvgHelp =
    R"(usage: marbler svg GENOME -o OUT.svg [--tolerance T] [--dpi N | --size WxH{cm,mm,in}]
                  [--stacked] [--simplify] [--stats]

Writes a flat (2D) design as an SVG file a printer can use: one Inkscape layer per ink (named
"Ink N #rrggbb", with the id ink-N) and one for the background (the bath no ink covers), each
holding exactly the region where that ink shows in the finished design: later inks knocked out
of it, everything clipped to the design's rectangle, so the layers tile the page without
overlapping. The outlines are the circles the drops and sprays laid, carried forward through
every later step; their vertices lie on the true boundary, and a vertex is added wherever two
neighbours would be more than T design units apart. Where the outline is straight, vertices
within T/100 of their neighbours' chord are dropped (chords stay <= T unless --simplify). The
viewBox is the design space in design units; width and height are in millimetres, a design
unit being a pixel at N dpi (default 96, the size an SVG without units has) or the design
fitted to a print size. Solid (3D) genomes and genomes with a source image cannot be drawn as
vectors (render them as rasters). Nothing is written unless the whole file is; exit status 0
success, 2 bad usage or bad input, 1 any other failure.

options:
  -o, --output OUT.svg   the SVG file to write (required)
  --tolerance T          the largest distance between neighbouring vertices, in design
                         units (default 1; larger gives smaller files); at most 4,000,000
                         vertices in all, more is bad input (give a larger T)
  --dpi N                the printed size: a design unit is a pixel at N dpi (default 96)
  --size WxH{cm,mm,in}   the printed size, e.g. 30x30cm; it must have the design's aspect
                         (within 0.5 %); excludes --dpi
  --stacked              the paths as they are painted instead of layers: the background
                         as a full rectangle, then every ink's whole outline, oldest first,
                         later inks covering earlier ones, unclipped and without units
                         (sizes in mm only when --dpi or --size is given)
  --simplify             where the outline is straight (every vertex within T/100 of the
                         chord) let chords span up to 16 T, waiving the spacing above
                         there: some 4 to 8 times fewer vertices
  --stats                print outlines, vertices (and those dropped as straight), bytes
                         and seconds on stdout
  -h, --help             this text
)";

int svg(std::span<const std::string> words) {
    Args args = parseArgs(words, {"o", "output", "tolerance", "dpi", "size"},
                          {"simplify", "stacked", "stats", "help", "h"});
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

    // The printed size: design units as pixels at --dpi, or fitted to --size.
    const bool sized = args.has("dpi") || args.has("size");
    if (args.has("dpi") && args.has("size")) throw InputError("--dpi and --size exclude each other");
    const double dpi = parseDpiOption(args, 96.0);
    std::optional<std::pair<double, double>> printSize;
    if (auto size = args.get("size")) printSize = parsePrintSize(*size);

    const std::string genomeName = args.positional[0];
    Genome genome = loadGenomeArgument("svg", genomeName);
    SvgPage page = pageAtDpi(genome.size.x, genome.size.y, dpi);
    if (printSize) {
        const double designAspect = genome.size.x / genome.size.y;
        const double printAspect = printSize->first / printSize->second;
        if (std::abs(printAspect / designAspect - 1.0) > 0.005)
            throw InputError("--size " + *args.get("size") + ": the design is " +
                             std::to_string(int(genome.size.x)) + " x " + std::to_string(int(genome.size.y)) +
                             " units; give a print size of the same aspect");
        page = {printSize->first * 25.4, printSize->second * 25.4};
    }

    const auto start = std::chrono::steady_clock::now();
    VectorDesign design;
    try {
        design = traceDesign(genome, options);
    } catch (const InputError& e) {
        throw InputError(genomeName + ": " + e.what());
    }
    const int decimals = decimalsFor(options.tolerance);
    const std::string text =
        args.has("stacked") ? toSvg(design, decimals, sized ? std::optional<SvgPage>(page) : std::nullopt)
                            : toLayeredSvg(knockOut(design, decimals), page, decimals);
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
