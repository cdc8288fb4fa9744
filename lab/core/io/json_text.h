// json_text.h — checks on JSON text before and after a parser sees it.
//
// JSON parsers (nlohmann's, and tinygltf's on top of it) recurse once per nesting level, so a
// file nested thousands of levels deep overflows the stack before any validation runs: bound the
// depth on the text first. And a parser's byte offset means little to a person; lineColumn
// turns it into "line L, column C".
//
// This file owns those two questions. It does not parse JSON.
#pragma once

#include "core/io/diagnostics.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace lab {

// Whether no array or object in `text` nests deeper than `maxDepth` (brackets inside strings do
// not count). Malformed text is the parser's to report; this only bounds its depth.
bool jsonNestingWithin(std::string_view text, int maxDepth);

// What keeps `text` from going to a JSON parser, as `file`'s diagnostic: nesting deeper than
// `maxDepth` (jsonNestingWithin), or a NUL byte, with its line and column — JSON text holds none
// (inside a string it is written \u0000), and nlohmann's parser takes one for the end of its input:
// "{...}\0anything" would read as "{...}" and the rest go unread. Nullopt when neither.
std::optional<Diagnostic> jsonTextProblem(std::string_view text, const std::string& file, int maxDepth);

// "line L, column C" (from 1) of byte `offset` in `text`.
std::string lineColumn(std::string_view text, std::size_t offset);

// What a JSON parser's error says without the place it names in its own words (the caller says it
// as lineColumn): nlohmann's "[json.exception.parse_error.101] parse error at line 2, column 16:
// syntax error while parsing value - invalid literal; last read: '"shininess": N'" becomes
// "syntax error while parsing value - invalid literal; last read: '"shininess": N'". The excerpt
// may hold ": " itself; the cut is the first one after the place. The whole message otherwise.
std::string parseErrorDetail(std::string_view what);

} // namespace lab
