#pragma once
/// \file catalogue.hpp
/// The built-in catalogue of benchmark surfaces (docs/algorithms.md 7.4), each defined by a
/// formula in the expression language, with its default box and expected topology.

#include <isopatch/geometry.hpp>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch {

struct CatalogueEntry {
  std::string_view name;
  std::string_view formula;  ///< in the expression language (expression.hpp)
  std::string_view description;
  Box box;             ///< default bounding box
  int genus = 0;       ///< expected genus of each closed component; -1 when open (clipped)
  int components = 1;  ///< expected number of connected components
  bool closed = true;  ///< the surface lies strictly inside its box
  bool smooth = true;  ///< false when f = 0 has singular points (grad f = 0 on the surface)
};

/// All entries, in a fixed order.
std::span<const CatalogueEntry> catalogue();

/// The entry of that name, or nullptr.
const CatalogueEntry* find_in_catalogue(std::string_view name);

/// Catalogue names closest to `name` (edit distance), best first, at most `count`.
std::vector<std::string> closest_catalogue_names(std::string_view name, std::size_t count = 1);

}  // namespace isopatch
