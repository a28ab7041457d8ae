// What the CLI and the explorer share: exit statuses, error types, and the inputs every command
// reads first (a preset, --set overrides and --method).
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/sweep.hpp"
#include "core/io/preset.hpp"

namespace foldlab::app {

// A registered command: run() is called after parsing when its subcommand was given, and returns
// the exit status.
using Command = std::function<int()>;

// Exit statuses of every command (the contract scripts rely on).
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitInvalidInput = 2;

// Bad input from the user: the message goes to stderr and the exit status is kExitInvalidInput.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The environment cannot do what was asked (no display, no EGL): exit kExitInternal, the message
// printed as it is.
class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct InputOptions {
  std::string preset_path;  // empty: the built-in default preset
  std::vector<std::string> assignments;
  std::string method;  // empty: the preset's
  std::string law;     // empty: the preset's law and constants
  // A link's inputs as KEY=VALUE (`gui --link`, core/io/link.hpp), applied after the law's
  // constants and before `assignments`.
  std::vector<std::string> link{};
  // The page's reading of its own address: a piece of the link that cannot be applied at all (an
  // unknown key, a value that is no number) is left out and said in StartInputs::link_notes
  // rather than stopping the start, since whoever opened a shared link has no command line to
  // correct. A command line's link stays strict.
  bool forgiving_link = false;
  // How messages name the option `assignments` came from, and whose inputs are refused, for a
  // second fabric beside the first (picture compare's B: "--b-set", "B's "), so that a refusal
  // never points at the first fabric's --set.
  std::string set_option = "--set";
  std::string whose{};
};

// The preset with the overrides applied and validated. Throws InputError listing every problem.
Preset resolve_inputs(const InputOptions& options);

// What the explorer starts from. A link may carry a value the model refuses (the page's address
// follows what the user typed, refused or not): it opens as a typed one shows, kept with its
// reason, rather than not at all.
struct StartInputs {
  Preset preset;  // with every override, or, when the link's values are refused, without them
  std::optional<Parameters> refused;  // then: every override, as the explorer's edits
  // The preset with every override but the link's: what a link's fabric is an edit of, so that
  // it does not pass for the preset itself. `preset` when there is no link, or when the link's
  // values are what makes the fabric valid.
  Preset origin;
  // With forgiving_link, each piece of the link left out, as a sentence that says what is shown
  // instead: "t = 'abc' is not a number, so t is the preset's 0.25 mm".
  std::vector<std::string> link_notes;
  // The file --preset meant (preset_file(); empty: the built-in default) and its inputs as read,
  // before any override: what a report names as edited.
  std::string preset_file;
  Parameters loaded;
};
// resolve_inputs, except that values the model refuses only with the link's are kept in
// `refused`. A key or value that cannot be applied at all is an InputError as for --set.
StartInputs resolve_start_inputs(const InputOptions& options);

// A sweep's axis as `foldlab sweep` and `picture sweep` take it, --from and --to as typed.
struct SweepAxisText {
  std::string key;
  std::string from;
  std::string to;
  int steps = 50;
  bool log = false;
  bool linear = false;
};
// The axis with its ends read as --set reads a value of the swept input (w from 100gsm, L from
// 1.4m; a bare number is in the input's unit) and checked by check_axis, a refused end that was a
// bare number with --set's hint. Throws InputError.
SweepAxis read_sweep_axis(const SweepAxisText& text);

// resolve_inputs with all the start knows (the file, the preset as read). With `axis` (`foldlab
// sweep`, `picture sweep`), the inputs are judged at the swept values, not at the preset's value
// of the swept input, which the sweep replaces (d = 800 mm is refused at the preset's L = 1400 mm,
// not when L runs from 1000 to 3000 mm): InputError, naming the first value and why, when no value
// of the range is valid; when the preset's own value is refused with the others, the preset holds
// the first valid one.
StartInputs resolve_inputs_in_full(const InputOptions& options, const SweepAxis* axis = nullptr);

// resolve_inputs for a report: the preset's name followed, when the overrides changed inputs, by
// those inputs as solved, "Default: ..., h = 1400 mm ... (edited: h = 5 mm)", since a preset's name
// may state values it no longer has.
Preset resolve_named_inputs(const InputOptions& options);

// A file named on the command line by the option that names it.
struct NamedPath {
  std::string_view option;
  std::string path;  // as typed; empty: not given
  // The file `path` opens when that is not `path` itself: a preset given by name (preset_input).
  std::string file{};
};

// --preset (or --b-preset) as an input of check_outputs: the file a preset name resolves to, so
// that `--preset myfab` and `--save-preset presets/myfab.json` are seen as one file. Throws
// InputError as resolving the inputs would when no file or preset has that name.
NamedPath preset_input(std::string_view option, const std::string& given);

// The checks every command makes on the files it will write, before any work: each output's
// folder exists, is a folder and can be written to (a picture must not render for seconds first),
// and no output is another output or one of the inputs. Outputs are compared with the files the
// inputs resolve to (device and inode, links followed); an output that does not exist yet cannot
// be an input. Throws InputError naming both options.
void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// Throws InputError unless `path` ends in `extension` (".png"; in any case, ".PNG" too): a
// command that writes one format must not put it under another's name, where a viewer would
// misread it. Empty paths (not given) pass.
void check_output_extension(std::string_view option, const std::string& path,
                            std::string_view extension, std::string_view format);
// The same, where any of `extensions` will do (a measurements file: .csv or .json).
void check_output_extension(std::string_view option, const std::string& path,
                            std::initializer_list<std::string_view> extensions,
                            std::string_view format);

// Runs a command's body: InputError and PresetError give exit 2, EnvironmentError and WriteError
// exit 1 with their message, anything else exit 1 as an internal error; messages go to stderr.
// SIGINT and SIGTERM remove the temporaries of files being written before they stop it
// (app/common/interrupt.hpp).
int guarded(const std::function<int()>& body);

}  // namespace foldlab::app
