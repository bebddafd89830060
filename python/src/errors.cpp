// The mapping of isopatch::Error to the exception classes of isopatch/_errors.py (errors.hpp).
#include "errors.hpp"

#include <pybind11/pybind11.h>
#include <isopatch/error.hpp>
#include <isopatch/expression.hpp>

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
    instance = cls(e.what(), py::arg("setting") = e.setting());
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
