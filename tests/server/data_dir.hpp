// A fresh --data-dir for a test, removed with everything in it at the end.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

namespace server_test {

class DataDir {
 public:
  DataDir() {
    char pattern[] = "/tmp/lpv-scenes-test-XXXXXX";
    if (!mkdtemp(pattern)) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~DataDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  DataDir(const DataDir&) = delete;
  DataDir& operator=(const DataDir&) = delete;

  std::string path() const { return path_.string(); }
  std::filesystem::path scenes() const { return path_ / "scenes"; }
  // The names of the files in the scenes folder, hidden ones included.
  std::set<std::string> scene_files() const {
    std::set<std::string> names;
    if (std::filesystem::exists(scenes()))
      for (const auto& entry : std::filesystem::directory_iterator(scenes())) names.insert(entry.path().filename());
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace server_test
