// check_report.cpp — report.txt lines, the HTML page and JUnit XML for `lab check`.
#include "cli/check_report.h"

#include "core/io/safe_text.h"

#include <algorithm>
#include <cstdio>

namespace lab {

namespace {

int count(const std::vector<CheckCase>& cases, bool failed) {
    return static_cast<int>(
        std::count_if(cases.begin(), cases.end(), [&](const CheckCase& c) { return c.failed() == failed; }));
}

} // namespace

std::string fixedDecimals(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

const char* toString(CheckCase::Verdict verdict) {
    switch (verdict) {
    case CheckCase::Verdict::Pass:
        return "PASS";
    case CheckCase::Verdict::Fail:
        return "FAIL";
    case CheckCase::Verdict::Missing:
        return "MISSING";
    case CheckCase::Verdict::Error:
        return "ERROR";
    case CheckCase::Verdict::Created:
        return "CREATED";
    case CheckCase::Verdict::Updated:
        return "UPDATED";
    case CheckCase::Verdict::Same:
        return "SAME";
    }
    return "?";
}

const char* toString(CheckCase::Kind kind) {
    switch (kind) {
    case CheckCase::Kind::Render:
        return "render";
    case CheckCase::Kind::SweepCell:
        return "sweep";
    case CheckCase::Kind::Plot:
        return "plot";
    }
    return "?";
}

std::string checkLine(const CheckCase& c, const std::string& reportFolder) {
    std::string verdict = toString(c.verdict);
    verdict.resize(std::max<std::size_t>(verdict.size() + 1, 9), ' ');
    std::string line = verdict + c.name;
    switch (c.verdict) {
    case CheckCase::Verdict::Pass:
    case CheckCase::Verdict::Same:
        return line + (c.figures.empty() ? "" : "  " + c.figures);
    case CheckCase::Verdict::Created:
    case CheckCase::Verdict::Updated:
        return line + (c.figures.empty() ? "" : "  (" + c.figures + ")");
    case CheckCase::Verdict::Missing:
    case CheckCase::Verdict::Error:
        return line + ": " + c.message;
    case CheckCase::Verdict::Fail:
        break;
    }
    line += "  " + (c.message.empty() ? c.figures : c.message);
    std::string files;
    for (const std::string* f : {&c.actual, &c.diff}) {
        if (!f->empty()) {
            files += (files.empty() ? "  -> " : ", ") + reportFolder + "/" + *f;
        }
    }
    return line + files;
}

std::string urlEncoded(std::string_view name) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (unsigned char ch : name) {
        if ((ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '.' ||
            ch == '_' || ch == '~' || ch == '-') {
            out += static_cast<char>(ch);
        } else {
            out += '%';
            out += kHex[ch >> 4];
            out += kHex[ch & 15];
        }
    }
    return out;
}

//----------------------------------------------------------------------------------------
// HTML
//----------------------------------------------------------------------------------------

namespace {

constexpr const char* kStyle = R"(
body { font: 15px/1.45 system-ui, sans-serif; margin: 1.5em auto; max-width: 1400px; padding: 0 1em; color: #1d1d1f; }
h1 { font-size: 1.5em; margin-bottom: .2em; }
.run { color: #555; margin-top: 0; }
.case { border: 1px solid #ddd; border-left: 6px solid #c62828; border-radius: 6px; padding: .6em 1em 1em; margin: 1.2em 0; }
.case.missing { border-left-color: #ef6c00; }
.case.error { border-left-color: #6a1b9a; }
.case h2 { font-size: 1.1em; margin: .2em 0 .4em; word-break: break-all; }
.verdict { display: inline-block; min-width: 5.5em; font-weight: 600; }
.FAIL { color: #c62828; } .MISSING { color: #ef6c00; } .ERROR { color: #6a1b9a; }
.PASS, .SAME { color: #2e7d32; } .CREATED, .UPDATED { color: #1565c0; }
.numbers { margin: .2em 0; } .numbers span { margin-right: 1.5em; }
.images { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; margin-top: .6em; }
figure { margin: 0; } figcaption { font-size: .85em; color: #555; text-align: center; }
img { image-rendering: pixelated; border: 1px solid #ccc; max-width: 100%; display: block; }
.swipe { position: relative; display: inline-block; cursor: pointer; }
.swipe img.over { position: absolute; left: 0; top: 0; }
.swipe input { width: 0; min-width: 100%; margin: .4em 0 0; } /* as wide as the image, not wider */
button { font: inherit; padding: .15em .8em; }
table { border-collapse: collapse; width: 100%; margin-top: .5em; }
td, th { text-align: left; padding: .2em .6em; border-bottom: 1px solid #eee; font-size: .92em; vertical-align: top; }
td.name { word-break: break-all; }
)";

// The slider shows actual left of the divider and golden right of it; a click or the button
// flips to the other whole image.
constexpr const char* kScript = R"(
function labSwipe(input) {
  var over = input.parentNode.querySelector('img.over');
  over.style.clipPath = 'inset(0 ' + (100 - input.value) + '% 0 0)';
}
function labFlip(id) {
  var box = document.getElementById(id), input = box.querySelector('input');
  input.value = input.value > 50 ? 0 : 100;
  labSwipe(input);
  box.querySelector('.which').textContent = input.value > 50 ? 'actual' : 'golden';
}
)";

std::string image(const std::string& prefix, const std::string& file, const std::string& caption,
                  const std::string& extra = "") {
    std::string src = xmlEscaped(prefix + urlEncoded(file));
    return "<figure><a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + xmlEscaped(caption) + "\"" + extra +
           "></a><figcaption>" + xmlEscaped(caption) + "</figcaption></figure>";
}

std::string failureBlock(const CheckCase& c, const std::string& prefix, int index) {
    std::string verdict = toString(c.verdict);
    std::string cls = c.verdict == CheckCase::Verdict::Missing ? " missing"
                      : c.verdict == CheckCase::Verdict::Error ? " error"
                                                               : "";
    std::string out = "<section class=\"case" + cls + "\" id=\"case-" + std::to_string(index) +
                      "\">\n<h2><span class=\"verdict " + verdict + "\">" + verdict + "</span> " + xmlEscaped(c.name) +
                      "</h2>\n";
    out +=
        "<p class=\"numbers\"><span>" + std::string(toString(c.kind)) + " of " + xmlEscaped(c.presetFile) + "</span>";
    if (!c.figures.empty()) {
        out += "<span>" + xmlEscaped(c.figures) + "</span>";
    }
    out += "</p>\n";
    if (!c.message.empty()) {
        out += "<p>" + xmlEscaped(c.message) + "</p>\n";
    }
    if (!c.tolerance.empty()) {
        out += "<p class=\"numbers\">tolerance: " + xmlEscaped(c.tolerance) + "</p>\n";
    }
    bool images = c.actual.ends_with(".png");
    if (images) {
        out += "<div class=\"images\">";
        if (!c.golden.empty()) {
            out += image(prefix, c.golden, "golden");
        }
        out += image(prefix, c.actual, "actual");
        if (!c.diff.empty()) {
            out += image(prefix, c.diff, "difference (16x; failing pixels magenta)");
        }
        if (!c.golden.empty()) {
            // Actual over golden, cut at the slider; the whole of either with a click.
            std::string id = "swipe-" + std::to_string(index);
            out += "<figure><div class=\"swipe\" id=\"" + id +
                   "\" onclick=\"if (event.target.tagName == 'IMG') labFlip('" + id + "')\">" + "<img src=\"" +
                   xmlEscaped(prefix + urlEncoded(c.golden)) + "\" alt=\"golden\">" + "<img class=\"over\" src=\"" +
                   xmlEscaped(prefix + urlEncoded(c.actual)) +
                   "\" alt=\"actual\" style=\"clip-path: inset(0 50% 0 0)\">" +
                   "<input type=\"range\" min=\"0\" max=\"100\" value=\"50\" oninput=\"labSwipe(this)\" "
                   "aria-label=\"actual left of the divider, golden right\">" +
                   "<button type=\"button\" onclick=\"labFlip('" + id +
                   "')\">flip</button> <span class=\"which\">actual | golden</span>"
                   "</div><figcaption>slide: actual left, golden right; click to flip</figcaption></figure>";
        }
        out += "</div>\n";
    } else if (!c.actual.empty() || !c.golden.empty()) {
        out += "<p>";
        if (!c.actual.empty()) {
            out += "<a href=\"" + xmlEscaped(prefix + urlEncoded(c.actual)) + "\">actual</a> ";
        }
        if (!c.golden.empty()) {
            out += "<a href=\"" + xmlEscaped(prefix + urlEncoded(c.golden)) + "\">golden</a>";
        }
        out += "</p>\n";
    }
    return out + "</section>\n";
}

} // namespace

std::string checkHtml(const std::vector<CheckCase>& cases, const CheckRun& run, const std::string& linkPrefix) {
    const int failed = count(cases, true), passed = count(cases, false);
    std::string title = "lab check: " + std::to_string(failed) + " failed, " + std::to_string(passed) + " passed";
    std::string out = "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
                      xmlEscaped(title) + "</title>\n<style>" + kStyle + "</style>\n<script>" + kScript +
                      "</script>\n</head>\n<body>\n";
    out += "<h1>" + xmlEscaped(title) + "</h1>\n<p class=\"run\">goldens in " + xmlEscaped(run.golden) + "; renders " +
           xmlEscaped(run.size) + ", sweep cells " + xmlEscaped(run.sweepSize) + (run.update ? "; --update" : "") +
           "</p>\n";
    int index = 0;
    for (const CheckCase& c : cases) {
        if (c.failed()) {
            out += failureBlock(c, linkPrefix, index);
        }
        ++index;
    }
    if (passed > 0) {
        out += "<h2>" + std::to_string(passed) + (failed ? " passing" : " cases, all passing") +
               "</h2>\n<table>\n<tr><th></th><th>case</th><th>kind</th><th>figures</th><th>tolerance</th><th>s</th></"
               "tr>\n";
        for (const CheckCase& c : cases) {
            if (!c.failed()) {
                std::string verdict = toString(c.verdict);
                out += "<tr><td class=\"" + verdict + "\">" + verdict + "</td><td class=\"name\">" +
                       xmlEscaped(c.name) + "</td><td>" + toString(c.kind) + "</td><td>" + xmlEscaped(c.figures) +
                       "</td><td>" + xmlEscaped(c.tolerance) + "</td><td>" + fixedDecimals(c.seconds, 2) +
                       "</td></tr>\n";
            }
        }
        out += "</table>\n";
    }
    return out + "</body>\n</html>\n";
}

//----------------------------------------------------------------------------------------
// JUnit XML
//----------------------------------------------------------------------------------------

std::string checkJunit(const std::vector<CheckCase>& cases, double seconds) {
    int failures = 0, errors = 0;
    for (const CheckCase& c : cases) {
        failures += c.verdict == CheckCase::Verdict::Fail || c.verdict == CheckCase::Verdict::Missing;
        errors += c.verdict == CheckCase::Verdict::Error;
    }
    std::string counts = "tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                         "\" errors=\"" + std::to_string(errors) + "\" skipped=\"0\" time=\"" +
                         fixedDecimals(seconds, 3) + "\"";
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"lab check\" " + counts +
                      ">\n  <testsuite name=\"lab check\" " + counts + ">\n";
    for (const CheckCase& c : cases) {
        out += "    <testcase classname=\"lab check." + std::string(toString(c.kind)) + "\" name=\"" +
               xmlEscaped(c.name) + "\" file=\"" + xmlEscaped(c.presetFile) + "\" time=\"" +
               fixedDecimals(c.seconds, 3) + "\"";
        if (!c.failed()) {
            out += "/>\n";
            continue;
        }
        std::string what = c.message.empty() ? c.figures : c.message; // a missing golden's says "no golden ..."
        std::string detail = what + (c.figures.empty() || what == c.figures ? "" : "\n" + c.figures) +
                             (c.tolerance.empty() ? "" : "\ntolerance: " + c.tolerance);
        // The figures and the tolerance in the message too: some test views show only the message.
        if (c.verdict == CheckCase::Verdict::Fail && !c.tolerance.empty()) {
            what += " (tolerance: " + c.tolerance + ")";
        }
        for (const std::string* f : {&c.golden, &c.actual, &c.diff}) {
            if (!f->empty()) {
                detail += "\n" + *f;
            }
        }
        const char* element = c.verdict == CheckCase::Verdict::Error ? "error" : "failure";
        out += ">\n      <" + std::string(element) + " type=\"" + toString(c.verdict) + "\" message=\"" +
               xmlEscaped(what) + "\">" + xmlEscaped(detail, false) + "</" + element + ">\n    </testcase>\n";
    }
    return out + "  </testsuite>\n</testsuites>\n";
}

} // namespace lab
