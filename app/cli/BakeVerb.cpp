// `marbler bake`: a design baked into an object's texture for other 3D tools (glTF, OBJ), or a
// solid design as a stack of cross-sections (spec/cli.md).

#include "cli/Cli.h"
#include "marbler/Bake.h"
#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Mesh.h"
#include "marbler/RenderToFile.h"
#include "marbler/Sampling.h"

#include "WindowModule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace marbler::cli {
namespace {
namespace fs = std::filesystem;

constexpr const char* BakeHelp =
    R"(usage: marbler bake GENOME --mesh NAME|FILE -o OUT.{glb,gltf,obj} [options]
       marbler bake GENOME --slices AXIS [--count N] -o DIR [options]

Bakes a design onto an object for other 3D tools: every texel of an N x N texture gets the
colour of the design at the point of the object's surface that the texel covers, the object
placed in the design's box as the window shows it. The object keeps its own texture
coordinates when it has them within [0, 1] (the built-in objects have their natural ones:
round and up, a cube by its faces), and a flat design lies on them, fitted into the texture by
its longer side, so the texture is the design itself. Otherwise each triangle, or pair of
triangles sharing an edge, gets a patch of its own (a mosaic that the object's UVs put back
together), and a flat design is projected onto the object along z, upright seen from the front.
The object is written in its own units with its normals: .glb (glTF 2.0 binary, the PNG
texture inside), .gltf (with OUT.bin and OUT.png beside it) or .obj (with OUT.mtl and OUT.png).

With --slices, writes a solid design as N cross-sections across AXIS (x, y or z), the centres
of N equal layers of the design box: DIR/slice-0000.png, ... (each as `marbler render --slice`
renders it), for voxel tools and print.

Nothing is left behind unless every file is written; exit status 0 success, 2 bad usage or
bad input, 1 any other failure.

options:
  -o, --output OUT          the mesh file (.glb, .gltf, .obj), or the folder for --slices
  --mesh NAME|FILE          vase, sphere, cube, torus, teapot, book, cushion, cloth, wall,
                            or a mesh file assimp reads (OBJ, STL, PLY, glTF, ...)
  --texture N               the texture's side in texels (default 2048, at most 16384)
  --aa MODE                 samples a texel or pixel: none, rgss (default for the texture;
                            none for slices), quincunx, grid2..grid8, checker4, rooks8
  --slices AXIS             a stack of cross-sections across x, y or z instead of a mesh
  --count N                 how many cross-sections (default 64, at most 10000)
  --width W, --height H     the size of each cross-section (default 1024 on the longer side)
  --threads N               worker threads (default: every core)
  --progress                show progress on stderr even when it is not a terminal
  --quiet                   no progress line
  -h, --help                this text
)";

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

int bakeMesh(const Args& args, const std::string& genomeName, const fs::path& outFile) {
    const std::string extension = lower(outFile.extension().string());
    const std::vector<std::string> known = texturedMeshExtensions();
    if (std::find(known.begin(), known.end(), extension) == known.end())
        throw InputError("'" + outFile.string() + "': unknown mesh format '" + extension +
                         "' (use .glb, .gltf or .obj)");
    BakeSettings settings;
    settings.textureSize = parseIntOption(args, "texture", 2048, 1, MaxBakeTexture);
    settings.aa = args.get("aa").value_or("rgss");
    aaPattern(settings.aa);
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);

    const Genome genome = loadGenomeArgument("bake", genomeName);
    if (genome.source)
        throw InputError(genomeName +
                         ": a design with a source image cannot be baked yet (only inks and the background)");

    const std::string meshName = *args.get("mesh");
    MeshData mesh = meshOf(meshName);
    if (!hasUsableUvs(mesh)) {
        if (!mesh.uvs.empty())
            std::cerr << "marbler bake: warning: " << meshName
                      << ": its texture coordinates leave [0, 1] (tiled or mirrored); baking into new ones\n";
        try {
            mesh = withGeneratedUvs(mesh, settings.textureSize);
        } catch (const InputError& e) {
            throw InputError("--mesh " + meshName + ": " + e.what());
        }
    }

    ProgressLine progress(args);
    RenderControl control;
    control.progress = [&](double f) {
        progress.show("baking " + std::to_string(static_cast<int>(f * 100.0)) + "%");
    };
    const BakedTexture baked = bakeTexture(genome, mesh, settings, &control);
    progress.finish();
    std::string name = genome.meta.name.value_or("marbled");
    writeTexturedMesh(mesh, baked.image, outFile, name);
    return ExitOk;
}

int bakeSlices(const Args& args, const std::string& genomeName, const fs::path& outDir) {
    const std::optional<int> axis = parseAxis(*args.get("slices"));
    if (!axis) throw InputError("--slices: '" + *args.get("slices") + "' is not an axis (x, y or z)");
    Slice slice;
    slice.axis = *axis;
    const int count = parseIntOption(args, "count", 64, 1, 10000);
    RenderSettings settings;
    settings.aa = args.get("aa").value_or("none");
    aaPattern(settings.aa);
    settings.threads = parseIntOption(args, "threads", 0, 0, 1024);
    const bool hasW = args.has("width"), hasH = args.has("height");
    const int width = parseIntOption(args, "width", 0, 1, MaxImageSide);
    const int height = parseIntOption(args, "height", 0, 1, MaxImageSide);

    const Genome genome = loadGenomeArgument("bake", genomeName);
    if (genome.dimension != 3)
        throw InputError(genomeName + ": --slices needs a solid (3D) genome; this one is flat (2D)");

    // The size of each section as `render` picks it: the plane's aspect kept for a missing side.
    slice.value = 0.5 * genome.size[slice.axis];
    settings.slice = slice;
    const Region plane = effectiveRegion(genome, settings);
    const double aspect = (plane.x1 - plane.x0) / (plane.y1 - plane.y0);
    auto pixels = [](double value) { return std::clamp(int(std::lround(value)), 1, MaxImageSide); };
    settings.width = hasW            ? width
                     : hasH          ? pixels(height * aspect)
                     : aspect >= 1.0 ? 1024
                                     : pixels(1024 * aspect);
    settings.height = hasH            ? height
                      : hasW          ? pixels(width / aspect)
                      : aspect >= 1.0 ? pixels(1024 / aspect)
                                      : 1024;
    checkRenderSettings(genome, settings);

    std::error_code ec;
    if (fs::exists(outDir, ec) && !fs::is_directory(outDir, ec))
        throw InputError("-o '" + outDir.string() + "': not a folder (--slices writes a folder of images)");
    const bool madeDir = !fs::exists(outDir, ec);
    fs::create_directories(outDir, ec);
    if (ec) throw RuntimeFailure("cannot create the folder '" + outDir.string() + "': " + ec.message());

    // Each image is written atomically; a failure part way removes the ones this run wrote.
    std::vector<fs::path> written;
    ProgressLine progress(args);
    try {
        for (int k = 0; k < count; ++k) {
            settings.slice->value = (k + 0.5) * genome.size[slice.axis] / count;
            char name[32];
            std::snprintf(name, sizeof name, "slice-%04d.png", k);
            const fs::path file = outDir / name;
            renderToFile(genome, settings, file);
            written.push_back(file);
            progress.show("slicing " + std::to_string((k + 1) * 100 / count) + "%");
        }
    } catch (...) {
        for (const fs::path& file : written)
            fs::remove(file, ec);
        if (madeDir) fs::remove(outDir, ec);
        throw;
    }
    return ExitOk;
}

int bake(std::span<const std::string> words) {
    const Args args = parseArgs(
        words, {"o", "output", "mesh", "texture", "aa", "slices", "count", "width", "height", "threads"},
        {"quiet", "progress", "help", "h"});
    if (args.has("help") || args.has("h")) {
        std::cout << BakeHelp;
        return ExitOk;
    }
    oneGenomeArgument(args, "bake");
    const std::optional<std::string> output = requiredOutput(args, "bake", "OUT");
    const bool slices = args.has("slices");
    if (slices == args.has("mesh"))
        throw InputError("give either --mesh NAME|FILE or --slices AXIS (see marbler bake --help)");
    for (const char* meshOnly : {"texture"})
        if (slices && args.has(meshOnly))
            throw InputError(std::string("--") + meshOnly + " only applies with --mesh");
    for (const char* slicesOnly : {"count", "width", "height"})
        if (!slices && args.has(slicesOnly))
            throw InputError(std::string("--") + slicesOnly + " only applies with --slices");
    return slices ? bakeSlices(args, args.positional[0], *output)
                  : bakeMesh(args, args.positional[0], *output);
}

} // namespace

int runBake(std::span<const std::string> words) {
    return guarded("bake", [&] { return bake(words); });
}

} // namespace marbler::cli
