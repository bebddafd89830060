#pragma once
// How the command-line tool reports a library error: the library speaks of its own settings
// (Error::setting(), e.g. "max_vertices"); the tool names its flags (--max-vertices) and gives each
// kind of error its own exit code.

#include <isopatch/error.hpp>

#include <string>

namespace isopatch::cli {

/// Exit code of the command-line tool for an error kind: 1 internal, 3 invalid argument, 4 unknown
/// surface, 5 parse error, 6 file error, 7 f not finite, 8 no surface, 9 budget or cancel, 10 singular
/// gradient (0 is success, 2 usage).
int exit_code(ErrorKind kind);

/// The flag of `isopatch mesh` that sets the Settings field `setting` ("max_vertices" ->
/// "--max-vertices"), or "" when no flag sets it (size_field, cancel, ...).
std::string flag_for_setting(const std::string& setting);

/// The one-line message for `e`: its text, followed by " (--flag)" when a flag sets the field it names.
std::string describe(const Error& e);

}  // namespace isopatch::cli
