#include "marbler/Separations.h"

#include "SvgNumber.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"

#include <clipper.hpp>
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace marbler {
namespace {

namespace cl = ClipperLib;

/// Design coordinates on the clipper's integer grid of 10^-decimals units.
class Grid {
public:
    explicit Grid(int decimals)
        : mScale(std::pow(10.0, decimals)) {}

    cl::IntPoint toGrid(const glm::dvec2& p) const {
        const double x = std::round(p.x * mScale), y = std::round(p.y * mScale);
        // The clipper's full range is 2^62; its products of two coordinates need 128 bits
        // beyond 2^30, which it handles, so only the range itself is checked.
        constexpr double Limit = 4.0e18;
        if (!(std::abs(x) < Limit) || !(std::abs(y) < Limit))
            throw RuntimeFailure("an outline point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                 ") lies too far out to knock the inks out at this precision");
        return {static_cast<cl::cInt>(x), static_cast<cl::cInt>(y)};
    }
    glm::dvec2 toDesign(const cl::IntPoint& p) const {
        return {static_cast<double>(p.X) / mScale, static_cast<double>(p.Y) / mScale};
    }

private:
    double mScale;
};

cl::Paths clipPaths(cl::ClipType type, const cl::Paths& subject, const cl::Paths& clip) {
    cl::Clipper clipper;
    clipper.AddPaths(subject, cl::ptSubject, true);
    clipper.AddPaths(clip, cl::ptClip, true);
    cl::Paths out;
    // Nonzero, as SVG fills the stacked outlines: a polygon that grazes itself within the
    // tolerance covers what it would cover there.
    if (!clipper.Execute(type, out, cl::pftNonZero, cl::pftNonZero))
        throw RuntimeFailure("the inks could not be knocked out of each other");
    return out;
}

std::vector<std::vector<glm::dvec2>> toRings(const cl::Paths& paths, const Grid& grid) {
    std::vector<std::vector<glm::dvec2>> rings;
    rings.reserve(paths.size());
    for (const cl::Path& path : paths) {
        if (path.size() < 3) continue;
        std::vector<glm::dvec2>& ring = rings.emplace_back();
        ring.reserve(path.size());
        for (const cl::IntPoint& p : path)
            ring.push_back(grid.toDesign(p));
    }
    return rings;
}

/// One PNG written with libpng, which reports errors by longjmp: every libpng call is made in
/// a function with no C++ objects to unwind, and the message kept for the exception after.
struct SeparationPng {
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::FILE* file = nullptr;
    char message[256] = {};
    ~SeparationPng() {
        if (png) png_destroy_write_struct(&png, info ? &info : nullptr);
        if (file) std::fclose(file);
    }
};

void separationPngError(png_structp png, png_const_charp message) {
    auto* state = static_cast<SeparationPng*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", message);
    png_longjmp(png, 1);
}

void separationPngWarning(png_structp, png_const_charp) {}

template <typename Body> bool separationPngCall(SeparationPng& state, Body body) {
    if (setjmp(png_jmpbuf(state.png))) return false;
    body();
    return true;
}

/// Writes rows of `bits` per pixel (1 or 8 grey, or 8 indexed with `palette`) to `file`.
void writeSeparationPng(const std::filesystem::path& file, const std::string& name, int width, int height,
                        int bits, const std::vector<Color>* palette, const std::vector<std::uint8_t>& pixels,
                        const std::optional<double>& dpi) {
    auto fail = [&](const std::string& reason) {
        throw RuntimeFailure("cannot write '" + name + "': " + reason);
    };
    SeparationPng state;
    state.file = std::fopen(file.c_str(), "wb");
    if (!state.file) fail(std::strerror(errno));
    state.png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, separationPngError, separationPngWarning);
    if (!state.png) fail("out of memory");
    state.info = png_create_info_struct(state.png);
    if (!state.info) fail("out of memory");
    std::vector<png_color> colors;
    if (palette)
        for (Color c : *palette)
            colors.push_back({c.r, c.g, c.b});
    // 1-bit rows packed eight pixels a byte, the first in the high bit.
    const std::size_t stride = bits == 1 ? (std::size_t(width) + 7) / 8 : std::size_t(width);
    std::vector<png_byte> row(stride);
    bool ok = separationPngCall(state, [&] {
        png_init_io(state.png, state.file);
        png_set_compression_level(state.png, 3);
        png_set_IHDR(state.png, state.info, png_uint_32(width), png_uint_32(height), bits,
                     palette ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
        if (palette) {
            png_set_PLTE(state.png, state.info, colors.data(), int(colors.size()));
            png_set_sRGB(state.png, state.info, PNG_sRGB_INTENT_PERCEPTUAL);
        }
        if (dpi) {
            auto perMetre = png_uint_32(std::lround(*dpi / 0.0254));
            png_set_pHYs(state.png, state.info, perMetre, perMetre, PNG_RESOLUTION_METER);
        }
        png_write_info(state.png, state.info);
    });
    for (int y = 0; y < height && ok; ++y) {
        const std::uint8_t* source = pixels.data() + std::size_t(y) * std::size_t(width);
        if (bits == 1) {
            std::fill(row.begin(), row.end(), png_byte(0));
            for (int x = 0; x < width; ++x)
                if (source[x] >= 128) row[std::size_t(x) / 8] |= png_byte(0x80u >> (x % 8));
        } else {
            std::copy(source, source + width, row.begin());
        }
        ok = separationPngCall(state, [&] { png_write_row(state.png, row.data()); });
    }
    if (ok) ok = separationPngCall(state, [&] { png_write_end(state.png, nullptr); });
    if (!ok) fail(state.message);
    std::FILE* handle = std::exchange(state.file, nullptr);
    const bool flushed = std::fflush(handle) == 0 && !std::ferror(handle);
    if (std::fclose(handle) != 0 || !flushed) fail(std::strerror(errno));
}

} // namespace

SeparatedDesign knockOut(const VectorDesign& design, int decimals) {
    if (decimals < 1 || decimals > 9) throw RuntimeFailure("knockOut: decimals must be 1 to 9");
    const Grid grid(decimals);
    SeparatedDesign out;
    out.width = design.width;
    out.height = design.height;
    out.background = design.background;
    out.palette = design.palette;

    const cl::Paths page = {{grid.toGrid({0.0, 0.0}), grid.toGrid({design.width, 0.0}),
                             grid.toGrid({design.width, design.height}), grid.toGrid({0.0, design.height})}};
    // Newest first: what an ink shows is what is inside the page and not yet covered by the
    // inks laid after it; then it covers that too.
    std::vector<cl::Paths> pieces(design.palette.size());
    cl::Paths covered;
    for (std::size_t k = design.outlines.size(); k-- > 0;) {
        const InkOutline& outline = design.outlines[k];
        cl::Paths polygon(1);
        polygon[0].reserve(outline.points.size());
        for (const glm::dvec2& p : outline.points)
            polygon[0].push_back(grid.toGrid(p));
        const cl::Paths inside = clipPaths(cl::ctIntersection, polygon, page);
        if (inside.empty()) continue;
        const cl::Paths visible = covered.empty() ? inside : clipPaths(cl::ctDifference, inside, covered);
        cl::Paths& piece = pieces.at(static_cast<std::size_t>(outline.color));
        piece.insert(piece.end(), visible.begin(), visible.end());
        covered = covered.empty() ? inside : clipPaths(cl::ctUnion, covered, inside);
    }

    InkLayer background;
    background.rings = toRings(covered.empty() ? page : clipPaths(cl::ctDifference, page, covered), grid);
    out.layers.push_back(std::move(background));
    for (std::size_t c = 0; c < pieces.size(); ++c) {
        InkLayer layer;
        layer.color = static_cast<int>(c);
        // The pieces of one ink do not overlap; the union joins those that touch.
        if (!pieces[c].empty()) layer.rings = toRings(clipPaths(cl::ctUnion, pieces[c], {}), grid);
        out.layers.push_back(std::move(layer));
    }
    return out;
}

std::string layerLabel(const SeparatedDesign& design, const InkLayer& layer) {
    if (layer.color < 0) return "Background " + toHex(design.background);
    return "Ink " + std::to_string(layer.color + 1) + " " +
           toHex(design.palette.at(std::size_t(layer.color)));
}

std::string toLayeredSvg(const SeparatedDesign& design, const SvgPage& page, int decimals) {
    std::size_t vertices = 0;
    for (const InkLayer& layer : design.layers)
        for (const auto& ring : layer.rings)
            vertices += ring.size();
    std::string out;
    out.reserve(1024 + vertices * (10 + 2 * decimals));
    auto number = [&](double v) { detail::appendSvgNumber(out, v, decimals); };
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"";
    out += svgLength(page.widthMm) + "\" height=\"" + svgLength(page.heightMm) + "\" viewBox=\"0 0 ";
    number(design.width);
    out += ' ';
    number(design.height);
    out += "\">\n";
    for (const InkLayer& layer : design.layers) {
        const std::string id = layer.color < 0 ? "background" : "ink-" + std::to_string(layer.color + 1);
        const Color color = layer.color < 0 ? design.background : design.palette.at(std::size_t(layer.color));
        out += "<g inkscape:groupmode=\"layer\" inkscape:label=\"" + layerLabel(design, layer) + "\" id=\"" +
               id + "\">\n";
        if (!layer.rings.empty()) {
            out += "<path fill=\"" + toHex(color) + "\" fill-rule=\"evenodd\" d=\"";
            for (std::size_t r = 0; r < layer.rings.size(); ++r) {
                const auto& ring = layer.rings[r];
                out += r == 0 ? "M" : " M";
                for (std::size_t k = 0; k < ring.size(); ++k) {
                    if (k == 1)
                        out += 'L';
                    else if (k > 1)
                        out += ' ';
                    number(ring[k].x);
                    out += ' ';
                    number(ring[k].y);
                }
                out += 'Z';
            }
            out += "\"/>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

RasterSeparations renderSeparations(const Genome& genome, const RenderSettings& settings,
                                    const RenderControl* control) {
    if (genome.source)
        throw InputError("separations cannot split a source image into inks (its pixels are no inks); "
                         "render the design as one image");
    if (genome.palette.size() > 255)
        throw InputError("separations hold at most 255 inks in an indexed PNG (this design has " +
                         std::to_string(genome.palette.size()) + ")");
    checkRenderSettings(genome, settings);
    const CpuRenderer renderer(genome);
    RasterSeparations out;
    out.width = settings.width;
    out.height = settings.height;
    out.background = genome.background;
    out.palette = genome.palette;
    const std::size_t layers = genome.palette.size() + 1;
    const std::size_t pixels = std::size_t(settings.width) * std::size_t(settings.height);
    out.coverage.assign(layers, std::vector<std::uint8_t>(pixels));
    out.indices.resize(pixels);
    // In strips, so the floats of the coverage stay a few megabytes at any size.
    const int rows = std::max(1, int((std::size_t(1) << 22) / (std::size_t(settings.width) * layers)));
    std::vector<float> strip;
    for (int y0 = 0; y0 < settings.height; y0 += rows) {
        const int y1 = std::min(settings.height, y0 + rows);
        strip.resize(std::size_t(y1 - y0) * std::size_t(settings.width) * layers);
        RenderControl part;
        if (control) {
            part.cancel = control->cancel;
            if (control->progress)
                part.progress = [&, y0, y1](double f) {
                    control->progress((y0 + f * (y1 - y0)) / settings.height);
                };
        }
        renderer.renderRowsCoverage(settings, y0, y1, strip.data(), control ? &part : nullptr);
        for (std::size_t p = 0, n = std::size_t(y1 - y0) * std::size_t(settings.width); p < n; ++p) {
            const float* w = strip.data() + p * layers;
            const std::size_t at = std::size_t(y0) * std::size_t(settings.width) + p;
            std::size_t most = 0;
            for (std::size_t k = 0; k < layers; ++k) {
                out.coverage[k][at] =
                    static_cast<std::uint8_t>(std::lround(std::clamp(w[k], 0.0f, 1.0f) * 255.0f));
                if (w[k] >= w[most]) most = k;
            }
            // Layer 0 is the background, the last entry of the indexed palette.
            out.indices[at] = static_cast<std::uint8_t>(most == 0 ? layers - 1 : most - 1);
        }
    }
    return out;
}

std::vector<std::string> separationFileNames(std::size_t inks) {
    std::vector<std::string> names = {"background.png"};
    for (std::size_t k = 1; k <= inks; ++k)
        names.push_back("ink-" + std::to_string(k) + ".png");
    names.push_back("indexed.png");
    return names;
}

std::vector<std::filesystem::path> writeSeparations(const RasterSeparations& separations,
                                                    const std::filesystem::path& folder,
                                                    const SeparationFileOptions& options) {
    if (options.maskBits != 1 && options.maskBits != 8)
        throw InputError("a separation mask holds 1 or 8 bits a pixel (got " +
                         std::to_string(options.maskBits) + ")");
    std::error_code error;
    if (std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error))
        throw InputError("'" + folder.string() + "' is a file; separations are written into a folder");
    std::filesystem::create_directories(folder, error);
    if (error) throw RuntimeFailure("cannot make the folder '" + folder.string() + "': " + error.message());
    const std::vector<std::string> names = separationFileNames(separations.palette.size());
    AtomicFileSet files;
    for (std::size_t k = 0; k < separations.coverage.size(); ++k) {
        AtomicFile& file = files.add(folder / names[k]);
        writeSeparationPng(file.temporary(), (folder / names[k]).string(), separations.width,
                           separations.height, options.maskBits, nullptr, separations.coverage[k],
                           options.dpi);
    }
    std::vector<Color> palette = separations.palette;
    palette.push_back(separations.background);
    AtomicFile& indexed = files.add(folder / names.back());
    writeSeparationPng(indexed.temporary(), (folder / names.back()).string(), separations.width,
                       separations.height, 8, &palette, separations.indices, options.dpi);
    return files.commit();
}

} // namespace marbler
