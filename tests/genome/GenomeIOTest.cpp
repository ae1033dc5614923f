// Genome files: every validation rule refuses its file with the right location, unknown keys
// warn, files round-trip exactly, saves are atomic, and the size and nesting limits hold.

#include "TestUtil.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

using namespace marbler;
namespace fs = std::filesystem;

namespace {

fs::path genomeData() {
    return test::dataDir() / "genome";
}

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
    {"version-newer",
     "version: made by a newer version of Marbler (format version 4; this one reads version 3)"},
    {"v2-stylus", "operations[0].tool: \"stylus\" needs format version 3 (the file says version 2)"},
    {"stylus-path-one-point", "operations[0].path: must be an array of 2 to 1000 points [x, y]"},
    {"stylus-path-repeat", "operations[0].path[1]: must differ from the point before it"},
    {"stylus-path-not-point", "operations[0].path[1]: must be a point [x, y]"},
    {"stylus-lambda-zero", "operations[0].lambda: must be > 0 (got 0)"},
    {"stylus-reach-negative", "operations[0].reach: must be > 0 (got -3)"},
    {"stylus-tines-zero", "operations[0].tines: must be in [1, 64] (got 0)"},
    {"stylus-tines-many", "operations[0].tines: must be in [1, 64] (got 65)"},
    {"stylus-rake-no-spacing", "operations[0].spacing: missing: a rake (tines > 1) needs the spacing"},
    {"stylus-pressure-count", "operations[0].pressure: must be an array of one number per path point, 2"},
    {"stylus-pressure-above-one", "operations[0].pressure[1]: must be in [0, 1] (got 1.5)"},
    {"stylus-steps-few", "operations[0].steps: must be at least max(4 L / reach"},
    {"stylus-steps-too-strong", "operations[0].steps: cannot be enough"},
    {"stylus-missing-reach", "operations[0].reach: missing"},
    {"stylus-3d", "operations[0].tool: \"stylus\" is not available in 3D"},
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
    // Version 2.
    {"teeth-one", "operations[5].teeth: must be an array of 2 to 1000 numbers (got an array of 1)"},
    {"teeth-too-many", "operations[5].teeth: must be an array of 2 to 1000 numbers (got an array of 1001)"},
    {"teeth-not-array", "operations[5].teeth: must be an array of 2 to 1000 numbers (got 100)"},
    {"teeth-not-number", "operations[5].teeth[1]: must be a number (got \"100\")"},
    {"teeth-not-increasing",
     "operations[5].teeth[2]: must be greater than the tooth before it (100; got 100)"},
    {"teeth-decreasing", "operations[5].teeth[5]: must be greater than the tooth before it (600; got -800)"},
    {"shift-missing", "operations[5].shift: missing"},
    {"shift-as-string", "operations[5].shift: must be a number (got \"40\")"},
    {"power-zero", "operations[5].power: must be > 0 (got 0)"},
    {"power-negative", "operations[5].power: must be > 0 (got -1)"},
    {"field-unknown", "operations[6].field: must be \"cells\" or \"cavity\" (got \"vortex\")"},
    {"field-missing", "operations[7].field: missing"},
    {"flow-size-count", "operations[6].size: must be an array of 2 numbers (got an array of 1)"},
    {"flow-size-zero", "operations[6].size[1]: must be > 0 (got 0)"},
    {"speed-null", "operations[6].speed: must be a number (got null)"},
    {"time-zero", "operations[6].time: must be > 0 (got 0)"},
    {"time-negative", "operations[7].time: must be > 0 (got -1.5)"},
    {"steps-fraction", "operations[6].steps: must be an integer (got 64.5)"},
    {"steps-zero", "operations[6].steps: must be in [1, 10000] (got 0)"},
    {"steps-too-many", "operations[6].steps: must be in [1, 10000] (got 10001)"},
    {"steps-too-few",
     "operations[6].steps: must be at least 32 |speed| time max(size) / min(size)^2 = 16 (got 15)"},
    {"steps-impossible",
     "operations[6].steps: cannot be enough: this speed, time and size need more than 10000 steps"},
    {"core-negative", "operations[4].core: must be >= 0 (got -1)"},
    {"core-as-string", "operations[3].core: must be a number (got \"25\")"},
    {"bleed-negative", "bleed: must be >= 0 (got -0.5)"},
    {"bleed-as-string", "bleed: must be a number (got \"1\")"},
    {"stretch-in-3d", "operations[7].tool: \"stretch\" is not available in 3D (2D only)"},
    {"flow-in-initial", "initial[2].tool: \"flow\" is not allowed in initial"},
    {"v1-stretch", "operations[5].tool: \"stretch\" needs format version 2 (the file says version 1)"},
    {"v1-flow", "operations[5].tool: \"flow\" needs format version 2 (the file says version 1)"},
    {"v1-core", "operations[4].core: needs format version 2 (the file says version 1)"},
    {"v1-core-zero", "operations[3].core: needs format version 2 (the file says version 1)"},
    {"v1-core-3d", "operations[3].core: needs format version 2 (the file says version 1)"},
    {"v1-bleed", "bleed: needs format version 2 (the file says version 1)"},
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
    g.meta.name = "small";
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
    for (const char* name : {"base-2d", "base-3d", "edge-3d", "base-2d-v2", "base-3d-v2"}) {
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

TEST(GenomeIO, UnknownKeysOfVersionTwoStrokesWarn) {
    // A key of another tool is unknown here: a flow has no radius, a stretch no core; both are
    // warned about with their place and ignored, and the file loads.
    nlohmann::ordered_json json =
        nlohmann::ordered_json::parse(test::readFile(genomeData() / "valid" / "base-2d-v2.marble.json"));
    json["operations"][5]["core"] = 5;
    json["operations"][6]["radius"] = 10;
    std::vector<std::string> warnings;
    Genome g = parseGenome(json.dump(), "v2", &warnings);
    EXPECT_EQ(warnings, (std::vector<std::string>{"v2: operations[5]: unknown key \"core\" ignored",
                                                  "v2: operations[6]: unknown key \"radius\" ignored"}));
    EXPECT_EQ(g.operations[5].core, 0.0);
    EXPECT_EQ(serializeGenome(g).find("\"radius\": 10"), std::string::npos);
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
    EXPECT_EQ(g.meta.toJson()["unicode"], "Marmorpapier \u00e9\u00f1 \u2603");
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
    for (const auto& entry : fs::directory_iterator(test::dataDir() / "examples"))
        files.push_back(entry.path());
    for (const auto& entry : fs::directory_iterator(genomeData() / "valid"))
        files.push_back(entry.path());
    std::vector<Genome> genomes;
    for (const fs::path& file : files)
        genomes.push_back(loadGenome(file));
    // The examples hold a version-2 design (marbled-paper), so the tests that iterate them
    // meet stretch, flow, a core and a bleed.
    EXPECT_TRUE(
        std::any_of(genomes.begin(), genomes.end(), [](const Genome& g) { return requiredVersion(g) == 2; }));
    for (const char* name : {"probes-0", "probes-1", "probes-2", "probes-3", "probes-4", "probes-v2-stretch",
                             "probes-v2-core", "probes-v2-flow"}) {
        nlohmann::ordered_json probes = nlohmann::ordered_json::parse(
            test::readFile(test::dataDir() / "conformance" / (std::string(name) + ".json")));
        genomes.push_back(parseGenome(probes["genome"].dump(), name));
    }
    genomes.push_back(smallGenome());
    ASSERT_GE(genomes.size(), 20u);
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
    std::vector<std::string> order = {"\"format\"",     "\"version\"", "\"dimension\"", "\"size\"",
                                      "\"background\"", "\"palette\"", "\"initial\"",   "\"operations\"",
                                      "\"source\"",     "\"meta\""};
    std::size_t last = 0;
    for (const std::string& key : order) {
        std::size_t at = text.find(key);
        ASSERT_NE(at, std::string::npos) << key;
        EXPECT_GT(at, last) << key;
        last = at;
    }
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(text);
    std::vector<std::string> combKeys;
    for (auto it = json["operations"][0].begin(); it != json["operations"][0].end(); ++it)
        combKeys.push_back(it.key());
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
    expectError(
        bad,
        "mem: initial[1].tool: \"vortex\" is not allowed in initial (only drop, spray and, in 3D, cylinder)");
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
    bad.meta.other["x"] = std::nan("");
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

TEST(GenomeIO, ValidateGenomeChecksVersionTwoInMemory) {
    Genome g = loadGenome(genomeData() / "valid" / "base-2d-v2.marble.json");
    ASSERT_EQ(g.operations[5].tool, Tool::Stretch);
    ASSERT_EQ(g.operations[6].tool, Tool::Flow);
    EXPECT_NO_THROW(validateGenome(g, "mem"));
    const double inf = std::numeric_limits<double>::infinity();

    auto expectError = [](const Genome& bad, const std::string& expected) {
        try {
            validateGenome(bad, "mem");
            ADD_FAILURE() << "accepted; expected " << expected;
        } catch (const GenomeError& e) {
            EXPECT_EQ(std::string(e.what()), expected);
        }
    };
    Genome bad = g;
    bad.operations[5].teeth = {0.0};
    expectError(bad, "mem: operations[5].teeth: must hold 2 to 1000 numbers (got 1)");
    bad = g;
    bad.operations[5].teeth.assign(1001, 0.0);
    for (std::size_t i = 0; i < bad.operations[5].teeth.size(); ++i)
        bad.operations[5].teeth[i] = double(i);
    expectError(bad, "mem: operations[5].teeth: must hold 2 to 1000 numbers (got 1001)");
    bad.operations[5].teeth.pop_back();
    EXPECT_NO_THROW(validateGenome(bad, "mem")) << "1,000 teeth are allowed";
    bad = g;
    bad.operations[5].teeth[3] = std::nan("");
    expectError(bad, "mem: operations[5].teeth[3]: must be finite (got nan)");
    bad = g;
    bad.operations[5].teeth[1] = 0.0;
    expectError(bad, "mem: operations[5].teeth[1]: must be greater than the tooth before it (0; got 0)");
    bad = g;
    bad.operations[5].shift = -inf;
    expectError(bad, "mem: operations[5].shift: must be finite (got -inf)");
    bad = g;
    bad.operations[5].power = 0.0;
    expectError(bad, "mem: operations[5].power: must be > 0 (got 0)");
    bad = g;
    bad.operations[6].extent.x = -250.0;
    expectError(bad, "mem: operations[6].size[0]: must be > 0 (got -250)");
    bad = g;
    bad.operations[6].speed = inf;
    expectError(bad, "mem: operations[6].speed: must be finite (got inf)");
    bad = g;
    bad.operations[6].time = 0.0;
    expectError(bad, "mem: operations[6].time: must be > 0 (got 0)");
    bad = g;
    bad.operations[6].steps = 15;
    expectError(
        bad,
        "mem: operations[6].steps: must be at least 32 |speed| time max(size) / min(size)^2 = 16 (got 15)");
    bad.operations[6].steps = 16;
    EXPECT_NO_THROW(validateGenome(bad, "mem")) << "exactly the fewest steps are enough";
    bad = g;
    bad.operations[6].steps = 0;
    expectError(bad, "mem: operations[6].steps: must be in [1, 10000] (got 0)");
    bad = g;
    bad.operations[6].field = static_cast<FlowField>(7);
    expectError(bad, "mem: operations[6].field: must be \"cells\" or \"cavity\"");
    bad = g;
    bad.operations[4].core = -0.5;
    expectError(bad, "mem: operations[4].core: must be >= 0 (got -0.5)");
    bad = g;
    bad.bleed = std::nan("");
    expectError(bad, "mem: bleed: must be finite (got nan)");
    bad.bleed = inf;
    expectError(bad, "mem: bleed: must be finite (got inf)");
    bad.bleed = -1.0;
    expectError(bad, "mem: bleed: must be >= 0 (got -1)");
}

TEST(GenomeIO, WriterWritesTheLowestVersion) {
    // A design with no version-2 feature is written as version 1, byte for byte as before
    // version 2 existed (written-v1 was saved by that writer), its cores of 0 and bleed of 0
    // left out.
    const fs::path old = genomeData() / "valid" / "written-v1.marble.json";
    const std::string oldText = test::readFile(old);
    Genome g = loadGenome(old);
    EXPECT_EQ(requiredVersion(g), 1);
    EXPECT_EQ(serializeGenome(g), oldText);
    bool swirls = false;
    for (Operation& op : g.operations)
        if (op.tool == Tool::Circle || op.tool == Tool::Vortex) {
            op.core = -0.0; // still the default: no turn changes
            swirls = true;
        }
    ASSERT_TRUE(swirls) << "written-v1 should hold a circle or vortex";
    g.bleed = 0.0;
    EXPECT_EQ(serializeGenome(g), oldText);
    for (const char* name : {"base-2d", "base-3d", "edge-3d"}) {
        std::string text =
            serializeGenome(loadGenome(genomeData() / "valid" / (std::string(name) + ".marble.json")));
        EXPECT_NE(text.find("\n  \"version\": 1,\n"), std::string::npos) << name;
        EXPECT_EQ(text.find("core"), std::string::npos) << name;
        EXPECT_EQ(text.find("bleed"), std::string::npos) << name;
    }

    // Each version-2 feature on its own makes it version 2, and only while it is there.
    auto versionOf = [](const Genome& genome) {
        return nlohmann::ordered_json::parse(serializeGenome(genome))["version"].get<int>();
    };
    Genome base = smallGenome();
    ASSERT_EQ(versionOf(base), 1);
    Genome cored = base;
    cored.operations.push_back(defaultOperation(Tool::Vortex, 2, {400, 300, 0}));
    EXPECT_EQ(versionOf(cored), 1);
    cored.operations.back().core = 12.5;
    EXPECT_EQ(versionOf(cored), 2);
    EXPECT_NE(serializeGenome(cored).find("\"core\": 12.5\n"), std::string::npos) << serializeGenome(cored);
    cored.operations.back().core = 0.0;
    EXPECT_EQ(versionOf(cored), 1);
    Genome bled = base;
    bled.bleed = 0.25;
    EXPECT_EQ(versionOf(bled), 2);
    for (Tool tool : {Tool::Stretch, Tool::Flow}) {
        Genome withTool = base;
        withTool.operations.push_back(defaultOperation(tool, 2, {400, 300, 0}));
        EXPECT_EQ(versionOf(withTool), 2) << toolSpec(tool).name;
    }
    // `bleed` sits between `source` and `meta`.
    bled.source = SourceImage{"paper.png"};
    std::string text = serializeGenome(bled);
    EXPECT_LT(text.find("\"source\""), text.find("\"bleed\": 0.25,"));
    EXPECT_LT(text.find("\"bleed\""), text.find("\"meta\""));
}

TEST(GenomeIO, AStylusIsWrittenAsVersionThreeAndRoundTrips) {
    // A stylus makes the file version 3; a rake says its spacing, pressure is written only when
    // a pen gave one, and what is read back is what was written, byte for byte.
    auto versionOf = [](const Genome& genome) {
        return nlohmann::ordered_json::parse(serializeGenome(genome))["version"].get<int>();
    };
    Genome g = smallGenome();
    ASSERT_LT(versionOf(g), 3);
    Operation stroke = defaultOperation(Tool::Stylus, 2, {400, 300, 0});
    stroke.path = {{100.5, 200.0}, {300.0, 260.0}, {420.0, 180.0}};
    stroke.steps = minimumStylusSteps(stroke);
    g.operations.push_back(stroke);
    EXPECT_EQ(versionOf(g), 3);
    std::string text = serializeGenome(g);
    EXPECT_EQ(text.find("pressure"), std::string::npos) << text;
    EXPECT_EQ(text.find("tines"), std::string::npos) << text;
    // The fields a stylus has (defaultOperation's centre is none of them).
    auto same = [](const Operation& a, const Operation& b) {
        return a.tool == b.tool && a.path == b.path && a.pressure == b.pressure && a.alpha == b.alpha &&
               a.lambda == b.lambda && a.reach == b.reach && a.tines == b.tines && a.steps == b.steps &&
               (a.tines == 1 || a.spacing == b.spacing);
    };
    EXPECT_TRUE(same(parseGenome(text, "saved").operations.back(), stroke));

    Operation& rake = g.operations.back();
    rake.tines = 3;
    rake.spacing = 25.0;
    rake.pressure = {1.0, 0.25, 0.5};
    rake.steps = minimumStylusSteps(rake);
    text = serializeGenome(g);
    EXPECT_NE(text.find("\"tines\": 3,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"spacing\": 25,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"pressure\": ["), std::string::npos) << text;
    Genome again = parseGenome(text, "saved");
    EXPECT_TRUE(same(again.operations.back(), rake));
    EXPECT_EQ(serializeGenome(again), text);
}

TEST(GenomeIO, VersionTwoRoundTripsExactly) {
    for (const char* name : {"base-2d-v2", "base-3d-v2"}) {
        const fs::path file = genomeData() / "valid" / (std::string(name) + ".marble.json");
        Genome g = loadGenome(file);
        EXPECT_EQ(requiredVersion(g), 2) << name;
        std::string text = serializeGenome(g);
        EXPECT_NE(text.find("\n  \"version\": 2,\n"), std::string::npos) << name;
        Genome again = parseGenome(text, "saved");
        EXPECT_EQ(again, g) << name;
        EXPECT_EQ(serializeGenome(again), text) << name;
        if (g.dimension == 3) continue; // its vectors are normalised on loading
        // What the file says survives: the same JSON, key for key, as the file (whose numbers
        // are all written in their shortest form), meta aside.
        nlohmann::ordered_json written = nlohmann::ordered_json::parse(text),
                               original = nlohmann::ordered_json::parse(test::readFile(file));
        EXPECT_EQ(written["operations"], original["operations"]) << name;
        EXPECT_EQ(written["bleed"], original["bleed"]) << name;
    }
    // Awkward values keep every bit: shortest doubles in teeth, a tiny core, a negative shift.
    Genome g = loadGenome(genomeData() / "valid" / "base-2d-v2.marble.json");
    g.operations[5].teeth = {-0.1, 1e-300, 0.30000000000000004, 7.5e15, 1e300};
    g.operations[5].shift = -1e-7;
    g.operations[5].power = 3.0000000000000004;
    g.operations[4].core = 5e-324;
    g.operations[6].extent = {0.1, 1e-3};
    g.operations[6].speed = -0.0;
    g.operations[6].steps = minimumFlowSteps(g.operations[6]);
    g.bleed = 0.1;
    Genome again = parseGenome(serializeGenome(g), "saved");
    EXPECT_EQ(again, g);
    EXPECT_EQ(serializeGenome(again), serializeGenome(g));
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
    for (const auto& entry : fs::directory_iterator(dir))
        left.push_back(entry.path().filename());
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
                for (std::size_t k = 1; k < param.choices.size(); ++k)
                    choices.push_back(int(k));
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
                EXPECT_EQ(serializeGenome(parseGenome(file, "mem")), file)
                    << spec.name << " " << dimension << "D choice " << choice;
            }
        }
    }
}

TEST(Registry, InkLayingToolsAreTheInitialStateAndPushForms) {
    for (const ToolSpec& spec : allTools()) {
        for (int dimension : {2, 3}) {
            EXPECT_EQ(allowedInInitial(spec.tool, dimension), spec.laysInk && spec.available(dimension))
                << spec.name;
            if (!spec.available(dimension)) continue;
            bool push = spec.form(dimension) == ShaderForm::PushArea ||
                        spec.form(dimension) == ShaderForm::PushVolume;
            // The shader's push form is the only one with an ink test (tools.glsl).
            if (spec.laysInk) {
                EXPECT_TRUE(push) << spec.name;
            }
            bool hasColor = false;
            for (const ParamSpec& param : spec.params(dimension))
                hasColor = hasColor || param.kind == ParamKind::Color;
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
            ASSERT_NO_THROW(validateGenome(
                [&] {
                    Genome g;
                    g.dimension = dimension;
                    g.palette = {Color{}};
                    (allowedInInitial(spec.tool, dimension) ? g.initial : g.operations).push_back(op);
                    return g;
                }(),
                "defaults"))
                << spec.name;
            for (const ParamSpec& param : spec.params(dimension)) {
                if (param.kind == ParamKind::Choice || param.kind == ParamKind::Position ||
                    param.kind == ParamKind::Direction || param.kind == ParamKind::Color)
                    continue;
                EXPECT_TRUE(param.range.contains(param.defaultValue)) << spec.name << "." << param.key;
                EXPECT_GE(param.mutationScale, 0.0) << spec.name << "." << param.key;
            }
        }
}

// ---- Wrapping bath (docs/genome-format.md, "Wrapping bath") ----

namespace wrapping {

/// A wrapped bath of 200 x 100 with a spray and a stretch, and `extra` steps appended.
std::string wrappedText(const std::string& version, const std::string& wrap,
                        const std::string& extraInitial = "", const std::string& extraOperations = "") {
    return R"({"format": "marbler-genome", "version": )" + version +
           R"(, "dimension": 2, "size": [200, 100], "background": "#ffffff", "palette": ["#000000"],
      "wrap": )" +
           wrap + R"(,
      "initial": [{"tool": "spray", "center": [195, 5], "radius": 20, "color": 0})" +
           extraInitial + R"(],
      "operations": [{"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [-10, 40, 90], "shift": 30, "power": 1})" +
           extraOperations + "]}";
}

std::string parseError(const std::string& text) {
    try {
        parseGenome(text, "w.json");
    } catch (const GenomeError& e) {
        return e.what();
    }
    return "(loaded without error)";
}

TEST(WrappingBath, ReadsWritesAndNeedsVersion3) {
    Genome g = parseGenome(wrappedText("3", "true"), "w.json");
    EXPECT_TRUE(g.wrap);
    nlohmann::ordered_json saved = toJson(g);
    EXPECT_EQ(saved["version"], 3);
    EXPECT_EQ(saved["wrap"], true);
    EXPECT_EQ(parseGenome(serializeGenome(g), "again.json"), g);
    // Without the wrap the same design is version 2 and the file has no "wrap".
    g.wrap = false;
    EXPECT_EQ(toJson(g)["version"], 2);
    EXPECT_FALSE(toJson(g).contains("wrap"));
    EXPECT_FALSE(parseGenome(wrappedText("3", "false"), "w.json").wrap);

    EXPECT_EQ(parseError(wrappedText("2", "true")),
              "w.json: wrap: needs format version 3 (the file says version 2)");
    EXPECT_EQ(parseError(wrappedText("3", "1")),
              R"(w.json: wrap: must be true, false, "straight", "half-drop" or "brick" (got 1))");
}

TEST(WrappingBath, AStepThatCannotWrapIsRefusedWithItsPlace) {
    auto expectRefused = [](const std::string& text, const std::string& where, const std::string& why) {
        std::string error = parseError(text);
        EXPECT_EQ(error.rfind("w.json: " + where + ": ", 0), 0u) << error;
        EXPECT_NE(error.find(why), std::string::npos) << error;
    };
    expectRefused(
        wrappedText("3", "true", R"(, {"tool": "drop", "center": [5, 5], "radius": 2, "color": 0})"),
        "initial[1].tool", "a drop pushes the inks");
    expectRefused(
        wrappedText(
            "3", "true", "",
            R"(, {"tool": "comb", "origin": [0, 0], "angle": 0, "alpha": 5, "lambda": 2, "spacing": 10})"),
        "operations[1].tool", "\"comb\" cannot wrap");
    expectRefused(
        wrappedText(
            "3", "true", "",
            R"(, {"tool": "stretch", "origin": [0, 0], "angle": 45, "teeth": [0, 100], "shift": 3, "power": 1})"),
        "operations[1].angle", "along an axis");
    // Along y (angle 90) the teeth must span the width, 200, not the height.
    expectRefused(
        wrappedText(
            "3", "true", "",
            R"(, {"tool": "stretch", "origin": [0, 0], "angle": 90, "teeth": [0, 100], "shift": 3, "power": 1})"),
        "operations[1].teeth", "from the first tooth to the last 200 (the design's width; got 100)");
    // The same steps are fine where the bath does not wrap.
    EXPECT_NO_THROW(parseGenome(
        wrappedText("3", "false", R"(, {"tool": "drop", "center": [5, 5], "radius": 2, "color": 0})"),
        "w.json"));

    Genome g = parseGenome(wrappedText("3", "true"), "w.json");
    g.source = SourceImage{"picture.png"};
    EXPECT_THROW(validateGenome(g, "mem"), GenomeError);
    try {
        validateGenome(g, "mem");
    } catch (const GenomeError& e) {
        EXPECT_STREQ(
            e.what(),
            "mem: wrap: a bath that wraps cannot have a source image (its edges would meet in a seam)");
    }
}

TEST(WrappingBath, HalfDropAndBrickLatticesAreReadWrittenAndChecked) {
    // The straight lattice by name is `true`, and is written so.
    Genome straight = parseGenome(wrappedText("3", R"("straight")"), "w.json");
    EXPECT_TRUE(straight.wrap);
    EXPECT_EQ(straight.lattice, Lattice::Straight);
    EXPECT_EQ(toJson(straight)["wrap"], true);
    EXPECT_EQ(straight, parseGenome(wrappedText("3", "true"), "w.json"));

    // Brick: the x-shift's teeth span the height (100) as in a straight repeat.
    Genome brick = parseGenome(wrappedText("3", R"("brick")"), "w.json");
    EXPECT_TRUE(brick.wrap);
    EXPECT_EQ(brick.lattice, Lattice::Brick);
    EXPECT_EQ(toJson(brick)["wrap"], "brick");
    EXPECT_EQ(toJson(brick)["version"], 3);
    EXPECT_EQ(parseGenome(serializeGenome(brick), "again.json"), brick);

    auto expectRefused = [](const std::string& text, const std::string& where, const std::string& why) {
        std::string error = parseError(text);
        EXPECT_EQ(error.rfind("w.json: " + where + ": ", 0), 0u) << error;
        EXPECT_NE(error.find(why), std::string::npos) << error;
    };
    // Half-drop: an x-shift by a function of y must repeat every h / 2 (50), not h.
    expectRefused(
        wrappedText("3", R"("half-drop")"), "operations[0].teeth",
        "from the first tooth to the last 50 (half the design's height, as a half-drop repeat needs; "
        "got 100)");
    // ... and a y-shift by a function of x every w (200), as straight.
    const std::string halfDropOk = R"({"format": "marbler-genome", "version": 3, "dimension": 2,
      "size": [200, 100], "background": "#ffffff", "palette": ["#000000"], "wrap": "half-drop",
      "initial": [{"tool": "spray", "center": [195, 5], "radius": 20, "color": 0}],
      "operations": [
        {"tool": "stretch", "origin": [0, 0], "angle": 0, "teeth": [-10, 15, 40], "shift": 30, "power": 1},
        {"tool": "stretch", "origin": [0, 0], "angle": 90, "teeth": [0, 120, 200], "shift": 8, "power": 2}]})";
    const Genome halfDrop = parseGenome(halfDropOk, "w.json");
    EXPECT_EQ(halfDrop.lattice, Lattice::HalfDrop);
    EXPECT_EQ(toJson(halfDrop)["wrap"], "half-drop");
    // Brick: a y-shift by a function of x must repeat every w / 2 (100).
    expectRefused(
        wrappedText(
            "3", R"("brick")", "",
            R"(, {"tool": "stretch", "origin": [0, 0], "angle": 90, "teeth": [0, 200], "shift": 3, "power": 1})"),
        "operations[1].teeth", "last 100 (half the design's width, as a brick repeat needs; got 200)");
    EXPECT_NO_THROW(parseGenome(
        wrappedText(
            "3", R"("brick")", "",
            R"(, {"tool": "stretch", "origin": [0, 0], "angle": 270, "teeth": [0, 100], "shift": 3, "power": 1})"),
        "w.json"));

    // A lattice the format does not know, or in an older version.
    expectRefused(wrappedText("3", R"("diagonal")"), "wrap",
                  R"(must be true, false, "straight", "half-drop" or "brick" (got "diagonal"))");
    expectRefused(wrappedText("3", "1"), "wrap", "must be true, false");
    expectRefused(wrappedText("2", R"("brick")"), "wrap", "needs format version 3 (the file says version 2)");

    // A tile too long across the columns or rows whose images a spray compares with.
    Genome tall = halfDrop;
    tall.size = {20, 100, 1000};
    tall.operations.clear();
    try {
        validateGenome(tall, "mem");
        ADD_FAILURE() << "a half-drop tile 5 times as tall as wide was accepted";
    } catch (const GenomeError& e) {
        EXPECT_STREQ(e.what(),
                     "mem: wrap: a half-drop repeat needs a design at most 4 times as tall as it is "
                     "wide (got 20 x 100)");
    }
    Genome wide = brick;
    wide.size = {500, 100, 1000};
    wide.operations.clear();
    EXPECT_THROW(validateGenome(wide, "mem"), GenomeError);
    wide.lattice = Lattice::Straight;
    EXPECT_NO_THROW(validateGenome(wide, "mem"));
}

} // namespace wrapping

// ---- end wrapping bath ----
