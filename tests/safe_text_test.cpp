// safe_text_test.cpp — what files contain cannot reach a terminal raw (issue 14): escapes for C0,
// DEL and C1 controls, \xNN for invalid UTF-8, no loss at a NUL, bounded quotes.
#include "core/io/safe_text.h"

#include <gtest/gtest.h>

#include <string>

namespace lab {
namespace {

using namespace std::string_literals;

TEST(SafeText, ControlCharactersBecomeVisibleEscapes) {
    EXPECT_EQ(printable("\x1b]0;pwned\x07"), "\\x1B]0;pwned\\x07");  // a window title
    EXPECT_EQ(printable("\x1b[2J\x1b[31m"), "\\x1B[2J\\x1B[31m");  // clear screen, red
    EXPECT_EQ(printable("a\rb"), "a\\rb");
    EXPECT_EQ(printable("del\x7f"), "del\\x7F");
    EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\u009B31m") << "C1 CSI encoded as UTF-8";
    EXPECT_EQ(printable("line one\nline two\ttab"), "line one\nline two\ttab") << "messages keep their lines";
    EXPECT_EQ(printable("line one\nline two\ttab", true), "line one\\nline two\\ttab");
}

TEST(SafeText, InvalidUtf8IsShownByteByByteAndValidTextIsKept) {
    EXPECT_EQ(printable("caf\xe9"), "caf\\xE9");                  // Latin-1, not UTF-8
    EXPECT_EQ(printable("\x9b" "31m"), "\\x9B31m") << "a raw C1 byte";
    EXPECT_EQ(printable("\xc0\xaf"), "\\xC0\\xAF") << "overlong";
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xED\\xA0\\x80") << "a surrogate";
    EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80") << "past U+10FFFF";
    EXPECT_EQ(printable("\xe2\x82"), "\\xE2\\x82") << "cut short";
    EXPECT_EQ(printable("θ = 45°, ≤ 1 — ok 🙂"), "θ = 45°, ≤ 1 — ok 🙂");
}

TEST(SafeText, ANulNeverEndsTheMessage) {
    std::string s = "a\0.gltf: more after it"s;
    EXPECT_EQ(printable(s), "a\\0.gltf: more after it");
    EXPECT_TRUE(hasNul(s));
    EXPECT_FALSE(hasNul("a.gltf"));
}

TEST(SafeText, QuotesAreBoundedAndSayHowLongTheValueWas) {
    EXPECT_EQ(inQuotes("red"), "\"red\"");
    EXPECT_EQ(inQuotes("a\nb"), "\"a\\nb\"");
    std::string uri = "data:application/octet-stream;base64," + std::string(21 << 20, 'A');
    std::string q = inQuotes(uri);
    EXPECT_LT(q.size(), 200u);
    EXPECT_NE(q.find(std::to_string(uri.size()) + " bytes"), std::string::npos) << q;
    // A cut never splits a character.
    std::string greek(200, 'a');
    greek += "θθθθ";
    EXPECT_EQ(printable(inQuotes(greek, 201)), inQuotes(greek, 201));
    EXPECT_EQ(inQuotes(greek, 201).find("\\x"), std::string::npos);
}

} // namespace
} // namespace lab
