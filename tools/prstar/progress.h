// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The progress bar of the prstar tool, on stderr, only when stderr is a terminal.

#ifndef PRSTAR_PROGRESS_H
#define PRSTAR_PROGRESS_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace prstar {

/// One line on stderr per long step ("phase"), redrawn in place with `\r` at most ten times a
/// second by a background thread:
///
///     reading torus.mesh (12.1 MiB)  |  0:02 elapsed                        (no fraction known)
///     classifying the vertices  [#######.......]  45%  0:03 elapsed, 0:04 left
///
/// and ended by a newline after `name ... done (3.51 s)` (no fraction known) or
/// `name  [####################] 100%  done (3.51 s)`.  `update()` (and the function returned by
/// `callback()`, meant for `CGAL::PR_star_octree::parameters::progress()`) only stores two atomic
/// counters, so it may be called after every leaf and from any thread.  Nothing is drawn, and no
/// thread is started, when the bar is disabled: `wanted` false (--quiet, --json) or stderr not a
/// terminal.
class Progress_bar {
public:
  explicit Progress_bar(bool wanted);
  ~Progress_bar();
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  bool enabled() const { return enabled_; }

  /// Ends the current phase (if any) and starts a new one, shown as a spinner with the elapsed
  /// time until `update()` gives a fraction.
  void phase(const std::string& name);
  /// `done` of `total` units of the current phase are done (leaves, bytes...).
  /// Calls from several threads (the library's parallel leaves) may arrive out of order: the bar
  /// keeps the largest `done`.
  void update(std::size_t done, std::size_t total) {
    total_.store(total, std::memory_order_relaxed);
    std::size_t seen = done_.load(std::memory_order_relaxed);
    while (seen < done && !done_.compare_exchange_weak(seen, done, std::memory_order_relaxed)) {
    }
  }
  /// A copyable `f(done, total)` that calls `update()`; valid while this bar lives.
  std::function<void(std::size_t, std::size_t)> callback() {
    return [this](std::size_t done, std::size_t total) { update(done, total); };
  }
  /// Ends the current phase: `name ... done (seconds)` and a newline.
  void finish();
  /// Seconds since the start of the current (or last) phase.
  double seconds() const;

private:
  void stop_thread();
  void draw(bool final_line);
  void tick();

  const bool enabled_;
  bool active_ = false;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
  std::atomic<std::size_t> done_{0}, total_{0};
  unsigned spin_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

/// `m:ss`, or `h:mm:ss` from one hour on.
std::string clock_string(double seconds);

} // namespace prstar

#endif // PRSTAR_PROGRESS_H
