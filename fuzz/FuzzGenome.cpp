// libFuzzer target: genome text from the fuzzer through everything that reads a genome file.
// An accepted genome must validate, save, load back equal and save to the same text, and
// render a tiny raster on the CPU; a refused one must be refused with a GenomeError. Anything
// else (a crash, a sanitizer report, another exception, a broken round trip) is a finding.

#include "marbler/CpuRenderer.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_genome: %s\n%s\n", what, detail.c_str());
    std::abort();
}

void renderTiny(marbler::Genome genome) {
    // The source image would be read from disk or decoded from a data URL: image decoding is
    // OpenImageIO's to fuzz, not ours.
    genome.source.reset();
    marbler::RenderSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.threads = 1;
    if (genome.dimension == 3) settings.slice = marbler::Slice{2, 0.5 * genome.size.z};
    try {
        marbler::CpuRenderer renderer(genome);
        marbler::Image image = renderer.render(settings);
        (void)image;
    } catch (const marbler::InputError&) {
        // The renderer may refuse a design it cannot sample (an absurd design space); it must
        // say so with an InputError, never crash.
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> warnings;
    marbler::Genome genome;
    try {
        genome = marbler::parseGenome(text, "fuzz.marble.json", &warnings);
    } catch (const marbler::GenomeError& e) {
        std::string_view message = e.what();
        if (message.find('\n') != std::string_view::npos) finding("multi-line error message", e.what());
        return 0;
    }

    std::string saved;
    try {
        marbler::validateGenome(genome, "fuzz.marble.json");
        saved = marbler::serializeGenome(genome);
        marbler::Genome again = marbler::parseGenome(saved, "saved.marble.json");
        if (!(again == genome)) finding("saved genome loads back different", saved);
        if (marbler::serializeGenome(again) != saved) finding("saving twice gives different text", saved);
    } catch (const marbler::GenomeError& e) {
        finding("accepted genome refused after saving", std::string(e.what()) + "\n" + saved);
    }
    renderTiny(genome);
    return 0;
}
