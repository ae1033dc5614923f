#include "marbler/Sampling.h"

#include "marbler/Error.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <sstream>

namespace marbler {
namespace {

std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

AaPattern grid(int n, bool checkerOnly) {
    AaPattern pattern;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (checkerOnly && (i + j) % 2 != 0) continue;
            pattern.offsets.push_back({(i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5});
        }
    pattern.weights.assign(pattern.offsets.size(), 1.0 / static_cast<double>(pattern.offsets.size()));
    return pattern;
}

} // namespace

const char* axisName(int axis) {
    return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

std::optional<int> parseAxis(std::string_view name) {
    if (name == "x" || name == "X") return 0;
    if (name == "y" || name == "Y") return 1;
    if (name == "z" || name == "Z") return 2;
    return std::nullopt;
}

Slice parseSlice(std::string_view text) {
    const std::size_t eq = text.find('=');
    const std::optional<int> axis =
        parseAxis(eq == std::string_view::npos ? std::string_view() : text.substr(0, eq));
    if (!axis)
        throw InputError("--slice: '" + std::string(text) +
                         "' is not AXIS=VALUE with AXIS x, y or z (e.g. z=500)");
    const std::string_view number = text.substr(eq + 1);
    Slice slice{*axis, 0.0};
    auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), slice.value);
    if (number.empty() || ec != std::errc() || end != number.data() + number.size() ||
        !std::isfinite(slice.value))
        throw InputError("--slice: '" + std::string(text) +
                         "' is not AXIS=VALUE with a number VALUE (e.g. z=500)");
    return slice;
}

SlicePlane slicePlane(int dimension, int axis, double value) {
    if (dimension != 3) return {};
    SlicePlane plane;
    plane.normalAxis = std::clamp(axis, 0, 2);
    // The two other axes in increasing order: y-z across x, x-z across y, x-y across z.
    plane.uAxis = plane.normalAxis == 0 ? 1 : 0;
    plane.vAxis = plane.normalAxis == 2 ? 1 : 2;
    plane.value = value;
    return plane;
}

SlicePlane slicePlane(int dimension, const Slice& slice, const glm::dvec3& size) {
    if (dimension != 3) return {};
    if (!slice.normal) return slicePlane(dimension, slice.axis, slice.value);
    const glm::dvec3 given = *slice.normal;
    const double length = std::sqrt(given.x * given.x + given.y * given.y + given.z * given.z);
    if (!(length > 0.0) || !std::isfinite(length)) return slicePlane(dimension, slice.axis, slice.value);
    const glm::dvec3 n = given / length;
    int nearest = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(n[i]) > std::abs(n[nearest])) nearest = i;
    // Along an axis exactly: the plane across it, which renders as it always has.
    if (n[(nearest + 1) % 3] == 0.0 && n[(nearest + 2) % 3] == 0.0)
        return slicePlane(dimension, nearest, n[nearest] > 0.0 ? slice.value : -slice.value);
    // The plane across the slice's axis, tilted: its axes, turned into this one, give the
    // plane's, so a section tilted by a handle keeps its look as it turns. Tilted nearly edge-on
    // to that axis, the nearest axis's plane gives them instead.
    const int axis =
        std::abs(n[std::clamp(slice.axis, 0, 2)]) >= 0.05 ? std::clamp(slice.axis, 0, 2) : nearest;
    SlicePlane plane = slicePlane(dimension, axis, 0.0);
    const auto dot = [](const glm::dvec3& a, const glm::dvec3& b) {
        return a.x * b.x + a.y * b.y + a.z * b.z;
    };
    const auto unitOf = [&](const glm::dvec3& a) { return a / std::sqrt(dot(a, a)); };
    const glm::dvec3 eu = plane.u(), ev = plane.v();
    plane.turned = true;
    plane.value = slice.value;
    plane.nTurned = n;
    plane.uTurned = unitOf(eu - dot(eu, n) * n);
    plane.vTurned = unitOf(ev - dot(ev, n) * n - dot(ev, plane.uTurned) * plane.uTurned);
    // The box's centre moved onto the plane; the extent is the box's span along each axis.
    const glm::dvec3 centre = 0.5 * size;
    const glm::dvec3 onPlane = centre + (slice.value - dot(centre, n)) * n;
    const auto spanOf = [&](const glm::dvec3& a) {
        return std::abs(a.x) * size.x + std::abs(a.y) * size.y + std::abs(a.z) * size.z;
    };
    plane.span = {spanOf(plane.uTurned), spanOf(plane.vTurned)};
    plane.origin = onPlane - 0.5 * plane.span.x * plane.uTurned - 0.5 * plane.span.y * plane.vTurned;
    return plane;
}

SlicePlane slicePlane(const Genome& genome, const std::optional<Slice>& slice) {
    if (genome.dimension != 3 || !slice) return {};
    return slicePlane(genome.dimension, *slice, genome.size);
}

glm::dvec2 sliceOffsetRange(const glm::dvec3& normal, const glm::dvec3& size) {
    glm::dvec2 range(0.0);
    for (int i = 0; i < 3; ++i) {
        const double reach = normal[i] * size[i];
        (reach < 0.0 ? range.x : range.y) += reach;
    }
    return range;
}

std::optional<glm::dvec3> parseDirection(std::string_view text, std::string_view what, std::string* error) {
    std::vector<double> numbers;
    bool ok = true;
    std::size_t at = 0;
    const auto separator = [](char c) { return c == ',' || c == ';' || c == ' ' || c == '\t'; };
    while (ok && at < text.size()) {
        while (at < text.size() && separator(text[at]))
            ++at;
        if (at == text.size()) break;
        std::size_t end = at;
        while (end < text.size() && !separator(text[end]))
            ++end;
        double value = 0.0;
        const char* first = text.data() + at;
        const char* last = text.data() + end;
        if (*first == '+') ++first;
        auto [stop, ec] = std::from_chars(first, last, value);
        ok = ec == std::errc() && stop == last && std::isfinite(value);
        numbers.push_back(value);
        at = end;
    }
    const std::string named = std::string(what) + " \"" + std::string(text) + "\": ";
    if (!ok || numbers.size() != 3) {
        if (error) *error = named + "type three numbers x, y, z (e.g. 1, 0, 1)";
        return std::nullopt;
    }
    const glm::dvec3 n{numbers[0], numbers[1], numbers[2]};
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    if (!(length > 0.0) || !std::isfinite(length)) {
        if (error) *error = named + "it has no direction (not all three may be 0)";
        return std::nullopt;
    }
    return n / length;
}

glm::dvec3 sliceNormal(const Slice& slice) {
    if (slice.normal) {
        const glm::dvec3 n = *slice.normal;
        const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
        if (length > 0.0 && std::isfinite(length)) return n / length;
    }
    return slicePlane(3, slice.axis).normal();
}

AaPattern aaPattern(std::string_view name) {
    AaPattern pattern;
    if (name == "none") {
        pattern.offsets = {{0.0, 0.0}};
        pattern.weights = {1.0};
    } else if (name == "rgss") {
        pattern.offsets = {
            {1.0 / 8, 3.0 / 8}, {3.0 / 8, -1.0 / 8}, {-1.0 / 8, -3.0 / 8}, {-3.0 / 8, 1.0 / 8}};
        pattern.weights.assign(4, 0.25);
    } else if (name == "quincunx") {
        pattern.offsets = {{0.0, 0.0}, {-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}};
        pattern.weights = {0.5, 0.125, 0.125, 0.125, 0.125};
    } else if (name.size() == 5 && name.substr(0, 4) == "grid" && name[4] >= '2' && name[4] <= '8') {
        pattern = grid(name[4] - '0', false);
    } else if (name == "checker4") {
        pattern = grid(4, true);
    } else if (name == "rooks8") {
        for (int r = 0; r < 8; ++r) {
            int c = (3 * r) % 8;
            pattern.offsets.push_back({(c + 0.5) / 8 - 0.5, (r + 0.5) / 8 - 0.5});
        }
        pattern.weights.assign(8, 1.0 / 8);
    } else {
        std::string list;
        for (const std::string& known : aaPatternNames())
            list += (list.empty() ? "" : ", ") + known;
        throw InputError("unknown antialiasing mode '" + std::string(name) + "' (one of " + list + ")");
    }
    pattern.name = std::string(name);
    return pattern;
}

std::vector<std::string> aaPatternNames() {
    return {"none",  "rgss",  "quincunx", "grid2", "grid3",    "grid4",
            "grid5", "grid6", "grid7",    "grid8", "checker4", "rooks8"};
}

Region effectiveRegion(const Genome& genome, const RenderSettings& settings) {
    if (settings.region) return *settings.region;
    const glm::dvec2 extent = slicePlane(genome, settings.slice).extent(genome.size);
    return {0.0, 0.0, extent.x, extent.y};
}

SampleFrame sampleFrame(const Genome& genome, const RenderSettings& settings) {
    const Region r = effectiveRegion(genome, settings);
    const double su = (r.x1 - r.x0) / settings.width;
    const double sv = (r.y1 - r.y0) / settings.height;
    const SlicePlane plane = slicePlane(genome, settings.slice);
    SampleFrame frame;
    frame.origin = plane.fromPlane({r.x0, r.y0});
    frame.du = su * plane.u();
    frame.dv = sv * plane.v();
    return frame;
}

void checkRenderSettings(const Genome& genome, const RenderSettings& settings) {
    const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    if (settings.width < 1 || settings.height < 1)
        throw InputError("image size " + size + " is empty (width and height must be at least 1)");
    if (settings.width > MaxImageSide || settings.height > MaxImageSide ||
        std::int64_t(settings.width) * settings.height > MaxImagePixels)
        throw InputError("image size " + size + " is too large (at most " + std::to_string(MaxImageSide) +
                         " pixels a side and " + std::to_string(MaxImagePixels) + " pixels in all)");
    if (settings.threads < 0)
        throw InputError("thread count must be >= 0 (got " + std::to_string(settings.threads) + ")");
    aaPattern(settings.aa); // throws for an unknown name
    if (genome.dimension == 3) {
        if (!settings.slice)
            throw InputError("a solid (3D) genome needs a slice to render a raster, e.g. --slice z=500");
        const Slice& s = *settings.slice;
        if (s.axis < 0 || s.axis > 2) throw InputError("slice axis must be x, y or z");
        if (!std::isfinite(s.value))
            throw InputError(std::string("slice ") + axisName(s.axis) + "=" + number(s.value) +
                             " is not a finite number");
        if (s.normal) {
            const glm::dvec3 n = *s.normal;
            if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) ||
                n.x * n.x + n.y * n.y + n.z * n.z == 0.0)
                throw InputError("slice normal " + number(n.x) + "," + number(n.y) + "," + number(n.z) +
                                 " is not a direction (three finite numbers, not all 0)");
        }
    } else if (settings.slice) {
        throw InputError("a slice needs a solid (3D) genome; this genome is flat (2D)");
    }
    if (settings.region) {
        const Region& r = *settings.region;
        if (!std::isfinite(r.x0) || !std::isfinite(r.y0) || !std::isfinite(r.x1) || !std::isfinite(r.y1))
            throw InputError("region has a number that is not finite");
        if (!(r.x0 < r.x1) || !(r.y0 < r.y1))
            throw InputError("region " + number(r.x0) + "," + number(r.y0) + "," + number(r.x1) + "," +
                             number(r.y1) + " is empty (need X0 < X1 and Y0 < Y1)");
    }
}

} // namespace marbler
