// csv_compare.cpp — number CSVs, read and compared.
#include "cli/csv_compare.h"

#include "core/io/safe_text.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lab {

namespace {

std::vector<std::string_view> fields(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t start = 0;
    while (true) {
        std::size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) {
            return out;
        }
        start = comma + 1;
    }
}

std::string shortNumber(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

} // namespace

std::optional<NumberCsv> parseNumberCsv(std::string_view text, std::string& error) {
    NumberCsv csv;
    std::size_t lineNumber = 0, start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        std::string_view line =
            text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
        start = end == std::string_view::npos ? text.size() : end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        if (line.empty()) {
            if (start < text.size()) {
                error = "line " + std::to_string(lineNumber) + " is empty";
                return std::nullopt;
            }
            break;
        }
        std::vector<std::string_view> cells = fields(line);
        if (lineNumber == 1) {
            for (std::string_view name : cells) {
                if (name.empty()) {
                    error = "line 1: an empty column name (expected a header such as theta_out_deg,diffuse,...)";
                    return std::nullopt;
                }
                csv.columns.emplace_back(name);
            }
            continue;
        }
        if (cells.size() != csv.columns.size()) {
            error = "line " + std::to_string(lineNumber) + ": " + std::to_string(cells.size()) +
                    " fields, the header has " + std::to_string(csv.columns.size());
            return std::nullopt;
        }
        std::vector<double>& row = csv.rows.emplace_back();
        for (std::size_t i = 0; i < cells.size(); ++i) {
            std::string cell(cells[i]); // strtod needs the NUL after it (the "C" locale: '.' decimals)
            char* parsed = nullptr;
            double v = cell.empty() || std::isspace(static_cast<unsigned char>(cell[0]))
                           ? NAN
                           : std::strtod(cell.c_str(), &parsed);
            if (parsed != cell.c_str() + cell.size() || !std::isfinite(v)) {
                error = "line " + std::to_string(lineNumber) + ", column " + std::to_string(i + 1) + ": " +
                        inQuotes(cells[i], 40) + " is not a number";
                return std::nullopt;
            }
            row.push_back(v);
        }
    }
    if (csv.columns.empty()) {
        error = "empty (expected a header line, then rows of numbers)";
        return std::nullopt;
    }
    if (csv.rows.empty()) {
        error = "a header but no rows";
        return std::nullopt;
    }
    return csv;
}

CsvComparison compareCsv(const NumberCsv& actual, const NumberCsv& golden, double tolerance) {
    CsvComparison out;
    if (actual.columns != golden.columns) {
        auto joined = [](const std::vector<std::string>& v) {
            std::string s;
            for (const std::string& c : v) {
                s += (s.empty() ? "" : ",") + c;
            }
            return s;
        };
        out.firstDifference =
            "columns " + inQuotes(joined(actual.columns), 200) + " vs golden " + inQuotes(joined(golden.columns), 200);
        out.figures = out.firstDifference;
        return out;
    }
    if (actual.rows.size() != golden.rows.size()) {
        out.firstDifference =
            std::to_string(actual.rows.size()) + " rows vs golden " + std::to_string(golden.rows.size());
        out.figures = out.firstDifference;
        return out;
    }
    for (std::size_t r = 0; r < actual.rows.size(); ++r) {
        for (std::size_t c = 0; c < actual.columns.size(); ++c) {
            double a = actual.rows[r][c], g = golden.rows[r][c], d = std::abs(a - g);
            out.maxDifference = std::max(out.maxDifference, d);
            if (d > tolerance && out.firstDifference.empty()) {
                // Line numbers as in the file (the header is line 1); the first column names the row.
                out.firstDifference = "line " + std::to_string(r + 2) + " (" + actual.columns[0] + " " +
                                      shortNumber(actual.rows[r][0]) + "), column " + actual.columns[c] + ": " +
                                      shortNumber(a) + " vs golden " + shortNumber(g) + " (difference " +
                                      shortNumber(d) + ")";
            }
        }
    }
    out.passes = out.firstDifference.empty();
    out.figures = "max difference " + shortNumber(out.maxDifference) + " over " + std::to_string(actual.rows.size()) +
                  " rows x " + std::to_string(actual.columns.size()) + " columns";
    return out;
}

} // namespace lab
