// The release files (issue 39): one version everywhere (CHANGELOG.md's top entry, `vantage
// --version` from CMake's project(), pyproject.toml, CITATION.cff), and the licence.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/cli_runner.h"

namespace vantage {
namespace {

std::string source_file(const std::string& name) {
  return testing::read_file(std::string(VANTAGE_SOURCE_DIR) + "/" + name);
}

// The first capture of `pattern` in `text`, or "" when it does not match.
std::string first_match(const std::string& text, const std::string& pattern) {
  std::smatch match;
  const std::regex re(pattern);
  return std::regex_search(text, match, re) ? match[1].str() : std::string();
}

TEST(ReleaseFiles, OneVersionEverywhere) {
  testing::ScratchDir scratch;
  const testing::CliRun run = testing::run_vantage("--version", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string version = first_match(run.out, "^([0-9]+\\.[0-9]+\\.[0-9]+)\\s*$");
  ASSERT_FALSE(version.empty()) << run.out;
  EXPECT_EQ(first_match(source_file("CHANGELOG.md"), "\\n## \\[([^\\]]+)\\]"), version);
  EXPECT_EQ(first_match(source_file("pyproject.toml"), "\\nversion = \"([^\"]+)\""), version);
  EXPECT_EQ(first_match(source_file("CITATION.cff"), "\\nversion: \"([^\"]+)\""), version);
}

TEST(ReleaseFiles, TheLicenceIsBsd3Clause) {
  EXPECT_THAT(source_file("LICENSE"), ::testing::StartsWith("BSD 3-Clause License\n"));
  EXPECT_THAT(source_file("CITATION.cff"), ::testing::HasSubstr("\nlicense: BSD-3-Clause\n"));
}

}  // namespace
}  // namespace vantage
