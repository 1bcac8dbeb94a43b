// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Small command-line helpers of the prstar tool: argument parsing, JSON and table output.

#ifndef PRSTAR_CLI_H
#define PRSTAR_CLI_H

#include <CGAL/PR_star_octree/bucket_size.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace prstar {

/// A usage error: reported with the subcommand's usage line, exit code 2.
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A number as the shortest text that reads back to the same double (`std::to_chars`): 0.04022809499999999
/// prints as "0.040228095" when that is the same double; "nan", "inf", "-inf" for the others.
inline std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// For people (tables): a number that is exactly a float32 (coordinates of a float32 file) as the
/// shortest text of that float ("0.99999976" rather than "0.9999997615814209"), others as `number()`.
inline std::string short_number(double v) {
  const float f = static_cast<float>(v);
  if (!std::isfinite(v) || static_cast<double>(f) != v) return number(v);
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, f);
  return std::string(buf, r.ptr);
}

/// The edit distance of two option or command names (insertions, deletions, substitutions and
/// swaps of two neighbours each count one).
inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

/// " (did you mean X?)" for the name of `candidates` closest to `given` (a typo: at most 2 edits, or
/// a prefix of one name only), or "".
inline std::string did_you_mean(const std::string& given, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = 3, prefixed = 0;
  std::string prefix_of;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(given, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
    if (given.size() >= 3 && c.compare(0, given.size(), given) == 0) {
      ++prefixed;
      prefix_of = c;
    }
  }
  if (best.empty() && prefixed == 1) best = prefix_of;
  return best.empty() ? "" : " (did you mean " + best + "?)";
}

/// Parses `--name value`, `--name=value`, `-o value`, flags and positional arguments.
class Arguments {
public:
  /// `flags`: options without a value; `options`: options with a value (names with dashes).
  Arguments(int argc, char** argv, int first, const std::vector<std::string>& flags,
            const std::vector<std::string>& options) {
    for (int i = first; i < argc; ++i) {
      std::string a = argv[i];
      if (a.size() > 1 && a[0] == '-' && !is_number(a)) {
        std::string value;
        bool has_value = false;
        const std::size_t eq = a.find('=');
        if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
          value = a.substr(eq + 1);
          a = a.substr(0, eq);
          has_value = true;
        }
        if (contains(flags, a)) {
          if (has_value) throw Usage_error("option " + a + " takes no value");
          flags_.push_back(a);
        } else if (contains(options, a)) {
          if (!has_value) {
            if (i + 1 >= argc) throw Usage_error("option " + a + " needs a value");
            value = argv[++i];
          }
          if (values_.count(a)) throw Usage_error("option " + a + " given twice");
          values_[a] = value;
        } else {
          std::vector<std::string> known = flags;
          known.insert(known.end(), options.begin(), options.end());
          throw Usage_error("unknown option " + a + did_you_mean(a, known));
        }
      } else
        positional_.push_back(a);
    }
  }

  bool flag(const std::string& name) const { return contains(flags_, name); }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
  }
  double get_double(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    double d = 0;
    if (!parse_finite(get(name), d))
      throw Usage_error("option " + name + ": '" + get(name) + "' is not a number");
    return d;
  }
  /// A fraction in [0, 1] given as a number ("0.3") or a percentage ("30%").
  double get_fraction(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    std::string s = get(name);
    const bool percent = !s.empty() && s.back() == '%';
    if (percent) s.pop_back();
    double d = 0;
    if (!parse_finite(s, d))
      throw Usage_error("option " + name + ": '" + get(name) + "' is not a fraction (e.g. 0.3 or 30%)");
    return percent ? d / 100 : d;
  }
  const std::vector<std::string>& positional() const { return positional_; }

private:
  static bool contains(const std::vector<std::string>& v, const std::string& s) {
    for (const std::string& x : v)
      if (x == s) return true;
    return false;
  }
  // `s` is a finite number and nothing else
  static bool parse_finite(const std::string& s, double& d) {
    std::size_t used = 0;
    try {
      d = std::stod(s, &used);
    } catch (...) {
      return false;
    }
    return !s.empty() && used == s.size() && std::isfinite(d);
  }
  static bool is_number(const std::string& s) {
    return s.size() > 1 && (std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.');
  }
  std::vector<std::string> flags_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
};

/// Parses a bucket threshold: a positive integer, `inf` or `auto` (the octree chooses).
inline std::size_t parse_bucket_size(const std::string& s) {
  if (s == "inf" || s == "infinity" || s == "Inf") return (std::numeric_limits<std::size_t>::max)();
  if (s == "auto") return CGAL::PR_star_octree::automatic_bucket_size;
  std::size_t used = 0;
  unsigned long long v = 0;
  try {
    if (!s.empty() && s[0] != '-') v = std::stoull(s, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != s.size() || v == 0)
    throw Usage_error("--kv: '" + s + "' is not a positive integer, 'inf' or 'auto'");
  return static_cast<std::size_t>(v);
}

inline std::string bucket_size_string(std::size_t kv) {
  if (kv == CGAL::PR_star_octree::automatic_bucket_size) return "auto";
  return kv == (std::numeric_limits<std::size_t>::max)() ? "inf" : std::to_string(kv);
}

/// A minimal JSON writer (objects, arrays, numbers, strings), enough for stable machine output.
class Json {
public:
  Json& begin_object() { return open('{'); }
  Json& end_object() { return close('}'); }
  Json& begin_array() { return open('['); }
  Json& end_array() { return close(']'); }
  Json& key(const std::string& k) {
    comma();
    out_ << quote(k) << ": ";
    after_key_ = true;
    return *this;
  }
  template <class T>
  Json& value(const T& v) {
    comma();
    if constexpr (std::is_same<T, bool>::value)
      out_ << (v ? "true" : "false");
    else if constexpr (std::is_floating_point<T>::value) {
      if (std::isfinite(v))
        out_ << number(static_cast<double>(v));
      else
        out_ << "null";
    } else if constexpr (std::is_arithmetic<T>::value)
      out_ << v;
    else
      out_ << quote(std::string(v));
    return *this;
  }
  Json& null() {
    comma();
    out_ << "null";
    return *this;
  }
  template <class T>
  Json& field(const std::string& k, const T& v) {
    key(k);
    return value(v);
  }
  std::string str() const { return out_.str(); }

private:
  Json& open(char c) {
    comma();
    out_ << c;
    first_.push_back(true);
    return *this;
  }
  Json& close(char c) {
    first_.pop_back();
    out_ << c;
    return *this;
  }
  void comma() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (!first_.empty()) {
      if (!first_.back()) out_ << ", ";
      first_.back() = false;
    }
  }
  static std::string quote(const std::string& s) {
    std::string r = "\"";
    for (char c : s) {
      switch (c) {
      case '"':
        r += "\\\"";
        break;
      case '\\':
        r += "\\\\";
        break;
      case '\n':
        r += "\\n";
        break;
      case '\t':
        r += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          r += buf;
        } else
          r += c;
      }
    }
    return r + "\"";
  }
  std::ostringstream out_;
  std::vector<bool> first_;
  bool after_key_ = false;
};

/// A plain-text table with right-aligned numeric columns.
class Table {
public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  /// Column `i` aligned to the left (text), not to the right (numbers); the first one always is.
  Table& align_left(std::size_t i) {
    left_.resize(std::max(left_.size(), i + 1), false);
    left_[i] = true;
    return *this;
  }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  std::string str() const {
    std::vector<std::size_t> w(header_.size(), 0);
    for (std::size_t i = 0; i < header_.size(); ++i) w[i] = header_[i].size();
    for (const auto& r : rows_)
      for (std::size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
    std::ostringstream s;
    auto line = [&](const std::vector<std::string>& r) {
      for (std::size_t i = 0; i < w.size(); ++i) {
        const std::string c = i < r.size() ? r[i] : "";
        const bool left = i == 0 || (i < left_.size() && left_[i]);
        s << (i ? "  " : "") << (left ? std::left : std::right) << std::setw(static_cast<int>(w[i])) << c;
      }
      s << '\n';
    };
    line(header_);
    std::size_t total = 0;
    for (std::size_t x : w) total += x;
    s << std::string(total + 2 * (w.size() - 1), '-') << '\n';
    for (const auto& r : rows_) line(r);
    return s.str();
  }

private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<bool> left_;
};

inline std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

/// Human-readable byte count.
inline std::string human_bytes(double b) {
  const char* unit[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (b >= 1024 && u < 4) {
    b /= 1024;
    ++u;
  }
  return fixed(b, u == 0 ? 0 : 1) + " " + unit[u];
}

} // namespace prstar

#endif // PRSTAR_CLI_H
