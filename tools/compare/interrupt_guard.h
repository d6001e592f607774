// Ctrl-C (SIGINT), SIGTERM and SIGHUP during `sweep`, `tune` or `ab`: the process ends at
// once, except while files are being written (a sweep point's file and the aggregates, an
// A/B report) — then as soon as they are renamed into place — so an interrupted sweep
// leaves every finished point saved, the aggregates matching them, and no temporary file.
//
// The signals are blocked in the thread that makes the guard and in every thread started
// after it (they inherit the mask: make the guard before the device, whose driver starts
// threads); one watcher thread waits for them (sigwait), takes `writes()` and ends the
// process with 128 + the signal's number, as the shell reports a killed command.
#pragma once

#include <atomic>
#include <csignal>
#include <mutex>
#include <string>
#include <thread>

namespace volgraph::compare {

class InterruptGuard {
 public:
  // `message`: what an interrupt leaves, printed before the exit (a sweep's saved points
  // are not an A/B report's).
  explicit InterruptGuard(std::string message = "every finished point is saved (the same command resumes)");
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Held while files are written; the watcher waits for it before ending the process.
  std::mutex& writes() { return writes_; }

 private:
  sigset_t signals_{}, before_{};
  std::mutex writes_;
  std::string message_;
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

}  // namespace volgraph::compare
