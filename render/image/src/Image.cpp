#include "marbler/Image.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace marbler {

double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

glm::dvec3 linearOf(Color c) {
    return {srgbToLinear(c.r / 255.0), srgbToLinear(c.g / 255.0), srgbToLinear(c.b / 255.0)};
}

double linearToSrgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

const float* srgbToLinearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[i] = static_cast<float>(srgbToLinear(i / 255.0));
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
        for (int b = 0; b < EncodeBuckets; ++b)
            bucketLevel[b] = encodeSrgb8Direct(double(b) / EncodeBuckets);
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
