// `marbler random`: a seeded random genome (spec/cli.md).

#include "cli/Cli.h"

#include "marbler/Error.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"

#include <iostream>

namespace marbler::cli {
namespace {

constexpr const char* Help = R"(usage: marbler random --dimension 2|3 --seed N -o OUT.marble.json

Writes a random genome: a harmonious palette, a bath covered with drops like a stone
pattern, then a few strokes of the traditional families (combed, chevron, nonpareil,
waved, swirled, vortices; in 3D also sphere strokes and egg-crate or ripple waves).
The same seed gives a byte-identical file on every machine.

options:
  --dimension 2|3   flat (paper) or solid marbling (default 2)
  --seed N          the seed, a non-negative 64-bit integer (required)
  -o, --output FILE the genome file to write (required); written atomically
  -h, --help        this text
)";

} // namespace

int runRandom(std::span<const std::string> words) {
    return guarded("random", [&] {
        Args args = parseArgs(words, {"dimension", "seed", "o", "output"}, {"h", "help"});
        if (args.has("h") || args.has("help")) {
            std::cout << Help;
            return ExitOk;
        }
        if (!args.positional.empty()) throw InputError("unexpected argument '" + args.positional[0] + "' (see marbler random --help)");
        int dimension = parseIntOption(args, "dimension", 2, 2, 3);
        std::uint64_t seed = parseSeedOption(args, "seed");
        std::optional<std::string> out = args.get("o");
        if (!out) out = args.get("output");
        if (!out || out->empty()) throw InputError("-o OUT.marble.json is required");
        saveGenome(randomGenome(seed, dimension), *out);
        return ExitOk;
    });
}

} // namespace marbler::cli
