#pragma once
// Small helpers shared by the subcommands: parameters, output checks, number formatting.

#include <map>
#include <string>
#include <vector>

namespace isopatch::cli {

/// Parses "name=value" items into a map. \throw InputError for a malformed item or a repeated name.
std::map<std::string, double> parse_params(const std::vector<std::string>& items);

/// Checks, before any work is done, that `path` has a known mesh extension and that its folder exists
/// and is writable. \throw IoError otherwise.
void check_output_path(const std::string& path);

/// Checks that the folder of `path` exists and is writable and that `path` is not a folder.
/// \throw IoError otherwise.
void check_writable_location(const std::string& path);

/// "12345" -> "12,345" style grouping for counts in summaries.
std::string group_digits(unsigned long long n);

}  // namespace isopatch::cli
