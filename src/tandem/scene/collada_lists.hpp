#pragma once
// A COLLADA file's index lists, checked before assimp reads the file: assimp 5.2 (Debian 12) keeps
// allocating without end on a <p> list holding a byte that is not part of a number (found by
// fuzz/targets' cfg target: "0 1 2 0\xff2 3" ran it out of memory), so tandem refuses such lists.

#include <filesystem>

namespace tandem {

/// Throws InputError naming the file unless the text of every <p>, <vcount> and <h> element is
/// made of digits, signs and white space only (COLLADA's lists of integers).
void check_collada_lists(const std::filesystem::path& file);

}  // namespace tandem
