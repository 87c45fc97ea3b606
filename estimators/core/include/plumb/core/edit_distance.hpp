// How far apart two names are, for the "did you mean" of every command that takes a name (topics,
// CSV columns).
#pragma once

#include <cstddef>
#include <string_view>

namespace plumb {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions that
// turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace plumb
