#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a command: the temporary files of writes in progress are removed
// (a file the command was replacing stays as it was), one line says what stopped it, and the process
// ends by the signal, so that the shell sees 130 or 143.

namespace isopatch::cli {

/// Installs the handlers (sigaction). The viewer, which waits for these signals itself (sigwait), blocks
/// them in every thread before they can arrive, so the handlers never run there.
void handle_interrupts();

}  // namespace isopatch::cli
