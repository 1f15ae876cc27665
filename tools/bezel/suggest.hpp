// tools/bezel/suggest.hpp — "did you mean" for a mistyped option or command.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace bezel::cli {

// Edits (insert, delete, replace one character, or swap two adjacent ones) that turn `a` into
// `b`: the optimal string alignment distance, a restricted Damerau–Levenshtein distance.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The name in `names` closest to `typed`, when it is close enough to be what was meant: at most
// one edit for names of three or four characters, two for longer ones ("--font-sise" finds
// "--font-size"); names of one or two characters ("-o") are never suggested, every short typo is
// that close to them. Ties go to the first name in `names`. Failing that, the one name `typed`
// begins ("--fore" finds "--foreground").
std::optional<std::string> closest_name(const std::string& typed, const std::vector<std::string>& names);

}  // namespace bezel::cli
