// number_format.h — the shortest decimal that reads back as the same float.
//
// Presets and plot CSV write numbers this way: 0.8f becomes "0.8", not "0.800000011920929", and
// parses back to exactly 0.8f. (std::to_chars for floats would do, but the browser build's
// libc++ does not have it.)
#pragma once

#include <string>

namespace lab {

// "nan", "inf" and "-inf" for non-finite values.
std::string shortestFloat(float value);

} // namespace lab
