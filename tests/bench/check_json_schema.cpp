// check_json_schema SCHEMA.json DOCUMENT.json: exit 0 when the document is valid, else 1
// with one line per problem (json_schema_subset.hpp); 2 when a file cannot be read.
#include "json_schema_subset.hpp"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: check_json_schema SCHEMA.json DOCUMENT.json\n");
    return 2;
  }
  nlohmann::json files[2];
  for (int i = 0; i < 2; ++i) {
    std::ifstream in(argv[i + 1]);
    files[i] = nlohmann::json::parse(in, nullptr, false);
    if (files[i].is_discarded()) {
      std::fprintf(stderr, "check_json_schema: %s is not JSON\n", argv[i + 1]);
      return 2;
    }
  }
  const std::vector<std::string> problems = schema_test::validate(files[0], files[1]);
  for (const std::string& problem : problems) std::printf("%s: %s\n", argv[2], problem.c_str());
  return problems.empty() ? 0 : 1;
}
