// The mapping of isopatch::Error to the exception classes of isopatch/_errors.py (errors.hpp).
#include "errors.hpp"

#include <pybind11/pybind11.h>
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>

#include <regex>
#include <string>

namespace py = pybind11;

namespace isopatch::python {

namespace {

const char* class_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Internal:
      return "InternalError";
    case ErrorKind::InvalidArgument:
      return "InputError";
    case ErrorKind::UnknownSurface:
      return "UnknownSurfaceError";
    case ErrorKind::Parse:
      return "ParseError";
    case ErrorKind::Io:
      return "IoError";
    case ErrorKind::Evaluation:
      return "EvaluationError";
    case ErrorKind::NoSurface:
      return "NoSurfaceError";
    case ErrorKind::Limit:
      return "LimitError";
    case ErrorKind::SingularSurface:
      return "SingularSurfaceError";
    case ErrorKind::Crease:
      return "CreaseError";
  }
  return "InternalError";
}

/// A message in Python's words: the command line's flags the library names (`--creases off`, a smaller
/// `--edge-length`, `--edge-length 0.05`, `--grid NAME`) become the keyword arguments of isopatch.mesh
/// (`creases="off"`, `edge_length`, `edge_length=0.05`, `grid=NAME`).
std::string in_python_words(const std::string& message) {
  static const std::regex flag(
      R"((^|[\s(,;])--([a-z][a-z-]*)(?: (off|auto|on|preview|default|fine|[A-Z]+|[0-9][0-9.eE+-]*)\b)?)");
  std::string out;
  std::size_t last = 0;
  for (std::sregex_iterator it(message.begin(), message.end(), flag), end; it != end; ++it) {
    const std::smatch& m = *it;
    out += message.substr(last, static_cast<std::size_t>(m.position(0)) - last);
    std::string name = m[2].str();
    for (char& c : name)
      if (c == '-') c = '_';
    out += m[1].str() + name;
    if (m[3].matched) {
      const std::string value = m[3].str();
      const bool placeholder = value.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ") == std::string::npos;
      const bool number = value.front() >= '0' && value.front() <= '9';
      out += placeholder || number ? "=" + value : "=\"" + value + "\"";
    }
    last = static_cast<std::size_t>(m.position(0) + m.length(0));
  }
  return out + message.substr(last);
}

void raise(const Error& e) {
  const py::module_ errors = py::module_::import("isopatch._errors");
  // An InputError about one setting is a SettingError (a subclass of InputError).
  const bool setting = e.kind() == ErrorKind::InvalidArgument && !e.setting().empty();
  const py::object cls = errors.attr(setting ? "SettingError" : class_name(e.kind()));
  py::object instance;
  if (const auto* parse = dynamic_cast<const ParseError*>(&e))
    instance = cls(e.what(), py::arg("line") = parse->line(), py::arg("column") = parse->column(),
                   py::arg("excerpt") = parse->excerpt());
  else
    instance = cls(in_python_words(e.what()), py::arg("setting") = e.setting());
  // The library's own words, which name the command line's flags, for the command line's front ends.
  instance.attr("command_line_message") = std::string(e.what());
  PyErr_SetObject(cls.ptr(), instance.ptr());
}

}  // namespace

void register_error_translator() {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      raise(e);
    }
  });
}

}  // namespace isopatch::python
