// `marbler random` and `marbler breed` through the built executable (spec/cli.md).

#include "TestUtil.h"

#include "marbler/Colourways.h"
#include "marbler/Generator.h"
#include "marbler/GenomeIO.h"
#include "marbler/Operators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

namespace marbler {
namespace {

namespace fs = std::filesystem;
using test::runMarbler;

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    if (!fs::exists(dir)) return names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

int lineCount(const std::string& text) {
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

/// Two random parents written by the executable itself.
struct Parents {
    fs::path dir, a, b, solid;
    explicit Parents(const std::string& name)
        : dir(test::outputDir(name)) {
        a = dir / "a.marble.json";
        b = dir / "b.marble.json";
        solid = dir / "solid.marble.json";
        EXPECT_EQ(runMarbler({"random", "--dimension", "2", "--seed", "1", "-o", a.string()}).exitCode, 0);
        EXPECT_EQ(runMarbler({"random", "--dimension", "2", "--seed", "2", "-o", b.string()}).exitCode, 0);
        EXPECT_EQ(runMarbler({"random", "--dimension", "3", "--seed", "3", "-o", solid.string()}).exitCode,
                  0);
    }
};

TEST(RandomVerb, SameSeedGivesByteIdenticalFiles) {
    fs::path dir = test::outputDir("random-same-seed");
    for (const char* dimension : {"2", "3"}) {
        fs::path one = dir / (std::string("one-") + dimension + ".marble.json");
        fs::path two = dir / (std::string("two-") + dimension + ".marble.json");
        test::RunResult r1 =
            runMarbler({"random", "--dimension", dimension, "--seed", "31337", "-o", one.string()});
        test::RunResult r2 = runMarbler(
            {"random", "--seed=31337", "--dimension=" + std::string(dimension), "--output", two.string()});
        ASSERT_EQ(r1.exitCode, 0) << r1.err;
        ASSERT_EQ(r2.exitCode, 0) << r2.err;
        std::string text = test::readFile(one);
        EXPECT_EQ(text, test::readFile(two));
        // The file is the library's genome for that seed, and it loads.
        EXPECT_EQ(text, serializeGenome(randomGenome(31337, std::stoi(dimension))));
        EXPECT_NO_THROW(loadGenome(one));
    }
    fs::path other = dir / "other.marble.json";
    ASSERT_EQ(runMarbler({"random", "--dimension", "2", "--seed", "31338", "-o", other.string()}).exitCode,
              0);
    EXPECT_NE(test::readFile(other), test::readFile(dir / "one-2.marble.json"));
}

TEST(RandomVerb, BadUsageExitsWithTwoAndOneLine) {
    fs::path dir = test::outputDir("random-bad");
    fs::path out = dir / "x.marble.json";
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"random", "--dimension", "2", "-o", out.string()},                 // no seed
             {"random", "--dimension", "4", "--seed", "1", "-o", out.string()},  // bad dimension
             {"random", "--dimension", "2", "--seed", "-5", "-o", out.string()}, // negative seed
             {"random", "--dimension", "2", "--seed", "1"},                      // no output
             {"random", "--dimension", "2", "--seed", "1", "--colour", "red", "-o", out.string()},
         }) {
        test::RunResult r = runMarbler(args);
        EXPECT_EQ(r.exitCode, 2) << args[2];
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST(RandomVerb, HelpDescribesEveryOption) {
    test::RunResult r = runMarbler({"random", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"--dimension", "--seed", "-o"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST(BreedVerb, WritesReproducibleChildren) {
    Parents parents("breed-children");
    fs::path out1 = parents.dir / "first", out2 = parents.dir / "second" / "nested";
    test::RunResult r1 =
        runMarbler({"breed", "alter", parents.a.string(), "--seed", "5", "-o", out1.string()});
    test::RunResult r2 =
        runMarbler({"breed", "alter", parents.a.string(), "--seed", "5", "-o", out2.string()});
    ASSERT_EQ(r1.exitCode, 0) << r1.err;
    ASSERT_EQ(r2.exitCode, 0) << r2.err;
    std::vector<std::string> names = filesIn(out1);
    ASSERT_EQ(names.size(), 8u);
    EXPECT_EQ(names.front(), "child-01.marble.json");
    EXPECT_EQ(names.back(), "child-08.marble.json");
    EXPECT_EQ(filesIn(out2), names);
    Genome parent = loadGenome(parents.a);
    for (const std::string& name : names) {
        EXPECT_EQ(test::readFile(out1 / name), test::readFile(out2 / name)) << name;
        Genome child = loadGenome(out1 / name);
        EXPECT_EQ(child.meta.toJson()["lineage"]["operator"], "alter");
        EXPECT_EQ(child.meta.toJson()["lineage"]["parents"][0], genomeId(parent));
        EXPECT_EQ(child.meta.toJson()["id"], genomeId(child));
    }
    // The files are what the library breeds from the loaded parent.
    BreedRequest request;
    request.parents = {parent};
    request.seed = 5;
    std::vector<Genome> children = breed(request);
    EXPECT_EQ(test::readFile(out1 / "child-03.marble.json"), serializeGenome(children[2]));

    fs::path other = parents.dir / "other";
    ASSERT_EQ(
        runMarbler({"breed", "alter", parents.a.string(), "--seed", "6", "-o", other.string()}).exitCode, 0);
    EXPECT_NE(test::readFile(other / "child-01.marble.json"), test::readFile(out1 / "child-01.marble.json"));
}

TEST(BreedVerb, ChildrenElsewhereEmbedTheirParentsSourceImage) {
    // A child written into another folder would name its parent's image with `..`, which the
    // source rule refuses; it carries the image instead, and renders.
    const fs::path root = test::outputDir("breed-source");
    fs::remove_all(root);
    fs::create_directories(root / "parent");
    fs::copy_file(test::dataDir() / "render" / "source-4x2.png", root / "parent" / "paper.png");
    Genome parent = loadGenome(test::dataDir() / "render" / "source-2d.marble.json");
    parent.source = SourceImage{"paper.png"};
    saveGenome(parent, root / "parent" / "p.marble.json");
    for (const fs::path& dir : {root / "kids", root / "parent" / "beside"}) {
        auto r = runMarbler({"breed", "alter", (root / "parent" / "p.marble.json").string(), "--seed", "3",
                             "--count", "2", "-o", dir.string()});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const Genome child = loadGenome(dir / "child-01.marble.json");
        ASSERT_TRUE(child.source);
        EXPECT_TRUE(child.source->image.starts_with("data:image/png;base64,"))
            << child.source->image.substr(0, 40);
        r = runMarbler({"render", (dir / "child-01.marble.json").string(), "-o", (dir / "c.png").string(),
                        "--width", "16"});
        EXPECT_EQ(r.exitCode, 0) << r.err;
    }
    // Beside the parent the path still holds.
    auto r = runMarbler({"breed", "alter", (root / "parent" / "p.marble.json").string(), "--seed", "3",
                         "--count", "1", "-o", (root / "parent").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(loadGenome(root / "parent" / "child-01.marble.json").source->image, "paper.png");
}

TEST(BreedVerb, EveryOperatorWithCountAndStrength) {
    Parents parents("breed-operators");
    struct Case {
        std::vector<std::string> args;
        std::size_t count;
    };
    std::vector<Case> cases{
        {{"breed", "alter", parents.a.string(), "--seed", "1", "--count", "3", "--strength", "0.2"}, 3},
        {{"breed", "recombine", parents.a.string(), parents.b.string(), parents.a.string(), "--seed", "2"},
         8},
        {{"breed", "swap", parents.a.string(), parents.b.string(), "--seed", "3", "--count", "2"}, 2},
        {{"breed", "reinit", parents.solid.string(), "--seed", "4", "--count", "1"}, 1},
    };
    int k = 0;
    for (Case& c : cases) {
        fs::path out = parents.dir / ("out" + std::to_string(k++));
        c.args.push_back("-o");
        c.args.push_back(out.string());
        test::RunResult r = runMarbler(c.args);
        ASSERT_EQ(r.exitCode, 0) << c.args[1] << ": " << r.err;
        std::vector<std::string> names = filesIn(out);
        EXPECT_EQ(names.size(), c.count) << c.args[1];
        for (const std::string& name : names) {
            Genome child = loadGenome(out / name);
            EXPECT_EQ(child.meta.toJson()["lineage"]["operator"], c.args[1]);
            EXPECT_EQ(child.meta.toJson()["lineage"]["generation"], 1);
        }
    }
}

// `marbler breed swap A B --count 8` wrote 4 + 4 identical genomes: every child must differ
// from the others and from the parents (meta aside), for every operator and count.
TEST(BreedVerb, NoTwoChildrenAreEqual) {
    Parents parents("breed-distinct");
    const std::vector<std::vector<std::string>> operators{
        {"alter", parents.a.string()},
        {"recombine", parents.a.string(), parents.b.string()},
        {"swap", parents.a.string(), parents.b.string()},
        {"reinit", parents.a.string()},
    };
    const std::string idA = genomeId(loadGenome(parents.a)), idB = genomeId(loadGenome(parents.b));
    for (const auto& op : operators)
        for (int count = 1; count <= 9; ++count) {
            SCOPED_TRACE(op[0] + " --count " + std::to_string(count));
            fs::path out = parents.dir / (op[0] + "-" + std::to_string(count));
            std::vector<std::string> args{"breed"};
            args.insert(args.end(), op.begin(), op.end());
            for (const std::string& a : {std::string("--seed"), std::string("11"), std::string("--count"),
                                         std::to_string(count), std::string("-o"), out.string()})
                args.push_back(a);
            test::RunResult r = runMarbler(args);
            ASSERT_EQ(r.exitCode, 0) << r.err;
            std::set<std::string> ids{idA, idB};
            std::vector<std::string> names = filesIn(out);
            ASSERT_EQ(names.size(), std::size_t(count));
            for (const std::string& name : names)
                EXPECT_TRUE(ids.insert(genomeId(loadGenome(out / name))).second)
                    << name << " repeats a design";
        }
}

TEST(BreedVerb, ColourwaysKeepTheStructureAndBreedOnlyTheInks) {
    // The window's Colourways mode on the command line: one parent's colourways at a strength,
    // or two parents' inks mixed.
    Parents parents("breed-colourway");
    const fs::path one = parents.dir / "one", mixed = parents.dir / "mixed";
    test::RunResult r = runMarbler({"breed", "colourway", parents.a.string(), "--seed", "3", "--count", "4",
                                    "--strength", "1", "-o", one.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Genome a = loadGenome(parents.a), b = loadGenome(parents.b);
    ColourwayRequest request;
    request.parents = {a};
    request.strength = 1.0;
    request.seed = 3;
    request.count = 4;
    const std::vector<Genome> expected = colourways(request);
    ASSERT_EQ(filesIn(one).size(), 4u);
    for (int i = 0; i < 4; ++i) {
        const Genome child = loadGenome(one / ("child-0" + std::to_string(i + 1) + ".marble.json"));
        EXPECT_TRUE(sameStructure(child, a)) << i;
        EXPECT_NE(child.palette, a.palette) << i;
        EXPECT_EQ(child.meta.toJson()["lineage"]["operator"], ColourwayOperator);
        EXPECT_EQ(genomeId(child), genomeId(expected[std::size_t(i)])) << i;
    }
    r = runMarbler(
        {"breed", "colourway", parents.a.string(), parents.b.string(), "--seed", "3", "-o", mixed.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    request.parents = {a, b};
    request.mix = true;
    request.count = 8;
    EXPECT_EQ(genomeId(loadGenome(mixed / "child-01.marble.json")), genomeId(colourways(request).front()));
}

TEST(BreedVerb, BadInputExitsWithTwoAndWritesNothing) {
    Parents parents("breed-bad");
    fs::path broken = parents.dir / "broken.marble.json";
    test::writeFile(broken, "{\"format\": \"marbler-genome\", \"version\": 1, \"dimension\": 2,");
    fs::path invalid = parents.dir / "invalid.marble.json";
    std::string text = test::readFile(parents.a);
    text.replace(text.find("\"radius\": "), 10, "\"radius\": -");
    test::writeFile(invalid, text);
    fs::path locked = parents.dir / "locked.marble.json";
    Genome withLock = loadGenome(parents.a);
    setLocks(withLock, Locks{.palette = true});
    saveGenome(withLock, locked);
    fs::path out = parents.dir / "out";
    struct Case {
        std::vector<std::string> args;
        std::string mentions;
    };
    std::vector<Case> cases{
        {{"breed", "mutate", parents.a.string(), "--seed", "1"}, "mutate"},
        {{"breed", "swap", parents.a.string(), "--seed", "1"}, "swap"},
        {{"breed", "alter", parents.a.string(), parents.b.string(), "--seed", "1"}, "alter"},
        {{"breed", "recombine", parents.a.string(), "--seed", "1"}, "recombine"},
        {{"breed", "alter", broken.string(), "--seed", "1"}, broken.string()},
        {{"breed", "recombine", parents.a.string(), invalid.string(), "--seed", "1"}, "initial[0].radius"},
        {{"breed", "alter", (parents.dir / "missing.marble.json").string(), "--seed", "1"},
         "missing.marble.json"},
        {{"breed", "swap", parents.a.string(), parents.solid.string(), "--seed", "1"}, "dimension"},
        {{"breed", "alter", parents.a.string(), "--seed", "1", "--strength", "2"}, "strength"},
        {{"breed", "alter", parents.a.string(), "--seed", "1", "--count", "0"}, "count"},
        {{"breed", "alter", parents.a.string()}, "seed"},
        {{"breed", "colourway", "--seed", "1"}, "colourway takes at least 1 parent"},
        {{"breed", "colourway", parents.a.string(), "--seed", "1", "--wildcard"}, "--wildcard"},
        {{"breed", "colourway", parents.a.string(), "--seed", "1", "--passed", parents.b.string()},
         "not steered"},
        {{"breed", "colourway", locked.string(), "--seed", "1"}, "locked"},
    };
    for (Case& c : cases) {
        c.args.push_back("-o");
        c.args.push_back(out.string());
        test::RunResult r = runMarbler(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.mentions;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(c.mentions), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out)) << c.mentions;
    }
    // Without -o, and with -o naming a file.
    EXPECT_EQ(runMarbler({"breed", "alter", parents.a.string(), "--seed", "1"}).exitCode, 2);
    EXPECT_EQ(
        runMarbler({"breed", "alter", parents.a.string(), "--seed", "1", "-o", parents.b.string()}).exitCode,
        2);
    EXPECT_EQ(test::readFile(parents.b), serializeGenome(randomGenome(2, 2)));
}

TEST(BreedVerb, HelpDescribesEveryOption) {
    test::RunResult r = runMarbler({"breed", "--help"});
    EXPECT_EQ(r.exitCode, 0);
    for (const char* word : {"--seed", "--count", "--strength", "-o", "alter", "recombine", "swap", "reinit",
                             "colourway", "--wildcard", "--no-fresh"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

} // namespace
} // namespace marbler
