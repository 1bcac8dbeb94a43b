// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one place where the prstar commands declare, parse, check and document their options, and
// where the rules every command shares live: exit statuses, the options common to several
// commands (--kv, --max-depth, -o/--output, --force, --json, --quiet, --help) with one meaning
// and one help text, and the output-file rules (never the input, an existing file only with
// --force, written through a temporary renamed at the end).

#ifndef PRSTAR_COMMAND_H
#define PRSTAR_COMMAND_H

#include "cli.h"
#include "progress.h"

#include <CGAL/PR_star_octree/IO/vtu_source.h>
#include <CGAL/PR_star_octree/Indexed_tetrahedral_mesh.h>
#include <CGAL/PR_star_octree/parameters.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace prstar {

/// The exit status of every command.
enum Exit_status : int {
  exit_success = 0,            ///< done (validate: the mesh is valid)
  exit_error = 1,              ///< an error: unreadable or malformed file, bad input, cannot write
  exit_usage = 2,              ///< a usage error: unknown option, missing or invalid argument
  exit_invalid_mesh = 3,       ///< validate only: the mesh was checked and is not valid
  exit_target_not_reached = 4, ///< simplify only: stopped before the target (the mesh reached is written)
};

using Mesh = CGAL::PR_star_octree::Indexed_tetrahedral_mesh<>;

class Options;

/// A command: its name, what it does, its options, and the function that runs it.
///
/// The common options are declared with the dedicated members, which fix their names, value
/// syntax, checks and help text; command-specific options with `option()` and `flag()`.  The
/// usage line and the option list of `--help` are generated from the declarations.
class Command {
public:
  using Run = std::function<int(const Options&)>;
  using Check = std::function<void(const Options&)>;

  Command(std::string name, std::string summary) : name_(std::move(name)), summary_(std::move(summary)) {}

  /// The paragraph of `--help` between the usage line and the options.
  Command& description(std::string text);
  /// The command-specific part of the usage line (default: generated from `option()` and
  /// `flag()`), e.g. "(--target F | --max-length L)".
  Command& synopsis(std::string text);
  /// Text printed after the option list by `--help`.
  Command& epilog(std::function<std::string()> text);

  /// One positional argument, a mesh file that is read and never overwritten.
  Command& input(std::string name = "MESH");
  /// The -o/--output file may also be given as a second positional argument (`convert IN OUT`).
  Command& output_positional();
  /// --kv: one bucket threshold (default: the library's default k_v).
  Command& kv(std::string default_value = "");
  /// --kv: a comma-separated list of bucket thresholds (default: the library's default k_v).
  Command& kv_list(std::string default_value = "");
  /// --max-depth: the depth bound of the octree, --compact: the compact tetrahedron array, and
  /// --coordinates: the precision of the stored coordinates.
  Command& max_depth();
  /// -o/--output (`option` empty) or another output option (e.g. "--csv"): a file written by
  /// the command.  `extension` is the one allowed extension (".vtu"), or empty for every mesh
  /// format the library writes.  Declaring an output declares --force.
  Command& output(std::string value_name, std::string extension, std::string help, bool required = false,
                  std::string option = "");
  /// The key list (or other detail) added to the help text of --json.
  Command& json_keys(std::string help);
  /// --quiet also silences the summary on stdout (commands whose result is a file).
  Command& quiet_silences_summary();
  /// A command-specific option with a value; `input_file`: it names a file that is read, which
  /// no output may overwrite.
  Command& option(std::string name, std::string value_name, std::string help, bool input_file = false);
  /// A command-specific flag.
  Command& flag(std::string name, std::string help);
  /// Command-specific checks of the parsed options, run after the common ones and before the
  /// output files are checked for existence; they throw `Usage_error`.
  Command& check(Check f);
  /// The function that runs the command; it returns an `Exit_status`.
  Command& run(Run f);
  /// The function that runs the command under mpirun (several ranks): the same options, and `-o`
  /// also takes a `.pvtu` (one piece per rank).  Without one, the command is not distributed.
  Command& run_distributed(Run f);
  bool is_distributed() const { return static_cast<bool>(run_distributed_); }

  const std::string& name() const { return name_; }
  const std::string& summary() const { return summary_; }
  std::string help() const;
  /// Parses `argv[first..argc)`, checks the options and the output files.
  /// \throws Usage_error (exit status 2) or std::runtime_error (an existing output without --force)
  /// `distributed`: parsed for `execute_distributed()` (-o also takes `.pvtu`).
  Options parse(int argc, char** argv, int first, bool distributed = false) const;
  /// Runs the command with the common settings of `options` in force (--threads, --max-memory).
  int execute(const Options& options) const;
  /// Runs the distributed form of the command (every rank calls it), --threads in force.
  int execute_distributed(const Options& options) const;

private:
  struct Declared {
    std::string name, value_name, help; // value_name empty: a flag
    bool input_file;
  };
  struct Output_decl {
    std::string option, value_name, extension, help;
    bool required;
  };
  friend class Options;
  std::string usage_line() const;

  std::string name_, summary_, description_, synopsis_;
  std::function<std::string()> epilog_;
  std::string input_;
  bool has_kv_ = false, kv_list_ = false, has_max_depth_ = false, quiet_summary_ = false;
  bool output_positional_ = false;
  std::string kv_default_, json_keys_;
  std::vector<Output_decl> outputs_;
  std::vector<Declared> specific_;
  Check check_;
  Run run_, run_distributed_;
};

/// The parsed and checked options of a command.
class Options {
public:
  /// The input mesh file (commands with `Command::input()`).
  const std::string& input() const { return input_; }
  /// The bucket threshold (a single --kv) and all of them (a list).
  std::size_t kv() const { return kvs_.front(); }
  const std::vector<std::size_t>& kvs() const { return kvs_; }
  std::size_t max_depth() const { return max_depth_; }
  /// The k_v the octree used, told by the command once the octree is built (`--kv auto`, the
  /// default, lets the octree choose): `kv_label()` and `json_kv()` report it.
  void set_used_kv(std::size_t kv, bool automatic) const {
    used_kv_ = kv;
    used_kv_automatic_ = automatic;
  }
  template <class Octree>
  void set_used_kv(const Octree& tree) const {
    set_used_kv(tree.bucket_size(), tree.has_automatic_bucket_size());
  }
  /// The k_v used, for people: "2048 (auto)", "50", "inf", or "auto" before the octree is built.
  std::string kv_label() const;
  std::size_t used_kv() const { return used_kv_ ? used_kv_ : kv(); }
  bool used_kv_automatic() const { return used_kv_automatic_; }
  /// --compact / --no-compact / neither: the octree's tetrahedra compact (named parameter
  /// `compact_tetrahedra`), plain, or chosen by the command (the default)
  enum class Compact { automatic, yes, no };
  Compact compact_choice() const { return compact_; }
  /// The tetrahedra stored compactly by a construction in place: only when --compact is given (in
  /// place, the peak is the construction's whatever the storage, and the plain array is faster).
  bool compact() const { return compact_ == Compact::yes; }
  /// The number of cells from which a command that can build by streaming (the compact array,
  /// never the plain one whole) does so by default: at 50M tetrahedra the streaming build took
  /// 0.6x the memory in 0.9-1.2x the time, at 3M 1.4x the time (results/compact.md).
  static constexpr std::uint64_t streaming_cells = std::uint64_t(1) << 25;
  /// Whether a command that can build by streaming from a file of `cells` cells should.
  bool stream(std::uint64_t cells) const {
    return compact_ == Compact::yes || (compact_ == Compact::automatic && cells >= streaming_cells);
  }
  /// --coordinates: how the octree stores the coordinates (named parameter `coordinate_precision`)
  CGAL::PR_star_octree::Coordinate_precision coordinate_precision() const { return precision_; }
  /// An output file, empty when not given: `output()` is -o/--output, `output("--csv")` another.
  std::string output(const std::string& option = "") const;
  bool force() const { return force_; }
  /// --threads: the number of threads (0: all the machine has)
  std::size_t threads() const { return threads_; }
  /// --max-memory: the memory a mesh read may need, in bytes (0: the default)
  std::size_t max_memory() const { return max_memory_; }
  bool json() const { return json_; }
  bool quiet() const { return quiet_; }
  /// Progress on stderr is wanted (the bar also needs a terminal): neither --quiet nor --json.
  bool show_progress() const { return !quiet_ && !json_; }
  /// A summary on stdout is wanted (--quiet silences it for commands whose result is a file).
  bool show_summary() const { return !(quiet_ && quiet_silences_summary_); }

  /// Command-specific options.
  bool flag(const std::string& name) const { return args_.flag(name); }
  bool has(const std::string& name) const { return args_.has(name); }
  std::string get(const std::string& name, const std::string& fallback = "") const {
    return args_.get(name, fallback);
  }
  double get_double(const std::string& name, double fallback) const {
    return args_.get_double(name, fallback);
  }
  /// A fraction given as a number or a percentage: "0.3" or "30%".
  double get_fraction(const std::string& name, double fallback) const {
    return args_.get_fraction(name, fallback);
  }

private:
  friend class Command;
  explicit Options(Arguments args) : args_(std::move(args)) {}
  Arguments args_;
  std::string input_;
  std::vector<std::size_t> kvs_;
  std::size_t max_depth_ = 0, threads_ = 0, max_memory_ = 0;
  std::vector<std::pair<std::string, std::string>> outputs_;
  bool force_ = false, json_ = false, quiet_ = false, quiet_silences_summary_ = false;
  Compact compact_ = Compact::automatic;
  CGAL::PR_star_octree::Coordinate_precision precision_ =
      CGAL::PR_star_octree::Coordinate_precision::as_input;
  mutable std::size_t used_kv_ = 0;
  mutable bool used_kv_automatic_ = false;
};

/// The point-data array of `point_data` named `name` (the first one when `name` is empty), as a
/// position in `point_data`; `name` is set to the array's name.  Errors name `input`: no such array
/// (with the arrays it has and the hint `--field x|y|z`), or a value that is not finite (its vertex).
std::size_t find_point_field(const std::vector<CGAL::PR_star_octree::Point_data_array>& point_data,
                             std::string& name, const std::string& input);

/// The mesh formats read and written, for the help texts.
std::string mesh_formats();
/// Parses a size in bytes: "1500000000", "800M", "64G", "2T" (powers of 1024), or "unlimited".
std::size_t parse_memory_size(const std::string& s);
/// Parses "N|inf|auto[,N|inf|auto...]".
std::vector<std::size_t> parse_bucket_list(const std::string& s);
/// k_v as a JSON value: a number, or the string "inf" (or "auto" before the octree chose).
Json& json_kv(Json& j, std::size_t kv);
/// The k_v the octree used as a JSON value, followed by the field `kv_automatic` (whether it chose).
Json& json_kv(Json& j, const Options& o);

/// Reads the mesh file `file` (any format the library reads), with a progress line.
Mesh read_mesh(const std::string& file, Progress_bar& progress);

/// For a command that writes no mesh: the source its streaming construction reads the tetrahedra
/// of `input` from (several passes, never holding the plain tetrahedron array), when it should
/// build so (`Options::stream()`: --compact, or by default 2^25 cells or more) and `input` is a
/// .vtu readable by ranges; empty otherwise, and the whole file is read by `read_mesh()` (with its
/// messages).  With --compact, a .vtu whose header cannot be read is an error here.
std::optional<CGAL::PR_star_octree::IO::Vtu_tetrahedron_source> streaming_source(const Options& o,
                                                                                 const std::string& input);

/// Writes `out` through a temporary file in the same folder, renamed to `out` at the end: an error
/// (or an interruption by SIGINT, SIGTERM, SIGHUP) never leaves a half-written `out` or the
/// temporary behind, and an existing `out` stays untouched until the new one is complete.
/// `write(tmp)` writes the temporary, whose name keeps the extension of `out` (it selects the
/// format): OUT.mesh -> OUT.prstar-tmp-PID.mesh.  A TetGen name OUT.node or OUT.ele stands for
/// both files, written and renamed together (and both checked by `Command::parse()`).
void write_through_temporary(const std::string& out, const std::function<void(const std::string&)>& write);
/// `write_through_temporary` of a text file: `body` writes to the stream; errors name `out` with the
/// OS reason.
void write_text_file(const std::string& out, const std::function<void(std::ostream&)>& body);
/// `write_through_temporary` with the library's writer chosen by the extension of `out`.
void write_mesh_file(const std::string& out, const Mesh& mesh);
/// The output extensions that keep every point array (from the library's format table): VTK XML and
/// legacy (named arrays), TetGen (node attributes, unnamed); comma-separated, as `Command::output` takes
/// them.
std::string point_data_outputs();

} // namespace prstar

#endif // PRSTAR_COMMAND_H
