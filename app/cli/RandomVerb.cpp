// `marbler random`: a seeded random genome (spec/cli.md).

#include "cli/Cli.h"

#include "marbler/Error.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"

#include <algorithm>
#include <iostream>

namespace marbler::cli {
namespace {

constexpr const char* RandomHelp =
    R"(usage: marbler random [--dimension 2|3 | --family NAME] --seed N -o OUT.marble.json
       marbler random --families

Writes a random genome: a harmonious palette, a bath covered with drops like a stone
pattern, then a few strokes of the traditional families (combed, chevron, nonpareil,
waved, swirled, vortices; in 3D also sphere strokes and egg-crate or ripple waves).
With --family, a design of one traditional pattern family (stone, nonpareil, peacock,
French curl, ...: see --families), in a palette of marbling's traditions; its
meta.family names the family, and breeding keeps it.
The same seed gives a byte-identical file on every machine.

options:
  --dimension 2|3   flat (paper) or solid marbling (default 2; a family has its own)
  --family NAME     a design of this pattern family
  --families        lists the families, one per line: name, kind, recipe
  --seed N          the seed, a non-negative 64-bit integer (required)
  -o, --output FILE the genome file to write (required); written atomically
  -h, --help        this text
)";

/// "stone, gel-git, ..." for messages.
std::string familyNames() {
    std::string names;
    for (const Family& f : allFamilies())
        names += (names.empty() ? "" : ", ") + std::string(f.name);
    return names;
}

} // namespace

int runRandom(std::span<const std::string> words) {
    return guarded("random", [&] {
        Args args =
            parseArgs(words, {"dimension", "family", "seed", "o", "output"}, {"h", "help", "families"});
        if (args.has("h") || args.has("help")) {
            std::cout << RandomHelp;
            return ExitOk;
        }
        if (!args.positional.empty())
            throw InputError("unexpected argument '" + args.positional[0] + "' (see marbler random --help)");
        if (args.has("families")) {
            for (const Family& f : allFamilies()) {
                std::string name(f.name);
                name.resize(std::max<std::size_t>(name.size(), 14), ' ');
                std::cout << name << (f.dimension == 3 ? "solid  " : "flat   ") << f.summary << "\n";
            }
            return ExitOk;
        }
        const Family* family = nullptr;
        if (std::optional<std::string> name = args.get("family")) {
            family = findFamily(*name);
            if (!family)
                throw InputError("--family: no family '" + *name + "' (one of " + familyNames() + ")");
            if (args.has("dimension") && parseIntOption(args, "dimension", 2, 2, 3) != family->dimension)
                throw InputError("--family " + *name + " is " +
                                 (family->dimension == 3 ? "solid (3D)" : "flat (2D)") +
                                 ", not --dimension " + *args.get("dimension"));
        }
        int dimension = parseIntOption(args, "dimension", 2, 2, 3);
        std::uint64_t seed = parseSeedOption(args, "seed");
        std::optional<std::string> out = args.get("o");
        if (!out) out = args.get("output");
        if (!out || out->empty()) throw InputError("-o OUT.marble.json is required");
        saveGenome(family ? familyGenome(*family, seed) : randomGenome(seed, dimension), *out);
        return ExitOk;
    });
}

} // namespace marbler::cli
