// check_report_test.cpp — lab check's plot CSV comparison and its report's escaping (issue 23).
// The files themselves (JUnit parsed by a real XML parser, the page's images) are checked on a
// real run by the `cli` test.
#include "cli/check_report.h"
#include "cli/csv_compare.h"

#include <gtest/gtest.h>

namespace lab {
namespace {

const char* kCsv = "theta_out_deg,diffuse,specular,total\n-1,0.5,0.25,0.75\n0,0.5,1,1.5\n1,0.5,0.25,0.75\n";

NumberCsv csv(const std::string& text) {
    std::string error;
    std::optional<NumberCsv> c = parseNumberCsv(text, error);
    EXPECT_TRUE(c) << error;
    return c.value_or(NumberCsv{});
}

TEST(PlotGolden, ACsvOfNumbersReads) {
    NumberCsv c = csv(kCsv);
    EXPECT_EQ(c.columns, (std::vector<std::string>{"theta_out_deg", "diffuse", "specular", "total"}));
    ASSERT_EQ(c.rows.size(), 3u);
    EXPECT_EQ(c.rows[1][2], 1.0);
    EXPECT_EQ(csv("a,b\r\n1,2\r\n").rows.size(), 1u); // CRLF too (a file edited elsewhere)
}

TEST(PlotGolden, TextThatIsNotACsvOfNumbersIsNamedByLineAndColumn) {
    struct Bad {
        std::string text, message;
    };
    for (const Bad& b :
         {Bad{"", "empty"}, Bad{"a,b\n", "a header but no rows"}, Bad{"a,,b\n1,2,3\n", "empty column name"},
          Bad{"a,b\n1,2\n3\n", "line 3: 1 fields, the header has 2"},
          Bad{"a,b\n1,x\n", "line 2, column 2: \"x\" is not a number"},
          Bad{"a,b\n1,nan\n", "line 2, column 2: \"nan\" is not a number"},
          Bad{"a,b\n1, 2\n", "line 2, column 2: \" 2\" is not a number"}, Bad{"a,b\n1,2\n\n3,4\n", "line 3 is empty"},
          Bad{std::string("\x89PNG\r\n\x1a\n\0\0", 10), "line 2"}}) {
        std::string error;
        EXPECT_FALSE(parseNumberCsv(b.text, error)) << b.text;
        EXPECT_NE(error.find(b.message), std::string::npos) << error;
    }
}

TEST(PlotGolden, OneValuePastTheToleranceFailsNamingItsLineAndColumn) {
    NumberCsv golden = csv(kCsv);
    EXPECT_TRUE(compareCsv(golden, golden, 0.0).passes);
    NumberCsv actual = golden;
    actual.rows[1][2] += 2e-5;
    CsvComparison cmp = compareCsv(actual, golden, 1e-5);
    EXPECT_FALSE(cmp.passes);
    EXPECT_EQ(cmp.firstDifference, "line 3 (theta_out_deg 0), column specular: 1.00002 vs golden 1 (difference 2e-05)")
        << cmp.firstDifference;
    EXPECT_TRUE(compareCsv(actual, golden, 3e-5).passes); // within a looser one
    actual.rows.pop_back();
    EXPECT_EQ(compareCsv(actual, golden, 1.0).firstDifference, "2 rows vs golden 3");
    NumberCsv renamed = golden;
    renamed.columns[3] = "sum";
    EXPECT_FALSE(compareCsv(renamed, golden, 1.0).passes);
}

TEST(CheckReport, NamesAreEscapedForXmlAndUrls) {
    EXPECT_EQ(xmlEscaped(R"(<a & "b" 'c'>)"), "&lt;a &amp; &quot;b&quot; &apos;c&apos;&gt;");
    EXPECT_EQ(xmlEscaped("bell\x07 and \xff"), "bell\\x07 and \\xFF"); // XML 1.0 forbids C0 controls; invalid UTF-8
    EXPECT_EQ(xmlEscaped("caf\xc3\xa9"), "caf\xc3\xa9");               // valid UTF-8 stays
    EXPECT_EQ(xmlEscaped("two\nlines", false), "two\nlines");          // a failure's details keep their lines
    EXPECT_EQ(xmlEscaped("two\nlines"), "two\\nlines");
    EXPECT_EQ(xmlEscaped("a\xEF\xBF\xBF b\xEF\xBF\xBE c\xEF\xBF\xBD"),
              "a\\uFFFF b\\uFFFE c\xEF\xBF\xBD"); // not XML; U+FFFD is
    EXPECT_EQ(urlEncoded("a b&c<\"d\".png"), "a%20b%26c%3C%22d%22.png");
    EXPECT_EQ(urlEncoded("05-full_phong.~x.png"), "05-full_phong.~x.png");
}

TEST(CheckReport, FailuresComeFirstWithTheirImagesAndTolerance) {
    std::vector<CheckCase> cases(2);
    cases[0].name = "01-pass";
    cases[0].figures = "max 0  mean 0.000";
    cases[1].name = "02-<fail>";
    cases[1].verdict = CheckCase::Verdict::Fail;
    cases[1].golden = "02-<fail>.golden.png";
    cases[1].actual = "02-<fail>.actual.png";
    cases[1].diff = "02-<fail>.diff.png";
    cases[1].tolerance = "pixel_tolerance 6 [preset]";
    std::string html = checkHtml(cases, CheckRun{"goldens", "512x512", "128x128"}, "../r/");
    std::size_t failure = html.find("02-&lt;fail&gt;"), pass = html.find("01-pass");
    ASSERT_NE(failure, std::string::npos);
    EXPECT_LT(failure, pass);
    EXPECT_NE(html.find("src=\"../r/02-%3Cfail%3E.golden.png\""), std::string::npos);
    EXPECT_NE(html.find("src=\"../r/02-%3Cfail%3E.diff.png\""), std::string::npos);
    EXPECT_NE(html.find("pixel_tolerance 6 [preset]"), std::string::npos);
    EXPECT_EQ(html.find("<fail>"), std::string::npos);
    std::string xml = checkJunit(cases, 1.5);
    EXPECT_NE(xml.find("tests=\"2\" failures=\"1\" errors=\"0\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("name=\"02-&lt;fail&gt;\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("<failure type=\"FAIL\""), std::string::npos) << xml;
}

} // namespace
} // namespace lab
