// figure_test.cpp — the plot figures (core/plots/figures.h) as SVG and PNG: the SVG parsed by a small
// strict XML reader and its curves compared with the CSV the same call returns, mapped by the
// figure's placement; labels present; text escaped; the PNG at scale 1 and 2 read back, its size
// and ink where the curve is.
#include "core/plots/figures.h"

#include "core/plots/energy.h"
#include "core/plots/plot_layout.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace lab {
namespace {

//----------------------------------------------------------------------------------------
// A strict reader for the XML the SVG writer may produce: a declaration, elements with quoted
// attributes, character data and the five predefined entities. Anything else fails the test.
//----------------------------------------------------------------------------------------

struct Element {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text; // the character data directly inside, entities resolved
    std::vector<std::unique_ptr<Element>> children;
};

class XmlReader {
public:
    explicit XmlReader(std::string_view s) : s_(s) {}

    std::unique_ptr<Element> document(std::string& error) {
        if (s_.substr(0, 5) == "<?xml") {
            std::size_t end = s_.find("?>");
            if (end == std::string_view::npos) {
                return fail(error, "unterminated declaration");
            }
            i_ = end + 2;
        }
        space();
        std::unique_ptr<Element> root = element(error);
        space();
        if (root && i_ != s_.size()) {
            return fail(error, "content after the root element");
        }
        return root;
    }

private:
    std::unique_ptr<Element> fail(std::string& error, const std::string& why) {
        if (error.empty()) {
            error = why + " at byte " + std::to_string(i_);
        }
        return nullptr;
    }
    void space() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) {
            ++i_;
        }
    }
    std::string name() {
        std::size_t start = i_;
        while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' || s_[i_] == ':' || s_[i_] == '_')) {
            ++i_;
        }
        return std::string(s_.substr(start, i_ - start));
    }
    // Character data up to `stop`, entities resolved; false on a bare '&' or '<' or an unknown entity.
    bool chars(char stop, std::string& out) {
        while (i_ < s_.size() && s_[i_] != stop) {
            char c = s_[i_];
            if (c == '<' && stop != '<') {
                return false;
            }
            if (c == '&') {
                static const std::pair<const char*, char> kEntities[] = {
                    {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
                bool known = false;
                for (auto [e, v] : kEntities) {
                    if (s_.substr(i_, std::strlen(e)) == e) {
                        out += v;
                        i_ += std::strlen(e);
                        known = true;
                        break;
                    }
                }
                if (!known) {
                    return false;
                }
                continue;
            }
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t' && c != '\r') {
                return false; // not allowed in XML 1.0
            }
            out += c;
            ++i_;
        }
        return true;
    }
    std::unique_ptr<Element> element(std::string& error) {
        if (i_ >= s_.size() || s_[i_] != '<') {
            return fail(error, "expected '<'");
        }
        ++i_;
        auto e = std::make_unique<Element>();
        e->name = name();
        if (e->name.empty()) {
            return fail(error, "element without a name");
        }
        for (;;) {
            space();
            if (s_.substr(i_, 2) == "/>") {
                i_ += 2;
                return e;
            }
            if (i_ < s_.size() && s_[i_] == '>') {
                ++i_;
                break;
            }
            std::string key = name();
            if (key.empty() || i_ + 1 >= s_.size() || s_[i_] != '=' || s_[i_ + 1] != '"') {
                return fail(error, "bad attribute in <" + e->name + ">");
            }
            i_ += 2;
            std::string value;
            if (!chars('"', value) || i_ >= s_.size()) {
                return fail(error, "bad attribute value in <" + e->name + ">");
            }
            ++i_;
            if (!e->attributes.emplace(key, value).second) {
                return fail(error, "attribute " + key + " twice");
            }
        }
        for (;;) {
            if (!chars('<', e->text)) {
                return fail(error, "bad character data in <" + e->name + ">");
            }
            if (i_ >= s_.size()) {
                return fail(error, "<" + e->name + "> not closed");
            }
            if (s_.substr(i_, 2) == "</") {
                i_ += 2;
                if (name() != e->name || i_ >= s_.size() || s_[i_] != '>') {
                    return fail(error, "mismatched end tag for <" + e->name + ">");
                }
                ++i_;
                return e;
            }
            std::unique_ptr<Element> child = element(error);
            if (!child) {
                return nullptr;
            }
            e->children.push_back(std::move(child));
        }
    }

    std::string_view s_;
    std::size_t i_ = 0;
};

std::unique_ptr<Element> parseSvg(const std::string& svg) {
    std::string error;
    std::unique_ptr<Element> root = XmlReader(svg).document(error);
    EXPECT_TRUE(root) << error;
    return root;
}

void collect(const Element& e, const std::string& name, std::vector<const Element*>& out) {
    if (e.name == name) {
        out.push_back(&e);
    }
    for (const auto& c : e.children) {
        collect(*c, name, out);
    }
}

std::vector<const Element*> all(const Element& root, const std::string& name) {
    std::vector<const Element*> out;
    collect(root, name, out);
    return out;
}

std::vector<std::string> texts(const Element& root) {
    std::vector<std::string> out;
    for (const Element* t : all(root, "text")) {
        out.push_back(t->text);
    }
    return out;
}

bool hasText(const Element& root, const std::string& text) {
    for (const std::string& t : texts(root)) {
        if (t == text) {
            return true;
        }
    }
    return false;
}

bool textContains(const Element& root, const std::string& part) {
    for (const std::string& t : texts(root)) {
        if (t.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

std::vector<glm::vec2> polylinePoints(const Element& root, const std::string& id) {
    for (const Element* p : all(root, "polyline")) {
        auto it = p->attributes.find("id");
        if (it != p->attributes.end() && it->second == id) {
            std::vector<glm::vec2> pts;
            std::istringstream in(p->attributes.at("points"));
            std::string pair;
            while (in >> pair) {
                std::size_t comma = pair.find(',');
                pts.push_back({std::strtof(pair.substr(0, comma).c_str(), nullptr), std::strtof(pair.substr(comma + 1).c_str(), nullptr)});
            }
            return pts;
        }
    }
    ADD_FAILURE() << "no polyline " << id;
    return {};
}

// The CSV's rows as numbers; the header checked.
std::vector<std::vector<float>> csvRows(const std::string& csv, const std::string& header) {
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, header);
    std::vector<std::vector<float>> rows;
    while (std::getline(in, line)) {
        std::vector<float> row;
        std::istringstream cells(line);
        std::string cell;
        while (std::getline(cells, cell, ',')) {
            row.push_back(std::strtof(cell.c_str(), nullptr));
        }
        rows.push_back(row);
    }
    return rows;
}

// The SVG's numbers have two decimals: within 0.005 of the figure's, and a little for float sums.
constexpr float kRounding = 0.0051f;

void expectPointsEqual(const std::vector<glm::vec2>& svg, const std::vector<glm::vec2>& expected) {
    ASSERT_EQ(svg.size(), expected.size());
    for (std::size_t i = 0; i < svg.size(); ++i) {
        EXPECT_NEAR(svg[i].x, expected[i].x, kRounding) << "point " << i;
        EXPECT_NEAR(svg[i].y, expected[i].y, kRounding) << "point " << i;
    }
}

FigureResult figure(const Preset& a, const FigureRequest& r, const Preset* b = nullptr) {
    std::string error;
    std::optional<FigureResult> f = makeFigure(a, b, r, error);
    EXPECT_TRUE(f) << error;
    return f ? *f : FigureResult{};
}

Preset phong() {
    Preset p;
    p.name = "Phong test";
    p.brdf = BrdfModel::Phong;
    p.material.shininess = 20.0f;
    return p;
}

//----------------------------------------------------------------------------------------

TEST(FigureSvg, LobeCurvesAreTheCsvSamplesMapped) {
    for (RadialScale scale : {RadialScale::Linear, RadialScale::Log}) {
        FigureRequest r{FigureKind::Lobe, 30.0f, scale};
        FigureResult f = figure(phong(), r);
        auto root = parseSvg(figureSvg(f.figure));
        ASSERT_TRUE(root);
        std::vector<std::vector<float>> rows = csvRows(f.csv, "theta_out_deg,diffuse,specular,total");
        ASSERT_EQ(rows.size(), 181u);
        for (auto [column, id] : {std::pair{1, "lobe-diffuse"}, std::pair{2, "lobe-specular"}, std::pair{3, "lobe-total"}}) {
            std::vector<glm::vec2> expected;
            for (const auto& row : rows) {
                float radius = plotRadius(row[std::size_t(column)], f.outer, scale);
                float t = glm::radians(row[0]);
                expected.push_back(f.offset + f.scale * glm::vec2(radius * std::sin(t), radius * std::cos(t)));
            }
            SCOPED_TRACE(id);
            expectPointsEqual(polylinePoints(*root, id), expected);
        }
    }
}

TEST(FigureSvg, LobeHasItsAxesLabelsLegendAndTitle) {
    FigureResult f = figure(phong(), {FigureKind::Lobe, 30.0f});
    auto root = parseSvg(figureSvg(f.figure));
    ASSERT_TRUE(root);
    EXPECT_EQ(root->name, "svg");
    EXPECT_EQ(root->attributes.at("viewBox"), "0 0 720.00 500.00");
    for (const char* label : {"0°", "30°", "60°", "90°", "N", "L", "R", "diffuse", "specular", "total", "0.5"}) {
        EXPECT_TRUE(hasText(*root, label)) << label;
    }
    EXPECT_TRUE(textContains(*root, "Phong test"));
    EXPECT_TRUE(textContains(*root, "θi = 30°"));
    EXPECT_TRUE(textContains(*root, "Phong (shininess 20)"));
    EXPECT_TRUE(textContains(*root, "radius: reflected intensity, linear"));
    EXPECT_EQ(all(*root, "title").at(0)->text, "Reflection lobe: Phong test");
}

TEST(FigureSvg, CompareSetAddsItsTotal) {
    Preset b = phong();
    b.name = "B side";
    b.material.shininess = 100.0f;
    FigureResult f = figure(phong(), {FigureKind::Lobe, 30.0f}, &b);
    auto root = parseSvg(figureSvg(f.figure));
    ASSERT_TRUE(root);
    EXPECT_EQ(polylinePoints(*root, "lobe-total-b").size(), 181u);
    EXPECT_TRUE(hasText(*root, "total B: B side"));
}

TEST(FigureSvg, OverlayCurvesAreTheCsvColumns) {
    FigureRequest r;
    r.kind = FigureKind::Overlay;
    r.overlayDeg = {60.0f, 25.0f, -10.0f};
    FigureResult f = figure(phong(), r);
    auto root = parseSvg(figureSvg(f.figure));
    ASSERT_TRUE(root);
    std::vector<std::vector<float>> rows = csvRows(f.csv, "theta_out_deg,total_at_60,total_at_25,total_at_-10");
    for (int i = 0; i < 3; ++i) {
        std::vector<glm::vec2> expected;
        for (const auto& row : rows) {
            float radius = plotRadius(row[std::size_t(i + 1)], f.outer, RadialScale::Linear);
            float t = glm::radians(row[0]);
            expected.push_back(f.offset + f.scale * glm::vec2(radius * std::sin(t), radius * std::cos(t)));
        }
        expectPointsEqual(polylinePoints(*root, "overlay-total-" + std::to_string(i + 1)), expected);
    }
    EXPECT_TRUE(hasText(*root, "total at θi = -10°"));
}

TEST(FigureSvg, AttenuationCurveIsTheCsvMapped) {
    Preset p = phong();
    p.lights[0].attenuation = {1.0f, 0.2f, 0.05f};
    p.lights[0].position = {2.0f, 0.0f, 0.0f};
    FigureRequest r;
    r.kind = FigureKind::Attenuation;
    FigureResult f = figure(p, r);
    auto root = parseSvg(figureSvg(f.figure));
    ASSERT_TRUE(root);
    std::vector<std::vector<float>> rows = csvRows(f.csv, "distance,attenuation");
    ASSERT_EQ(rows.size(), 201u);
    EXPECT_FLOAT_EQ(rows.back()[0], f.maxDistance);
    std::vector<glm::vec2> expected;
    for (const auto& row : rows) {
        expected.push_back(f.offset + f.scale * glm::vec2(row[0] / f.maxDistance, row[1]));
    }
    expectPointsEqual(polylinePoints(*root, "attenuation"), expected);
    for (const char* label : {"distance d", "Att", "0", "0.5", "1"}) {
        EXPECT_TRUE(hasText(*root, label)) << label;
    }
    EXPECT_TRUE(textContains(*root, "Att(d) = 1 / (1 + 0.2·d + 0.05·d²)"));
    EXPECT_TRUE(textContains(*root, "the model, at d = 2.00"));
}

TEST(FigureSvg, AlbedoCurveIsTheCsvMapped) {
    FigureRequest r;
    r.kind = FigureKind::Albedo;
    r.incidentDeg = 40.0f;
    FigureResult f = figure(phong(), r);
    auto root = parseSvg(figureSvg(f.figure));
    ASSERT_TRUE(root);
    std::vector<std::vector<float>> rows = csvRows(f.csv, "theta_in_deg,diffuse,specular,total,total_r,total_g,total_b");
    ASSERT_EQ(rows.size(), 90u);
    std::vector<glm::vec2> expected;
    for (const auto& row : rows) {
        expected.push_back(f.offset + f.scale * glm::vec2(row[0] / 90.0f, row[3] / f.outer));
    }
    expectPointsEqual(polylinePoints(*root, "albedo-total"), expected);
    EXPECT_TRUE(hasText(*root, "θi = 40°"));
    EXPECT_TRUE(textContains(*root, "incident angle θi"));
}

TEST(FigureSvg, AMissingLightIsAnError) {
    Preset p = phong();
    FigureRequest r;
    r.kind = FigureKind::Attenuation;
    r.light = 3;
    std::string error;
    EXPECT_FALSE(makeFigure(p, nullptr, r, error));
    EXPECT_EQ(error, "light 4 does not exist (the preset has 1)");
    p.lights.clear();
    r.light = 0;
    EXPECT_FALSE(makeFigure(p, nullptr, r, error));
    EXPECT_EQ(error, "the preset has no lights");
}

TEST(FigureSvg, TextFromThePresetIsEscaped) {
    Preset p = phong();
    p.name = "<b>&\"x\"' \x01\xff";
    FigureResult f = figure(p, {FigureKind::Lobe, 30.0f});
    std::string svg = figureSvg(f.figure);
    auto root = parseSvg(svg);
    ASSERT_TRUE(root);
    EXPECT_EQ(all(*root, "title").at(0)->text, "Reflection lobe: <b>&\"x\"' \\x01\\xFF");
}

TEST(FigureSvg, TheStrictReaderRefusesBrokenXml) {
    for (const char* bad : {"<svg><g></svg>", "<svg a=\"1\" a=\"2\"/>", "<svg>&nbsp;</svg>", "<svg>a < b</svg>",
                            "<svg/><svg/>", "<svg a='1'/>", "<svg>\x01</svg>"}) {
        std::string error;
        EXPECT_FALSE(XmlReader(bad).document(error)) << bad;
    }
}

//----------------------------------------------------------------------------------------

TEST(FigurePng, ScaleSetsTheSizeAndTheCurveIsInked) {
    FigureResult f = figure(phong(), {FigureKind::Lobe, 30.0f});
    TempFolder tmp;
    for (float scale : {1.0f, 2.0f}) {
        FigureFiles files;
        files.png = tmp.path() / "lobe.png";
        files.pngScale = scale;
        std::string error;
        ASSERT_TRUE(writeFigure(f, files, error)) << error;
        std::optional<Image> image = readPng(*files.png, error);
        ASSERT_TRUE(image) << error;
        EXPECT_EQ(image->width, static_cast<int>(720 * scale));
        EXPECT_EQ(image->height, static_cast<int>(500 * scale));
        auto pixel = [&](glm::vec2 at) {
            int x = static_cast<int>(at.x * scale), y = static_cast<int>(at.y * scale);
            const std::uint8_t* p = &image->rgb[(std::size_t(y) * std::size_t(image->width) + std::size_t(x)) * 3];
            return std::array<int, 3>{p[0], p[1], p[2]};
        };
        // The total's tip (its sample at the mirror angle) is drawn in near-black; a corner is white.
        std::vector<std::vector<float>> rows = csvRows(f.csv, "theta_out_deg,diffuse,specular,total");
        const auto& tip = rows[90 + 30];
        float radius = plotRadius(tip[3], f.outer, RadialScale::Linear);
        glm::vec2 at = f.offset + f.scale * glm::vec2(radius * std::sin(glm::radians(30.0f)), radius * std::cos(glm::radians(30.0f)));
        std::array<int, 3> ink = pixel(at);
        EXPECT_LT(ink[0] + ink[1] + ink[2], 3 * 120) << "scale " << scale;
        std::array<int, 3> corner = pixel({715.0f, 495.0f});
        EXPECT_EQ(corner, (std::array<int, 3>{255, 255, 255}));
        // The title is drawn: dark pixels in its first line.
        int dark = 0;
        for (int y = static_cast<int>(18 * scale); y < static_cast<int>(36 * scale); ++y) {
            for (int x = static_cast<int>(18 * scale); x < static_cast<int>(200 * scale); ++x) {
                dark += image->rgb[(std::size_t(y) * std::size_t(image->width) + std::size_t(x)) * 3] < 100;
            }
        }
        EXPECT_GT(dark, static_cast<int>(60 * scale * scale)) << "scale " << scale;
    }
}

TEST(FigurePng, ScaleIsClampedAndWritesFailWithTheFileNamed) {
    Figure f;
    f.width = 100;
    f.height = 50;
    EXPECT_EQ(rasterizeFigure(f, 100.0f).width, 800);
    EXPECT_EQ(rasterizeFigure(f, 0.0f).width, 25);
    EXPECT_EQ(rasterizeFigure(f, std::nanf("")).width, 100);
    FigureResult r;
    r.figure = f;
    FigureFiles files;
    files.svg = "/nonexistent-folder/x.svg";
    std::string error;
    EXPECT_FALSE(writeFigure(r, files, error));
    EXPECT_NE(error.find("/nonexistent-folder"), std::string::npos) << error;
}

TEST(FigurePng, ThickLinesCoverTheirWidth) {
    Figure f;
    f.width = 40;
    f.height = 20;
    // 4 px wide about y = 10.5: rows 9 to 11 covered, 8 and 12 half (their centres on the edges).
    f.shapes.push_back(FigureLine{{{5.0f, 10.5f}, {35.0f, 10.5f}}, 4.0f, {0, 0, 0}, ""});
    Image image = rasterizeFigure(f, 1.0f);
    auto grey = [&](int x, int y) { return image.rgb[(std::size_t(y) * 40 + std::size_t(x)) * 3]; };
    for (int y : {9, 10, 11}) {
        EXPECT_EQ(grey(20, y), 0) << y; // inside: full ink
    }
    for (int y : {8, 12}) {
        EXPECT_NEAR(grey(20, y), 128, 2) << y; // the edge rows: half
    }
    EXPECT_EQ(grey(20, 13), 255); // beyond the edge: none
    EXPECT_EQ(grey(20, 3), 255);
}

// The curves a legend tells apart differ by their dash as well as their colour (core/plots/theme.h):
// in the SVG a stroke-dasharray each (the total solid), in the PNG gaps along the line.
TEST(FigureSvg, CurvesALegendTellsApartHaveDashesOfTheirOwn) {
    Preset b = phong();
    b.material.shininess = 100.0f;
    auto dashOfId = [](const Element& root, const std::string& id) {
        for (const Element* p : all(root, "polyline")) {
            if (auto it = p->attributes.find("id"); it != p->attributes.end() && it->second == id) {
                auto d = p->attributes.find("stroke-dasharray");
                return d == p->attributes.end() ? std::string("solid") : d->second;
            }
        }
        ADD_FAILURE() << "no polyline " << id;
        return std::string();
    };
    auto root = parseSvg(figureSvg(figure(phong(), {FigureKind::Lobe, 30.0f}, &b).figure));
    ASSERT_TRUE(root);
    std::set<std::string> lobe;
    for (const char* id : {"lobe-diffuse", "lobe-specular", "lobe-total", "lobe-total-b"}) {
        lobe.insert(dashOfId(*root, id));
    }
    EXPECT_EQ(lobe.size(), 4u) << "four curves, four dashes";
    EXPECT_EQ(dashOfId(*root, "lobe-total"), "solid");
    EXPECT_EQ(dashOfId(*root, "lobe-diffuse"), "7.00 5.00");
    FigureRequest r;
    r.kind = FigureKind::Overlay;
    auto overlay = parseSvg(figureSvg(figure(phong(), r).figure));
    ASSERT_TRUE(overlay);
    std::set<std::string> angles;
    for (int i = 1; i <= 3; ++i) {
        angles.insert(dashOfId(*overlay, "overlay-total-" + std::to_string(i)));
    }
    EXPECT_EQ(angles.size(), 3u) << "three angles, three dashes";
}

TEST(FigurePng, DashesLeaveGapsAndDotsAreRound) {
    const std::vector<glm::vec2> line{{0.0f, 0.0f}, {30.0f, 0.0f}, {30.0f, 30.0f}};
    std::vector<std::vector<glm::vec2>> runs = dashRuns(line, {7.0f, 5.0f});
    ASSERT_EQ(runs.size(), 5u); // dashes start at 0, 12, 24 (round the corner), 36, 48 along the 60
    EXPECT_EQ(runs[0], (std::vector<glm::vec2>{{0, 0}, {7, 0}}));
    EXPECT_EQ(runs[2], (std::vector<glm::vec2>{{24, 0}, {30, 0}, {30, 1}}));
    EXPECT_EQ(runs[4], (std::vector<glm::vec2>{{30, 18}, {30, 25}}));
    std::vector<std::vector<glm::vec2>> dots = dashRuns(line, {0.0f, 10.0f});
    ASSERT_EQ(dots.size(), 6u); // at 0, 10, …, 50 (one that would begin at the line's very end is left out)
    for (const auto& d : dots) {
        ASSERT_EQ(d.size(), 2u);
        EXPECT_EQ(d[0], d[1]);
    }
    EXPECT_EQ(dashRuns(line, {}).size(), 1u) << "solid";
    EXPECT_EQ(dashRuns(line, {0.1f, 0.1f}).size(), 1u) << "a pattern under half a pixel is drawn solid";

    Figure f;
    f.width = 40;
    f.height = 10;
    f.shapes.push_back(FigureLine{{{2.0f, 5.0f}, {38.0f, 5.0f}}, 2.0f, {0, 0, 0}, "", {7.0f, 5.0f}});
    Image image = rasterizeFigure(f, 1.0f);
    auto grey = [&](int x) { return image.rgb[(std::size_t(5) * 40 + std::size_t(x)) * 3]; };
    EXPECT_LT(grey(5), 64) << "in the first dash";
    EXPECT_EQ(grey(11), 255) << "in the first gap (9..14 with the round caps' 1 px)";
    EXPECT_LT(grey(17), 64) << "in the second dash";
}

} // namespace
} // namespace lab
