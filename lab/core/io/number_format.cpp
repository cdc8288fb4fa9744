// number_format.cpp — %.{1..9}g until the text reads back as the same float.
#include "core/io/number_format.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lab {

std::string shortestFloat(float value) {
    if (std::isnan(value)) {
        return "nan";
    }
    if (std::isinf(value)) {
        return value > 0 ? "inf" : "-inf";
    }
    char buf[48];
    // An integer in fewer significant digits than it has would come out in exponent form
    // ("9e+01" for 90); write integers as integers.
    if (value == std::trunc(value) && std::abs(value) < 1e15f) {
        std::snprintf(buf, sizeof buf, "%.0f", static_cast<double>(value));
        return buf;
    }
    // Nine significant digits always round-trip a float; most values need far fewer.
    for (int precision = 1; precision <= 9; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(value));
        if (std::strtof(buf, nullptr) == value) {
            break;
        }
    }
    return buf;
}

} // namespace lab
