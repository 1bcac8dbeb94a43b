// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project
//
// The test harness shared by every test program of test/PR_star_octree: checks that count and
// report failures (with both values for comparisons), skips for optional inputs, the data folders
// given on the command line, and the summary line with the exit code.
//
//   CHECK(cond)                       the condition holds
//   CHECK_MSG(cond, a << b)           the same, with a streamed explanation printed on failure
//   CHECK_EQUAL(actual, expected)     actual == expected; prints both values on failure
//   CHECK_NEAR(actual, expected, t)   |actual - expected| <= t (NaN fails)
//   CHECK_CLOSE(actual, expected, r)  |actual - expected| <= r max(|actual|, |expected|) (NaN fails)
//   CHECK_THROWS(E, text, statement)  the statement throws an E whose what() contains `text`
//   FAIL(a << b)                      an unconditional failure with a message
//   prstar_test::skip(what)           an optional part of the test did not run (e.g. a missing file)
//   prstar_test::Failure_context c(s) names `s` after any failure reported while `c` is alive
//   return prstar_test::summary("test_name");   at the end of main: the exit code
//
// A program that ran no check at all fails: a test whose loops never ran is not a pass.
// Every counter lives in inline functions, so several translation units of one test program share
// them.

#ifndef PRSTAR_TEST_HARNESS_H
#define PRSTAR_TEST_HARNESS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

#include <sys/stat.h>

namespace prstar_test {

struct Counters {
  long long checks = 0;
  long long failures = 0;
  long long skips = 0;
};

inline Counters& counters() {
  static Counters c;
  return c;
}

/// The number of failures so far (to detect failures in a block, see `Failure_context`).
inline long long failures() {
  return counters().failures;
}
inline long long checks() {
  return counters().checks;
}

/// Failure messages printed in full (100, or $PRSTAR_TEST_MAX_PRINTED); later failures are only
/// counted.
inline long long max_printed_failures() {
  static const long long n = [] {
    const char* e = std::getenv("PRSTAR_TEST_MAX_PRINTED");
    return e ? std::atoll(e) : 100LL;
  }();
  return n;
}

inline void record_check() {
  ++counters().checks;
}

inline void record_failure(const char* file, int line, const std::string& message) {
  const long long n = ++counters().failures;
  if (n <= max_printed_failures())
    std::cerr << file << ":" << line << ": CHECK failed: " << message << std::endl;
  else if (n == max_printed_failures() + 1)
    std::cerr << "(further failures are counted, not printed)" << std::endl;
}

/// An optional part of a test did not run; printed and counted, never a failure.
inline void skip(const std::string& what) {
  ++counters().skips;
  std::cout << "SKIPPED: " << what << std::endl;
}

/// While alive, names `what` after the failures reported in its scope (printed once, when it dies).
class Failure_context {
public:
  explicit Failure_context(std::string what) : what_(std::move(what)), before_(failures()) {}
  ~Failure_context() {
    if (failures() != before_) std::cerr << "  ... while checking " << what_ << std::endl;
  }
  Failure_context(const Failure_context&) = delete;
  Failure_context& operator=(const Failure_context&) = delete;

private:
  std::string what_;
  long long before_;
};

namespace detail {

template <class T, class = void>
struct is_streamable : std::false_type {};
template <class T>
struct is_streamable<T, std::void_t<decltype(std::declval<std::ostream&>() << std::declval<const T&>())>>
    : std::true_type {};

template <class T, class = void>
struct is_range : std::false_type {};
template <class T>
struct is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>())),
                               decltype(std::end(std::declval<const T&>()))>> : std::true_type {};

template <class T, class = void>
struct is_pair : std::false_type {};
template <class T>
struct is_pair<
    T, std::void_t<decltype(std::declval<const T&>().first), decltype(std::declval<const T&>().second)>>
    : std::true_type {};

template <class T>
void print(std::ostream& os, const T& v);

template <class T>
void print_value(std::ostream& os, const T& v) {
  if constexpr (std::is_same_v<T, bool>)
    os << (v ? "true" : "false");
  else if constexpr (std::is_enum_v<T>)
    os << static_cast<long long>(v);
  else if constexpr (std::is_floating_point_v<T>)
    os << std::setprecision(17) << v;
  else if constexpr (std::is_same_v<T, char> || std::is_same_v<T, signed char> ||
                     std::is_same_v<T, unsigned char>)
    os << static_cast<int>(v);
  else if constexpr (is_streamable<T>::value)
    os << v;
  else if constexpr (is_pair<T>::value) {
    os << "(";
    print(os, v.first);
    os << ", ";
    print(os, v.second);
    os << ")";
  } else if constexpr (is_range<T>::value) {
    std::size_t n = 0;
    os << "[";
    for (const auto& x : v) {
      if (n < 16) {
        if (n) os << ", ";
        print(os, x);
      }
      ++n;
    }
    if (n > 16) os << ", ...";
    os << "] (" << n << " elements)";
  } else
    os << "<value>";
}

template <class T>
void print(std::ostream& os, const T& v) {
  print_value(os, v);
}

template <class T>
std::string to_string(const T& v) {
  std::ostringstream os;
  print(os, v);
  return os.str();
}

// a == b, also between integers of different signedness (a negative value equals no unsigned one).
template <class A, class B>
bool equal_values(const A& a, const B& b) {
  if constexpr (std::is_integral_v<A> && std::is_integral_v<B> && !std::is_same_v<A, bool> &&
                !std::is_same_v<B, bool> && std::is_signed_v<A> != std::is_signed_v<B>) {
    if constexpr (std::is_signed_v<A>)
      return a >= 0 && static_cast<std::make_unsigned_t<A>>(a) == b;
    else
      return b >= 0 && a == static_cast<std::make_unsigned_t<B>>(b);
  } else
    return a == b;
}

template <class A, class B>
void check_equal(const A& a, const B& b, const char* ta, const char* tb, const char* file, int line) {
  record_check();
  if (equal_values(a, b)) return;
  record_failure(file, line,
                 std::string(ta) + " == " + tb + "\n    actual:   " + to_string(a) +
                     "\n    expected: " + to_string(b));
}

inline void check_near(double a, double b, double tolerance, const char* ta, const char* tb, const char* file,
                       int line) {
  record_check();
  if (std::abs(a - b) <= tolerance) return; // false for NaN
  std::ostringstream os;
  os << std::setprecision(17) << ta << " ~ " << tb << " (absolute tolerance " << tolerance
     << ")\n    actual:   " << a << "\n    expected: " << b << "\n    difference: " << a - b;
  record_failure(file, line, os.str());
}

inline void check_close(double a, double b, double relative, const char* ta, const char* tb, const char* file,
                        int line) {
  record_check();
  if (std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b))) return; // false for NaN
  std::ostringstream os;
  os << std::setprecision(17) << ta << " ~ " << tb << " (relative tolerance " << relative
     << ")\n    actual:   " << a << "\n    expected: " << b << "\n    difference: " << a - b;
  record_failure(file, line, os.str());
}

} // namespace detail

/// The folders given on the command line of every test program: argv[1] the generated inputs (made
/// by the `generate_test_inputs` fixture: a missing one is a failure), argv[2] the optional shared
/// real meshes (absent on most machines: their checks are skipped).
struct Data_folders {
  std::string generated, shared;

  Data_folders(int argc, char** argv) : generated(argc > 1 ? argv[1] : ""), shared(argc > 2 ? argv[2] : "") {}

  static bool exists(const std::string& path) {
    struct stat st;
    return !path.empty() && ::stat(path.c_str(), &st) == 0;
  }
  bool has_shared() const { return exists(shared); }

  /// The path of a generated input; a failure when it is missing.
  std::optional<std::string> generated_file(const std::string& name) const {
    const std::string path = generated + "/" + name;
    record_check();
    if (generated.empty() || !exists(path)) {
      record_failure(__FILE__, __LINE__, "missing generated input " + path);
      return std::nullopt;
    }
    return path;
  }

  /// The path of a shared real mesh, or nothing (and a skip) when it is absent.
  std::optional<std::string> shared_file(const std::string& name) const {
    if (!has_shared()) return std::nullopt; // reported once by `report_shared()`
    const std::string path = shared + "/" + name;
    if (!exists(path)) {
      skip("shared mesh " + path + " absent");
      return std::nullopt;
    }
    return path;
  }

  /// Prints (once per program) that the real-mesh checks are skipped when the folder is absent.
  bool report_shared() const {
    if (has_shared()) return true;
    skip("shared data folder '" + shared + "' absent: real-mesh checks");
    return false;
  }
};

/// Prints the summary line and returns the exit code: 0 when checks ran and none failed.
inline int summary(const std::string& program) {
  const Counters& c = counters();
  std::cout << program << ": " << c.checks << " checks, " << c.failures << " failures, " << c.skips
            << " skipped" << std::endl;
  if (c.checks == 0) {
    std::cerr << program << ": no check ran" << std::endl;
    return 1;
  }
  return c.failures == 0 ? 0 : 1;
}

} // namespace prstar_test

#define CHECK(cond)                                                                                          \
  do {                                                                                                       \
    ::prstar_test::record_check();                                                                           \
    if (!(cond)) ::prstar_test::record_failure(__FILE__, __LINE__, #cond);                                   \
  } while (0)

#define CHECK_MSG(cond, message)                                                                             \
  do {                                                                                                       \
    ::prstar_test::record_check();                                                                           \
    if (!(cond)) {                                                                                           \
      std::ostringstream prstar_test_os_;                                                                    \
      prstar_test_os_ << #cond << ": " << message;                                                           \
      ::prstar_test::record_failure(__FILE__, __LINE__, prstar_test_os_.str());                              \
    }                                                                                                        \
  } while (0)

#define FAIL(message)                                                                                        \
  do {                                                                                                       \
    ::prstar_test::record_check();                                                                           \
    std::ostringstream prstar_test_os_;                                                                      \
    prstar_test_os_ << message;                                                                              \
    ::prstar_test::record_failure(__FILE__, __LINE__, prstar_test_os_.str());                                \
  } while (0)

#define CHECK_EQUAL(actual, expected)                                                                        \
  ::prstar_test::detail::check_equal((actual), (expected), #actual, #expected, __FILE__, __LINE__)

#define CHECK_NEAR(actual, expected, tolerance)                                                              \
  ::prstar_test::detail::check_near((actual), (expected), (tolerance), #actual, #expected, __FILE__, __LINE__)

#define CHECK_CLOSE(actual, expected, relative)                                                              \
  ::prstar_test::detail::check_close((actual), (expected), (relative), #actual, #expected, __FILE__, __LINE__)

#define CHECK_THROWS(Exception, text, ...)                                                                   \
  do {                                                                                                       \
    ::prstar_test::record_check();                                                                           \
    try {                                                                                                    \
      __VA_ARGS__;                                                                                           \
      ::prstar_test::record_failure(__FILE__, __LINE__, "no " #Exception " from: " #__VA_ARGS__);            \
    } catch (const Exception& prstar_test_e_) {                                                              \
      if (std::string(prstar_test_e_.what()).find(text) == std::string::npos)                                \
        ::prstar_test::record_failure(__FILE__, __LINE__,                                                    \
                                      std::string("message '") + prstar_test_e_.what() + "' lacks '" +       \
                                          (text) + "'");                                                     \
    }                                                                                                        \
  } while (0)

#endif // PRSTAR_TEST_HARNESS_H
