// `marbler paper`: a procedural marbled paper in one command (spec/cli.md, marbler/Paper.h).

#include "cli/Cli.h"

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Paper.h"
#include "marbler/RenderToFile.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <system_error>

namespace marbler::cli {
namespace {

constexpr const char* PaperHelp = R"(usage: marbler paper [options] --seed N -o OUT

Makes a marbled paper: layers of ink drops at Poisson-disk spaced points, one colour each and
smaller for each later colour, combed by a few stretch passes along the sheet, each weaker
than the one before, with a slight bleed. Writes the image OUT (its format by extension, the
print resolution in the file, the genome inside PNG and TIFF) and the genome beside it as
OUT's name with .marble.json. The same options and seed give the same files.

The default recipe is the procedural marbled-paper post's, as published: painted circles on
the first colour, radii and shifts shrinking by the golden ratio, tooth gaps growing by it,
teeth ending at the borders, and a bath that wraps, so the sheet is a straight-repeat tile
(docs/paper.md). --recipe classic makes Marbler's first papers: drops that push each other
on a cream bath, with no wrap.

options:
  --recipe NAME         post (default) or classic
  --repeat LATTICE      the post's repeat: straight (default), half-drop (each column
                        dropped half a sheet) or brick (each row moved half a sheet); its
                        passes' teeth span the period the repeat needs (docs/genome-format.md)
  --size WxH{cm,mm,in}  the sheet, e.g. 21x29.7cm (default: A4, 21x29.7cm); the design is
                        measured in millimetres of it
  --dpi N               print resolution: the image is the size times N pixels (default 300)
  --colors K            inks, 1 to 16 (default 5)
  --passes P            stretch passes, 0 to 10 (default 3)
  --pastel              pale, soft inks on a white bath (default: random inks on cream)
  --seed N              the seed, a non-negative 64-bit integer (required)
  -o, --output OUT      the image to write (required): .png, .tif/.tiff, .jpg/.jpeg, .exr
  --threads N           worker threads (default: every core)
  --progress            show progress on stderr even when it is not a terminal
  --quiet               no progress line
  -h, --help            this text
)";

/// The genome beside an image: "sheet.png" gives "sheet.marble.json".
std::filesystem::path genomeBeside(const std::filesystem::path& image) {
    std::filesystem::path file = image;
    return file.replace_extension(".marble.json");
}

int paper(std::span<const std::string> words) {
    Args args = parseArgs(
        words, {"size", "dpi", "colors", "passes", "seed", "o", "output", "threads", "recipe", "repeat"},
        {"pastel"});
    if (args.has("h") || args.has("help")) {
        std::cout << PaperHelp;
        return ExitOk;
    }
    if (!args.positional.empty())
        throw InputError("unexpected argument '" + args.positional[0] + "' (see marbler paper --help)");

    // Every option is checked before anything is made or written.
    std::pair<double, double> inches = parsePrintSize(args.get("size").value_or("21x29.7cm"));
    const double dpi = parseDpiOption(args, 300.0);
    PaperOptions options;
    const std::string recipe = args.get("recipe").value_or("post");
    if (recipe == "classic")
        options.recipe = PaperRecipe::Classic;
    else if (recipe != "post")
        throw InputError("--recipe: must be post or classic (got '" + recipe + "')");
    // ---- --repeat (docs/genome-format.md, "Half-drop and brick repeats") ----
    if (auto repeat = args.get("repeat")) {
        const std::optional<Lattice> lattice = latticeFromName(*repeat);
        if (!lattice)
            throw InputError("--repeat: must be straight, half-drop or brick (got '" + *repeat + "')");
        if (options.recipe == PaperRecipe::Classic && *lattice != Lattice::Straight)
            throw InputError("--repeat " + *repeat +
                             ": the classic recipe does not wrap; --recipe post makes repeats");
        options.lattice = *lattice;
    }
    // ---- end --repeat ----
    // Millimetres, to the micrometre: "21x29.7cm" is 210 x 297, not 210.00000000000003.
    options.width = std::round(inches.first * 25.4 * 1000.0) / 1000.0;
    options.height = std::round(inches.second * 25.4 * 1000.0) / 1000.0;
    options.colors = parseIntOption(args, "colors", options.colors, 1, MaxPaperColors);
    options.passes = parseIntOption(args, "passes", options.passes, 0, MaxPaperPasses);
    options.pastel = args.has("pastel");
    const std::uint64_t seed = parseSeedOption(args, "seed");
    const std::optional<std::string> out = requiredOutput(args, "paper");
    const std::filesystem::path image(*out);
    const std::filesystem::path genomeFile = genomeBeside(image);

    RenderSettings settings;
    settings.width = pixelsOf(inches.first * dpi, "--size at --dpi (width)");
    settings.height = pixelsOf(inches.second * dpi, "--size at --dpi (height)");
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);
    const Genome genome = paperGenome(seed, options);

    ExportOptions exportOptions;
    exportOptions.dpi = dpi;
    ProgressLine progress(args);
    RenderControl control;
    control.progress = [&](double f) {
        progress.show("rendering " + std::to_string(static_cast<int>(f * 100.0)) + "%");
    };
    renderToFile(genome, settings, image, exportOptions, &control);
    progress.finish();
    try {
        saveGenome(genome, genomeFile);
    } catch (...) {
        // Both files or neither.
        std::error_code ignored;
        std::filesystem::remove(image, ignored);
        throw;
    }
    return ExitOk;
}

} // namespace

int runPaper(std::span<const std::string> words) {
    return guarded("paper", [&] { return paper(words); });
}

} // namespace marbler::cli
