#pragma once
// Long library calls from Python: run without the GIL, stoppable by Ctrl-C.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace isopatch::python {

/// Runs `work(cancel)` on a worker thread while the calling thread, without the GIL, waits for it and
/// every 50 ms takes the GIL back to run Python's signal handlers (PyErr_CheckSignals). When one raises
/// (Ctrl-C: KeyboardInterrupt), `*cancel` becomes true, the library stops at its next check, and once
/// the worker has ended that Python exception is raised (whatever the worker ended with). Otherwise
/// returns what `work` returned or rethrows what it threw. Other Python threads run meanwhile; `work`
/// must take the GIL (pybind11::gil_scoped_acquire) around any call into Python.
template <class Work>
auto run_released(Work&& work) -> decltype(work(static_cast<const std::atomic<bool>*>(nullptr))) {
  using Result = decltype(work(static_cast<const std::atomic<bool>*>(nullptr)));
  std::atomic<bool> cancel{false};
  std::optional<Result> result;
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  std::thread worker([&] {
    try {
      result.emplace(work(&cancel));
    } catch (...) {
      error = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_all();
  });
  {
    const pybind11::gil_scoped_release release;
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
      finished.wait_for(lock, std::chrono::milliseconds(50));
      if (done || interrupted) continue;
      lock.unlock();
      {
        const pybind11::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) {
          interrupted = true;  // the Python error stays set on this thread until we raise it below
          cancel.store(true);
        }
      }
      lock.lock();
    }
  }
  worker.join();
  if (interrupted) throw pybind11::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace isopatch::python
