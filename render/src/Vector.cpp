#include "marbler/Vector.h"

#include "SvgNumber.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"
#include "marbler/Separations.h"
#include "marbler/Tools.h"
#include "marbler/Workers.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <exception>
#include <mutex>
#include <numbers>
#include <optional>

namespace marbler {
namespace {

/// Samples taken round every circle before refinement. Refinement only looks between samples
/// (at both ends and the midpoint), so a lobe a later stroke pulls out of a stretch whose ends
/// and middle land close together would be missed; many short starting stretches make that
/// unlikely.
constexpr int InitialSamples = 64;

/// One ink's circle carried forward through the steps after it, refined adaptively.
class OutlineTracer {
public:
    OutlineTracer(const std::vector<PreparedOp>& ops, std::size_t step, const VectorOptions& options,
                  std::atomic<std::size_t>& traced, std::atomic<std::size_t>& gaps)
        : mOps(ops)
        , mStep(step)
        , mCenter(ops[step].c.x, ops[step].c.y)
        , mRadius(ops[step].r)
        , mOptions(options)
        , mTraced(traced)
        , mGaps(gaps) {}

    /// The circle's point at angle theta, mapped through every later step.
    glm::dvec2 at(double theta) const {
        glm::dvec3 p(mCenter.x + mRadius * std::cos(theta), mCenter.y + mRadius * std::sin(theta), 0.0);
        for (std::size_t j = mStep + 1; j < mOps.size(); ++j)
            p = forwardMap(mOps[j], p);
        return {p.x, p.y};
    }

    std::vector<glm::dvec2> trace() {
        std::vector<glm::dvec2> out;
        const double step = 2.0 * std::numbers::pi / InitialSamples;
        glm::dvec2 first = at(0.0), previous = first;
        push(out, first);
        for (int i = 1; i <= InitialSamples; ++i) {
            double ta = (i - 1) * step, tb = i * step;
            glm::dvec2 next = i == InitialSamples ? first : at(tb);
            refine(ta, previous, tb, next, 0, out);
            if (i < InitialSamples) push(out, next);
            previous = next;
        }
        return out;
    }

private:
    void push(std::vector<glm::dvec2>& out, const glm::dvec2& p) {
        if (mTraced.fetch_add(1, std::memory_order_relaxed) >= mOptions.maxVertices)
            throw InputError("a tolerance of " + formatTolerance() + " needs more than " +
                             std::to_string(mOptions.maxVertices) + " vertices; give a larger tolerance");
        out.push_back(p);
    }

    std::string formatTolerance() const {
        char text[32];
        auto [end, ec] = std::to_chars(text, text + sizeof text, mOptions.tolerance);
        return std::string(text, ec == std::errc() ? end : text);
    }

    /// Appends the points strictly between a and b. The midpoint is looked at even when a and
    /// b are close, so a filament a stroke pulls out between two close samples is not missed.
    void refine(double ta, const glm::dvec2& pa, double tb, const glm::dvec2& pb, int depth,
                std::vector<glm::dvec2>& out) {
        const double tol = mOptions.tolerance;
        double tm = 0.5 * (ta + tb);
        glm::dvec2 pm = at(tm);
        bool wide = glm::distance(pa, pb) > tol || glm::distance(pa, pm) > tol || glm::distance(pm, pb) > tol;
        if (!wide) return;
        if (depth >= mOptions.maxDepth) {
            mGaps.fetch_add(1, std::memory_order_relaxed);
            push(out, pm);
            return;
        }
        refine(ta, pa, tm, pm, depth + 1, out);
        push(out, pm);
        refine(tm, pm, tb, pb, depth + 1, out);
    }

    const std::vector<PreparedOp>& mOps;
    std::size_t mStep;
    glm::dvec2 mCenter;
    double mRadius;
    const VectorOptions& mOptions;
    std::atomic<std::size_t>& mTraced;
    std::atomic<std::size_t>& mGaps;
};

// ---- Issue 23: outlines on a wrapping bath ----
/// Where the bath wraps, `outline` (traced in the plane: every step of such a bath commutes with
/// the lattice's translations, so its forward maps carry the lattice's images of a circle to the
/// images of its outline) and each of its images over the lattice whose box reaches into the
/// tile [0, w) x [0, h): ink that a pass carries out over one edge comes back in over the other.
/// Elsewhere the outline alone, where its box reaches the design space. Empty: it shows nowhere.
/// `lo` and `hi` bound the outline as traced.
std::vector<InkOutline> imagesInTile(InkOutline outline, const glm::dvec2& lo, const glm::dvec2& hi,
                                     const Genome& genome) {
    const double w = genome.size.x, h = genome.size.y;
    auto reaches = [&](const glm::dvec2& o) {
        return hi.x + o.x > 0.0 && hi.y + o.y > 0.0 && lo.x + o.x < w && lo.y + o.y < h;
    };
    std::vector<InkOutline> images;
    if (!genome.wrap) {
        if (reaches(glm::dvec2(0.0))) images.push_back(std::move(outline));
        return images;
    }
    // The lattice of the tile: (w, h/2) and (0, h) half-drop, (w, 0) and (w/2, h) brick.
    const glm::dvec2 shift = genome.lattice == Lattice::HalfDrop ? glm::dvec2(0.0, 0.5 * h)
                             : genome.lattice == Lattice::Brick  ? glm::dvec2(0.5 * w, 0.0)
                                                                 : glm::dvec2(0.0);
    const glm::dvec2 a(w, shift.y), b(shift.x, h);
    auto add = [&](long i, long j) {
        const glm::dvec2 o = double(i) * a + double(j) * b;
        if (!reaches(o)) return;
        InkOutline image = outline;
        if (i != 0 || j != 0)
            for (glm::dvec2& p : image.points)
                p += o;
        images.push_back(std::move(image));
    };
    // Each image's offset is i a + j b; b.x = 0 but for brick and a.y = 0 but for half-drop, so
    // one index's range follows from one coordinate and the other's from the first (with a margin).
    if (shift.x > 0.0) {
        for (long j = long(std::floor(-hi.y / h)) - 2; j <= long(std::ceil((h - lo.y) / h)) + 2; ++j)
            for (long i = long(std::floor((-hi.x - double(j) * b.x) / w)) - 2;
                 i <= long(std::ceil((w - lo.x - double(j) * b.x) / w)) + 2; ++i)
                add(i, j);
    } else {
        for (long i = long(std::floor(-hi.x / w)) - 2; i <= long(std::ceil((w - lo.x) / w)) + 2; ++i)
            for (long j = long(std::floor((-hi.y - double(i) * a.y) / h)) - 2;
                 j <= long(std::ceil((h - lo.y - double(i) * a.y) / h)) + 2; ++j)
                add(i, j);
    }
    return images;
}
// ---- end issue 23 ----

/// Distance from p to the segment a-b.
double distanceToSegment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    glm::dvec2 ab = b - a;
    double len2 = glm::dot(ab, ab);
    double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::distance(p, a + t * ab);
}

/// Drops vertices where the outline is straight: from each kept vertex the next kept one is the
/// farthest whose chord is at most straightChord x tolerance long and passes within
/// `straightness` x tolerance of every vertex it replaces. Returns how many were dropped.
std::size_t simplify(std::vector<glm::dvec2>& points, const VectorOptions& options) {
    const double tol = options.straightChord * options.tolerance;
    const double deviation = options.straightness * options.tolerance;
    const std::size_t n = points.size();
    if (n < 4) return 0;
    std::vector<glm::dvec2> kept;
    kept.reserve(n);
    std::size_t a = 0;
    kept.push_back(points[0]);
    while (a < n) {
        // Candidates run up to n, the first point again, which closes the polygon.
        auto point = [&](std::size_t i) { return points[i % n]; };
        std::size_t b = a + 1;
        // At most 256 vertices merged into one chord, which bounds the work where an outline is
        // sampled densely.
        for (std::size_t c = a + 2; c <= n && c <= a + 256; ++c) {
            if (glm::distance(point(a), point(c)) > tol) break;
            bool straight = true;
            for (std::size_t k = a + 1; k < c && straight; ++k)
                straight = distanceToSegment(point(k), point(a), point(c)) <= deviation;
            if (!straight) break;
            b = c;
        }
        if (b >= n) break;
        kept.push_back(points[b]);
        a = b;
    }
    std::size_t dropped = n - kept.size();
    points = std::move(kept);
    return dropped;
}

} // namespace

VectorDesign traceDesign(const Genome& genome, const VectorOptions& options) {
    if (genome.dimension != 2)
        throw InputError(
            "vector output needs a flat (2D) genome; this one is solid (3D): render a cross-section "
            "with marbler render --slice");
    if (genome.source)
        throw InputError(
            "vector output cannot draw a source image (its marbled pixels have no outlines); render "
            "the design as a raster with marbler render");
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
        throw InputError("the tolerance must be a positive number of design units");

    VectorDesign design;
    design.width = genome.size.x;
    design.height = genome.size.y;
    design.background = genome.background;
    design.palette = genome.palette;
    design.bleed = genome.bleed;
    const std::vector<PreparedOp> ops = prepare(genome);
    std::vector<std::size_t> inks;
    for (std::size_t i = 0; i < ops.size(); ++i)
        if (toolSpec(ops[i].tool).laysInk && ops[i].color >= 0) inks.push_back(i);

    // Outlines are independent: one worker per core takes the next ink from a counter. The
    // vertex cap counts every vertex traced, so whether it is reached does not depend on timing.
    // A failed outline stops the others after their current one.
    std::atomic<std::size_t> traced{0}, gaps{0};
    std::vector<std::vector<InkOutline>> outlines(inks.size()); // empty: shows nowhere
    std::vector<std::size_t> dropped(inks.size(), 0);
    forEachOnCores(inks.size(), [&](std::size_t k) {
        OutlineTracer tracer(ops, inks[k], options, traced, gaps);
        InkOutline outline;
        outline.step = inks[k];
        outline.color = ops[inks[k]].color;
        outline.points = tracer.trace();
        // An outline whose bounding box misses the design space cannot colour any of it
        // (its region lies inside that box); on a wrapping bath its images may.
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (const glm::dvec2& p : outline.points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        dropped[k] = simplify(outline.points, options);
        outlines[k] = imagesInTile(std::move(outline), lo, hi, genome);
        if (outlines[k].empty()) dropped[k] = 0;
    });

    design.gapsAtDepthCap = gaps.load();
    for (std::size_t k = 0; k < inks.size(); ++k) {
        if (outlines[k].empty()) {
            ++design.outlinesOutside;
            continue;
        }
        design.droppedAsStraight += dropped[k];
        for (InkOutline& outline : outlines[k]) {
            design.vertexCount += outline.points.size();
            design.outlines.push_back(std::move(outline));
        }
    }
    return design;
}

int decimalsFor(double tolerance) {
    if (!(tolerance > 0.0)) return 9;
    return std::clamp(static_cast<int>(std::ceil(-std::log10(tolerance / 100.0))), 1, 9);
}

SvgPage pageAtDpi(double width, double height, double dpi) {
    return {width / dpi * 25.4, height / dpi * 25.4};
}

std::string svgLength(double mm) {
    std::string out;
    detail::appendSvgNumber(out, mm, 3);
    return out + "mm";
}

std::string toSvg(const VectorDesign& design, int decimals, const std::optional<SvgPage>& page) {
    std::string out;
    out.reserve(64 + design.vertexCount * (10 + 2 * decimals));
    auto number = [&](double v) { detail::appendSvgNumber(out, v, decimals); };
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ";
    number(design.width);
    out += ' ';
    number(design.height);
    out += "\" width=\"";
    if (page)
        out += svgLength(page->widthMm);
    else
        number(design.width);
    out += "\" height=\"";
    if (page)
        out += svgLength(page->heightMm);
    else
        number(design.height);
    out += "\">\n<rect x=\"0\" y=\"0\" width=\"";
    number(design.width);
    out += "\" height=\"";
    number(design.height);
    out += "\" fill=\"" + toHex(design.background) + "\"/>\n";
    for (const InkOutline& outline : design.outlines) {
        out += "<path fill=\"" + toHex(design.palette.at(outline.color)) + "\" d=\"M";
        for (std::size_t k = 0; k < outline.points.size(); ++k) {
            if (k == 1)
                out += 'L';
            else if (k > 1)
                out += ' ';
            number(outline.points[k].x);
            out += ' ';
            number(outline.points[k].y);
        }
        out += "Z\"/>\n";
    }
    out += "</svg>\n";
    return out;
}

void writeSvg(const VectorDesign& design, const std::filesystem::path& file, int decimals, double dpi) {
    writeFileAtomically(file, toLayeredSvg(knockOut(design, decimals),
                                           pageAtDpi(design.width, design.height, dpi), decimals));
}

} // namespace marbler
