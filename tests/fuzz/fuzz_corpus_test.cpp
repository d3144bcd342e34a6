// The fuzz targets' corpora, replayed in the unit tests through the targets themselves
// (fuzz/targets): every input a fuzzing run found a fault with (fuzz/regression/TARGET/) must now
// pass without an escaping exception (a crash fails the test program), and every seed
// (fuzz/seeds/TARGET/ and the project's files that fuzz/project-seeds names) must be accepted.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.hpp"
#include "targets/fuzz_target.hpp"

namespace tandem::fuzz {
namespace {

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder,
                                            const std::string& extension = "") {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(folder))
    return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The seeds of `target`: fuzz/seeds/TARGET/ and the project's files fuzz/project-seeds names.
std::vector<std::filesystem::path> seeds(std::string_view target) {
  const std::filesystem::path root = test::source_dir();
  std::vector<std::filesystem::path> files = files_in(root / "fuzz/seeds" / target);
  std::ifstream list(root / "fuzz/project-seeds");
  std::string line;
  while (std::getline(list, line)) {
    std::istringstream fields(line);
    std::string name, pattern;
    if (line.empty() || line[0] == '#' || !(fields >> name >> pattern) || name != target)
      continue;
    const std::size_t star = pattern.find("/*");
    EXPECT_NE(star, std::string::npos) << "fuzz/project-seeds: pattern " << pattern;
    if (star == std::string::npos)
      continue;
    const auto found = files_in(root / pattern.substr(0, star), pattern.substr(star + 2));
    EXPECT_FALSE(found.empty()) << "fuzz/project-seeds: nothing matches " << pattern;
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

}  // namespace

void PrintTo(const Target& target, std::ostream* os) {
  *os << target.name;
}

namespace {

class FuzzCorpus : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzCorpus, EverySeedIsAccepted) {
  const std::vector<std::filesystem::path> files = seeds(GetParam().name);
  ASSERT_FALSE(files.empty()) << "no seeds for the target " << GetParam().name;
  for (const auto& file : files) {
    bool accepted = false;
    EXPECT_NO_THROW(accepted = GetParam().run(read_bytes(file))) << file;
    EXPECT_TRUE(accepted) << file << " is refused";
  }
}

TEST_P(FuzzCorpus, EveryRegressionInputPasses) {
  const auto files = files_in(test::source_dir() / "fuzz/regression" / GetParam().name);
  if (files.empty())
    GTEST_SKIP() << "no fault found with the target " << GetParam().name << " so far";
  for (const auto& file : files)
    EXPECT_NO_THROW(GetParam().run(read_bytes(file))) << file;
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus,
                         ::testing::ValuesIn(targets().begin(), targets().end()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace tandem::fuzz
