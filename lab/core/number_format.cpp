// number_format.cpp — %.{1..9}g until the text reads back as the same float.
#include "core/number_format.h"

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
    char buf[32];
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
