// The isopatch command-line tool: arguments -> Settings -> one library call -> output.
// Errors print one line on stderr, naming the flag at fault, and exit with a code per kind
// (error_report.hpp).
#include <isopatch/error.hpp>
#include <isopatch/version.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <new>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "commands.hpp"
#include "error_report.hpp"
#include "interrupts.hpp"

namespace {

/// Parses the command line and runs the chosen command; returns the exit code (error_report.hpp).
int run(int argc, char** argv) {
  using namespace isopatch;
  CLI::App app{"isopatch: good-quality triangle meshes of smooth implicit surfaces f(x,y,z) = 0"};
  app.set_version_flag("--version", "isopatch " + std::string(kVersion));
  app.require_subcommand(1);
  std::map<std::string, cli::Runner> runners;
  runners["mesh"] = cli::add_mesh_command(app);
  runners["surfaces"] = cli::add_surfaces_command(app);
  runners["render"] = cli::add_render_command(app);
  runners["analyze"] = cli::add_analyze_command(app);
  runners["compare"] = cli::add_compare_command(app);
  runners["view"] = cli::add_view_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (const auto& [name, runner] : runners)
      if (app.got_subcommand(name)) return runner();
    return 2;
  } catch (const Error& e) {
    std::fprintf(stderr, "isopatch: %s\n", cli::describe(e).c_str());
    return cli::exit_code(e.kind());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "isopatch: out of memory\n");
    return cli::exit_code(ErrorKind::Limit);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "isopatch: internal error: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
#if defined(__GLIBC__)
  // Large arrays (the clean-up's per-vertex and per-triangle arrays) straight from the system, so that
  // freeing one returns its pages: glibc otherwise raises this threshold after the first such free and
  // serves later large arrays from its heap, whose freed holes stay resident. A sphere of 1M vertices
  // peaked at 365 MB resident without this and 274 MB with it, in about the same time (docs/algorithms.md,
  // "Memory layout").
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  isopatch::cli::handle_interrupts();
  try {
    return run(argc, argv);
  } catch (...) {  // setting up the commands failed (out of memory): nothing else can throw out of run
    std::fprintf(stderr, "isopatch: internal error while setting up the command line\n");
    return 1;
  }
}
