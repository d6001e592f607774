// The GoogleTest main of volgraph's test binaries: GoogleTest's own, plus a deadline on
// every case. ctest runs a binary's cases in groups (tests/gtest_groups.cmake), one process
// each, so that the Vulkan or Dawn start-up is paid once a group; a case that runs past
// its deadline is a hang: the process prints the case's name and exits at once, so a hang
// fails fast and names itself (the group's ctest TIMEOUT is only the backstop).
//
//   --case-seconds=N   the deadline of each case (default 120; 0: none). ctest passes it.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace {

// A watchdog thread that ends the process when a case has run longer than its deadline.
class CaseDeadline : public ::testing::EmptyTestEventListener {
 public:
  explicit CaseDeadline(int seconds) : seconds_(seconds), watchdog_([this] { watch(); }) {}
  ~CaseDeadline() override {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    watchdog_.join();
  }

  void OnTestStart(const ::testing::TestInfo& info) override {
    std::lock_guard lock(mutex_);
    running_ = std::string(info.test_suite_name()) + "." + info.name();
    deadline_ = std::chrono::steady_clock::now() + std::chrono::seconds(seconds_);
    changed_.notify_all();
  }
  void OnTestEnd(const ::testing::TestInfo&) override {
    std::lock_guard lock(mutex_);
    running_.clear();
    changed_.notify_all();
  }

 private:
  void watch() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
      if (running_.empty()) {
        changed_.wait(lock);
        continue;
      }
      const std::string running = running_;
      if (changed_.wait_until(lock, deadline_) == std::cv_status::timeout && running_ == running &&
          std::chrono::steady_clock::now() >= deadline_) {
        std::fprintf(stderr, "\n[  TIMEOUT ] %s ran past its deadline of %d s (--case-seconds): a hang\n", running.c_str(), seconds_);
        std::fflush(stderr);
        std::_Exit(1);
      }
    }
  }

  const int seconds_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::string running_;
  std::chrono::steady_clock::time_point deadline_;
  bool stopping_ = false;
  std::thread watchdog_;  // last: started once the members it reads exist
};

// Takes --case-seconds=N out of argv; the default when absent.
int take_case_seconds(int& argc, char** argv, int fallback) {
  constexpr const char* kFlag = "--case-seconds=";
  int seconds = fallback;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], kFlag, std::strlen(kFlag)) == 0) {
      seconds = std::atoi(argv[i] + std::strlen(kFlag));
      continue;
    }
    argv[kept++] = argv[i];
  }
  argc = kept;
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  const int seconds = take_case_seconds(argc, argv, 120);
  ::testing::InitGoogleTest(&argc, argv);
  if (seconds > 0) ::testing::UnitTest::GetInstance()->listeners().Append(new CaseDeadline(seconds));
  return RUN_ALL_TESTS();
}
