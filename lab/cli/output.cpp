// output.cpp — formatted, escaped printing for the command line (see output.h).
#include "cli/output.h"

#include "core/io/safe_text.h"

#include <cstdarg>
#include <string>

namespace lab {

void print(std::FILE* stream, const char* format, ...) {
    std::va_list args;
    va_start(args, format);
    std::va_list again;
    va_copy(again, args);
    int n = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string text(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
    if (n > 0) {
        std::vsnprintf(text.data(), text.size() + 1, format, again);
    }
    va_end(again);
    print(stream, std::string_view(text));
}

void print(std::FILE* stream, std::string_view text) {
    std::string safe = printable(text);
    std::fwrite(safe.data(), 1, safe.size(), stream);
}

} // namespace lab
