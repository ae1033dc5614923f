// libFuzzer target: bytes from the fuzzer as a genome's `source` image, in a data: URL, as a
// stranger's genome can carry one (marbler/SourceDecoder.h). The allow-list by content
// (SourceFormat.h) must pass only PNG, JPEG, TIFF, OpenEXR and WebP, each to its own reader, and
// the decoder must refuse what it cannot read with a one-line GenomeError. Anything else (a
// crash, a sanitizer report, a hang, another exception) is a finding. OpenImageIO and the
// format libraries are Debian's, not instrumented: the fuzzer sees coverage of Marbler's code
// only, while AddressSanitizer still catches what they do to memory Marbler gave them.

#include "marbler/Error.h"
#include "marbler/Genome.h"
#include "marbler/SourceDecoder.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_source: %s\n%s\n", what, detail.c_str());
    std::abort();
}

std::string base64(const std::uint8_t* data, std::size_t size) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve(size / 3 * 4 + 4);
    std::uint32_t buffer = 0;
    int bits = 0;
    for (std::size_t i = 0; i < size; ++i) {
        buffer = (buffer << 8) | data[i];
        bits += 8;
        while (bits >= 6) {
            bits -= 6;
            out += alphabet[(buffer >> bits) & 63u];
        }
    }
    if (bits > 0) out += alphabet[(buffer << (6 - bits)) & 63u];
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    marbler::Genome genome;
    genome.fileName = "fuzz-source";
    genome.source = marbler::SourceImage{"data:image/png;base64," + base64(data, size)};
    try {
        marbler::LinearRaster raster = marbler::decodeSourceImage(genome);
        if (raster.width < 1 || raster.height < 1 ||
            raster.rgb.size() != std::size_t(raster.width) * std::size_t(raster.height) * 3)
            finding("a decoded raster of inconsistent size");
    } catch (const marbler::GenomeError& e) {
        if (std::string(e.what()).find('\n') != std::string::npos)
            finding("multi-line error message", e.what());
    }
    return 0;
}
