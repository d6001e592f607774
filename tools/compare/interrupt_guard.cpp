#include "tools/compare/interrupt_guard.h"

#include <pthread.h>

#include <cstdio>
#include <cstdlib>
#include <utility>

namespace volgraph::compare {

InterruptGuard::InterruptGuard(std::string message) : message_(std::move(message)) {
  sigemptyset(&signals_);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals_, signal);
  pthread_sigmask(SIG_BLOCK, &signals_, &before_);
  watcher_ = std::thread([this] {
    int signal = 0;
    sigwait(&signals_, &signal);
    if (done_) return;  // the guard's own wake-up at its end
    const std::lock_guard<std::mutex> lock(writes_);
    std::fprintf(stderr, "\nvolgraph: interrupted; %s\n", message_.c_str());
    std::_Exit(128 + signal);
  });
}

InterruptGuard::~InterruptGuard() {
  done_ = true;
  pthread_kill(watcher_.native_handle(), SIGTERM);  // wakes its sigwait
  watcher_.join();
  pthread_sigmask(SIG_SETMASK, &before_, nullptr);
}

}  // namespace volgraph::compare
