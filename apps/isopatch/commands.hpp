#pragma once
// The subcommands of the isopatch tool. Each registers its options on the CLI11 app and returns the
// function that runs it (after parsing) and yields the process exit code.

#include <CLI/CLI.hpp>

#include <functional>

namespace isopatch::cli {

using Runner = std::function<int()>;

/// `isopatch mesh SURFACE -o OUT ...`: mesh a surface and write the mesh.
Runner add_mesh_command(CLI::App& app);
/// `isopatch analyze MESH [--surface S]`: quality and accuracy metrics of a mesh.
Runner add_analyze_command(CLI::App& app);
/// `isopatch render MESH -o OUT.png ...`: draw a mesh (shaded, wireframe, curvature, ...) into a PNG.
Runner add_render_command(CLI::App& app);
/// `isopatch surfaces`: list the built-in catalogue.
Runner add_surfaces_command(CLI::App& app);
/// `isopatch view [MESH | SURFACE] [--port N]`: the live viewer in the browser (loopback only).
Runner add_view_command(CLI::App& app);
/// `isopatch compare SURFACE`: the meshers side by side at matched vertex counts.
Runner add_compare_command(CLI::App& app);

}  // namespace isopatch::cli
