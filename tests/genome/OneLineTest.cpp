// oneLine: a library's message on one line of Marbler's own (cli.md), as the PNG, TIFF,
// OpenImageIO and assimp readers' errors are reported.

#include "marbler/OneLine.h"

#include <gtest/gtest.h>

using marbler::oneLine;

TEST(OneLine, JoinsALibrarysLinesWithASemicolon) {
    EXPECT_EQ(oneLine("PNG read error: IDAT: incorrect header check\nPNG library error\n"),
              "PNG read error: IDAT: incorrect header check; PNG library error");
    EXPECT_EQ(oneLine("first\r\nsecond"), "first; second");
}

TEST(OneLine, TurnsOtherControlCharactersIntoSpacesAndDropsTrailingSpace) {
    EXPECT_EQ(oneLine("a\tb\x01"
                      "c\x7f"
                      "d  \n\n"),
              "a b c d");
    EXPECT_EQ(oneLine("ends with space   "), "ends with space");
}

TEST(OneLine, KeepsAnEmptyOrBlankMessageEmptyAndUtf8Intact) {
    EXPECT_EQ(oneLine(""), "");
    EXPECT_EQ(oneLine("\n \n"), "");
    EXPECT_EQ(oneLine("Çiçek: ünreadable\nzweite Zeile"), "Çiçek: ünreadable; zweite Zeile");
}
