#pragma once
// isopatch errors as Python exceptions: each ErrorKind has its class in isopatch._errors, raised with
// the library's message unchanged (and, for a ParseError, its line and column; for an error about a
// setting, that setting's name).

namespace isopatch::python {

/// Registers the pybind11 exception translator that does the mapping. Called once at import.
void register_error_translator();

}  // namespace isopatch::python
