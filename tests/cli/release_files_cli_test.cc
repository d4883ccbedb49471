// The release files (issue 39): the version defined once, in VERSION (`vantage --version` from
// CMake's project(), which reads it, and pyproject.toml, which reads it too), repeated by
// CHANGELOG.md's top entry and CITATION.cff; and the licence.

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

TEST(ReleaseFiles, OneVersionDefinedOnce) {
  testing::ScratchDir scratch;
  const testing::CliRun run = testing::run_vantage("--version", scratch);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string version = first_match(run.out, "^([0-9]+\\.[0-9]+\\.[0-9]+)\\s*$");
  ASSERT_FALSE(version.empty()) << run.out;
  EXPECT_EQ(first_match(source_file("CHANGELOG.md"), "\\n## \\[([^\\]]+)\\]"), version);
  EXPECT_EQ(source_file("VERSION"), version + "\n");
  const std::string pyproject = source_file("pyproject.toml");
  EXPECT_THAT(pyproject, ::testing::HasSubstr("\ndynamic = [\"version\"]"));
  EXPECT_THAT(pyproject, ::testing::HasSubstr("\nversion = {file = \"VERSION\"}\n"));
  EXPECT_THAT(pyproject, ::testing::Not(::testing::HasSubstr("\nversion = \"")));
  EXPECT_EQ(first_match(source_file("CITATION.cff"), "\\nversion: \"([^\"]+)\""), version);
}

TEST(ReleaseFiles, TheLicenceIsBsd3Clause) {
  EXPECT_THAT(source_file("LICENSE"), ::testing::StartsWith("BSD 3-Clause License\n"));
  EXPECT_THAT(source_file("CITATION.cff"), ::testing::HasSubstr("\nlicense: BSD-3-Clause\n"));
}

}  // namespace
}  // namespace vantage
