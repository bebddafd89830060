// Handlers of SIGINT and SIGTERM, see interrupts.hpp.
#include "interrupts.hpp"

#include <isopatch/mesh_io.hpp>

#include <csignal>
#include <cstring>

#include <unistd.h>

namespace isopatch::cli {
namespace {

/// Only async-signal-safe calls: unlink (remove_unfinished_files), write, signal, raise.
void on_interrupt(int signal_number) {
  remove_unfinished_files();
  const char* message = signal_number == SIGINT
                            ? "\nisopatch: interrupted (SIGINT); no file left half-written\n"
                            : "\nisopatch: stopped (SIGTERM); no file left half-written\n";
  const ssize_t ignored = ::write(STDERR_FILENO, message, std::strlen(message));
  static_cast<void>(ignored);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace

void handle_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace isopatch::cli
