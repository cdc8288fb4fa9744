// output.h — the one way the command line prints: every line, on stdout or stderr, goes through
// printable() (core/io/safe_text.h), so paths, names and messages that came from files or arguments
// reach the terminal escaped, whole (a NUL does not cut them) and never as control sequences.
#pragma once

#include <cstdio>
#include <string_view>

namespace lab {

// printf-style, then escaped, then written to `stream`. (A %s argument ends at a NUL: pass text
// that may hold one, such as a message with a file's contents, to the overload below.)
[[gnu::format(printf, 2, 3)]] void print(std::FILE* stream, const char* format, ...);
// `text`, whole, escaped.
void print(std::FILE* stream, std::string_view text);

} // namespace lab
