// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace prstar {

namespace {

// Columns of the terminal on stderr (80 when unknown).
std::size_t terminal_width() {
  struct winsize w;
  if (::ioctl(2, TIOCGWINSZ, &w) == 0 && w.ws_col >= 20) return w.ws_col;
  return 80;
}

// `s` cut to at most `n` characters, "..." marking the cut.
std::string fit(const std::string& s, std::size_t n) {
  if (s.size() <= n) return s;
  if (n <= 3) return s.substr(0, n);
  return s.substr(0, n - 3) + "...";
}

} // namespace

std::string clock_string(double seconds) {
  if (!(seconds >= 0)) seconds = 0;
  const unsigned long long s = static_cast<unsigned long long>(seconds);
  char buf[48];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%llu:%02llu:%02llu", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%llu:%02llu", s / 60, s % 60);
  return buf;
}

Progress_bar::Progress_bar(bool wanted) : enabled_(wanted && ::isatty(2)) {}

Progress_bar::~Progress_bar() {
  // Reached with a phase still open only when an exception ends the command: the line is
  // cleared, not reported as done (the error message follows on stderr).
  if (!active_) return;
  active_ = false;
  if (!enabled_) return;
  stop_thread();
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}

void Progress_bar::phase(const std::string& name) {
  finish();
  name_ = name;
  start_ = std::chrono::steady_clock::now();
  done_.store(0);
  total_.store(0);
  spin_ = 0;
  active_ = true;
  if (!enabled_) return;
  draw(false);
  stop_ = false;
  thread_ = std::thread([this] { tick(); });
}

void Progress_bar::finish() {
  if (!active_) return;
  active_ = false;
  if (!enabled_) return;
  stop_thread();
  draw(true);
}

double Progress_bar::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress_bar::stop_thread() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Progress_bar::tick() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) draw(false);
}

void Progress_bar::draw(bool final_line) {
  const double t = seconds();
  const std::size_t width = terminal_width() - 1; // never the last column: no wrapping
  std::string line;
  if (final_line) {
    // A phase with a known total ends as a full bar, the others as "... done".
    char buf[64];
    if (total_.load(std::memory_order_relaxed) == 0) {
      std::snprintf(buf, sizeof buf, " ... done (%.2f s)", t);
      line = fit(name_, width > std::strlen(buf) ? width - std::strlen(buf) : 0) + buf;
    } else {
      std::snprintf(buf, sizeof buf, "] 100%%  done (%.2f s)", t);
      const std::size_t fixed_part = 3 + std::strlen(buf);
      std::size_t bar = width > fixed_part + name_.size() ? width - fixed_part - name_.size() : 0;
      bar = std::max<std::size_t>(10, std::min<std::size_t>(20, bar));
      const std::size_t room = width > fixed_part + bar ? width - fixed_part - bar : 0;
      line = fit(name_, room) + "  [" + std::string(bar, '#') + buf;
    }
  } else {
    const std::size_t total = total_.load(std::memory_order_relaxed);
    const std::size_t done = std::min(done_.load(std::memory_order_relaxed), total);
    if (total == 0) {
      static const char spinner[] = "|/-\\";
      const std::string tail = std::string("  ") + spinner[spin_++ % 4] + "  " + clock_string(t) + " elapsed";
      line = fit(name_, width > tail.size() ? width - tail.size() : 0) + tail;
    } else {
      const double f = double(done) / double(total);
      char percent[16];
      std::snprintf(percent, sizeof percent, "%4d%%", static_cast<int>(std::floor(100 * f)));
      std::string times = "  " + clock_string(t) + " elapsed";
      if (done > 0 && done < total)
        times += ", " + clock_string(t * double(total - done) / double(done)) + " left";
      // name + "  [" + bar + "] " + percent + times, the bar between 10 and 40 columns
      const std::size_t fixed_part = 4 + 5 + times.size();
      std::size_t bar = width > fixed_part + name_.size() ? width - fixed_part - name_.size() : 0;
      bar = std::max<std::size_t>(10, std::min<std::size_t>(40, bar));
      const std::size_t name_room = width > fixed_part + bar ? width - fixed_part - bar : 0;
      const std::size_t filled = static_cast<std::size_t>(f * double(bar));
      line = fit(name_, name_room) + "  [" + std::string(filled, '#') + std::string(bar - filled, '.') + "]" +
             percent + times;
    }
  }
  std::fprintf(stderr, "\r\033[K%s%s", line.c_str(), final_line ? "\n" : "");
  std::fflush(stderr);
}

} // namespace prstar
