#include "marbler/Sampling.h"

#include "marbler/Error.h"

#include <array>
#include <bit>
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

const char* axisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

} // namespace

AaPattern aaPattern(std::string_view name) {
    AaPattern pattern;
    if (name == "none") {
        pattern.offsets = {{0.0, 0.0}};
        pattern.weights = {1.0};
    } else if (name == "rgss") {
        pattern.offsets = {{1.0 / 8, 3.0 / 8}, {3.0 / 8, -1.0 / 8}, {-1.0 / 8, -3.0 / 8}, {-3.0 / 8, 1.0 / 8}};
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
        for (const std::string& known : aaPatternNames()) list += (list.empty() ? "" : ", ") + known;
        throw InputError("unknown antialiasing mode '" + std::string(name) + "' (one of " + list + ")");
    }
    pattern.name = std::string(name);
    return pattern;
}

std::vector<std::string> aaPatternNames() {
    return {"none", "rgss", "quincunx", "grid2", "grid3", "grid4", "grid5", "grid6", "grid7", "grid8", "checker4",
            "rooks8"};
}

Region effectiveRegion(const Genome& genome, const RenderSettings& settings) {
    if (settings.region) return *settings.region;
    const glm::dvec3& s = genome.size;
    if (genome.dimension == 3 && settings.slice) {
        switch (settings.slice->axis) {
        case 0: return {0.0, 0.0, s.y, s.z};
        case 1: return {0.0, 0.0, s.x, s.z};
        default: break;
        }
    }
    return {0.0, 0.0, s.x, s.y};
}

SampleFrame sampleFrame(const Genome& genome, const RenderSettings& settings) {
    Region r = effectiveRegion(genome, settings);
    double su = (r.x1 - r.x0) / settings.width;
    double sv = (r.y1 - r.y0) / settings.height;
    SampleFrame frame;
    int axis = genome.dimension == 3 && settings.slice ? settings.slice->axis : 2;
    double c = genome.dimension == 3 && settings.slice ? settings.slice->value : 0.0;
    switch (axis) {
    case 0: // x = c: columns along y, rows along z
        frame.origin = {c, r.x0, r.y0};
        frame.du = {0.0, su, 0.0};
        frame.dv = {0.0, 0.0, sv};
        break;
    case 1: // y = c: columns along x, rows along z
        frame.origin = {r.x0, c, r.y0};
        frame.du = {su, 0.0, 0.0};
        frame.dv = {0.0, 0.0, sv};
        break;
    default:
        frame.origin = {r.x0, r.y0, c};
        frame.du = {su, 0.0, 0.0};
        frame.dv = {0.0, sv, 0.0};
        break;
    }
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
    if (settings.threads < 0) throw InputError("thread count must be >= 0 (got " + std::to_string(settings.threads) + ")");
    aaPattern(settings.aa); // throws for an unknown name
    if (genome.dimension == 3) {
        if (!settings.slice)
            throw InputError("a solid (3D) genome needs a slice to render a raster, e.g. --slice z=500");
        const Slice& s = *settings.slice;
        if (s.axis < 0 || s.axis > 2) throw InputError("slice axis must be x, y or z");
        if (!std::isfinite(s.value))
            throw InputError(std::string("slice ") + axisName(s.axis) + "=" + number(s.value) + " is not a finite number");
    } else if (settings.slice) {
        throw InputError("a slice needs a solid (3D) genome; this genome is flat (2D)");
    }
    if (settings.region) {
        const Region& r = *settings.region;
        if (!std::isfinite(r.x0) || !std::isfinite(r.y0) || !std::isfinite(r.x1) || !std::isfinite(r.y1))
            throw InputError("region has a number that is not finite");
        if (!(r.x0 < r.x1) || !(r.y0 < r.y1))
            throw InputError("region " + number(r.x0) + "," + number(r.y0) + "," + number(r.x1) + "," + number(r.y1) +
                             " is empty (need X0 < X1 and Y0 < Y1)");
    }
}

double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

const float* srgbToLinearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = static_cast<float>(srgbToLinear(i / 255.0));
        return t;
    }();
    return table.data();
}

namespace {

std::uint8_t encodeSrgb8Direct(double linear) {
    if (!(linear > 0.0)) return 0; // also NaN
    if (linear >= 1.0) return 255;
    return static_cast<std::uint8_t>(std::floor(linearToSrgb(linear) * 255.0 + 0.5));
}

/// Buckets of the fast encoder: fine enough that a bucket spans less than one 8-bit level even
/// where sRGB is steepest (slope 12.92 * 255 per unit near black).
constexpr int EncodeBuckets = 8192;

struct EncodeTables {
    /// threshold[k]: the smallest linear value that encodes to k or more. Found by bisecting the
    /// direct encoder over the bit patterns of doubles (ordered like the values when positive),
    /// so the table encoder gives exactly the direct encoder's answers without a pow per call.
    std::array<double, 257> threshold{};
    /// The level of each bucket's lower end.
    std::array<std::uint8_t, EncodeBuckets> bucketLevel{};

    EncodeTables() {
        for (int k = 1; k < 256; ++k) {
            std::uint64_t lo = std::bit_cast<std::uint64_t>(0.0), hi = std::bit_cast<std::uint64_t>(1.0);
            while (hi - lo > 1) {
                std::uint64_t mid = lo + (hi - lo) / 2;
                (encodeSrgb8Direct(std::bit_cast<double>(mid)) >= k ? hi : lo) = mid;
            }
            threshold[k] = std::bit_cast<double>(hi);
        }
        threshold[256] = 2.0; // above every input that reaches the table
        for (int b = 0; b < EncodeBuckets; ++b) bucketLevel[b] = encodeSrgb8Direct(double(b) / EncodeBuckets);
    }
};

const EncodeTables& encodeTables() {
    static const EncodeTables tables;
    return tables;
}

} // namespace

std::uint8_t encodeSrgb8(double linear) {
    if (!(linear > 0.0)) return 0; // also NaN
    if (linear >= 1.0) return 255;
    const EncodeTables& tables = encodeTables();
    int k = tables.bucketLevel[static_cast<int>(linear * EncodeBuckets)];
    // A bucket spans less than a level, so at most one step up; the second is a safety margin.
    k += linear >= tables.threshold[k + 1];
    k += linear >= tables.threshold[k + 1];
    return static_cast<std::uint8_t>(k);
}

} // namespace marbler
