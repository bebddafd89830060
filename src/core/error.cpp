// Exit codes of the command-line tool, one per kind of bad input.
#include <isopatch/error.hpp>

namespace isopatch {

int exit_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Internal:
      return 1;
    case ErrorKind::InvalidArgument:
      return 3;
    case ErrorKind::UnknownSurface:
      return 4;
    case ErrorKind::Parse:
      return 5;
    case ErrorKind::Io:
      return 6;
    case ErrorKind::Evaluation:
      return 7;
    case ErrorKind::NoSurface:
      return 8;
    case ErrorKind::Limit:
      return 9;
    case ErrorKind::SingularSurface:
      return 10;
  }
  return 1;
}

}  // namespace isopatch
