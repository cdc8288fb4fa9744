// share_link_test.cpp — preset links round-trip exactly, and broken links are refused with a reason.
#include "core/scene/share_link.h"

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
    ASSERT_EQ(link.rfind("p=", 0), 0u);
    Diagnostics d;
    auto parsed = parseLink("#" + link, ".", d);
    ASSERT_TRUE(parsed) << toString(d);
    ASSERT_TRUE(std::holds_alternative<Preset>(*parsed));
    EXPECT_EQ(std::get<Preset>(*parsed), p);
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
        {"#zoom=3", "", "expected #preset=<name> or #p="},
        {"#p=" + std::string(70000, 'A'), "", "longer than"},
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

} // namespace
} // namespace lab
