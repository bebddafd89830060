#pragma once
// The recursive-descent parser of the expression language (grammar in include/isopatch/expression.hpp).

#include "expr/dag.hpp"

#include <map>
#include <string>
#include <string_view>

namespace isopatch::expr {

/// Parses `source` into `dag` and returns the node of f. Definitions named in `params` take the
/// parameter's value instead of their own expression.
/// \throw ParseError for a malformed formula, InputError for a parameter that names no definition
NodeId parse(std::string_view source, const std::map<std::string, double>& params, Dag& dag);

}  // namespace isopatch::expr
