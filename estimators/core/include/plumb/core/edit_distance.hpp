// How far apart two names are, for the "did you mean" of every command that takes a name (topics,
// CSV columns).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace plumb {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions that
// turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);

// What a mistyped `name` was probably meant to be, among `candidates`: the names within a few edits
// (a third of its length, 2 to 4: more would be another name altogether) or that it begins (a name
// cut short), the closest first, at most three; none when `name` is one of them.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates);
// "did you mean a, b or c?" for closest_names(), or "" for none.
std::string did_you_mean(const std::vector<std::string>& names);

}  // namespace plumb
