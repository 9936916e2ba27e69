// levrt against the Khronos glTF-Validator (npm gltf-validator, run by tools/validate_gltf.js)
// over the corpus tools/make_gltf_conformance_corpus.py writes (valid files and mutants): every
// file the validator calls an error is refused by `levrt render` (exit 2, one line naming the
// file and the glTF path, nothing written) and every file it finds valid is rendered, apart from
// the deliberate differences docs/gltf_conformance.md lists, each of which must still behave as
// listed. Without node or the validator the test skips, saying so, unless
// LEVRT_REQUIRE_GLTF_VALIDATOR is set (CI sets it: .ci/run).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {
namespace fs = std::filesystem;
using levrt_test::CommandRun;
using levrt_test::run_levrt;
using levrt_test::run_shell;
using levrt_test::shell_quote;

const std::string kSource = LEVRT_SOURCE_DIR;

// docs/gltf_conformance.md's table rows "| `FILE` | error or valid | refused or read | why |":
// file -> whether levrt refuses it.
std::map<std::string, bool> documented_differences() {
  std::ifstream doc(kSource + "/docs/gltf_conformance.md");
  std::map<std::string, bool> refused_by_levrt;
  std::string line;
  while (std::getline(doc, line)) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::size_t end = line.find('`', 3);
    std::stringstream cells(line.substr(end + 1));
    std::string skip, validator, levrt;
    std::getline(cells, skip, '|');
    std::getline(cells, validator, '|');
    std::getline(cells, levrt, '|');
    refused_by_levrt[line.substr(3, end - 3)] = levrt.find("refused") != std::string::npos;
  }
  return refused_by_levrt;
}

TEST(GltfValidator, LevrtRefusesWhatTheValidatorCallsAnErrorApartFromTheDocumentedList) {
  const std::string validate = "node " + shell_quote(kSource + "/tools/validate_gltf.js");
  if (run_shell(validate + " --check").exit_code != 0) {
    if (std::getenv("LEVRT_REQUIRE_GLTF_VALIDATOR"))
      FAIL() << "node or the npm package gltf-validator is missing (third_party/install-deps.sh)";
    GTEST_SKIP() << "node or the npm package gltf-validator is absent: run "
                    "third_party/install-deps.sh to compare levrt with the Khronos validator";
  }
  const levrt_test::TempDir temp("levrt_gltf_validator_");
  const fs::path corpus = temp.path() / "corpus";
  const CommandRun made =
      run_shell("python3 " + shell_quote(kSource + "/tools/make_gltf_conformance_corpus.py") + " " +
                shell_quote(corpus.string()));
  ASSERT_EQ(made.exit_code, 0) << made.output;
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(corpus))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 50u);

  std::string command = validate;
  for (const std::string& file : files) command += " " + shell_quote((corpus / file).string());
  const CommandRun validated = run_shell(command);
  ASSERT_EQ(validated.exit_code, 0) << validated.output;
  std::map<std::string, std::string> validator_errors;  // file -> its error codes ("" if valid)
  std::istringstream lines(validated.output);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::string file, count, codes;
    std::getline(cells, file, '\t');
    std::getline(cells, count, '\t');
    std::getline(cells, codes, '\t');
    validator_errors[file] = count == "0" ? "" : codes;
  }
  ASSERT_EQ(validator_errors.size(), files.size()) << validated.output;

  const std::map<std::string, bool> documented = documented_differences();
  std::size_t agree = 0, differ_as_documented = 0;
  std::set<std::string> unseen_documented;
  for (const auto& [file, refused] : documented) unseen_documented.insert(file);
  for (const std::string& file : files) {
    const std::string path = (corpus / file).string();
    const fs::path out = temp.path() / "x.png";
    const CommandRun r = run_levrt(
        {"render", "--scene", path, "--width", "8", "--height", "8", "--out", out.string()});
    const bool refused = r.exit_code == 2;
    if (refused) {
      // One line naming the file and, after it, where in the glTF the problem is.
      EXPECT_EQ(r.output.rfind("levrt: " + path + ": ", 0), 0u) << r.output;
      EXPECT_GT(r.output.size(), ("levrt: " + path + ": \n").size()) << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
      EXPECT_FALSE(fs::exists(out)) << file;
    } else {
      EXPECT_EQ(r.exit_code, 0) << file << ": " << r.output;
    }
    fs::remove(out);
    const bool validator_error = !validator_errors[file].empty();
    const auto listed = documented.find(file);
    unseen_documented.erase(file);
    if (refused == validator_error) {
      ++agree;
      EXPECT_EQ(listed, documented.end())
          << file << " is listed in docs/gltf_conformance.md but levrt agrees with the validator";
    } else if (listed != documented.end() && listed->second == refused) {
      ++differ_as_documented;
    } else {
      ADD_FAILURE() << file << ": the validator says "
                    << (validator_error ? validator_errors[file] : std::string("valid"))
                    << ", levrt " << (refused ? "refused it: " : "read it: ") << r.output;
    }
  }
  EXPECT_TRUE(unseen_documented.empty())
      << "docs/gltf_conformance.md lists files the corpus lacks, the first: "
      << *unseen_documented.begin();
  std::cout << "validator agreement: " << agree << " of " << files.size() << " files agree, "
            << differ_as_documented << " differ as docs/gltf_conformance.md documents\n";
}

}  // namespace
