// libFuzzer target: bytes from the fuzzer read as a PNG or TIFF image that may carry a genome
// (marbler/GenomeImage.h), as every verb and the window read an image given as a design. The
// reader must refuse what it cannot read with a one-line InputError; a genome it finds goes
// through the genome parser, which must accept it or refuse it with a GenomeError. Anything else
// (a crash, a sanitizer report, a hang, another exception) is a finding.

#include "marbler/Error.h"
#include "marbler/GenomeImage.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_image: %s\n%s\n", what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::span<const unsigned char> bytes(data, size);
    // Both readers see every input, whatever its signature says.
    for (marbler::ImageKind kind : {marbler::ImageKind::Png, marbler::ImageKind::Tiff}) {
        try {
            std::optional<std::string> text = marbler::readGenomeText(bytes, kind, "fuzz-image");
            if (text) (void)marbler::parseEmbeddedGenome(*text, kind, "fuzz-image");
            (void)marbler::genomeFromXmp(std::string_view(reinterpret_cast<const char*>(data), size));
        } catch (const marbler::InputError& e) {
            if (std::string(e.what()).find('\n') != std::string::npos)
                finding("multi-line error message", e.what());
        }
    }
    return 0;
}
