#pragma once
// The command-line tools of bench/ (the CGAL peer, the ideal-lattice yardstick) report errors as
// `isopatch mesh` does: one line on stderr and isopatch's exit code for the kind of error.
#include <isopatch/error.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "error_report.hpp"

namespace isopatch::bench {

/// Parses argv into `app` and returns run()'s exit code. A usage error exits 2 (help and version 0);
/// an isopatch::Error prints "TOOL: message" and exits with the tool's exit code for its kind
/// (error_report.hpp); any other exception is an internal error, exit 1.
template <class Run>
int run_tool(const char* tool, CLI::App& app, int argc, char** argv, Run&& run) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    return run();
  } catch (const isopatch::Error& e) {
    std::fprintf(stderr, "%s: %s\n", tool, cli::describe(e).c_str());
    return cli::exit_code(e.kind());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", tool, e.what());
    return 1;
  }
}

}  // namespace isopatch::bench
