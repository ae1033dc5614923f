// Names from a design's own family and inks (issue 29): a peacock is never "Bouquet", colour words
// from the palette, colourways named from theirs, and no two designs given one name.
#include "marbler/Colourways.h"
#include "marbler/Families.h"
#include "marbler/Generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

namespace marbler {
namespace {

/// The name without its leading colour word (the noun).
std::string nounOf(const Genome& g) {
    const std::string name = g.meta.name.value_or("");
    const std::string word = colorWord(g.palette[std::size_t(mainInk(g))]);
    EXPECT_EQ(name.rfind(word + " ", 0), 0u) << name << " starts with its main ink's word " << word;
    return name.substr(word.size() + 1);
}

TEST(Names, AFamilysDesignIsNamedWithItsOwnWords) {
    for (const Family& family : allFamilies()) {
        const std::vector<std::string> own = familyNouns(family.name);
        std::set<std::string> seen;
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            const Genome g = familyGenome(family, seed);
            const std::string noun = nounOf(g);
            EXPECT_NE(std::find(own.begin(), own.end(), noun), own.end())
                << g.meta.name.value_or("") << " is a " << family.name << ": its noun is not the family's";
            seen.insert(noun);
        }
        EXPECT_GT(seen.size(), 1u) << family.name << " names vary with the seed";
    }
    // A peacock is never a "Bouquet" (the issue's "Sage Bouquet").
    const Family* peacock = findFamily("peacock");
    ASSERT_NE(peacock, nullptr);
    for (std::uint64_t seed = 1; seed <= 100; ++seed)
        EXPECT_EQ(familyGenome(*peacock, seed).meta.name->find("Bouquet"), std::string::npos);
    // A design of no family is named with words of no family.
    const std::vector<std::string> plain = familyNouns("");
    for (std::uint64_t seed = 0; seed < 100; ++seed)
        for (int dimension : {2, 3}) {
            const Genome g = randomGenome(seed, dimension);
            EXPECT_NE(std::find(plain.begin(), plain.end(), nounOf(g)), plain.end())
                << g.meta.name.value_or("");
        }
}

TEST(Names, FamilyNamesAreDeterministicFromTheSeed) {
    for (const Family& family : allFamilies())
        EXPECT_EQ(familyGenome(family, 17).meta.name, familyGenome(family, 17).meta.name) << family.name;
    EXPECT_EQ(randomGenome(5, 2).meta.name, randomGenome(5, 2).meta.name);
}

TEST(Names, NoFamilyNounIsAnotherFamilysName) {
    // Words of no family hold no family's name ("Peacock", "Bouquet", "Chevron", ...).
    const std::vector<std::string> plain = familyNouns("");
    for (const Family& f : allFamilies())
        for (const std::string& w : plain) {
            std::string lower = w;
            std::transform(lower.begin(), lower.end(), lower.begin(),
                           [](unsigned char c) { return std::tolower(c); });
            EXPECT_EQ(std::string(f.name).find(lower), std::string::npos) << w << " names " << f.name;
        }
}

TEST(Names, PaletteWordsNameTheInksThatCoverMost) {
    Genome g = randomGenome(3, 2);
    g.palette = {{110, 35, 135}, {128, 70, 27}, {52, 98, 78}};
    for (Operation& op : g.initial)
        op.color = 0;
    EXPECT_EQ(paletteWords(g, 1), "Purple");
    // The second ink covers next most.
    g.initial.back().color = 2;
    EXPECT_EQ(paletteWords(g, 2), "Purple and Harbour Green");
    g.initial.front().color = 1;
    const std::string three = paletteWords(g, 3);
    EXPECT_EQ(three.rfind("Purple", 0), 0u) << three;
    EXPECT_NE(three.find("Russet"), std::string::npos) << three;
    EXPECT_NE(three.find(", "), std::string::npos) << three;
    EXPECT_EQ(colorWord({128, 70, 27}), "Russet");
    EXPECT_EQ(colorWord({52, 98, 78}), "Harbour Green");
    EXPECT_EQ(colorWord({110, 35, 135}), "Purple");
}

TEST(Names, ColourwaysAreNamedFromTheirOwnPalette) {
    const Family* gelGit = findFamily("gel-git");
    ASSERT_NE(gelGit, nullptr);
    Genome parent = familyGenome(*gelGit, 9);
    const std::string parentWord = colorWord(parent.palette[std::size_t(mainInk(parent))]);
    const std::string noun = nounOf(parent);
    ColourwayRequest request;
    request.parents = {parent};
    request.seed = 4;
    request.generation = 2;
    const std::vector<Genome> children = colourways(request);
    ASSERT_FALSE(children.empty());
    int recoloured = 0;
    for (const Genome& child : children) {
        const std::string name = child.meta.name.value_or("");
        const std::string word = colorWord(child.palette[std::size_t(mainInk(child))]);
        // Its own colour word and the parent's noun, then the bred suffix.
        EXPECT_EQ(name.rfind(word + " " + noun + " (g2 #", 0), 0u) << name;
        if (word != parentWord) ++recoloured;
    }
    EXPECT_GT(recoloured, 0) << "some colourway has a main ink of another colour than the parent's";
}

TEST(Names, UniqueNamesTakeANumber) {
    EXPECT_EQ(uniqueName("Harbour Green", {}), "Harbour Green");
    EXPECT_EQ(uniqueName("Harbour Green", {"Harbour Green"}), "Harbour Green 2");
    EXPECT_EQ(uniqueName("Harbour Green", {"Harbour Green", "Harbour Green 2"}), "Harbour Green 3");
    // A bred name keeps its suffix last, so its children carry the number.
    EXPECT_EQ(uniqueName("Russet Current (g4 #1)", {"Russet Current (g4 #1)"}), "Russet Current 2 (g4 #1)");
}

} // namespace
} // namespace marbler
