// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "command.h"

#include <CGAL/PR_star_octree.h>
#include <CGAL/PR_star_octree/IO.h>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <cstring>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <stdexcept>

#include <limits>
#include <memory>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace prstar {

namespace {

using Octree = CGAL::PR_star_octree_3<>;

// The help texts of the common options: the only place they are written.
const char* const help_kv = "bucket threshold k_v of the octree: a positive integer, inf (one leaf), or\n"
                            "auto (chosen from the mesh, the work and the cache; `prstar stats` shows why)";
const char* const help_kv_list = "bucket thresholds k_v of the octree: positive integers, inf (one leaf) or\n"
                                 "auto (chosen from the mesh), comma-separated, one row each";
const std::string help_compact =
    "store the octree's tetrahedra compactly: about 5 bytes each instead of 16, the same results;\n"
    "each leaf decodes its tetrahedra once (see `prstar stats` for the bytes per tetrahedron).\n"
    "Default: compact where the command builds by streaming from a .vtu of 2^25 cells or more\n"
    "(stats, and boundary, curvature and validate with no output), plain elsewhere";
const char* const help_no_compact = "store the plain tetrahedron array (four indices each), never streaming";
const char* const help_coordinates =
    "how the octree stores the coordinates: as the file has them (default: 32-bit floats\n"
    "for a Float32 VTK file, a .meshb of version 1, ...), float32 (12 bytes per vertex,\n"
    "each coordinate rounded to the nearest float) or double; predicates are exact either way";
const std::string help_max_depth =
    "depth bound of the octree, 1 to 64 (default " + std::to_string(Octree::default_max_depth) + ")";
const char* const help_force = "overwrite an existing output file (never the input)";
const char* const help_threads = "number of threads (default: all the cores)";
const char* const help_max_memory =
    "the memory the mesh may need, e.g. 800M, 64G or unlimited (default: the memory\n"
    "available / 1.3); a file announcing a bigger mesh is refused before it is read";
const char* const help_json = "print the result as one JSON object on stdout, and no progress";
const char* const help_quiet = "no progress on stderr";
const char* const help_quiet_summary = "no progress on stderr, and no summary on stdout";
const char* const help_help = "show this help";

bool ends_with(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

bool file_exists(const std::string& f) {
  struct stat st;
  return ::stat(f.c_str(), &st) == 0;
}

// The same name, or two names of one existing file.
bool same_file(const std::string& a, const std::string& b) {
  if (a == b) return true;
  struct stat sa, sb;
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

// One option of the help text: the label in a column, the text after it, its continuation lines
// indented to the same column.
void help_line(std::ostringstream& s, const std::string& label, const std::string& text, std::size_t column) {
  s << "  " << label << std::string(column > label.size() ? column - label.size() : 1, ' ');
  for (char c : text) {
    s << c;
    if (c == '\n') s << std::string(column + 2, ' ');
  }
  s << '\n';
}

// The files a mesh file name stands for: itself, or for TetGen both NAME.node and NAME.ele (the
// companion's extension in the case of the first letter of the given one, as the library's
// reader and writer do).
std::vector<std::string> mesh_files(const std::string& name) {
  const std::size_t dot = name.find_last_of('.'), slash = name.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {name};
  std::string ext = name.substr(dot + 1);
  const bool upper = !ext.empty() && std::isupper(static_cast<unsigned char>(ext[0]));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string base = name.substr(0, dot + 1);
  if (ext == "node") return {name, base + (upper ? "ELE" : "ele")};
  if (ext == "ele") return {base + (upper ? "NODE" : "node"), name};
  return {name};
}

// The files written for the output file name `name`: those of `mesh_files()`, and for XDMF also
// the HDF5 file of its heavy data, NAME.h5 (written unless the XDMF is inline).
std::vector<std::string> written_files(const std::string& name) {
  std::vector<std::string> r = mesh_files(name);
  const auto* format = CGAL::PR_star_octree::IO::find_mesh_format<>(name);
  if (format != nullptr && std::string(format->key) == "xdmf")
    r.push_back(CGAL::PR_star_octree::IO::internal::xdmf_h5_name(name)); // the writer's own rule
  return r;
}

std::string base_name(const std::string& file) {
  const std::size_t slash = file.find_last_of('/');
  return slash == std::string::npos ? file : file.substr(slash + 1);
}

// The temporaries being written (at most two: TetGen's pair), removed by a fatal signal.
char pending_temporary[2][4096];
volatile std::sig_atomic_t pending_temporaries = 0;

extern "C" void remove_temporary_and_reraise(int sig) {
  for (int i = 0; i < pending_temporaries && i < 2; ++i) ::unlink(pending_temporary[i]);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_signal_cleanup() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old;
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue; // e.g. nohup
    struct sigaction a;
    std::memset(&a, 0, sizeof a);
    a.sa_handler = remove_temporary_and_reraise;
    sigemptyset(&a.sa_mask);
    ::sigaction(sig, &a, nullptr);
  }
}

// Throws when `file` is a folder (a missing or unreadable file is reported by the reader, which
// knows what it needs: for TetGen both the .node and the .ele).
void check_readable(const std::string& file) {
  struct stat st;
  if (::stat(file.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw std::runtime_error(file + ": is a directory, not a mesh file");
}

// Throws, with the OS's reason, when `file` cannot be created or replaced: its folder must exist
// and be writable (the output is written to a temporary there and renamed), and `file` must not
// be a folder.
void check_writable(const std::string& file) {
  struct stat st;
  if (::stat(file.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw std::runtime_error(file + ": is a directory, not a file");
  const std::size_t slash = file.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : file.substr(0, slash);
  if (::stat(folder.c_str(), &st) != 0)
    throw std::runtime_error(file + ": cannot write it: the folder " + folder + ": " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode))
    throw std::runtime_error(file + ": cannot write it: " + folder + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(file + ": cannot write it: the folder " + folder + ": " + std::strerror(errno));
}

// `message` with every occurrence of `from` replaced by `to`.
std::string replace_all(std::string message, const std::string& from, const std::string& to) {
  for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
    message.replace(at, from.size(), to);
  return message;
}

} // namespace

Command& Command::description(std::string text) {
  description_ = std::move(text);
  return *this;
}
Command& Command::synopsis(std::string text) {
  synopsis_ = std::move(text);
  return *this;
}
Command& Command::epilog(std::function<std::string()> text) {
  epilog_ = std::move(text);
  return *this;
}
Command& Command::input(std::string name) {
  input_ = std::move(name);
  return *this;
}
Command& Command::output_positional() {
  output_positional_ = true;
  return *this;
}
Command& Command::kv(std::string default_value) {
  has_kv_ = true;
  kv_list_ = false;
  kv_default_ =
      default_value.empty() ? bucket_size_string(Octree::default_bucket_size) : std::move(default_value);
  return *this;
}
Command& Command::kv_list(std::string default_value) {
  kv(std::move(default_value));
  kv_list_ = true;
  return *this;
}
Command& Command::max_depth() {
  has_max_depth_ = true;
  return *this;
}
Command& Command::output(std::string value_name, std::string extension, std::string help, bool required,
                         std::string option) {
  outputs_.push_back(
      {std::move(option), std::move(value_name), std::move(extension), std::move(help), required});
  return *this;
}
Command& Command::json_keys(std::string help) {
  json_keys_ = std::move(help);
  return *this;
}
Command& Command::quiet_silences_summary() {
  quiet_summary_ = true;
  return *this;
}
Command& Command::option(std::string name, std::string value_name, std::string help, bool input_file) {
  specific_.push_back({std::move(name), std::move(value_name), std::move(help), input_file});
  return *this;
}
Command& Command::flag(std::string name, std::string help) {
  specific_.push_back({std::move(name), "", std::move(help), false});
  return *this;
}
Command& Command::check(Check f) {
  check_ = std::move(f);
  return *this;
}
Command& Command::run(Run f) {
  run_ = std::move(f);
  return *this;
}

std::string Command::usage_line() const {
  std::string u = "prstar " + name_;
  if (!input_.empty()) u += " " + input_;
  if (!synopsis_.empty())
    u += " " + synopsis_;
  else
    for (const Declared& d : specific_)
      u += " [" + d.name + (d.value_name.empty() ? "" : " " + d.value_name) + "]";
  if (has_kv_) u += kv_list_ ? " [--kv N|inf|auto[,N...]]" : " [--kv N|inf|auto]";
  if (has_max_depth_) u += " [--max-depth D] [--compact|--no-compact] [--coordinates input|float32|double]";
  if (!input_.empty()) u += " [--threads N] [--max-memory SIZE]";
  for (const Output_decl& o : outputs_) {
    if (o.option.empty() && output_positional_) continue; // in the synopsis
    const std::string s = (o.option.empty() ? "-o" : o.option) + " " + o.value_name;
    u += o.required ? " " + s : " [" + s + "]";
  }
  if (!outputs_.empty()) u += " [--force]";
  return u + " [--json] [--quiet]";
}

std::string Command::help() const {
  std::vector<std::pair<std::string, std::string>> lines;
  for (const Declared& d : specific_)
    lines.push_back({d.name + (d.value_name.empty() ? "" : " " + d.value_name), d.help});
  if (has_kv_)
    lines.push_back({kv_list_ ? "--kv N|inf|auto[,N...]" : "--kv N|inf|auto",
                     (kv_list_ ? help_kv_list : help_kv) + std::string("\n(default ") + kv_default_ + ")"});
  if (has_max_depth_) {
    lines.push_back({"--max-depth D", help_max_depth});
    lines.push_back({"--compact", help_compact});
    lines.push_back({"--no-compact", help_no_compact});
    lines.push_back({"--coordinates input|float32|double", help_coordinates});
  }
  if (!input_.empty()) {
    lines.push_back({"--threads N", help_threads});
    lines.push_back({"--max-memory SIZE", help_max_memory});
  }
  for (const Output_decl& o : outputs_)
    lines.push_back({(o.option.empty() ? "-o, --output" : o.option) + " " + o.value_name,
                     o.help + (o.extension.empty()
                                   ? std::string(" (") + CGAL::PR_star_octree::IO::writable_extensions() + ")"
                                   : std::string())});
  if (!outputs_.empty()) lines.push_back({"--force", help_force});
  lines.push_back({"--json", help_json + (json_keys_.empty() ? "" : "\n" + json_keys_)});
  lines.push_back({"--quiet", quiet_summary_ ? help_quiet_summary : help_quiet});
  lines.push_back({"-h, --help", help_help});
  std::size_t column = 0;
  for (const auto& l : lines) column = std::max(column, l.first.size() + 2);

  std::ostringstream s;
  s << "usage: " << usage_line() << "\n\n";
  if (!description_.empty()) s << description_ << "\n\n";
  s << "options:\n";
  for (const auto& l : lines) help_line(s, l.first, l.second, column);
  if (epilog_) s << epilog_();
  return s.str();
}

Options Command::parse(int argc, char** argv, int first, bool distributed) const {
  std::vector<std::string> flags{"--json", "--quiet"}, values;
  if (!outputs_.empty()) flags.push_back("--force");
  for (const Declared& d : specific_) (d.value_name.empty() ? flags : values).push_back(d.name);
  if (has_kv_) values.push_back("--kv");
  if (has_max_depth_) {
    values.push_back("--max-depth");
    flags.push_back("--compact");
    flags.push_back("--no-compact");
    values.push_back("--coordinates");
  }
  if (!input_.empty()) {
    values.push_back("--threads");
    values.push_back("--max-memory");
  }
  for (const Output_decl& o : outputs_) {
    if (o.option.empty()) {
      values.push_back("-o");
      values.push_back("--output");
    } else
      values.push_back(o.option);
  }
  Options o(Arguments(argc, argv, first, flags, values));
  const Arguments& args = o.args_;

  const std::vector<std::string>& positional = args.positional();
  if (!input_.empty()) {
    if (positional.empty()) throw Usage_error("missing " + input_);
    if (positional.size() > (output_positional_ ? 2u : 1u))
      throw Usage_error("unexpected argument '" + positional.back() + "'");
    o.input_ = positional[0];
  } else if (!positional.empty())
    throw Usage_error("unexpected argument '" + positional[0] + "'");
  o.json_ = args.flag("--json");
  o.quiet_ = args.flag("--quiet");
  o.force_ = args.flag("--force");
  o.quiet_silences_summary_ = quiet_summary_;

  o.kvs_ = {Octree::default_bucket_size};
  if (has_kv_) {
    o.kvs_ = parse_bucket_list(args.get("--kv", kv_default_));
    if (!kv_list_ && o.kvs_.size() != 1) throw Usage_error("--kv takes one value here");
  }
  if (args.has("--threads")) {
    const double n = args.get_double("--threads", 0);
    if (n < 1 || n > 4096 || n != std::floor(n)) throw Usage_error("--threads must be a positive integer");
    o.threads_ = static_cast<std::size_t>(n);
  }
  if (args.has("--max-memory")) o.max_memory_ = parse_memory_size(args.get("--max-memory"));
  o.max_depth_ = Octree::default_max_depth;
  if (has_max_depth_) {
    const double depth = args.get_double("--max-depth", double(Octree::default_max_depth));
    if (depth < 1 || depth > 64 || depth != std::floor(depth))
      throw Usage_error("--max-depth must be in 1..64");
    o.max_depth_ = static_cast<std::size_t>(depth);
    if (args.flag("--compact") && args.flag("--no-compact"))
      throw Usage_error("--compact and --no-compact cannot both be given");
    if (args.flag("--compact")) o.compact_ = Options::Compact::yes;
    if (args.flag("--no-compact")) o.compact_ = Options::Compact::no;
    if (args.has("--coordinates")) {
      const std::string c = args.get("--coordinates");
      using CGAL::PR_star_octree::Coordinate_precision;
      if (c == "input")
        o.precision_ = Coordinate_precision::as_input;
      else if (c == "float32")
        o.precision_ = Coordinate_precision::float32;
      else if (c == "double")
        o.precision_ = Coordinate_precision::point_3;
      else
        throw Usage_error("--coordinates must be input, float32 or double, not '" + c + "'");
    }
  }

  // Output files: the format, never an input, never twice the same file.
  std::vector<std::string> inputs;
  if (!o.input_.empty()) inputs.push_back(o.input_);
  for (const Declared& d : specific_)
    if (d.input_file && args.has(d.name)) inputs.push_back(args.get(d.name));
  for (const Output_decl& d : outputs_) {
    std::string value;
    const std::string label = d.option.empty() ? "-o" : d.option;
    if (d.option.empty()) {
      const bool second = output_positional_ && positional.size() == 2;
      if (int(args.has("-o")) + int(args.has("--output")) + int(second) > 1)
        throw Usage_error("give the output once");
      value = second ? positional[1] : args.has("-o") ? args.get("-o") : args.get("--output");
    } else
      value = args.get(d.option);
    if (value.empty()) {
      if (d.required)
        throw Usage_error("missing " + (d.option.empty() && output_positional_ ? d.value_name
                                                                               : label + " " + d.value_name));
      continue;
    }
    if (distributed && d.option.empty() && ends_with(value, ".pvtu")) {
      // one piece per rank
    } else if (d.extension.empty()) {
      if (!CGAL::PR_star_octree::IO::is_writable_extension(value))
        throw Usage_error(value + ": cannot write this format (writable: " +
                          CGAL::PR_star_octree::IO::writable_extensions() + ")");
    } else {
      // a comma-separated list of accepted extensions
      bool accepted = false;
      std::string list;
      for (std::size_t start = 0; start <= d.extension.size();) {
        const std::size_t comma = std::min(d.extension.find(',', start), d.extension.size());
        const std::string e = d.extension.substr(start, comma - start);
        accepted = accepted || ends_with(value, e);
        list += (list.empty() ? "" : comma == d.extension.size() ? " or " : ", ") + e;
        start = comma + 1;
      }
      if (!accepted) throw Usage_error(value + ": the output must be a " + list + " file");
    }
    for (const std::string& in : inputs)
      for (const std::string& a : mesh_files(in))
        for (const std::string& b : written_files(value))
          if (same_file(a, b)) throw Usage_error("the output " + value + " would overwrite the input");
    for (const auto& earlier : o.outputs_)
      if (same_file(value, earlier.second))
        throw Usage_error((earlier.first.empty() ? "-o" : earlier.first) + " and " + label +
                          " name the same file");
    o.outputs_.push_back({d.option, value});
  }

  if (check_) check_(o);

  // Before any work: the input can be read, the outputs can be written (the OS's reason if not).
  if (!o.input_.empty()) check_readable(o.input_);
  for (const auto& out : o.outputs_)
    for (const std::string& f : written_files(out.second)) {
      if (!o.force_ && file_exists(f))
        throw std::runtime_error(f + ": the file exists (use --force to overwrite it)");
      check_writable(f);
    }
  return o;
}

std::string Options::output(const std::string& option) const {
  for (const auto& o : outputs_)
    if (o.first == option) return o.second;
  return "";
}

void write_text_file(const std::string& out, const std::function<void(std::ostream&)>& body) {
  write_through_temporary(out, [&](const std::string& tmp) {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error(out + ": cannot open the file for writing: " + std::strerror(errno));
    body(f);
    f.flush();
    if (!f) throw std::runtime_error(out + ": cannot write the output file: " + std::strerror(errno));
  });
}

std::size_t find_point_field(const std::vector<CGAL::PR_star_octree::Point_data_array>& pd, std::string& name,
                             const std::string& input) {
  const auto it = name.empty()
                      ? pd.begin()
                      : std::find_if(pd.begin(), pd.end(), [&](const auto& a) { return a.name == name; });
  if (it == pd.end()) {
    std::string known;
    for (const auto& d : pd) known += (known.empty() ? "" : ", ") + d.name;
    throw std::runtime_error(input + ": " +
                             (name.empty() ? std::string("the mesh has no point data")
                                           : "no point-data array named '" + name + "'") +
                             (known.empty() ? "" : " (it has: " + known + ")") +
                             "; use --field x|y|z for a coordinate");
  }
  name = it->name;
  for (std::size_t v = 0; v < it->values.size(); ++v)
    if (!std::isfinite(it->values[v]))
      throw std::runtime_error(input + ": field '" + name + "' is not finite at vertex " + std::to_string(v));
  return static_cast<std::size_t>(it - pd.begin());
}

std::string point_data_outputs() {
  std::string r;
  for (const auto& f : CGAL::PR_star_octree::IO::mesh_formats<>)
    if (f.point_data_kept == CGAL::PR_star_octree::IO::Point_data_kept::all_arrays)
      for (const char* e : f.extensions)
        if (e != nullptr) r += (r.empty() ? "." : ",.") + std::string(e);
  return r;
}

std::string mesh_formats() {
  std::string r = "Mesh files, read and written, by extension:\n";
  for (const auto& f : CGAL::PR_star_octree::IO::mesh_formats<>) {
    std::string e = std::string(".") + f.extensions[0];
    if (f.extensions[1] != nullptr) e += std::string("/.") + f.extensions[1];
    r += "  " + e + std::string(e.size() < 12 ? 12 - e.size() : 1, ' ') + f.name + "\n";
  }
  return r;
}

std::vector<std::size_t> parse_bucket_list(const std::string& s) {
  std::vector<std::size_t> r;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    r.push_back(parse_bucket_size(s.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return r;
}

Json& json_kv(Json& j, std::size_t kv) {
  if (kv == Octree::infinite_bucket_size) return j.value("inf");
  if (kv == Octree::automatic_bucket_size) return j.value("auto");
  return j.value(kv);
}

Json& json_kv(Json& j, const Options& o) {
  return json_kv(j, o.used_kv()).field("kv_automatic", o.used_kv_automatic());
}

std::string Options::kv_label() const {
  if (used_kv() == Octree::automatic_bucket_size) return "auto"; // (chosen by each rank's octree)
  return bucket_size_string(used_kv()) + (used_kv_automatic_ ? " (auto)" : "");
}

Command& Command::run_distributed(Run f) {
  run_distributed_ = std::move(f);
  return *this;
}

namespace {
// --threads, in force while the returned object lives
std::shared_ptr<void> thread_limit(const Options& options) {
#ifdef CGAL_LINKED_WITH_TBB
  if (options.threads() > 0)
    return std::make_shared<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                 options.threads());
#else
  (void)options;
#endif
  return nullptr;
}
} // namespace

int Command::execute_distributed(const Options& options) const {
  const auto threads = thread_limit(options);
  return run_distributed_(options);
}

namespace {
// A --max-memory value a quarter above `needed`, in MiB or GiB.
std::string memory_suggestion(std::size_t needed) {
  const double want = 1.25 * double(needed);
  if (want < double(std::size_t(1) << 30))
    return std::to_string(static_cast<std::size_t>(std::ceil(want / double(1 << 20)))) + "M";
  return std::to_string(static_cast<std::size_t>(std::ceil(want / double(std::size_t(1) << 30)))) + "G";
}
} // namespace

int Command::execute(const Options& options) const {
  const auto threads = thread_limit(options);
  // A mesh is refused before it is read when it cannot fit: the limit leaves room for the octree
  // built on it (about a quarter more when it is built in place).
  const std::size_t available = CGAL::PR_star_octree::IO::Memory_limit::available();
  const std::size_t limit = options.max_memory() != 0 ? options.max_memory()
                            : available == CGAL::PR_star_octree::IO::Memory_limit::unlimited
                                ? available
                                : static_cast<std::size_t>(double(available) / 1.3);
  const CGAL::PR_star_octree::IO::Memory_limit memory(limit);
  try {
    return run_(options);
  } catch (const CGAL::PR_star_octree::IO::Memory_limit_error& e) {
    throw std::runtime_error(std::string(e.what()) +
                             (options.max_memory() != 0 ? " (the limit of --max-memory)"
                                                        : " (the limit: the memory available / 1.3)") +
                             "; to try anyway, raise the limit with --max-memory SIZE " +
                             "(e.g. --max-memory " + memory_suggestion(e.needed()) + ", or unlimited)");
  }
}

std::size_t parse_memory_size(const std::string& s) {
  if (s == "unlimited") return CGAL::PR_star_octree::IO::Memory_limit::unlimited;
  std::size_t digits = 0;
  while (digits < s.size() && std::isdigit(static_cast<unsigned char>(s[digits]))) ++digits;
  const std::string suffix = s.substr(digits);
  int shift = -1;
  if (suffix.empty() || suffix == "B")
    shift = 0;
  else if (suffix == "K" || suffix == "KB" || suffix == "KiB")
    shift = 10;
  else if (suffix == "M" || suffix == "MB" || suffix == "MiB")
    shift = 20;
  else if (suffix == "G" || suffix == "GB" || suffix == "GiB")
    shift = 30;
  else if (suffix == "T" || suffix == "TB" || suffix == "TiB")
    shift = 40;
  if (digits == 0 || digits > 12 || shift < 0)
    throw Usage_error("--max-memory: '" + s + "' is not a size (e.g. 800M, 64G, 2T or unlimited)");
  const unsigned long long n = std::stoull(s.substr(0, digits));
  if (n == 0) throw Usage_error("--max-memory must be positive");
  if (n > ((std::numeric_limits<std::size_t>::max)() >> shift))
    return CGAL::PR_star_octree::IO::Memory_limit::unlimited;
  return static_cast<std::size_t>(n) << shift;
}

Mesh read_mesh(const std::string& file, Progress_bar& progress) {
  struct stat st;
  const bool sized = ::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode);
  progress.phase("reading " + file + (sized ? " (" + human_bytes(double(st.st_size)) + ")" : ""));
  Mesh mesh;
  CGAL::PR_star_octree::IO::read_tetrahedral_mesh(file, mesh);
  progress.finish();
  if (!mesh.skipped_cells.empty()) { // what the file has beyond tetrahedra is not lost silently
    std::string what;
    for (const auto& c : mesh.skipped_cells)
      what += (what.empty() ? "" : ", ") + std::to_string(c.second) + " " + c.first +
              (c.second == 1 ? "" : "(s)");
    std::cerr << "prstar: " << file << ": note: " << mesh.tetrahedra.size()
              << " tetrahedra kept; skipped the other cells: " << what << '\n';
  }
  return mesh;
}

std::optional<CGAL::PR_star_octree::IO::Vtu_tetrahedron_source> streaming_source(const Options& o,
                                                                                 const std::string& input) {
  std::optional<CGAL::PR_star_octree::IO::Vtu_tetrahedron_source> source;
  if (o.compact_choice() == Options::Compact::no ||
      CGAL::PR_star_octree::IO::internal::lower_extension(input) != "vtu")
    return source;
  try {
    source.emplace(input);
  } catch (const std::exception&) {
    if (o.compact_choice() == Options::Compact::yes) throw;
  }
  if (source && (!source->supported() || !o.stream(source->number_of_cells()))) source.reset();
  return source;
}

void write_through_temporary(const std::string& out, const std::function<void(const std::string&)>& write) {
  const std::size_t dot = out.find_last_of('.');
  const std::size_t slash = out.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string mark = ".prstar-tmp-" + std::to_string(::getpid());
  const std::string tmp = has_ext ? out.substr(0, dot) + mark + out.substr(dot) : out + mark;
  // What the writer makes: OUT, or for TetGen OUT.node and OUT.ele (and their temporaries).
  // An XDMF file's .h5 is a third companion (its name in the .xdmf is set right before the rename).
  const std::vector<std::string> tmps = written_files(tmp), outs = written_files(out);
  install_signal_cleanup();
  pending_temporaries = 0;
  for (std::size_t i = 0; i < tmps.size() && i < 2; ++i) {
    if (tmps[i].size() >= sizeof pending_temporary[i]) break;
    std::memcpy(pending_temporary[i], tmps[i].c_str(), tmps[i].size() + 1);
    pending_temporaries = static_cast<std::sig_atomic_t>(i + 1);
  }
  auto clean = [&] {
    pending_temporaries = 0;
    for (const std::string& t : tmps) std::remove(t.c_str());
  };
  try {
    write(tmp);
    if (tmps.size() == 2 && outs[1].size() > 3 && outs[1].compare(outs[1].size() - 3, 3, ".h5") == 0 &&
        file_exists(tmps[1])) {
      // the .xdmf names its heavy data file: the final name, not the temporary's
      std::ifstream in(tmp, std::ios::binary);
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      in.close();
      text = replace_all(text, base_name(tmps[1]) + ":", base_name(outs[1]) + ":");
      std::ofstream o(tmp, std::ios::binary | std::ios::trunc);
      o << text;
      o.close();
      if (!o) throw std::runtime_error(out + ": cannot write the output file: " + std::strerror(errno));
    }
    for (std::size_t i = 0; i < tmps.size(); ++i)
      if (!(i >= mesh_files(tmp).size() && !file_exists(tmps[i])) && // an inline XDMF has no .h5
          std::rename(tmps[i].c_str(), outs[i].c_str()) != 0)
        throw std::runtime_error(outs[i] + ": cannot write the output file: " + std::strerror(errno));
  } catch (const std::bad_alloc&) {
    clean();
    throw;
  } catch (const std::exception& e) {
    clean();
    // The user knows the output by its name, not by the temporary's.
    std::string message = e.what();
    for (std::size_t i = 0; i < tmps.size(); ++i) message = replace_all(message, tmps[i], outs[i]);
    throw std::runtime_error(message);
  } catch (...) {
    clean();
    throw;
  }
  pending_temporaries = 0;
}

void write_mesh_file(const std::string& out, const Mesh& mesh) {
  write_through_temporary(
      out, [&](const std::string& tmp) { CGAL::PR_star_octree::IO::write_tetrahedral_mesh(tmp, mesh); });
}

} // namespace prstar
