#pragma once
// The composite examples the tests run over: every examples/*.ipatch, by file name, sorted.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace isopatch::test {

inline std::vector<std::string> example_files() {
  std::vector<std::string> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(ISOPATCH_SOURCE_DIR) + "/examples"))
    if (entry.path().extension() == ".ipatch") files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

inline std::string example_path(const std::string& name) {
  return std::string(ISOPATCH_SOURCE_DIR) + "/examples/" + name;
}

}  // namespace isopatch::test
