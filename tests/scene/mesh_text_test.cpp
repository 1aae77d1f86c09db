// Tests of the text helpers of rayo's PLY, STL and OFF readers (apps/scene/mesh_text.h): line
// numbers and offsets, words, whole numbers only, and safe quoting of what a file holds.
#include "apps/scene/mesh_text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rayo {
namespace {

TEST(MeshText, LinesCountFromTheirFirstNumberAndKeepTheirOffset) {
    TextLines lines("a\r\nbb\n\nc", 10);
    std::string_view line;
    ASSERT_TRUE(lines.next(line));
    EXPECT_EQ(line, "a\r");
    EXPECT_EQ(lines.number(), 10u);
    EXPECT_EQ(lines.offset(), 3u);
    ASSERT_TRUE(lines.next(line));
    EXPECT_EQ(line, "bb");
    ASSERT_TRUE(lines.next(line));
    EXPECT_EQ(line, "");
    ASSERT_TRUE(lines.next(line));
    EXPECT_EQ(line, "c");
    EXPECT_EQ(lines.number(), 13u);
    EXPECT_FALSE(lines.next(line));
    EXPECT_EQ(lines.number(), 13u);
    std::vector<std::string_view> words;
    split_words(" \tone two\r\vthree\f", words);
    EXPECT_EQ(words, (std::vector<std::string_view>{"one", "two", "three"}));
    split_words(std::string_view("a\0b c", 5), words);
    ASSERT_EQ(words.size(), 2u);  // a NUL byte is not a blank
    EXPECT_EQ(words[0].size(), 3u);
}

TEST(MeshText, NumbersAreWholeWordsOnly) {
    double value = 0;
    for (const char* ok : {"1", "-2", "+3", ".5", "1.", "1e-3", "2E+4", "nan", "inf", "-inf"}) {
        EXPECT_TRUE(parse_number(ok, value)) << ok;
    }
    EXPECT_TRUE(parse_number("+.25", value));
    EXPECT_EQ(value, 0.25);
    for (const char* bad : {"", "1-5", "1FF", "0x10", "1e38200", "++1", "+-1", "1,5", " 1", "-"}) {
        EXPECT_FALSE(parse_number(bad, value)) << bad;
    }
    long long integer = 0;
    EXPECT_TRUE(parse_integer("-5", integer));
    EXPECT_EQ(integer, -5);
    EXPECT_TRUE(parse_integer("+7", integer));
    EXPECT_EQ(integer, 7);
    for (const char* bad : {"", "2.0", "3t", "1e3", "99999999999999999999", "+"}) {
        EXPECT_FALSE(parse_integer(bad, integer)) << bad;
    }
}

TEST(MeshText, QuotedEscapesAndShortens) {
    EXPECT_EQ(quote_word("face"), "'face'");
    EXPECT_EQ(quote_word(std::string_view("a\0\xff", 3)), "'a\\x00\\xff'");
    EXPECT_EQ(quote_word(std::string(100, '7')), "'" + std::string(48, '7') + "...'");
}

}  // namespace
}  // namespace rayo
