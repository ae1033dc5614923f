#include "marbler/Separations.h"

#include "marbler/Error.h"

#include <clipper.hpp>

#include <charconv>
#include <cmath>

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

void writeCoordinate(std::string& out, double value, int decimals) {
    char text[64];
    auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
    if (ec != std::errc()) throw RuntimeFailure("a coordinate cannot be written");
    std::string_view s(text, end - text);
    if (s.find('.') != std::string_view::npos) {
        while (s.back() == '0')
            s.remove_suffix(1);
        if (s.back() == '.') s.remove_suffix(1);
    }
    if (s == "-0") s = "0";
    out.append(s);
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
    auto number = [&](double v) { writeCoordinate(out, v, decimals); };
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

} // namespace marbler
