// Genome files: every validation rule refuses its file with the right location, unknown keys
// warn, files round-trip exactly, saves are atomic, and the size and nesting limits hold.

#include "TestUtil.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

using namespace marbler;
namespace fs = std::filesystem;

namespace {

fs::path genomeData() { return test::dataDir() / "genome"; }

/// Each file of tests/data/genome/invalid and the substring its error must contain: the file
/// name, the JSON location and the rule.
struct InvalidCase {
    const char* file;
    const char* expected;
};

const InvalidCase InvalidCases[] = {
    {"syntax-error", "syntax-error.marble.json: line 3, column 16: JSON syntax error"},
    {"not-an-object", ": must be a JSON object (got an array of 3)"},
    {"format-wrong", "format: must be \"marbler-genome\" (got \"marbler-genom\")"},
    {"format-missing", "format: missing"},
    {"version-newer", "version: made by a newer version"},
    {"version-fraction", "version: must be an integer (got 1.5)"},
    {"dimension-four", "dimension: must be 2 or 3 (got 4)"},
    {"size-negative", "size[1]: must be > 0 (got -800)"},
    {"size-count", "size: must be an array of 2 numbers"},
    {"background-malformed", "background: must be a colour \"#rrggbb\" (got \"#12345g\")"},
    {"palette-empty", "palette: must be an array of 1 to 16 colours"},
    {"palette-seventeen", "palette: must be an array of 1 to 16 colours (got an array of 17)"},
    {"palette-malformed", "palette[2]: must be a colour"},
    {"initial-not-array", "initial: must be an array"},
    {"operations-missing", "operations: missing"},
    {"initial-stroke", "initial[2].tool: \"comb\" is not allowed in initial"},
    {"tool-unknown", "operations[0].tool: unknown tool \"rake\""},
    {"tool-missing", "operations[1].tool: missing"},
    {"tool-3d-only", "operations[3].tool: \"sphere\" is not available in 2D"},
    {"cylinder-in-2d", "initial[0].tool: \"cylinder\" is not available in 2D"},
    {"entry-not-object", "operations[1]: must be an object"},
    {"param-missing", "operations[0].lambda: missing"},
    {"vector-count", "initial[0].center: must be an array of 2 numbers"},
    {"number-as-string", "initial[0].center[1]: must be a number (got \"400\")"},
    {"scalar-as-array", "operations[2].angle: must be a number"},
    {"radius-negative", "operations[3].radius: must be > 0 (got -2)"},
    {"lambda-zero", "operations[4].lambda: must be > 0 (got 0)"},
    {"spacing-negative", "operations[0].spacing: must be > 0 (got -80)"},
    {"wavelength-zero", "operations[1].wavelength: must be > 0 (got 0)"},
    {"color-fraction", "initial[1].color: must be an integer palette index (got 1.5)"},
    {"color-out-of-range", "initial[0].color: must be an index into the palette, 0 to 2 (got 3)"},
    {"color-negative", "initial[0].color: must be an index into the palette"},
    {"source-in-3d", "source: only allowed in 2D"},
    {"source-not-object", "source: must be an object"},
    {"source-image-missing", "source.image: missing"},
    {"meta-not-object", "meta: must be an object"},
    {"direction-zero", "operations[0].direction: must be non-zero"},
    {"normal-zero", "operations[6].normal: must be non-zero"},
    {"axis-zero", "initial[1].axis: must be non-zero"},
    {"normal-parallel", "operations[0].normal: must not be parallel to direction"},
    {"eggcrate-single", "operations[1].amplitude: must be an array of 2 numbers"},
    {"ripple-pair", "operations[2].wavelength: must be a number"},
    {"shape-unknown", "operations[1].shape: must be \"eggcrate\" or \"ripple\""},
    {"vector-2d-in-3d", "operations[3].center: must be an array of 3 numbers"},
    {"nested-too-deep", "nested deeper than 64 levels"},
    {"number-overflow", "line 43, column 13: JSON number overflow parsing '1e999'"},
};

std::string loadError(const fs::path& file) {
    try {
        loadGenome(file);
    } catch (const GenomeError& e) {
        return e.what();
    }
    return "(loaded without error)";
}

/// A small valid 2D genome in memory.
Genome smallGenome() {
    Genome g;
    g.dimension = 2;
    g.size = {800.0, 600.0, 1000.0};
    g.palette = {Color{1, 2, 3}, Color{200, 100, 50}};
    Operation drop = defaultOperation(Tool::Drop, 2, {400.0, 300.0, 0.0});
    drop.color = 1;
    g.initial.push_back(drop);
    g.operations.push_back(defaultOperation(Tool::Comb, 2, {0.0, 0.0, 0.0}));
    g.meta["name"] = "small";
    return g;
}

std::string entryJson(int i) {
    return R"({"tool":"drop","center":[)" + std::to_string(i % 1000) + R"(,5],"radius":3,"color":0})";
}

/// A 2D genome text with `count` drops in `initial`.
std::string genomeWithDrops(std::size_t count) {
    std::string text = R"({"format":"marbler-genome","version":1,"dimension":2,"size":[1000,1000],)"
                       R"("background":"#000000","palette":["#ffffff"],"operations":[],"initial":[)";
    for (std::size_t i = 0; i < count; ++i) {
        if (i) text += ',';
        text += entryJson(static_cast<int>(i));
    }
    return text + "]}";
}

} // namespace

TEST(GenomeIO, EveryInvalidFileIsRefusedWithItsLocation) {
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(genomeData() / "invalid")) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, std::size(InvalidCases)) << "every invalid file needs a row in InvalidCases";
    for (const InvalidCase& c : InvalidCases) {
        fs::path file = genomeData() / "invalid" / (std::string(c.file) + ".marble.json");
        ASSERT_TRUE(fs::exists(file)) << file;
        std::string message = loadError(file);
        EXPECT_NE(message.find(file.string() + ": "), std::string::npos) << "must name the file: " << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << c.file << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

TEST(GenomeIO, ErrorCarriesFileAndLocation) {
    fs::path file = genomeData() / "invalid" / "radius-negative.marble.json";
    try {
        loadGenome(file);
        FAIL() << "loaded";
    } catch (const GenomeError& e) {
        EXPECT_EQ(e.file(), file.string());
        EXPECT_EQ(e.location(), "operations[3].radius");
        EXPECT_EQ(std::string(e.what()), file.string() + ": operations[3].radius: must be > 0 (got -2)");
    }
}

TEST(GenomeIO, ValidFilesLoad) {
    for (const char* name : {"base-2d", "base-3d", "edge-3d"}) {
        std::vector<std::string> warnings;
        fs::path file = genomeData() / "valid" / (std::string(name) + ".marble.json");
        Genome g = loadGenome(file, &warnings);
        EXPECT_TRUE(warnings.empty()) << name;
        EXPECT_EQ(g.baseDirectory, (genomeData() / "valid").string());
        validateGenome(g, name);
    }
}

TEST(GenomeIO, UnknownKeysWarnAndLoad) {
    std::vector<std::string> warnings;
    fs::path file = genomeData() / "valid" / "unknown-keys.marble.json";
    Genome g = loadGenome(file, &warnings);
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_EQ(warnings[0], file.string() + ": operations[0]: unknown key \"speed\" ignored");
    EXPECT_EQ(warnings[1], file.string() + ": source: unknown key \"fit\" ignored");
    EXPECT_EQ(warnings[2], file.string() + ": unknown key \"comment\" ignored");
    ASSERT_TRUE(g.source.has_value());
    EXPECT_EQ(g.source->image, "paper.png");
    EXPECT_EQ(g.operations[0].tool, Tool::Comb);
    // The unknown keys are not saved back.
    std::string text = serializeGenome(g);
    EXPECT_EQ(text.find("speed"), std::string::npos);
    EXPECT_EQ(text.find("comment"), std::string::npos);
}

TEST(GenomeIO, ParsedValuesAndNormalisation) {
    Genome g = loadGenome(genomeData() / "valid" / "edge-3d.marble.json");
    EXPECT_EQ(g.dimension, 3);
    EXPECT_EQ(g.size, glm::dvec3(1000.5, 0.1, 1e6));
    EXPECT_EQ(g.initial[0].color, 1); // written 1.0: integral, accepted
    // Axis (1e-200, 0, 3e-200): tiny but non-zero, normalised without underflow.
    EXPECT_NEAR(g.initial[1].axis.x, 1.0 / std::sqrt(10.0), 1e-15);
    EXPECT_NEAR(g.initial[1].axis.z, 3.0 / std::sqrt(10.0), 1e-15);
    for (const Operation& op : g.operations) {
        if (op.tool != Tool::Comb && op.tool != Tool::Line && op.tool != Tool::Wave) continue;
        EXPECT_NEAR(glm::length(op.direction), 1.0, 1e-15);
        EXPECT_NEAR(glm::length(op.normal), 1.0, 1e-15);
        EXPECT_NEAR(glm::dot(op.direction, op.normal), 0.0, 1e-15);
    }
    // (1, 1e-8, 0) against a direction far from it: only the component along it is removed.
    const Operation& comb = g.operations[0];
    glm::dvec3 d = glm::normalize(glm::dvec3(0.1, 0.2, 0.30000000000000004));
    glm::dvec3 n = glm::dvec3(1, 1e-8, 0) - glm::dot(glm::dvec3(1, 1e-8, 0), d) * d;
    n = glm::normalize(n);
    EXPECT_NEAR(glm::length(comb.normal - n), 0.0, 1e-14);
    EXPECT_EQ(g.meta["unicode"], "Marmorpapier \u00e9\u00f1 \u2603");
}

TEST(GenomeIO, NearlyParallelNormalIsMadeOrthogonal) {
    // sine of the angle ~1e-7: allowed, and one Gram-Schmidt pass would leave a visible skew.
    std::string text = test::readFile(genomeData() / "valid" / "base-3d.marble.json");
    Genome g = parseGenome(text, "base");
    g.operations[0].direction = {1.0, 2.0, 3.0};
    g.operations[0].normal = glm::dvec3(1.0, 2.0, 3.0) + glm::dvec3(0.0, 3e-7, -2e-7);
    Genome reloaded = parseGenome(serializeGenome(g), "saved");
    const Operation& op = reloaded.operations[0];
    EXPECT_NEAR(glm::dot(op.direction, op.normal), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(op.normal), 1.0, 1e-15);
    // And the normalised genome is a fixed point: saving and loading again changes nothing.
    EXPECT_EQ(parseGenome(serializeGenome(reloaded), "again"), reloaded);
}

TEST(GenomeIO, RoundTripsExactly) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::dataDir() / "examples")) files.push_back(entry.path());
    for (const auto& entry : fs::directory_iterator(genomeData() / "valid")) files.push_back(entry.path());
    std::vector<Genome> genomes;
    for (const fs::path& file : files) genomes.push_back(loadGenome(file));
    for (int i = 0; i < 5; ++i) {
        nlohmann::ordered_json probes = nlohmann::ordered_json::parse(
            test::readFile(test::dataDir() / "conformance" / ("probes-" + std::to_string(i) + ".json")));
        genomes.push_back(parseGenome(probes["genome"].dump(), "probes-" + std::to_string(i)));
    }
    genomes.push_back(smallGenome());
    ASSERT_GE(genomes.size(), 12u);
    for (const Genome& g : genomes) {
        std::string text = serializeGenome(g);
        Genome again = parseGenome(text, "saved");
        EXPECT_EQ(again, g) << text.substr(0, 400);
        EXPECT_EQ(serializeGenome(again), text) << "serialisation is stable";
    }
}

TEST(GenomeIO, SerialisedFormIsStableAndClean) {
    Genome g = smallGenome();
    g.operations[0].alpha = 0.1;
    g.operations[0].angle = -0.0;
    g.source = SourceImage{"paper.png"};
    std::string text = serializeGenome(g);
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    // Top-level and entry key order.
    std::vector<std::string> order = {"\"format\"", "\"version\"", "\"dimension\"", "\"size\"",  "\"background\"",
                                      "\"palette\"", "\"initial\"", "\"operations\"", "\"source\"", "\"meta\""};
    std::size_t last = 0;
    for (const std::string& key : order) {
        std::size_t at = text.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, last) << key;
        last = at;
    }
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    std::vector<std::string> combKeys;
    for (auto it = json["operations"][0].begin(); it != json["operations"][0].end(); ++it) combKeys.push_back(it.key());
    EXPECT_EQ(combKeys, (std::vector<std::string>{"tool", "origin", "angle", "alpha", "lambda", "spacing"}));
    // Integral doubles are written as integers, others in shortest form; 2D sizes have 2 numbers.
    EXPECT_NE(text.find("\"spacing\": 80\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\"alpha\": 0.1,"), std::string::npos) << text;
    EXPECT_TRUE(json["size"][0].is_number_integer());
    EXPECT_EQ(json["size"].size(), 2u);
    EXPECT_EQ(json["background"], "#f3ecdc");
    // Two-space indent.
    EXPECT_NE(text.find("\n  \"version\": 1,\n"), std::string::npos);
}

TEST(GenomeIO, ValidateGenomeChecksInMemory) {
    Genome g = smallGenome();
    EXPECT_NO_THROW(validateGenome(g, "mem"));

    auto expectError = [](const Genome& bad, const std::string& expected) {
        try {
            validateGenome(bad, "mem");
            ADD_FAILURE() << "accepted; expected " << expected;
        } catch (const GenomeError& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
    };
    Genome bad = g;
    bad.operations[0].lambda = -1;
    expectError(bad, "mem: operations[0].lambda: must be > 0 (got -1)");
    bad = g;
    bad.initial[0].center.y = std::numeric_limits<double>::infinity();
    expectError(bad, "mem: initial[0].center[1]: must be finite (got inf)");
    bad = g;
    bad.initial[0].color = 2;
    expectError(bad, "mem: initial[0].color: must be an index into the palette, 0 to 1 (got 2)");
    bad = g;
    bad.initial.push_back(defaultOperation(Tool::Vortex, 2, {1, 1, 0}));
    expectError(bad, "mem: initial[1].tool: \"vortex\" is not allowed in initial (only drop, spray and, in 3D, cylinder)");
    bad = g;
    bad.operations.push_back(defaultOperation(Tool::Sphere, 2, {1, 1, 0}));
    expectError(bad, "mem: operations[1].tool: \"sphere\" is not available in 2D");
    bad = g;
    bad.palette.clear();
    expectError(bad, "mem: palette: must hold 1 to 16 colours (got 0)");
    bad = g;
    bad.size.x = 0;
    expectError(bad, "mem: size[0]: must be > 0 (got 0)");
    bad = g;
    bad.meta["x"] = std::nan("");
    expectError(bad, "mem: meta.x: must be finite (got nan)");

    Genome solid = loadGenome(genomeData() / "valid" / "base-3d.marble.json");
    EXPECT_NO_THROW(validateGenome(solid, "mem"));
    bad = solid;
    bad.operations[0].normal = bad.operations[0].direction * -3.0;
    expectError(bad, "mem: operations[0].normal: must not be parallel to direction");
    bad = solid;
    bad.source = SourceImage{"a.png"};
    expectError(bad, "mem: source: only allowed in 2D designs");
}

TEST(GenomeIO, EntryLimit) {
    EXPECT_NO_THROW(parseGenome(genomeWithDrops(MaxEntries), "limit"));
    try {
        parseGenome(genomeWithDrops(MaxEntries + 1), "limit");
        FAIL() << "accepted 10,001 entries";
    } catch (const GenomeError& e) {
        EXPECT_NE(std::string(e.what()).find("at most 10000"), std::string::npos) << e.what();
    }
}

TEST(GenomeIO, FileSizeLimit) {
    fs::path dir = test::outputDir("GenomeIO.FileSizeLimit");
    // A valid genome padded with trailing whitespace up to the limit loads; one byte more is
    // refused before parsing.
    std::string text = genomeWithDrops(3);
    std::string atLimit = text + std::string(MaxFileBytes - text.size(), ' ');
    test::writeFile(dir / "at-limit.marble.json", atLimit);
    EXPECT_NO_THROW(loadGenome(dir / "at-limit.marble.json"));
    test::writeFile(dir / "over-limit.marble.json", atLimit + " ");
    std::string message = loadError(dir / "over-limit.marble.json");
    EXPECT_NE(message.find("larger than 16 MiB"), std::string::npos) << message;
    EXPECT_THROW(parseGenome(atLimit + " ", "text"), GenomeError);
}

TEST(GenomeIO, DeepNestingIsRefusedCleanly) {
    for (std::size_t depth : {65u, 1000u, 1000000u}) {
        std::string text = std::string(depth, '[') + std::string(depth, ']');
        try {
            parseGenome(text, "deep");
            FAIL() << "accepted depth " << depth;
        } catch (const GenomeError& e) {
            EXPECT_EQ(std::string(e.what()), "deep: JSON nested deeper than 64 levels");
        }
    }
    // Within the limit, nesting in meta is kept.
    std::string meta = std::string(60, '[') + std::string(60, ']');
    std::string text = genomeWithDrops(1);
    text.back() = ',';
    text += "\"meta\":{\"deep\":" + meta + "}}";
    Genome g = parseGenome(text, "ok");
    EXPECT_EQ(parseGenome(serializeGenome(g), "again"), g);
}

TEST(GenomeIO, MissingFileIsAGenomeError) {
    std::string message = loadError("/nonexistent/nothing.marble.json");
    EXPECT_NE(message.find("/nonexistent/nothing.marble.json: cannot read"), std::string::npos) << message;
    message = loadError(test::dataDir());
    EXPECT_NE(message.find("cannot read"), std::string::npos) << message;
}

TEST(GenomeIO, SaveAndLoad) {
    fs::path dir = test::outputDir("GenomeIO.SaveAndLoad");
    Genome g = loadGenome(genomeData() / "valid" / "edge-3d.marble.json");
    saveGenome(g, dir / "a.marble.json");
    EXPECT_EQ(loadGenome(dir / "a.marble.json"), g);
    // Overwrites, and leaves nothing else in the folder.
    Genome small = smallGenome();
    saveGenome(small, dir / "a.marble.json");
    EXPECT_EQ(loadGenome(dir / "a.marble.json"), small);
    std::vector<fs::path> left;
    for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename());
    EXPECT_EQ(left, std::vector<fs::path>{"a.marble.json"});
}

TEST(GenomeIO, FailedSaveLeavesTargetAndNoTemporary) {
    fs::path dir = test::outputDir("GenomeIO.FailedSave");
    EXPECT_THROW(writeFileAtomically(dir / "missing-folder" / "a.json", "x"), RuntimeFailure);
    EXPECT_FALSE(fs::exists(dir / "missing-folder"));

    // A target that is a folder: rename fails after the temporary is written; it must go.
    fs::create_directory(dir / "target-is-folder");
    EXPECT_THROW(writeFileAtomically(dir / "target-is-folder", "x"), RuntimeFailure);
    EXPECT_TRUE(fs::is_directory(dir / "target-is-folder"));

    // A read-only folder: the old file stays as it was (unless we are root, who may write).
    fs::path readOnly = dir / "read-only";
    fs::create_directory(readOnly);
    test::writeFile(readOnly / "a.json", "old");
    ::chmod(readOnly.c_str(), 0555);
    bool root = ::geteuid() == 0;
    if (!root) {
        EXPECT_THROW(writeFileAtomically(readOnly / "a.json", "new"), RuntimeFailure);
    }
    ::chmod(readOnly.c_str(), 0755);
    if (!root) {
        EXPECT_EQ(test::readFile(readOnly / "a.json"), "old");
    }

    std::vector<fs::path> left;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) left.push_back(entry.path().filename());
    EXPECT_EQ(left, std::vector<fs::path>{"a.json"}) << "no temporary files left behind";

    // Failure message names the file.
    try {
        writeFileAtomically(dir / "missing-folder" / "a.json", "x");
    } catch (const RuntimeFailure& e) {
        EXPECT_NE(std::string(e.what()).find("missing-folder/a.json"), std::string::npos) << e.what();
    }
}

// ---- The tool registry (Params.h) ------------------------------------------------------------

TEST(Registry, EveryToolIsFoundByItsNameAndSavesAndLoadsInEveryDimension) {
    for (const ToolSpec& spec : allTools()) {
        ASSERT_EQ(&toolSpec(spec.tool), &spec);
        ASSERT_EQ(findTool(spec.name), &spec) << spec.name;
        EXPECT_TRUE(spec.in2D || spec.in3D) << spec.name;
        for (int dimension : {2, 3}) {
            if (!spec.available(dimension)) continue;
            // Every choice of its choice parameters (a wave's shapes) goes through a file.
            std::vector<int> choices{0};
            for (const ParamSpec& param : spec.params(dimension))
                for (std::size_t k = 1; k < param.choices.size(); ++k) choices.push_back(int(k));
            for (int choice : choices) {
                Genome g;
                g.dimension = dimension;
                g.palette = {Color{}};
                Operation op = defaultOperation(spec.tool, dimension, {500, 500, 500});
                for (const ParamSpec& param : spec.params(dimension))
                    if (param.kind == ParamKind::Choice) setComponent(param, op, 0, choice);
                (allowedInInitial(spec.tool, dimension) ? g.initial : g.operations).push_back(op);
                // (A ripple keeps the egg-crate's second numbers in memory, unsaved: compare files.)
                std::string file = serializeGenome(g);
                EXPECT_EQ(serializeGenome(parseGenome(file, "mem")), file) << spec.name << " " << dimension << "D choice " << choice;
            }
        }
    }
}

TEST(Registry, InkLayingToolsAreTheInitialStateAndPushForms) {
    for (const ToolSpec& spec : allTools()) {
        for (int dimension : {2, 3}) {
            EXPECT_EQ(allowedInInitial(spec.tool, dimension), spec.laysInk && spec.available(dimension)) << spec.name;
            if (!spec.available(dimension)) continue;
            bool push = spec.form(dimension) == ShaderForm::PushArea || spec.form(dimension) == ShaderForm::PushVolume;
            // The shader's push form is the only one with an ink test (tools.glsl).
            if (spec.laysInk) {
                EXPECT_TRUE(push) << spec.name;
            }
            bool hasColor = false;
            for (const ParamSpec& param : spec.params(dimension)) hasColor = hasColor || param.kind == ParamKind::Color;
            EXPECT_EQ(hasColor, spec.laysInk) << spec.name << " " << dimension << "D";
        }
    }
    EXPECT_EQ(initialToolsText(), "drop, spray and, in 3D, cylinder");
}

TEST(Registry, DefaultsLieInTheirRanges) {
    for (const ToolSpec& spec : allTools())
        for (int dimension : {2, 3}) {
            if (!spec.available(dimension)) continue;
            Operation op = defaultOperation(spec.tool, dimension, {500, 500, 500});
            ASSERT_NO_THROW(validateGenome([&] {
                Genome g;
                g.dimension = dimension;
                g.palette = {Color{}};
                (allowedInInitial(spec.tool, dimension) ? g.initial : g.operations).push_back(op);
                return g;
            }(), "defaults")) << spec.name;
            for (const ParamSpec& param : spec.params(dimension)) {
                if (param.kind == ParamKind::Choice || param.kind == ParamKind::Position
                    || param.kind == ParamKind::Direction || param.kind == ParamKind::Color)
                    continue;
                EXPECT_TRUE(param.range.contains(param.defaultValue)) << spec.name << "." << param.key;
                EXPECT_GE(param.mutationScale, 0.0) << spec.name << "." << param.key;
            }
        }
}
