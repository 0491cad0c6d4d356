// The files lpv-bench reads besides requests: suites and results. Anything wrong with them
// is BadInput (exit status 2), its message naming the file and the field.
#pragma once

#include "api/bench_results.hpp"
#include "api/bench_suite.hpp"
#include "tools/common/program_main.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

class BadInput : public tools::InputError {
 public:
  using tools::InputError::InputError;
};

struct SuiteFile {
  std::filesystem::path path;  // absolute
  api::BenchSuite suite;       // its scene files made absolute (they are relative to the suite file)
};

// `name_or_path`: a suite file, or the name of one in bench/suites of the source tree this
// lpv-bench was built from (suite_names()).
SuiteFile load_suite(const std::string& name_or_path);
// The names load_suite finds in bench/suites, sorted: read from the directory, so the help
// lists every suite there is.
std::vector<std::string> suite_names();

api::BenchResults load_results(const std::filesystem::path& path);

std::string read_text_file(const std::filesystem::path& path);  // throws BadInput
void write_text_file(const std::filesystem::path& path, const std::string& text);  // atomically

}  // namespace bench
