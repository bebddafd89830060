// `isopatch surfaces`: the built-in catalogue with boxes, topology and formulas.
#include <isopatch/catalogue.hpp>

#include <cstdio>
#include <string>

#include "commands.hpp"

namespace isopatch::cli {

Runner add_surfaces_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("surfaces", "List the built-in surfaces with their formulas and boxes");
  (void)cmd;
  return [] {
    for (const CatalogueEntry& e : catalogue()) {
      const std::string topology = e.closed ? "genus " + std::to_string(e.genus) : "open";
      std::printf("%-13s %-9s box %s\n", std::string(e.name).c_str(), topology.c_str(),
                  format_box(e.box).c_str());
      std::printf("              %s%s\n", std::string(e.description).c_str(),
                  e.smooth ? "" : " (not smooth)");
      std::string formula(e.formula);
      for (char& c : formula)
        if (c == '\n') c = ' ';
      std::printf("              f = %s\n\n", formula.c_str());
    }
    return 0;
  };
}

}  // namespace isopatch::cli
