#pragma once
// A COLLADA file's index lists, checked before assimp reads the file: assimp 5.2 (Debian 12) keeps
// allocating without end on a <p> list holding a byte that is not part of a number (found by
// fuzz/targets' cfg target: "0 1 2 0\xff2 3" ran it out of memory), so tandem refuses such lists.
// It also reads an accessor's values without checking them against the array they come from (a
// <float_array> without its count made it read through a null pointer), so tandem checks that
// every array has a count and every accessor stays within its array.

#include <filesystem>

namespace tandem {

/// Throws InputError naming the file unless the text of every <p>, <vcount> and <h> element is
/// made of digits, signs and white space only (COLLADA's lists of integers), every array
/// (<float_array>, <int_array>, ...) has a whole-number count, and every <accessor> names an array
/// of the file and reads within its count.
void check_collada_lists(const std::filesystem::path& file);

}  // namespace tandem
