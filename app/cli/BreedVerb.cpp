// `marbler breed`: offspring of genome files by a genetic operator (spec/cli.md).

#include "cli/Cli.h"

#include "marbler/AtomicFile.h"
#include "marbler/Colourways.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "marbler/Operators.h"
#include "marbler/SourcePath.h"
#include "marbler/Steer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace marbler::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* BreedHelp =
    R"(usage: marbler breed OPERATOR PARENT... --seed N [--count K] [--strength S] -o DIR
                    [--wildcard] [--passed FILE,...] [--picks ROUNDS.json] [--candidates N]
                    [--no-fresh]

Writes K children of the PARENT genome files (or PNG or TIFF images that carry genomes), made
by a genetic operator, as DIR/child-01.marble.json, DIR/child-02.marble.json, ... (DIR is
created if missing).
The same parents, operator, seed and options give the same children.

operators:
  alter      one parent: every parameter of its strokes perturbed by its mutation
             scale times the strength; the tools and their order stay
  recombine  two or more parents: crossover (one-point or uniform) of their strokes,
             on the initial state of each parent in turn
  swap       two parents: the initial state (with palette and background) of one with
             the strokes of the other, both ways (children 1 and 2); further children
             are gentle variations of these two, alternately
  reinit     one parent: a new initial drop pattern, the same strokes
  colourway  colourways, as the window's Colourways mode: the structure of one parent kept
             exactly and only its inks and background bred (at --strength; 1 gives
             palettes of their own), or with two or more parents their inks mixed; a
             parent whose palette is locked is refused

No two children are equal, and none equals a parent (meta aside): a child that would
repeat one is drawn again, or becomes a gentle variation of itself, which its
meta.lineage.variation records (the id it varies and the strength).
Parts locked in a parent's meta.locks (palette, initial, operations) are never changed.
Each child records meta.lineage (parents' ids, operator, seed, generation) and meta.id.
A parent's source image is named from DIR; one outside DIR (which a genome may not read,
see marbler render --help) is embedded in the child as a data: URI instead.

Steering (docs/breeding.md): with --passed and --picks the children are ranked by what the
picks say, as the window's "Steer by my picks" does: many candidates are drawn (the operator's
own children, variations of the palette, the strokes or the initial state at steps that adapt
to the picks, recombination with earlier picks, fresh designs of every generator) and the most
promising K shown, the last one for exploration; a line
"steered: ..." says why. The PARENTs are this round's picks, --passed the designs passed over
beside them; ROUNDS.json holds the earlier rounds, oldest first:
  {"rounds": [{"picked": ["a.marble.json"], "passed": ["b.marble.json", ...],
               "disliked": ["c.marble.json"]}, ...]}
(files relative to ROUNDS.json's folder; "disliked" marks "less like this"). Without a round
that has a pick and a design passed over, breeding is as without steering. The window's
Wildcard cell is --wildcard here, and the window with it off is --no-fresh as well.

options:
  --seed N          the seed, a non-negative 64-bit integer (required)
  --count K         how many children, 1 to 1000 (default 8)
  --strength S      alteration strength, 0 to 1 (default 0.5; alter and colourway)
  --wildcard        the last child is a fresh design of the parents' family (or a random one),
                    as the window's Wildcard cell, against breeding fatigue
  -o, --output DIR  the folder to write the children into (required)
  --passed FILES    designs passed over beside the parents, comma-separated (steering)
  --picks FILE      the earlier rounds of picks, as above (steering)
  --candidates N    how many candidates steering ranks, K to 1000 (default 24)
  --no-fresh        steering shows no fresh designs: every child varies the picks
  -h, --help        this text
)";

std::string childName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "child-%02d.marble.json", index);
    return name;
}

/// Base64 (RFC 4648, padded), for an embedded source image.
std::string encodeBase64(const std::string& bytes) {
    static constexpr char Digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= std::uint32_t(static_cast<unsigned char>(bytes[i + 2]));
        out += Digits[(v >> 18) & 63];
        out += Digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? Digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? Digits[v & 63] : '=';
    }
    return out;
}

/// The image as a data: URI, when its format is one a data URI may carry and it is small
/// enough to leave the genome within its size limit; nullopt otherwise.
std::optional<std::string> dataUriOf(const fs::path& file) {
    const std::string extension = lowerExtension(file);
    const std::map<std::string, std::string> types{
        {".png", "image/png"},   {".jpg", "image/jpeg"}, {".jpeg", "image/jpeg"}, {".tif", "image/tiff"},
        {".tiff", "image/tiff"}, {".bmp", "image/bmp"},  {".exr", "image/x-exr"}};
    auto type = types.find(extension);
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (type == types.end() || ec || size > MaxFileBytes / 2) return std::nullopt;
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) return std::nullopt;
    return "data:" + type->second + ";base64," + encodeBase64(bytes);
}

/// A relative `source` image was relative to its parent's folder; the child lives in DIR. Where
/// the image lies outside DIR, the path from DIR would lead out of the child's folder, which
/// the source rule (SourcePath.h) refuses: an image the parent could read (in its own folder)
/// is embedded into the child instead, so the child renders and can be shared as it is. An
/// image the parent itself could not read without --allow-external-source is left as a path,
/// and refused alike.
void rebaseSource(Genome& child, const fs::path& dir) {
    if (!child.source || isDataUri(child.source->image)) return;
    const SourceLocation parent = locateSource(child);
    fs::path image(child.source->image);
    if (image.is_absolute()) return;
    fs::path base = child.baseDirectory.empty() ? fs::path(".") : fs::path(child.baseDirectory);
    fs::path target = fs::absolute(base / image).lexically_normal();
    const fs::path rebased = target.lexically_proximate(fs::absolute(dir).lexically_normal());
    child.source->image = rebased.generic_string();
    if (parent.kind != SourceLocation::Kind::Inside || (!rebased.empty() && *rebased.begin() != "..")) return;
    if (std::optional<std::string> embedded = dataUriOf(parent.file)) child.source->image = *embedded;
}

/// The comma-separated entries of an option (empty entries skipped).
std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) out.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return out;
}

/// The rounds of --picks (see the help): each file relative to the JSON file's folder.
std::vector<PickRound> readPickRounds(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file + ": cannot be read");
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(file + ": not JSON (" + e.what() + ")");
    }
    if (!json.is_object() || !json.contains("rounds") || !json["rounds"].is_array())
        throw InputError(file + ": expected {\"rounds\": [...]} at /");
    const fs::path base = fs::path(file).parent_path();
    std::vector<PickRound> rounds;
    for (std::size_t r = 0; r < json["rounds"].size(); ++r) {
        const nlohmann::json& entry = json["rounds"][r];
        const std::string where = file + ": /rounds/" + std::to_string(r);
        if (!entry.is_object()) throw InputError(where + ": expected an object");
        PickRound round;
        for (const char* key : {"picked", "passed", "disliked"}) {
            if (!entry.contains(key)) continue;
            if (!entry[key].is_array()) throw InputError(where + "/" + key + ": expected a list of files");
            std::vector<Genome>& into = std::string(key) == "picked"   ? round.picked
                                        : std::string(key) == "passed" ? round.passed
                                                                       : round.disliked;
            for (std::size_t k = 0; k < entry[key].size(); ++k) {
                const std::string at = where + "/" + key + "/" + std::to_string(k);
                if (!entry[key][k].is_string()) throw InputError(at + ": expected a file name");
                // The design's own message names its file; the entry says where it was asked for.
                try {
                    into.push_back(
                        loadGenomeArgument("breed", (base / entry[key][k].get<std::string>()).string()));
                } catch (const InputError& e) {
                    throw InputError(at + ": " + e.what());
                }
            }
        }
        rounds.push_back(std::move(round));
    }
    return rounds;
}

} // namespace

int runBreed(std::span<const std::string> words) {
    return guarded("breed", [&] {
        Args args =
            parseArgs(words, {"seed", "count", "strength", "o", "output", "passed", "picks", "candidates"},
                      {"h", "help", "wildcard", "no-fresh"});
        if (args.has("h") || args.has("help")) {
            std::cout << BreedHelp;
            return ExitOk;
        }
        if (args.positional.empty())
            throw InputError("an operator is required: alter, recombine, swap, reinit or colourway");
        const bool colourway = args.positional[0] == "colourway";
        std::optional<GeneticOperator> op =
            colourway ? std::optional(GeneticOperator::Alter) : parseOperator(args.positional[0]);
        if (!op)
            throw InputError("unknown operator '" + args.positional[0] +
                             "' (alter, recombine, swap, reinit or colourway)");
        if (colourway)
            for (const char* steering : {"passed", "picks", "candidates", "no-fresh"})
                if (args.has(steering))
                    throw InputError(std::string("--") + steering +
                                     ": colourways are not steered (only the operators are)");
        if (colourway && args.has("wildcard"))
            throw InputError("--wildcard: colourways keep the parent's structure, a wildcard would not");

        BreedRequest request;
        request.op = *op;
        int parents = static_cast<int>(args.positional.size()) - 1;
        if (colourway && parents < 1) throw InputError("colourway takes at least 1 parent (got 0)");
        if (!colourway && (parents < minParents(*op) || (maxParents(*op) > 0 && parents > maxParents(*op)))) {
            std::string want = maxParents(*op) == 0 ? "at least " + std::to_string(minParents(*op))
                                                    : std::to_string(minParents(*op));
            throw InputError(std::string(operatorName(*op)) + " takes " + want + " parent" +
                             (minParents(*op) == 1 && maxParents(*op) == 1 ? "" : "s") + " (got " +
                             std::to_string(parents) + ")");
        }
        request.seed = parseSeedOption(args, "seed");
        request.count = parseIntOption(args, "count", 8, 1, MaxChildren);
        request.strength = parseDoubleOption(args, "strength", 0.5);
        if (request.strength < 0.0 || request.strength > 1.0)
            throw InputError("--strength: must be between 0 and 1 (got " + *args.get("strength") + ")");
        std::optional<std::string> out = args.get("o");
        if (!out) out = args.get("output");
        if (!out || out->empty()) throw InputError("-o DIR is required");
        fs::path dir(*out);
        std::error_code ec;
        if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
            throw InputError(dir.string() + ": exists and is not a folder");

        for (std::size_t i = 1; i < args.positional.size(); ++i)
            request.parents.push_back(loadGenomeArgument("breed", args.positional[i]));

        // Everything is bred and serialised before the first byte is written, so bad input
        // never leaves a partial set of children.
        // Steering (issue 26): the rounds of picks, oldest first, then this one.
        SteerResult steered;
        std::vector<Genome> children;
        if (colourway) {
            ColourwayRequest colours;
            colours.parents = request.parents;
            colours.mix = request.parents.size() > 1;
            colours.strength = request.strength;
            colours.seed = request.seed;
            colours.count = request.count;
            children = colourways(colours);
        } else {
            SteerRequest steer;
            steer.breed = request;
            steer.candidates =
                parseIntOption(args, "candidates", SteerCandidates, request.count, MaxChildren);
            steer.fresh = !args.has("no-fresh");
            if (std::optional<std::string> picks = args.get("picks")) steer.rounds = readPickRounds(*picks);
            if (args.has("passed") || args.has("picks")) {
                PickRound now;
                now.picked = request.parents;
                if (std::optional<std::string> passed = args.get("passed"))
                    for (const std::string& file : splitList(*passed))
                        now.passed.push_back(loadGenomeArgument("breed", file));
                steer.rounds.push_back(std::move(now));
            }
            steered = steerBreed(steer);
            children = std::move(steered.children);
        }
        // As the window's wildcard cell: the last child gives its place to a fresh design.
        if (args.has("wildcard") && children.size() > 1)
            children.back() = wildcardChild(request, children.back());
        std::vector<std::string> texts;
        for (Genome& child : children) {
            rebaseSource(child, dir);
            texts.push_back(serializeGenome(child));
        }

        bool created = !fs::exists(dir, ec);
        fs::create_directories(dir, ec);
        if (ec) throw RuntimeFailure("cannot create " + dir.string() + ": " + ec.message());
        // Written under temporary names first and renamed only when all are written: an I/O
        // failure half way leaves no children at all.
        try {
            AtomicFileSet files;
            for (std::size_t i = 0; i < texts.size(); ++i)
                files.add(dir / childName(static_cast<int>(i) + 1)).write(texts[i]);
            files.commit();
        } catch (...) {
            if (created) fs::remove(dir, ec); // only removes it when empty
            throw;
        }
        for (std::size_t i = 0; i < children.size(); ++i)
            std::cout << (dir / childName(static_cast<int>(i) + 1)).string() << "  "
                      << children[i].meta.name.value_or("") << '\n';
        if (!steered.explanation.empty()) std::cout << "steered: " << steered.explanation << '\n';
        return ExitOk;
    });
}

} // namespace marbler::cli
