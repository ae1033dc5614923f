// `marbler render`: a raster of a genome (spec/cli.md), on the CPU by default, with the GL back
// end on request.

#include "cli/Cli.h"
#include "cli/RenderSeparations.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Growth.h"
#include "marbler/ImageFormats.h"
#include "marbler/ObjectView.h"
#include "marbler/PrintProfile.h"
#include "marbler/RenderToFile.h"
#include "marbler/Repeat.h"
#include "marbler/Sampling.h"

#include "WindowModule.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

namespace marbler::cli {
namespace {

constexpr const char* RenderHelp = R"(usage: marbler render GENOME -o OUT [options]

Renders a genome to a raster image. GENOME is a genome file or a PNG or TIFF image Marbler
wrote, which carries its genome; every PNG and TIFF written carries the genome too. The format follows OUT's extension: .png, .tif/.tiff,
.jpg/.jpeg (8-bit sRGB) or .exr (linear half float). Nothing is written unless the whole image
is; exit status 0 success, 2 bad usage or bad input, 1 any other failure.

options:
  -o, --output OUT          the image file to write (required)
  --width W                 width in pixels; alone, the height keeps the region's aspect
  --height H                height in pixels; alone, the width keeps the region's aspect
                            (default: 1024 pixels on the longer side)
  --aa MODE                 antialiasing: none (default), rgss, quincunx, grid2..grid8,
                            checker4, rooks8; samples are averaged in linear light
  --region X0,Y0,X1,Y1      the part of the design space to render (default: all of it; for a
                            slice, in the slice's own axes: x-y for z=, x-z for y=, y-z for x=)
  --slice AXIS=VALUE        a cross-section of a solid (3D) genome, e.g. z=500; required in 3D
  --steps K                 the design after its first K steps (the entries of "initial",
                            then of "operations"; 0 is the bare bath), from 0 to the number of
                            steps; the image carries that partial design
  --dpi N                   print resolution written into the file
  --size WxH{cm,mm,in}      print size, e.g. 42x59.4cm; with --dpi it sets the pixel size
  --threads N               worker threads (default: every core)
  --gpu                     render with the OpenGL back end (needs a GL 4.3 context)
  --mesh NAME|FILE          show the design on an object: vase, sphere, cube, torus, teapot,
                            book, cushion, cloth, wall or a mesh file (needs --view); a solid
                            design is carved from its block, a flat one laid on the object's
                            texture coordinates (a mesh file needs its own UVs for
                            that); drawn by the CPU with no display, or with --gpu by OpenGL
  --view YAW,PITCH          orbit camera angles in degrees for --mesh
  --supersample 1|3|5       supersampling of --mesh renders: n x n samples a pixel (default 3)
  --cut NX,NY,NZ,OFFSET     cut the --mesh object open: the part where NX*x + NY*y + NZ*z >
                            OFFSET (design coordinates) is removed, showing the marbled inside
  --allow-external-source   read the genome's source image even where it lies outside the
                            genome's folder (an absolute path, `..`, a link leading out); by
                            default such a genome is refused, so a shared genome cannot read
                            your other files
  --repeat mirror           a seamless repeat tile for print and textiles: the render and its
                            mirror images 2 x 2 (twice the width and height: the design at
                            the top left, its horizontal mirror at the top right, the vertical
                            mirrors of both below), so every edge meets its own mirror image
                            and the tile wraps without a seam; the other options apply to the
                            design (--size and --dpi: each quarter has that print size)
  --yardage WxL{cm,mm,in}   a length of fabric of a design whose bath wraps (straight,
                            half-drop or brick, docs/genome-format.md): W across, L along,
                            the design repeated on its lattice at the print size --size of
                            one tile and --dpi, e.g. --size 32x32cm --dpi 150 --yardage
                            140x300cm; streamed by rows as large renders are
  --separations DIR         separations a printer can use, into the folder DIR (made if
                            missing; -o is then optional): a mask per layer (background.png,
                            ink-1.png, ... in palette order; white where the ink is, 8-bit
                            coverage with --aa's samples) and indexed.png, whose palette is the
                            inks and then the background; a flat design or a --slice; bleed
                            drawn as hard edges, as in svg
  --mask-bits 1|8           the masks' depth with --separations (default 8; 1: on where at
                            least half the pixel is the ink, for screens)
  --icc PRINTER.icc         a CMYK TIFF for a printer: the sRGB render converted by LittleCMS
                            to the colour space of the given CMYK output (printer) profile,
                            which is embedded; OUT must be .tif or .tiff; not with --mesh,
                            --gpu, --repeat or --separations
  --intent NAME             how --icc maps colours the printer cannot print: perceptual
                            (default), relative, saturation or absolute (colorimetric)
  --bits 8|16               bits a sample of the --icc TIFF (default 8; 16 from the linear
                            average, for further grading)
  --progress                show progress on stderr even when it is not a terminal
  --quiet                   no progress line
  -h, --help                this text
)";

int renderGenome(const Args& args, const std::string& genomeName, const Genome& genome,
                 RenderSettings settings, const ExportOptions& exportOptions,
                 const std::optional<std::pair<double, double>>& printSize,
                 const std::filesystem::path& outFile);

int render(std::span<const std::string> words) {
    Args args = parseArgs(words, {"o",       "output",  "width",  "height", "aa",          "region",
                                  "slice",   "dpi",     "size",   "mesh",   "view",        "supersample",
                                  "cut",     "threads", "repeat", "steps",  "separations", "mask-bits",
                                  "yardage", "icc",     "intent", "bits"},
                          {"gpu", "quiet", "progress", "allow-external-source", "help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << RenderHelp;
        return ExitOk;
    }
    oneGenomeArgument(args, "render");
    // --separations DIR may stand in for -o (RenderSeparations.h).
    const std::optional<std::string> output =
        separationsWithoutOutput(args) ? std::string() : requiredOutput(args, "render", "OUT");
    const std::filesystem::path outFile(*output);

    // Everything the command line can check is checked before the genome is read.
    RenderSettings settings;
    settings.aa = args.get("aa").value_or("none");
    aaPattern(settings.aa);
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);
    if (auto region = args.get("region")) {
        std::vector<double> r = parseNumberList("region", *region, 4);
        settings.region = Region{r[0], r[1], r[2], r[3]};
    }
    if (auto slice = args.get("slice")) settings.slice = parseSlice(*slice);
    ExportOptions exportOptions;
    if (args.has("dpi")) exportOptions.dpi = parseDpiOption(args, 0.0);
    std::optional<std::pair<double, double>> printSize;
    if (auto size = args.get("size")) {
        printSize = parsePrintSize(*size);
        if (!exportOptions.dpi) throw InputError("--size needs --dpi to give the pixel size");
        if (args.has("width") || args.has("height"))
            throw InputError("--size and --width/--height exclude each other");
    }
    if (auto repeat = args.get("repeat"); repeat && *repeat != "mirror")
        throw InputError("--repeat: '" + *repeat +
                         "' is not a repeat Marbler makes; 'mirror' is the one (an exact "
                         "straight repeat is impossible for drops)");
    // ---- --yardage (docs/cli.md, "Yardage") ----
    if (auto text = args.get("yardage")) {
        parsePrintSize(*text);
        if (!printSize) throw InputError("--yardage needs --size (the print size of one tile) and --dpi");
        for (const char* other : {"repeat", "mesh", "slice", "separations", "gpu"})
            if (args.has(other))
                throw InputError(std::string("--yardage and --") + other + " exclude each other");
    }
    // ---- end --yardage ----
    const bool meshMode = args.has("mesh");
    if (meshMode && !args.has("view")) throw InputError("--mesh needs --view YAW,PITCH");
    for (const char* meshOnly : {"view", "supersample", "cut"})
        if (!meshMode && args.has(meshOnly))
            throw InputError(std::string("--") + meshOnly + " only applies with --mesh");
    if (auto cut = args.get("cut")) {
        std::vector<double> plane = parseNumberList("cut", *cut, 4);
        if (plane[0] == 0.0 && plane[1] == 0.0 && plane[2] == 0.0)
            throw InputError("--cut: the plane's normal NX,NY,NZ must not be zero (got '" + *cut + "')");
    }

    if (args.has("mask-bits") && !args.has("separations"))
        throw InputError("--mask-bits only applies with --separations");
    const int steps = parseIntOption(args, "steps", -1, 0, std::numeric_limits<int>::max());
    // ---- --icc: a CMYK TIFF for a printer's profile (marbler/PrintProfile.h) ----
    for (const char* iccOnly : {"intent", "bits"})
        if (args.has(iccOnly) && !args.has("icc"))
            throw InputError(std::string("--") + iccOnly + " only applies with --icc");
    if (auto icc = args.get("icc")) {
        for (const char* other : {"mesh", "gpu", "repeat", "separations"})
            if (args.has(other))
                throw InputError(
                    std::string("--icc and --") + other +
                    " exclude each other (the CMYK TIFF is of the flat render, made on the CPU)");
        if (const std::string ext = lowerExtension(outFile); ext != ".tif" && ext != ".tiff")
            throw InputError("--icc writes a CMYK TIFF: OUT must end in .tif or .tiff (got '" +
                             outFile.string() + "')");
        if (auto intent = args.get("intent"); intent && !parseRenderingIntent(*intent))
            throw InputError("--intent: '" + *intent +
                             "' is not a rendering intent; perceptual, relative, saturation or absolute");
        if (const int bits = parseIntOption(args, "bits", 8, 8, 16); bits != 8 && bits != 16)
            throw InputError("--bits: must be 8 or 16 (got " + *args.get("bits") + ")");
        // The profile is read and checked before the genome (and read again to convert).
        loadPrintProfile(*icc);
    }
    // ---- end --icc ----

    const std::string genomeName = args.positional[0];
    Genome genome = loadGenomeArgument("render", genomeName);
    genome.allowExternalSource = args.has("allow-external-source");
    if (steps >= 0) {
        if (static_cast<std::size_t>(steps) > stepCount(genome))
            throw InputError(genomeName + ": --steps: must be between 0 and the design's " +
                             std::to_string(stepCount(genome)) + " steps (got " + std::to_string(steps) +
                             ")");
        genome = designAfterSteps(genome, static_cast<std::size_t>(steps));
    }

    try {
        return renderGenome(args, genomeName, genome, settings, exportOptions, printSize, outFile);
    } catch (const InputError& e) {
        // One line that names the file: the genome, unless the message names one already.
        std::string message = e.what();
        if (message.find('\'') != std::string::npos || message.starts_with(genomeName)) throw;
        throw InputError(genomeName + ": " + message);
    }
}

int renderGenome(const Args& args, const std::string& genomeName, const Genome& genome,
                 RenderSettings settings, const ExportOptions& exportOptions,
                 const std::optional<std::pair<double, double>>& printSize,
                 const std::filesystem::path& outFile) {
    const bool meshMode = args.has("mesh");
    auto withGenome = [&](const std::string& message) { return genomeName + ": " + message; };
    if (genome.dimension == 3 && !settings.slice && !meshMode)
        throw InputError(withGenome("a solid (3D) genome needs --slice AXIS=VALUE (e.g. z=" +
                                    std::to_string(static_cast<int>(genome.size.z / 2)) + ") or --mesh"));
    if (genome.dimension == 2 && settings.slice)
        throw InputError(withGenome("--slice needs a solid (3D) genome; this one is flat (2D)"));

    // Pixel size: --size with --dpi, else --width/--height keeping the region's aspect, else
    // 1024 on the longer side.
    int width = 0, height = 0;
    if (printSize) {
        width = pixelsOf(printSize->first * *exportOptions.dpi, "--size at --dpi (width)");
        height = pixelsOf(printSize->second * *exportOptions.dpi, "--size at --dpi (height)");
    } else if (meshMode) {
        width = parseIntOption(args, "width", 1024, 1, MaxImageSide);
        height = parseIntOption(args, "height", args.has("width") ? width : 1024, 1, MaxImageSide);
        if (!args.has("width") && args.has("height")) width = height;
    } else {
        // The region and slice are checked before the aspect is taken from them.
        RenderSettings probe = settings;
        probe.width = probe.height = 1;
        checkRenderSettings(genome, probe);
        Region region = effectiveRegion(genome, settings);
        double aspect = (region.x1 - region.x0) / (region.y1 - region.y0);
        bool hasW = args.has("width"), hasH = args.has("height");
        if (hasW) width = parseIntOption(args, "width", 0, 1, MaxImageSide);
        if (hasH) height = parseIntOption(args, "height", 0, 1, MaxImageSide);
        if (hasW && !hasH) height = pixelsOf(width / aspect, "the height for width " + std::to_string(width));
        if (hasH && !hasW)
            width = pixelsOf(height * aspect, "the width for height " + std::to_string(height));
        if (!hasW && !hasH) {
            if (aspect >= 1.0) {
                width = 1024;
                height = pixelsOf(1024 / aspect, "the height for width 1024");
            } else {
                height = 1024;
                width = pixelsOf(1024 * aspect, "the width for height 1024");
            }
        }
    }
    settings.width = width;
    settings.height = height;
    // ---- --yardage: the region the tile covers, repeated to the fabric's size ----
    if (auto text = args.get("yardage")) {
        const std::pair<double, double> yardage = parsePrintSize(*text); // checked in render()
        if (!genome.wrap || genome.dimension != 2)
            throw InputError(withGenome("--yardage needs a design whose bath wraps (\"wrap\" in the genome; "
                                        "marbler paper makes one), or its tiles would meet in seams"));
        const Region tile = effectiveRegion(genome, settings);
        const double across = yardage.first / printSize->first, along = yardage.second / printSize->second;
        settings.region = Region{tile.x0, tile.y0, tile.x0 + (tile.x1 - tile.x0) * across,
                                 tile.y0 + (tile.y1 - tile.y0) * along};
        settings.width = pixelsOf(yardage.first * *exportOptions.dpi, "--yardage at --dpi (width)");
        settings.height = pixelsOf(yardage.second * *exportOptions.dpi, "--yardage at --dpi (length)");
    }
    // ---- end --yardage ----
    if (args.has("separations")) {
        writeRenderSeparations(args, genome, settings, exportOptions.dpi);
        if (outFile.empty()) return ExitOk;
    }
    const bool repeat = args.has("repeat");
    if (repeat && (2 * std::int64_t(width) > MaxImageSide || 2 * std::int64_t(height) > MaxImageSide ||
                   4 * std::int64_t(width) * height > MaxImagePixels))
        throw InputError("--repeat mirror: the tile of " + std::to_string(2 * std::int64_t(width)) + " x " +
                         std::to_string(2 * std::int64_t(height)) + " pixels is too large (at most " +
                         std::to_string(MaxImageSide) + " pixels a side and " +
                         std::to_string(MaxImagePixels) + " pixels in all)");

    ProgressLine progress(args);
    RenderControl control;
    control.progress = [&](double f) {
        progress.show("rendering " + std::to_string(static_cast<int>(f * 100.0)) + "%");
    };

    // The object, its camera and its cut (--mesh).
    std::optional<MeshSettings> object;
    if (meshMode) {
        MeshSettings mesh;
        mesh.width = width;
        mesh.height = height;
        mesh.mesh = *args.get("mesh");
        std::vector<double> view = parseNumberList("view", *args.get("view"), 2);
        mesh.yaw = view[0];
        mesh.pitch = view[1];
        mesh.supersample = parseIntOption(args, "supersample", 3, 1, 5);
        if (mesh.supersample != 1 && mesh.supersample != 3 && mesh.supersample != 5)
            throw InputError("--supersample: must be 1, 3 or 5 (got " + *args.get("supersample") + ")");
        if (auto cut = args.get("cut")) {
            std::vector<double> plane = parseNumberList("cut", *cut, 4);
            mesh.cut = CutPlane{{plane[0], plane[1], plane[2]}, plane[3]};
        }
        mesh.threads = settings.threads;
        object = mesh;
    }
    // The image carries the design it shows, as renderToFile's do.
    ExportOptions carrying = exportOptions;
    carrying.genome = serializeGenome(genome);

    if (object && !args.has("gpu")) {
        // The CPU's own object path: rasterised and coloured here, with no display and no GL.
        const Image image = renderObjectOnCpu(genome, meshOf(object->mesh), *object, &control);
        progress.finish();
        writeImage(repeat ? mirrorRepeat(image) : image, outFile, carrying);
        return ExitOk;
    }
    if (args.has("gpu")) {
#ifdef MARBLER_HAVE_GUI
        gl::ViewRequest request;
        request.useGl = true;
        request.raster = settings;
        request.object = object;
        const Image image = app::windowModule().renderView(genome, request);
        writeImage(repeat ? mirrorRepeat(image) : image, outFile, carrying);
        return ExitOk;
#else
        throw RuntimeFailure("--gpu needs the OpenGL back end, and this build has none (built without "
                             "MARBLER_BUILD_GUI)");
#endif
    }

    if (repeat) {
        // The tile is made in memory from the whole render (strips would need each one twice).
        Image image = CpuRenderer(genome).render(settings, &control);
        progress.finish();
        writeImage(mirrorRepeat(image), outFile, exportOptions);
        return ExitOk;
    }
    if (auto icc = args.get("icc")) {
        // ---- --icc (checked in render()) ----
        CmykTiffOptions cmyk;
        cmyk.intent = parseRenderingIntent(args.get("intent").value_or("perceptual")).value();
        cmyk.bitsPerSample = parseIntOption(args, "bits", 8, 8, 16);
        cmyk.dpi = exportOptions.dpi;
        renderToCmykTiff(genome, settings, outFile, loadPrintProfile(*icc), cmyk, &control);
        progress.finish();
        return ExitOk;
    }
    renderToFile(genome, settings, outFile, exportOptions, &control);
    progress.finish();
    return ExitOk;
}

} // namespace

int runRender(std::span<const std::string> words) {
    return guarded("render", [&] { return render(words); });
}

} // namespace marbler::cli
