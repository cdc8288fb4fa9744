// csv_compare.h — a CSV of numbers (the lobe CSV `lab plot --out` writes) against its golden,
// value by value within an absolute tolerance, naming the first line and column that differ.
//
// It reads text only; the files are read and written by check.cpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lab {

// A header line of column names, then rows of as many finite numbers.
struct NumberCsv {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
};

// Nullopt with a one-line `error` ("line 3, column 2: "abc" is not a number") for text that is
// not such a CSV: empty, no header, a row of another width, a field that is no finite number.
std::optional<NumberCsv> parseNumberCsv(std::string_view text, std::string& error);

struct CsvComparison {
    bool passes = false;
    double maxDifference = 0.0;  // over the values compared (all of them when the shapes agree)
    std::string figures;         // "max difference 3e-07 over 181 rows x 4 columns"
    std::string firstDifference; // "" when it passes: the shape, or the first value past the tolerance
};

CsvComparison compareCsv(const NumberCsv& actual, const NumberCsv& golden, double tolerance);

} // namespace lab
