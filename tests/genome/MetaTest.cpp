// A genome's meta, typed: every known key reads into its field and writes back, unknown keys and
// values of a wrong type survive untouched (and read as absent), reading never throws, and a file
// loaded and saved keeps its meta byte for byte (key order, 30 rather than 30.0).

#include "TestUtil.h"

#include "marbler/GenomeIO.h"
#include "marbler/Meta.h"
#include "marbler/Operators.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace marbler;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

/// Every key Meta knows, with a value of the type its readers take, in no particular order.
const char* const EveryKnownKey = R"j({
  "locks": {"palette": true, "initial": false, "operations": true},
  "name": "Stone (g3 #7)",
  "lineage": {"parents": ["00112233445566aa", "ffeeddccbbaa9988"], "operator": "alter",
              "seed": 18446744073709551615, "child": 7, "strength": 0.25,
              "variation": {"of": "0123456789abcdef", "strength": 0.075}, "redraws": 2,
              "generation": 3, "change": "2 drops moved"},
  "id": "0123456789abcdef",
  "family": "peacock",
  "seed": 42,
  "generator": "marbler-random-3",
  "paper": {"size": [210, 297], "unit": "mm", "colors": 3},
  "editor": {"muted": [{"step": 1, "part": "operations", "operation": {"tool": "tine"}}]},
  "view": {"yaw": 30, "pitch": -12.5}
})j";

/// A design's text as Marbler writes it, with `meta` as given (parsed, so in its order).
std::string fileWithMeta(const std::string& metaText) {
    Genome g;
    g.palette = {{0x20, 0x30, 0x40}};
    Operation drop;
    drop.tool = Tool::Drop;
    drop.radius = 50.0;
    drop.color = 0;
    g.initial.push_back(drop);
    Json root = toJson(g);
    root["meta"] = Json::parse(metaText);
    return root.dump(2) + "\n";
}

} // namespace

TEST(Meta, EveryKnownKeyReadsIntoItsField) {
    const Meta m = Meta::fromJson(Json::parse(EveryKnownKey));
    EXPECT_EQ(m.name, "Stone (g3 #7)");
    EXPECT_EQ(m.id, "0123456789abcdef");
    EXPECT_EQ(m.family, "peacock");
    EXPECT_EQ(m.seed, 42u);
    EXPECT_EQ(m.generator, "marbler-random-3");
    ASSERT_TRUE(m.paper);
    EXPECT_EQ((*m.paper)["unit"], "mm");
    ASSERT_TRUE(m.lineage);
    EXPECT_EQ(m.lineage->parents, (std::vector<std::string>{"00112233445566aa", "ffeeddccbbaa9988"}));
    EXPECT_EQ(m.lineage->op, "alter");
    EXPECT_EQ(m.lineage->seed, 18446744073709551615ull);
    EXPECT_EQ(m.lineage->child, 7);
    EXPECT_EQ(m.lineage->strength, 0.25);
    ASSERT_TRUE(m.lineage->variation);
    EXPECT_EQ(m.lineage->variation->of, "0123456789abcdef");
    EXPECT_EQ(m.lineage->variation->strength, 0.075);
    EXPECT_EQ(m.lineage->redraws, 2);
    EXPECT_EQ(m.lineage->generation, 3);
    EXPECT_EQ(m.lineage->change, "2 drops moved");
    ASSERT_TRUE(m.editor && m.editor->muted);
    EXPECT_EQ(m.editor->muted->size(), 1u);
    ASSERT_TRUE(m.view);
    EXPECT_EQ(m.view->yaw, 30.0);
    EXPECT_EQ(m.view->pitch, -12.5);
    ASSERT_TRUE(m.locks);
    EXPECT_EQ(m.locks->palette, true);
    EXPECT_EQ(m.locks->initial, false);
    EXPECT_EQ(m.locks->operations, true);
    EXPECT_TRUE(m.other.empty());
}

TEST(Meta, EveryKnownKeyRoundTripsByteForByte) {
    const Json read = Json::parse(EveryKnownKey);
    EXPECT_EQ(Meta::fromJson(read).toJson().dump(2), read.dump(2));
    // Through a file: the whole file, as Marbler writes it, comes back the same.
    const std::string file = fileWithMeta(EveryKnownKey);
    EXPECT_EQ(serializeGenome(parseGenome(file, "meta.marble.json")), file);
}

TEST(Meta, FieldsSetInCodeWriteInTheOrderMarblerAlwaysWroteThem) {
    Meta m;
    m.id = "0123456789abcdef";
    m.lineage = MetaLineage{};
    m.lineage->generation = 2;
    m.lineage->op = "swap";
    m.lineage->parents = std::vector<std::string>{"a", "b"};
    m.family = "nonpareil";
    m.generator = "marbler-family-1";
    m.seed = 7;
    m.name = "Nonpareil";
    EXPECT_EQ(m.toJson().dump(),
              R"({"name":"Nonpareil","seed":7,"generator":"marbler-family-1","family":"nonpareil",)"
              R"("lineage":{"parents":["a","b"],"operator":"swap","generation":2},"id":"0123456789abcdef"})");
    EXPECT_TRUE(Meta{}.empty());
    EXPECT_FALSE(m.empty());
}

TEST(Meta, UnknownKeysSurviveInTheirPlace) {
    const char* text = R"({"note":"by hand","name":"Mine","lineage":{"mine":[1,2],"generation":4},)"
                       R"("view":{"yaw":10,"roll":5},"zzz":{"deep":[true,null]}})";
    const Meta m = Meta::fromJson(Json::parse(text));
    EXPECT_EQ(m.note.value_or(""), "by hand"); // a known key since issue 29, kept in its place
    EXPECT_EQ(m.other["zzz"]["deep"][0], true);
    EXPECT_EQ(m.lineage->other["mine"][1], 2);
    EXPECT_EQ(m.view->other["roll"], 5);
    EXPECT_EQ(m.toJson().dump(), text);
    const std::string file = fileWithMeta(text);
    EXPECT_EQ(serializeGenome(parseGenome(file, "stranger.marble.json")), file);
}

TEST(Meta, WrongTypesReadAsAbsentAndAreKeptAsTheyWere) {
    const char* text = R"({"name":5,"id":["x"],"family":true,"seed":-3,"generator":2,"paper":"A4",)"
                       R"("lineage":{"parents":"p","operator":1,"seed":1.5,"child":"7","strength":"x",)"
                       R"("variation":3,"redraws":0.5,"generation":"3","change":false},)"
                       R"("editor":"open","view":{"yaw":"east","pitch":null},)"
                       R"("locks":{"palette":"yes","initial":1,"operations":null}})";
    Meta m;
    ASSERT_NO_THROW(m = Meta::fromJson(Json::parse(text)));
    EXPECT_FALSE(m.name || m.id || m.family || m.seed || m.generator || m.paper || m.editor);
    ASSERT_TRUE(m.lineage);
    const MetaLineage& l = *m.lineage;
    EXPECT_FALSE(l.parents || l.op || l.seed || l.child || l.strength || l.variation || l.redraws ||
                 l.generation || l.change);
    ASSERT_TRUE(m.view);
    EXPECT_FALSE(m.view->yaw || m.view->pitch);
    ASSERT_TRUE(m.locks);
    EXPECT_FALSE(m.locks->palette || m.locks->initial || m.locks->operations);
    EXPECT_EQ(m.toJson().dump(), text);
    // Still there for a reader that asks only whether a key is (alterGenome and a family).
    EXPECT_TRUE(m.has(MetaKey::Family) && m.has(MetaKey::Editor));
    EXPECT_FALSE(Meta{}.has(MetaKey::Family));
    // Not an object at all: lineage, view, locks, a whole meta.
    const Meta flat = Meta::fromJson(Json::parse(R"({"lineage":[1],"view":2,"locks":"all"})"));
    EXPECT_FALSE(flat.lineage || flat.view || flat.locks);
    EXPECT_EQ(flat.toJson().dump(), R"({"lineage":[1],"view":2,"locks":"all"})");
    EXPECT_TRUE(Meta::fromJson(Json::parse("[1,2]")).empty());
    EXPECT_TRUE(Meta::fromJson(Json()).empty());
}

TEST(Meta, WrongTypedValuesReadAsAbsentByTheBreedingReaders) {
    Genome g;
    g.meta = Meta::fromJson(Json::parse(R"({"lineage":{"generation":"3"},"locks":{"palette":"yes"}})"));
    EXPECT_EQ(lineageGeneration(g), 0);
    EXPECT_FALSE(locksOf(g).palette);
    // Setting locks replaces the unreadable ones; unlocking everything removes the key.
    setLocks(g, Locks{true, false, false});
    EXPECT_EQ(g.meta.toJson()["locks"].dump(), R"({"palette":true,"initial":false,"operations":false})");
    setLocks(g, Locks{});
    EXPECT_FALSE(g.meta.toJson().contains("locks"));
}

TEST(Meta, AChangedValueIsWrittenAnewInItsPlace) {
    Meta m = Meta::fromJson(Json::parse(R"({"view":{"yaw":30,"pitch":20},"name":"A","x":1})"));
    // Unchanged, 30 stays 30 (not 30.0).
    EXPECT_EQ(m.toJson().dump(), R"({"view":{"yaw":30,"pitch":20},"name":"A","x":1})");
    m.view->yaw = 45.5;
    m.name = "B";
    m.seed = 9;
    EXPECT_EQ(m.toJson().dump(), R"({"view":{"yaw":45.5,"pitch":20.0},"name":"B","x":1,"seed":9})");
    m.erase(MetaKey::View);
    m.erase(MetaKey::Name);
    EXPECT_EQ(m.toJson().dump(), R"({"x":1,"seed":9})");
}

TEST(Meta, AChildKeepsItsParentsKeysBetweenItsNameAndItsLineage) {
    const Meta home = Meta::fromJson(
        Json::parse(R"j({"seed":5,"note":"n","name":"Stone (g2 #1)","lineage":{"generation":2},)j"
                    R"j("id":"aa","locks":{"palette":true},"generator":"g","family":"f"})j"));
    Meta child = home.keptByChild();
    EXPECT_FALSE(child.name || child.seed || child.generator || child.id || child.lineage);
    child.id = "bb";
    child.lineage = MetaLineage{};
    child.lineage->generation = 3;
    child.name = "Stone (g3 #1)";
    EXPECT_EQ(child.toJson().dump(), R"j({"name":"Stone (g3 #1)","note":"n","locks":{"palette":true},)j"
                                     R"j("family":"f","lineage":{"generation":3},"id":"bb"})j");
}

// Issue 29: a design carries the user's note (meta.note), read, written and kept, by its bred
// children too (as every key but name, seed, generator, id and lineage).
TEST(Meta, ANoteIsReadWrittenAndKept) {
    const auto meta = Meta::fromJson(
        nlohmann::ordered_json::parse(R"({"name": "Harbour Green", "note": "for the scarf"})"));
    ASSERT_TRUE(meta.note.has_value());
    EXPECT_EQ(*meta.note, "for the scarf");
    EXPECT_EQ(meta.toJson().dump(), R"({"name":"Harbour Green","note":"for the scarf"})");
    EXPECT_EQ(meta.keptByChild().note.value_or(""), "for the scarf");
    Meta erased = meta;
    erased.erase(MetaKey::Note);
    EXPECT_EQ(erased.toJson().dump(), R"({"name":"Harbour Green"})");
    // A note that is no string is kept as it was, not read.
    const auto odd = Meta::fromJson(nlohmann::ordered_json::parse(R"({"note": 3})"));
    EXPECT_FALSE(odd.note.has_value());
    EXPECT_EQ(odd.toJson().dump(), R"({"note":3})");
}

TEST(Meta, EveryExampleKeepsItsBytesThroughLoadAndSave) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::dataDir() / "examples"))
        files.push_back(entry.path());
    ASSERT_FALSE(files.empty());
    for (const fs::path& file : files) {
        const std::string text = test::readFile(file);
        const Json read = Json::parse(text);
        const Genome g = loadGenome(file);
        // The meta, byte for byte; and the whole file is a fixed point of load and save.
        EXPECT_EQ(toJson(g)["meta"].dump(2), read["meta"].dump(2)) << file;
        const std::string saved = serializeGenome(g);
        EXPECT_EQ(serializeGenome(parseGenome(saved, file.string())), saved) << file;
    }
}
