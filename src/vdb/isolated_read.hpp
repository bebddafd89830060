#pragma once
// OpenVDB's reading in a child process. OpenVDB 10 trusts the sizes a file declares: a chunk marked
// "uncompressed" of more bytes than its node holds is copied into the node's buffer before the size is
// checked (bloscFromStream, zipFromStream), a heap overflow that a corrupt or hostile .vdb triggers
// (found by fuzz_vdb_reader). The layout pre-scan (vdb_prescan.hpp) cannot see inside a grid's tree, so
// the tree is read by a forked copy of the process: memory it corrupts is its own, and a crash there
// is an IoError here. What it read comes back through a pipe as plain numbers.

#include <functional>
#include <string>

#include "vdb/sparse_samples.hpp"

namespace isopatch::vdb {

/// The processor seconds the child may spend on a file of `file_bytes`: 2 s and 10 s per megabyte
/// (OpenVDB reads tens of megabytes a second; a hostile file of 80 KB kept it busy 35 s).
int reading_seconds(std::size_t file_bytes);

/// Runs `read` (which fills the chosen grid's name) in a child process and returns its samples, and
/// the grid's name in `chosen`. The child may spend `cpu_seconds` (>= 1) of processor time and four
/// times that on the wall clock. An isopatch Error thrown by `read` is thrown here again, of the same
/// kind (InputError with its setting; any other kind as IoError) and message.
/// \throw IoError("<name>: the file is corrupt: OpenVDB failed reading it (...)") when the child dies
///        (a signal, an abort of a sanitizer) or its answer is malformed; IoError("... OpenVDB did not
///        finish reading it in N s ...") past either limit; IoError when no child can be started.
SparseSamples read_in_child(const std::string& name, int cpu_seconds, std::string& chosen,
                            const std::function<SparseSamples(std::string&)>& read);

}  // namespace isopatch::vdb
