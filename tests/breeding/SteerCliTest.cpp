// `marbler breed` with the picks (--passed, --picks; docs/breeding.md): the same ranking as the
// window, said in a `steered:` line, and bad rounds refused with where they are wrong.

#include "TestUtil.h"

#include "marbler/Families.h"
#include "marbler/GenomeIO.h"
#include "marbler/Steer.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace marbler {
namespace {

namespace fs = std::filesystem;
using test::runMarbler;

/// Zebras picked over other families, written as files, and a rounds file naming them.
struct Rounds {
    fs::path dir;
    std::vector<PickRound> rounds;
    std::string passedNow;
    fs::path parent;
    explicit Rounds(const std::string& name)
        : dir(test::outputDir(name)) {
        std::string json = R"({"rounds": [)";
        for (int r = 0; r < 2; ++r) {
            PickRound round;
            const std::string pick = "pick-" + std::to_string(r) + ".marble.json";
            round.picked.push_back(familyGenome(*findFamily("zebra"), 100 + r));
            saveGenome(round.picked.back(), dir / pick);
            json += std::string(r ? "," : "") + R"({"picked": [")" + pick + R"("], "passed": [)";
            int k = 0;
            for (const char* other : {"stone", "chevron", "shawl"}) {
                const std::string file = "pass-" + std::to_string(r) + "-" + other + ".marble.json";
                round.passed.push_back(familyGenome(*findFamily(other), 200 + r));
                saveGenome(round.passed.back(), dir / file);
                json += std::string(k++ ? "," : "") + "\"" + file + "\"";
            }
            json += "]}";
            rounds.push_back(round);
        }
        json += "]}";
        test::writeFile(dir / "rounds.json", json);
        parent = dir / "parent.marble.json";
        PickRound now;
        now.picked.push_back(familyGenome(*findFamily("zebra"), 102));
        saveGenome(now.picked.back(), parent);
        now.passed.push_back(familyGenome(*findFamily("stone"), 202));
        saveGenome(now.passed.back(), dir / "now-stone.marble.json");
        passedNow = (dir / "now-stone.marble.json").string();
        rounds.push_back(now);
    }
};

TEST(SteerCli, BreedsWhatTheWindowWouldAndSaysWhy) {
    Rounds r("steer-cli");
    const fs::path out = r.dir / "children";
    const test::RunResult run =
        runMarbler({"breed", "alter", r.parent.string(), "--seed", "9", "--passed", r.passedNow, "--picks",
                    (r.dir / "rounds.json").string(), "-o", out.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("steered: more like your last 3 picks"), std::string::npos) << run.out;
    // The same children as steerBreed over the same rounds (the files on disk).
    SteerRequest request;
    request.rounds = r.rounds;
    request.breed.parents = {loadGenome(r.parent)};
    request.breed.seed = 9;
    const SteerResult expected = steerBreed(request);
    ASSERT_EQ(expected.children.size(), 8u);
    for (std::size_t i = 0; i < expected.children.size(); ++i) {
        char name[48];
        std::snprintf(name, sizeof name, "child-%02zu.marble.json", i + 1);
        EXPECT_EQ(genomeId(loadGenome(out / name)), genomeId(expected.children[i])) << name;
    }
}

TEST(SteerCli, TheWindowsWildcardCellOnAndOff) {
    // --wildcard is the window's Wildcard cell: the last child a fresh zebra; --no-fresh is the
    // window with it off: every child a variation of the pick.
    Rounds r("steer-cli-wildcard");
    const auto run = [&](const std::string& name, std::vector<std::string> extra) {
        std::vector<std::string> args{"breed",
                                      "alter",
                                      r.parent.string(),
                                      "--seed",
                                      "9",
                                      "--passed",
                                      r.passedNow,
                                      "--picks",
                                      (r.dir / "rounds.json").string(),
                                      "-o",
                                      (r.dir / name).string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::RunResult result = runMarbler(args);
        EXPECT_EQ(result.exitCode, 0) << result.err;
        std::vector<Genome> children;
        for (int i = 1; i <= 8; ++i)
            children.push_back(loadGenome(r.dir / name / ("child-0" + std::to_string(i) + ".marble.json")));
        return children;
    };
    const auto opOf = [](const Genome& g) { return g.meta.lineage.value_or(MetaLineage{}).op.value_or(""); };
    const std::vector<Genome> plain = run("plain", {});
    const std::vector<Genome> wild = run("wild", {"--wildcard"});
    const std::vector<Genome> variations = run("variations", {"--no-fresh"});
    // The wildcard takes the last child's place and leaves the others as they were.
    EXPECT_EQ(opOf(wild.back()), "wildcard");
    EXPECT_EQ(wild.back().meta.family, std::optional<std::string>("zebra"));
    EXPECT_EQ(wild.back().meta.lineage->child, std::optional<int>(8));
    for (std::size_t i = 0; i + 1 < wild.size(); ++i)
        EXPECT_EQ(genomeId(wild[i]), genomeId(plain[i])) << i;
    int freshWithout = 0;
    for (const Genome& child : variations) {
        freshWithout += opOf(child) == "wildcard";
        EXPECT_EQ(child.meta.lineage->parents.value_or(std::vector<std::string>{}).size(), 1u) << opOf(child);
    }
    EXPECT_EQ(freshWithout, 0);
    EXPECT_GE(
        std::count_if(plain.begin(), plain.end(), [&](const Genome& g) { return opOf(g) == "wildcard"; }), 3);
}

TEST(SteerCli, ABadRoundsFileIsNamedWithWhere) {
    Rounds r("steer-cli-bad");
    test::writeFile(r.dir / "bad.json", R"({"rounds": [{"picked": "pick-0.marble.json"}]})");
    const test::RunResult run = runMarbler({"breed", "alter", r.parent.string(), "--seed", "9", "--picks",
                                            (r.dir / "bad.json").string(), "-o", (r.dir / "none").string()});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("bad.json: /rounds/0/picked: expected a list of files"), std::string::npos)
        << run.err;
    EXPECT_FALSE(fs::exists(r.dir / "none"));
}

TEST(SteerCli, AMissingDesignInTheRoundsIsNamedWithWhereItWasAskedFor) {
    Rounds r("steer-cli-missing");
    test::writeFile(r.dir / "missing.json",
                    R"({"rounds": [{"picked": ["pick-0.marble.json"], "passed": ["nope.marble.json"]}]})");
    const test::RunResult run =
        runMarbler({"breed", "alter", r.parent.string(), "--seed", "9", "--picks",
                    (r.dir / "missing.json").string(), "-o", (r.dir / "none").string()});
    EXPECT_EQ(run.exitCode, 2);
    // The rounds file and the entry, then the design's own file.
    EXPECT_NE(run.err.find("missing.json: /rounds/0/passed/0: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("nope.marble.json"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(r.dir / "none"));
}

} // namespace
} // namespace marbler
