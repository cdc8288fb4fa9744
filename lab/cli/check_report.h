// check_report.h — what `lab check` found, case by case, and the three ways it is written down:
// report.txt (the lines the command printed), index.html (golden, actual and difference side by
// side, for people) and JUnit XML (for a CI's test view: GitHub Actions, GitLab).
//
// A case is one comparison: a preset's render, one cell of its sweep, or its plot. This file
// only formats: it renders nothing, compares nothing and writes no files (check.cpp does).
#pragma once

#include "core/io/safe_text.h" // xmlEscaped

#include <string>
#include <string_view>
#include <vector>

namespace lab {

struct CheckCase {
    enum class Kind { Render, SweepCell, Plot };
    enum class Verdict { Pass, Fail, Missing, Error, Created, Updated, Same };

    Kind kind = Kind::Render;
    Verdict verdict = Verdict::Pass;
    std::string name; // "05-full-phong", "05-full-phong.plot", "05-full-phong.sweep[shininess=10]"
    std::string presetFile;
    std::string figures;   // "max 3  mean 0.012  over tolerance 0.000%", or the first differing value
    std::string tolerance; // the tolerance that applied and where it came from
    std::string message;   // why it failed (or erred), one line
    // Files in the report folder, relative to it; empty when there is none.
    std::string golden, actual, diff;
    double seconds = 0.0;

    bool failed() const { return verdict == Verdict::Fail || verdict == Verdict::Missing || verdict == Verdict::Error; }
};

// "PASS", "FAIL", "MISSING", "ERROR", "CREATED", "UPDATED", "SAME".
const char* toString(CheckCase::Verdict verdict);
// "render", "sweep", "plot".
const char* toString(CheckCase::Kind kind);

// `v` with `digits` decimals, as the report's figures are written ("0.517").
std::string fixedDecimals(double v, int digits);

// The line `lab check` prints for the case: "FAIL     05-full-phong  max 40 ..." and the files.
std::string checkLine(const CheckCase& c, const std::string& reportFolder);

// Where the run looked and what it used, for the top of the page.
struct CheckRun {
    std::string golden;    // the golden folder as given
    std::string size;      // "512x512"
    std::string sweepSize; // "128x128"
    bool update = false;
};

// The HTML page: failures first (golden, actual and difference side by side, with a slider and a
// flip between golden and actual), then the passing cases in a table. `linkPrefix` goes before
// every file name in the report folder ("" when the page is in that folder). Self-contained: no
// server, no script or style from elsewhere; every name escaped.
std::string checkHtml(const std::vector<CheckCase>& cases, const CheckRun& run, const std::string& linkPrefix);

// JUnit XML: one <testsuite> ("lab check"), one <testcase> a case (classname the kind, name the
// case's name, file the preset), <failure> for a differing or missing golden, <error> for a case
// that could not be compared. Valid XML 1.0 whatever the names hold.
std::string checkJunit(const std::vector<CheckCase>& cases, double seconds);

// `name` as a relative URL path segment: every byte but [A-Za-z0-9._~-] percent-encoded.
std::string urlEncoded(std::string_view name);

} // namespace lab
