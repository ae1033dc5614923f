// `marbler info`: a summary and exit 0 for a valid genome, one stderr line and exit 2 for a bad
// one (spec/cli.md).

#include "TestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace marbler;

namespace {

std::string genomeFile(const std::string& folder, const std::string& name) {
    return (test::dataDir() / "genome" / folder / (name + ".marble.json")).string();
}

} // namespace

TEST(InfoVerb, SummarisesAValidGenome) {
    std::string file = (test::dataDir() / "examples" / "five-stones.marble.json").string();
    test::RunResult run = test::runMarbler({"info", file});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_NE(run.out.find("file:       " + file + "\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("dimension:  2\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("size:       1000 x 1000\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("palette:    4 colours: #1f3b5a #b8412c #e0b44c #2e6e5e\n"), std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("background: #f3ecdc\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("initial:    5 (drop 5)\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("operations: 4 (comb 2, wave 1, vortex 1)\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("name:       Five stones, combed and swirled\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("version:    1\n"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("bleed:"), std::string::npos) << "no bleed, no line: " << run.out;
}

TEST(InfoVerb, SummarisesAVersionTwoGenome) {
    test::RunResult run = test::runMarbler({"info", genomeFile("valid", "base-2d-v2")});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_NE(run.out.find("version:    2\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("bleed:      1.5 design units\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("operations: 8 (line 1, comb 1, wave 1, circle 1, vortex 1, stretch 1, flow 2)\n"),
              std::string::npos)
        << run.out;
    const std::string paper = (test::dataDir() / "examples" / "marbled-paper.marble.json").string();
    run = test::runMarbler({"info", paper});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("version:    2\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("bleed:      1.2 design units\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("operations: 5 (vortex 1, stretch 3, flow 1)\n"), std::string::npos) << run.out;
    run = test::runMarbler({"info", genomeFile("valid", "base-3d-v2")});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("version:    2\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("bleed:      0.5 design units\n"), std::string::npos) << run.out;
}

TEST(InfoVerb, SummarisesASolidGenome) {
    test::RunResult run = test::runMarbler({"info", genomeFile("valid", "base-3d")});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("dimension:  3\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("size:       1000 x 1000 x 600\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("initial:    2 (drop 1, cylinder 1)\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("operations: 7 (line 1, comb 1, wave 2, circle 1, sphere 1, vortex 1)\n"),
              std::string::npos)
        << run.out;
}

TEST(InfoVerb, WarnsAboutUnknownKeysButSucceeds) {
    std::string file = genomeFile("valid", "unknown-keys");
    test::RunResult run = test::runMarbler({"info", file});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(test::lineCount(run.err), 3) << run.err;
    EXPECT_NE(run.err.find("marbler info: warning: " + file + ": unknown key \"comment\" ignored\n"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.out.find("source:     paper.png\n"), std::string::npos) << run.out;
}

TEST(InfoVerb, BadGenomeGivesOneLineAndExit2) {
    for (const char* name :
         {"radius-negative", "syntax-error", "nested-too-deep", "version-newer", "normal-parallel",
          "v1-stretch", "v1-bleed", "steps-too-few", "teeth-not-increasing"}) {
        std::string file = genomeFile("invalid", name);
        test::RunResult run = test::runMarbler({"info", file});
        EXPECT_EQ(run.exitCode, 2) << name;
        EXPECT_EQ(run.out, "") << name;
        EXPECT_EQ(test::lineCount(run.err), 1) << run.err;
        EXPECT_TRUE(run.err.starts_with("marbler info: " + file + ": ")) << run.err;
    }
    std::string file = genomeFile("invalid", "radius-negative");
    EXPECT_EQ(test::runMarbler({"info", file}).err,
              "marbler info: " + file + ": operations[3].radius: must be > 0 (got -2)\n");
}

TEST(InfoVerb, BadUsage) {
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{"info"},
                                               {"info", "a.json", "b.json"},
                                               {"info", "--bogus", "a.json"},
                                               {"info", "/no/such/file.marble.json"}}) {
        test::RunResult run = test::runMarbler(args);
        EXPECT_EQ(run.exitCode, 2) << args.back();
        EXPECT_EQ(test::lineCount(run.err), 1) << run.err;
    }
}

TEST(InfoVerb, Help) {
    test::RunResult run = test::runMarbler({"info", "--help"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.out.find("usage: marbler info GENOME"), std::string::npos) << run.out;
}

TEST(InfoVerb, SaysWhenTheBathWraps) {
    const std::filesystem::path file = test::outputDir("info-wrap") / "tile.marble.json";
    test::writeFile(file, R"({"format": "marbler-genome", "version": 3, "dimension": 2, "size": [200, 100],
      "background": "#ffffff", "palette": ["#000000"], "wrap": true,
      "initial": [{"tool": "spray", "center": [195, 5], "radius": 20, "color": 0}], "operations": []})");
    test::RunResult run = test::runMarbler({"info", file.string()});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("version:    3\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("wrap:       the bath wraps: a straight-repeat tile\n"), std::string::npos)
        << run.out;
    // A half-drop lattice is named (issue 29).
    std::string text = test::readFile(file);
    text.replace(text.find("\"wrap\": true"), 12, "\"wrap\": \"half-drop\"");
    test::writeFile(file, text);
    run = test::runMarbler({"info", file.string()});
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("wrap:       the bath wraps: a half-drop repeat tile\n"), std::string::npos)
        << run.out;
    // Without the wrap, no line.
    run = test::runMarbler({"info", genomeFile("valid", "base-2d-v2")});
    EXPECT_EQ(run.out.find("wrap:"), std::string::npos) << run.out;
}
