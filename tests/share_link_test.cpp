// share_link_test.cpp — preset links round-trip exactly, and broken links are refused with a reason.
#include "core/share/share_link.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

TEST(Link, Base64UrlRoundTripsEveryLength) {
    std::string bytes;
    for (int i = 0; i < 300; ++i) {
        bytes += static_cast<char>(i * 37);
        std::optional<std::string> back = base64UrlDecode(base64UrlEncode(bytes));
        ASSERT_TRUE(back);
        ASSERT_EQ(*back, bytes);
    }
    EXPECT_EQ(base64UrlEncode("\xfb\xff"), "-_8"); // the URL-safe characters, no padding
    EXPECT_FALSE(base64UrlDecode("abc$"));
    EXPECT_FALSE(base64UrlDecode("a"));
}

TEST(Link, PresetRoundTripsThroughTheFragment) {
    Preset p;
    p.name = "shared";
    p.brdf = BrdfModel::CookTorrance;
    p.material.diffuse = {0.1f, 0.2f, 0.3f};
    p.lights.push_back(LightDesc{});
    p.lights[1].type = LightType::Spot;
    std::string link = presetLink(p, std::nullopt);
    ASSERT_EQ(link.rfind("z=", 0), 0u);
    // Only what differs from the defaults, deflated: far shorter than the whole preset.
    EXPECT_LT(link.size(), 160u) << link; // the whole preset, minified: about 1100 characters
    Diagnostics d;
    auto parsed = parseLink("#" + link, ".", d);
    ASSERT_TRUE(parsed) << toString(d);
    ASSERT_TRUE(std::holds_alternative<Preset>(*parsed));
    EXPECT_EQ(std::get<Preset>(*parsed), p);
}

TEST(Link, APresetLinkCarriesOnlyWhatDiffersFromTheDefaults) {
    Preset p;
    p.material.shininess = 80.0f;
    std::optional<std::string> json = inflateBytes(*base64UrlDecode(presetLink(p, std::nullopt).substr(2)), 1 << 20);
    ASSERT_TRUE(json);
    EXPECT_EQ(*json, R"({"material":{"shininess":80}})");
    // A preset with fewer lights than the defaults cannot be a patch: it is whole, and still exact.
    p.lights.clear();
    Diagnostics d;
    auto parsed = parseLink(presetLink(p, std::nullopt), ".", d);
    ASSERT_TRUE(parsed) << toString(d);
    EXPECT_EQ(std::get<Preset>(*parsed), p);
}

TEST(Link, AnExerciseRoundTripsThroughTheFragment) {
    Exercise e;
    e.title = "Find the shininess";
    e.instructions = "Match the highlight.";
    e.start.material.shininess = 10.0f;
    e.start.lights.push_back(LightDesc{});
    e.start.lights[1].position = {-1.0f, 0.5f, 3.0f};
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.open = {"material.shininess"};
    e.hints = {"n is the exponent."};
    e.tolerance.maxMean = 0.25f;
    e.tolerance.fields = {{"material.shininess", 5.0f}};
    std::string link = exerciseLink(e, std::nullopt);
    ASSERT_EQ(link.rfind("x=", 0), 0u);
    Diagnostics d;
    auto parsed = parseLink(link, ".", d);
    ASSERT_TRUE(parsed) << toString(d);
    ASSERT_TRUE(std::holds_alternative<Exercise>(*parsed));
    EXPECT_EQ(std::get<Exercise>(*parsed), e);
    EXPECT_EQ(exerciseLink(e, std::string("03-shininess")), "exercise=03-shininess");
    auto named = parseLink("#exercise=03-shininess", ".", d);
    ASSERT_TRUE(named);
    EXPECT_EQ(std::get<LinkedExerciseName>(*named).name, "03-shininess");
}

// Found by fuzz_exercise: the start of an exercise's link is what differs from the defaults, so a
// plane with the default sphere's 64 x 32 subdivisions left them out, and the link came back with
// a plane's own default of 16 x 16 (a z= scene was merged over the defaults; an x= start was not).
TEST(Link, AnExercisesStartKeepsWhatItSharesWithTheDefaults) {
    Exercise e;
    e.title = "Shape the spot light";
    e.start.model.builtin = Builtin::Plane;
    e.start.model.subdivisions = Preset{}.model.subdivisions; // 64 x 32, as the default sphere's
    e.target = e.start;
    e.target.material.shininess = 60.0f;
    e.open = {"material.shininess"};
    Diagnostics d;
    auto parsed = parseLink(exerciseLink(e, std::nullopt), ".", d);
    ASSERT_TRUE(parsed) << toString(d);
    EXPECT_EQ(std::get<Exercise>(*parsed).start.model, e.start.model);
    EXPECT_EQ(std::get<Exercise>(*parsed), e);
}

TEST(Link, AShareUrlReplacesTheBasesOwnFragment) {
    EXPECT_EQ(shareUrl("https://c.example.org/lab/", "preset=05"), "https://c.example.org/lab/#preset=05");
    EXPECT_EQ(shareUrl("https://c.example.org/lab/index.html#old", "z=abc"), "https://c.example.org/lab/index.html#z=abc");
}

TEST(Link, BundledPresetsGoByName) {
    EXPECT_EQ(presetLink(Preset{}, std::string("05-full-phong")), "preset=05-full-phong");
    Diagnostics d;
    auto parsed = parseLink("preset=05-full-phong", ".", d);
    ASSERT_TRUE(parsed);
    EXPECT_EQ(std::get<LinkedPresetName>(*parsed).name, "05-full-phong");
}

TEST(Link, BrokenLinksAreRefusedWithAReason) {
    struct Case {
        std::string fragment, where, message;
    };
    const Case cases[] = {
        {"#p=%%%", "p", "not valid base64url"},
        {"#p=" + base64UrlEncode("{not json"), "line 1, column 3", "invalid JSON"},
        {"#p=" + base64UrlEncode(R"({"format": "lighting-lab-preset", "version": 1, "material": {"shininess": -1}})"),
         "material.shininess", "in [0.001, 1000000]"},
        {"#preset=../../etc/passwd", "preset", "not the name of a bundled preset"},
        {"#preset=", "preset", "not the name"},
        {"#zoom=3", "", "expected #preset=<name>, #exercise=<name>, #z="},
        {"#z=" + base64UrlEncode("not deflated"), "z", "not deflated data"},
        // Just over 1 MiB of spaces deflates to about 10 KB (a link within the length limit): inflating
        // stops at the preset's limit.
        {"#z=" + base64UrlEncode(deflateBytes(std::string((1u << 20) + 1000, ' '))), "z", "more than 1048576 bytes"},
        {"#z=" + base64UrlEncode(deflateBytes("[1, 2]")), "z", "not a JSON object"},
        {"#z=" + base64UrlEncode(deflateBytes(R"({"material": {"shininess": -1}})")), "material.shininess", "in [0.001"},
        {"#x=" + base64UrlEncode(deflateBytes(R"({"format": "lighting-lab-exercise", "version": 1})")), "title", "missing"},
        {"#exercise=a/b", "exercise", "not the name of a bundled exercise"},
        {"#p=" + std::string(70000, 'A'), "", "longer than 16384 characters (it has 70002)"},
    };
    for (const Case& c : cases) {
        Diagnostics d;
        EXPECT_FALSE(parseLink(c.fragment, ".", d)) << c.fragment.substr(0, 60);
        ASSERT_FALSE(d.empty());
        EXPECT_EQ(d[0].file, "link");
        EXPECT_EQ(d[0].where, c.where) << d[0].str();
        EXPECT_NE(d[0].message.find(c.message), std::string::npos) << d[0].str();
    }
}

// A fragment over kMaxLinkChars is refused for its length before anything of it is decoded: one
// that is no base64url at all says so only when it fits. The page's own saved state may be longer.
TEST(Link, AFragmentOverTheLimitIsRefusedBeforeDecoding) {
    const std::string notBase64(kMaxLinkChars - 2, '%');
    for (const char* kind : {"z=", "x=", "p="}) {
        Diagnostics fits, over;
        EXPECT_FALSE(parseLink(kind + notBase64, ".", fits));
        ASSERT_EQ(fits.size(), 1u);
        EXPECT_NE(fits[0].message.find("not valid base64url"), std::string::npos) << fits[0].str(); // it was decoded
        EXPECT_FALSE(parseLink("#" + std::string(kind) + notBase64 + "%", ".", over));
        ASSERT_EQ(over.size(), 1u);
        EXPECT_EQ(over[0].message, linkTooLong(kMaxLinkChars + 1)) << over[0].str(); // it was not
    }
    // A real scene with a long description: refused as an address, opened as the saved state.
    Preset p;
    std::string text;
    for (unsigned i = 0; text.size() < 3 * kMaxLinkChars; ++i) {
        text += std::to_string(i * 2654435761u) + " "; // digits that do not deflate away
    }
    p.description = text;
    const std::string link = presetLink(p, std::nullopt);
    ASSERT_GT(link.size(), kMaxLinkChars);
    Diagnostics address, saved;
    EXPECT_FALSE(parseLink(link, ".", address));
    std::optional<Linked> back = parseLink(link, ".", saved, nullptr, kMaxSavedLinkChars);
    ASSERT_TRUE(back) << toString(saved);
    EXPECT_EQ(std::get<Preset>(*back).description, text);
}

} // namespace
} // namespace lab
