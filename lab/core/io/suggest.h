// suggest.h — "did you mean …?" for a misspelt preset key, name or sweep key: the closest
// candidate within a few edits (Levenshtein distance), quoted as every value in a message is.
// It does not know what the candidates are: the preset reader and the sweep parser pass theirs.
#pragma once

#include "core/io/safe_text.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace lab {

// The number of single-byte insertions, deletions and substitutions that turn a into b.
std::size_t editDistance(std::string_view a, std::string_view b);

// ` (did you mean "x"?)` for the candidate closest to `word` within max(2, |word|/3) edits, else "".
template <typename Names> std::string suggestion(std::string_view word, const Names& candidates) {
    std::string_view best;
    if (word.size() > 64) {
        return {}; // no key or name is that long (and the distance would cost its length times theirs)
    }
    std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (std::string_view c : candidates) {
        std::size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best.empty() ? std::string{} : " (did you mean " + inQuotes(best) + "?)";
}

} // namespace lab
