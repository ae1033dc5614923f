#include "SrgbProfile.h"

#include "marbler/Image.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace marbler::detail {
namespace {

using Matrix = std::array<std::array<double, 3>, 3>;
using Vector = std::array<double, 3>;

Vector times(const Matrix& m, const Vector& v) {
    Vector r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r[std::size_t(i)] += m[std::size_t(i)][std::size_t(j)] * v[std::size_t(j)];
    return r;
}

Matrix times(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k)
                r[std::size_t(i)][std::size_t(j)] +=
                    a[std::size_t(i)][std::size_t(k)] * b[std::size_t(k)][std::size_t(j)];
    return r;
}

Matrix inverse(const Matrix& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Matrix r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // The cofactor of (j, i), by cyclic indices.
            const std::size_t a = std::size_t((j + 1) % 3), b = std::size_t((j + 2) % 3);
            const std::size_t c = std::size_t((i + 1) % 3), d = std::size_t((i + 2) % 3);
            r[std::size_t(i)][std::size_t(j)] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
        }
    return r;
}

Vector xyzOfChromaticity(double x, double y) {
    return {x / y, 1.0, (1.0 - x - y) / y};
}

/// The profile connection space's white (ICC: D50, as s15Fixed16 numbers round it).
constexpr Vector D50{0.9642, 1.0, 0.8249};

/// Bradford chromatic adaptation from `from` white to `to` white.
Matrix bradford(const Vector& from, const Vector& to) {
    const Matrix b{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const Vector s = times(b, from), d = times(b, to);
    Matrix scale{};
    for (int i = 0; i < 3; ++i)
        scale[std::size_t(i)][std::size_t(i)] = d[std::size_t(i)] / s[std::size_t(i)];
    return times(inverse(b), times(scale, b));
}

class Writer {
public:
    void u8(unsigned v) { mBytes.push_back(static_cast<unsigned char>(v)); }
    void u16(unsigned v) { u8(v >> 8), u8(v & 0xff); }
    void u32(std::uint32_t v) { u16(v >> 16), u16(v & 0xffff); }
    void s15f16(double v) {
        u32(static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(v * 65536.0))));
    }
    void sig(const char* s) {
        for (int i = 0; i < 4; ++i)
            u8(static_cast<unsigned char>(s[i]));
    }
    void zeros(std::size_t n) { mBytes.insert(mBytes.end(), n, 0); }
    void align() {
        while (mBytes.size() % 4)
            u8(0);
    }
    std::size_t size() const { return mBytes.size(); }
    void put32(std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            mBytes[at + std::size_t(i)] = static_cast<unsigned char>(v >> (24 - 8 * i));
    }
    std::vector<unsigned char> take() { return std::move(mBytes); }

private:
    std::vector<unsigned char> mBytes;
};

std::vector<unsigned char> buildProfile() {
    // Linear sRGB to XYZ (D65) from the primaries and white of IEC 61966-2-1, then to D50.
    const Vector white = xyzOfChromaticity(0.3127, 0.3290);
    Matrix primaries{};
    const double xy[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    for (int c = 0; c < 3; ++c) {
        const Vector p = xyzOfChromaticity(xy[c][0], xy[c][1]);
        for (int i = 0; i < 3; ++i)
            primaries[std::size_t(i)][std::size_t(c)] = p[std::size_t(i)];
    }
    const Vector weights = times(inverse(primaries), white);
    Matrix toXyz = primaries;
    for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c)
            toXyz[std::size_t(i)][std::size_t(c)] *= weights[std::size_t(c)];
    const Matrix adapt = bradford(white, D50);
    const Matrix toD50 = times(adapt, toXyz);

    Writer w;
    // Header (ICC.1:2001-04, version 2.1).
    w.zeros(4);        // size, filled in at the end
    w.zeros(4);        // preferred CMM: none
    w.u32(0x02100000); // version 2.1
    w.sig("mntr"), w.sig("RGB "), w.sig("XYZ ");
    for (unsigned v : {2026u, 12u, 3u, 0u, 0u, 0u}) // a fixed date: the same bytes in every file
        w.u16(v);
    w.sig("acsp");
    w.zeros(4 + 4 + 4 + 4 + 8); // platform, flags, manufacturer, model, attributes
    w.u32(0);                   // perceptual intent
    for (double v : D50)
        w.s15f16(v);
    w.zeros(4);  // creator
    w.zeros(44); // reserved
    struct Tag {
        const char* sig;
        std::size_t offset = 0, size = 0;
    };
    std::array<Tag, 9> tags{Tag{"desc"}, Tag{"cprt"}, Tag{"wtpt"}, Tag{"chad"}, Tag{"rXYZ"},
                            Tag{"gXYZ"}, Tag{"bXYZ"}, Tag{"rTRC"}, Tag{"gTRC"}};
    // The blue curve shares the red one's data, as the green does.
    const std::size_t tableAt = w.size();
    w.u32(std::uint32_t(tags.size() + 1));
    w.zeros(12 * (tags.size() + 1));

    auto begin = [&](Tag& t) {
        w.align();
        t.offset = w.size();
    };
    auto end = [&](Tag& t) { t.size = w.size() - t.offset; };

    const std::string description = SrgbIccProfileName;
    begin(tags[0]); // textDescriptionType
    w.sig("desc"), w.zeros(4);
    w.u32(std::uint32_t(description.size() + 1));
    for (char c : description)
        w.u8(static_cast<unsigned char>(c));
    w.u8(0);
    w.zeros(4 + 4);      // Unicode language and count
    w.zeros(2 + 1 + 67); // ScriptCode code, count and text
    end(tags[0]);

    const std::string copyright = "No copyright, use freely (made by Marbler from IEC 61966-2-1)";
    begin(tags[1]); // textType
    w.sig("text"), w.zeros(4);
    for (char c : copyright)
        w.u8(static_cast<unsigned char>(c));
    w.u8(0);
    end(tags[1]);

    auto xyzTag = [&](Tag& t, const Vector& v) {
        begin(t);
        w.sig("XYZ "), w.zeros(4);
        for (double x : v)
            w.s15f16(x);
        end(t);
    };
    xyzTag(tags[2], D50);
    begin(tags[3]); // s15Fixed16ArrayType: the adaptation from the device's white
    w.sig("sf32"), w.zeros(4);
    for (const auto& row : adapt)
        for (double x : row)
            w.s15f16(x);
    end(tags[3]);
    for (int c = 0; c < 3; ++c)
        xyzTag(tags[std::size_t(4 + c)],
               {toD50[0][std::size_t(c)], toD50[1][std::size_t(c)], toD50[2][std::size_t(c)]});

    constexpr int CurvePoints = 1024;
    begin(tags[7]); // curveType
    w.sig("curv"), w.zeros(4);
    w.u32(CurvePoints);
    for (int i = 0; i < CurvePoints; ++i)
        w.u16(static_cast<unsigned>(std::lround(65535.0 * srgbToLinear(double(i) / (CurvePoints - 1)))));
    end(tags[7]);
    tags[8].offset = tags[7].offset, tags[8].size = tags[7].size;
    w.align();

    std::size_t at = tableAt + 4;
    auto entry = [&](const char* sig, const Tag& t) {
        std::uint32_t s = 0;
        for (int i = 0; i < 4; ++i)
            s = (s << 8) | static_cast<unsigned char>(sig[i]);
        w.put32(at, s), w.put32(at + 4, std::uint32_t(t.offset)), w.put32(at + 8, std::uint32_t(t.size));
        at += 12;
    };
    for (const Tag& t : tags)
        entry(t.sig, t);
    entry("bTRC", tags[7]);
    w.put32(0, std::uint32_t(w.size()));
    return w.take();
}

} // namespace

const std::vector<unsigned char>& srgbIccProfile() {
    static const std::vector<unsigned char> profile = buildProfile();
    return profile;
}

} // namespace marbler::detail
