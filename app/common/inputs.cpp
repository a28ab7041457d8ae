#include "app/common/inputs.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "app/common/interrupt.hpp"
#include "app/common/presets_dir.hpp"
#include "core/io/io.hpp"
#include "core/model/settings.hpp"
#include "core/model/text_format.hpp"
#include "core/model/wrinkle_law.hpp"

namespace foldlab::app {

namespace {

// The overrides in the order every command applies them: a law with its published constants
// (which --set c, K or p then override), the link's inputs, --set, --method.
std::vector<std::string> overrides(const InputOptions& options, bool with_link) {
  std::vector<std::string> assignments;
  if (!options.law.empty()) {
    assignments.push_back("law=" + options.law);
    WrinkleLawKind kind{};
    if (parse_wrinkle_law(options.law, kind)) {
      assignments.push_back("c=" +
                            detail::shortest_number(wrinkle_law(kind).published_load_constant_c()));
      assignments.emplace_back("p=1");
    }
  }
  if (with_link) {
    assignments.insert(assignments.end(), options.link.begin(), options.link.end());
  }
  assignments.insert(assignments.end(), options.assignments.begin(), options.assignments.end());
  if (!options.method.empty()) {
    assignments.push_back("method=" + options.method);
  }
  return assignments;
}

// The refusals, each with what a bare number meant when the value that set it was one and the
// explorer shows the input in another unit: `w=150` is 150 N/mm², not the 150 g/m² of its slider.
std::string refusals(const std::vector<ValidationIssue>& issues,
                     const std::vector<std::string>& assignments, const std::string& whose = {}) {
  std::string out;
  for (const ValidationIssue& issue : issues) {
    out += whose + issue.message;
    const InputSpec* spec = find_input_by_field(issue.field);
    for (auto it = assignments.rbegin(); spec != nullptr && it != assignments.rend(); ++it) {
      const std::size_t eq = it->find('=');
      if (eq != std::string::npos && std::string_view(*it).substr(0, eq) == spec->key) {
        if (const std::optional<std::string> hint = bare_number_hint(*spec, it->substr(eq + 1))) {
          out += " (" + *hint + ")";
        }
        break;
      }
    }
    out += '\n';
  }
  return out;
}

// A piece of a link that cannot be applied on its own (an unknown key, a value that is no number,
// no KEY=VALUE): the reason, else nothing.
std::optional<std::string> unusable_link_piece(const Parameters& preset, const std::string& piece) {
  Parameters scratch = preset;
  const std::vector<std::string> errors = apply_assignments(scratch, {piece});
  if (errors.empty()) {
    return std::nullopt;
  }
  return errors.front();
}

// What a forgiving link says of a piece it left out, with what is shown in its place.
std::string link_note(const std::string& piece, const std::string& reason, const Preset& preset,
                      const Parameters& shown) {
  const std::size_t eq = piece.find('=');
  if (eq == std::string::npos || eq == 0) {
    return "'" + detail::cut(piece) + "' is no KEY=VALUE, so it is left out";
  }
  const std::string key = piece.substr(0, eq);
  const InputSpec* spec = find_input(key);
  if (spec == nullptr) {
    return "'" + detail::cut(key) + "' is no key FoldLab knows (known: " + known_keys() +
           "), so it is left out";
  }
  const std::optional<double> now = spec->value(shown);
  const std::optional<double> preset_value = spec->value(preset.parameters);
  const std::string value = now ? shown_quantity(*spec, *now) : std::string(spec->choice(shown));
  const bool as_preset = now ? preset_value && *preset_value == *now
                             : spec->choice(shown) == spec->choice(preset.parameters);
  return reason + ", so " + key + " is " + (as_preset ? "the preset's " : "") + value;
}

// The file --preset means: `given` itself when it is a file or a path (or empty, the default),
// else the preset of that name as the Presets panel lists it ("Linen (medium weight)", or one
// saved in the explorer; presets_dir.hpp's presets_named). Throws InputError naming the presets
// there are when none is, and the presets it could mean when it is ambiguous.
std::string preset_file(const std::string& given) {
  std::error_code error;
  if (given.empty() || given.find('/') != std::string::npos ||
      std::filesystem::exists(given, error)) {
    return given;
  }
  const std::vector<NamedPreset> named = presets_named(given);
  if (named.size() == 1) {
    return named.front().file.string();
  }
  if (!named.empty()) {
    std::vector<std::string> each;
    for (const NamedPreset& preset : named) {
      each.push_back("\"" + detail::cut(preset.name) + "\" (" + preset.file.string() + ")");
    }
    throw InputError("--preset " + detail::cut(given) +
                     " names more than one preset, none of "
                     "them exactly: " +
                     detail::join(each, "; ") + ". Give the name as it is written, or the file.");
  }
  const std::vector<std::string> names = preset_names();
  throw InputError("--preset " + detail::cut(given) +
                   ": there is no such file, and no preset is named so. The presets: " +
                   (names.empty() ? std::string("none") : detail::join(names, "; ")) + ".");
}

Preset load(const std::string& file) {
  try {
    return file.empty() ? default_preset() : load_preset(file);
  } catch (const PresetError& e) {
    throw InputError(e.what());
  }
}

// The inputs of a sweep, judged along its range: `all` where it is valid itself, else with the
// swept input at the first value the others accept; a range with none is refused.
Parameters judged_along(const Parameters& all, const SweepAxis& axis,
                        const std::vector<std::string>& assignments) {
  for (int i = 0; i < axis.steps; ++i) {
    Parameters at = all;
    set_number(at, axis.key, axis.value(i));
    if (validate(at).empty()) {
      return validate(all).empty() ? all : at;
    }
  }
  Parameters first = all;
  set_number(first, axis.key, axis.from);
  std::string reasons = refusals(validate(first), assignments);
  reasons.pop_back();  // the final newline
  throw InputError("no value of the range is valid given the other inputs; at " + axis.key + " = " +
                   detail::shortest_number(axis.from) + ": " + reasons);
}

// The preset's name, and the inputs the overrides changed from `loaded` as solved after it.
std::string edited_name(const Preset& solved, const Parameters& loaded) {
  std::vector<std::string> changed;
  for (const InputSpec& spec : input_table()) {
    if (spec.kind == InputKind::stiffness_K) {
      continue;  // K is c at the Poisson ratio: a change of either shows as c (or nu)
    }
    const std::optional<double> now = spec.value(solved.parameters);
    if (now) {
      if (*now != spec.value(loaded)) {
        changed.push_back(std::string(input_symbol(spec)) + " = " + shown_quantity(spec, *now));
      }
    } else if (spec.choice(solved.parameters) != spec.choice(loaded)) {
      changed.push_back(std::string(spec.key) + " = " +
                        std::string(spec.choice(solved.parameters)));
    }
  }
  if (changed.empty()) {
    return solved.name;
  }
  return solved.name + " (edited: " + detail::join_comma(changed) + ")";
}

// --method and --law beside a --set of the same key: applied in order, the option would win
// without a word.
std::vector<std::string> option_clashes(const InputOptions& options) {
  std::vector<std::string> problems;
  const auto clash = [&](std::string_view flag, const std::string& value, std::string_view key) {
    if (value.empty()) {
      return;
    }
    for (const std::string& assignment : options.assignments) {
      if (std::string_view(assignment).substr(0, assignment.find('=')) == key) {
        problems.push_back(std::string(flag) + " " + detail::cut(value) + " and " +
                           options.set_option + " " + detail::cut(assignment) + ": both set " +
                           std::string(key) + "; which one is meant?");
      }
    }
  };
  clash("--method", options.method, "method");
  clash("--law", options.law, "law");
  return problems;
}

StartInputs resolve(const InputOptions& given, bool keep_refused, const SweepAxis* axis = nullptr) {
  StartInputs start;
  start.preset_file = preset_file(given.preset_path);
  start.preset = load(start.preset_file);
  start.loaded = start.preset.parameters;
  InputOptions options = given;
  // Left out before anything is applied: a piece that cannot be read says nothing of the fabric.
  std::vector<std::pair<std::string, std::string>> left_out;  // the piece, why
  if (options.forgiving_link) {
    std::vector<std::string> keys_seen;
    std::erase_if(options.link, [&](const std::string& piece) {
      std::optional<std::string> reason = unusable_link_piece(start.preset.parameters, piece);
      const std::string key = piece.substr(0, piece.find('='));
      if (!reason && std::find(keys_seen.begin(), keys_seen.end(), key) != keys_seen.end()) {
        reason = key + " is given twice in the link; the first value is used";
      }
      keys_seen.push_back(key);
      if (reason) {
        left_out.emplace_back(piece, *reason);
      }
      return reason.has_value();
    });
  }
  const Preset loaded = start.preset;
  const auto finish = [&](StartInputs& out) {
    const Parameters& shown = out.refused ? *out.refused : out.preset.parameters;
    for (const auto& [piece, reason] : left_out) {
      out.link_notes.push_back(link_note(piece, reason, loaded, shown));
    }
  };
  // What cannot be applied, named by the option it came with (it does not depend on the values
  // applied before it).
  std::string problems;
  for (const std::string& repeated : repeated_keys(options.link, "--link")) {
    problems += repeated + "\n";
  }
  for (const std::string& repeated : repeated_keys(options.assignments, options.set_option)) {
    problems += repeated + "\n";
  }
  for (const std::string& clash : option_clashes(options)) {
    problems += clash + "\n";
  }
  Parameters scratch = start.preset.parameters;
  for (const std::string& error : apply_assignments(scratch, options.link)) {
    problems += "--link " + error + "\n";
  }
  for (const std::string& error : apply_assignments(scratch, overrides(options, false))) {
    problems += options.set_option + " " + error + "\n";
  }
  Parameters all = start.preset.parameters;
  apply_assignments(all, overrides(options, true));
  Parameters without_link = start.preset.parameters;
  apply_assignments(without_link, overrides(options, false));
  const bool origin_valid = validate(without_link).empty();
  start.origin = start.preset;
  start.origin.parameters = origin_valid ? without_link : all;
  // Range problems as well: a value that did not parse left the preset's (valid) value in place,
  // so every range problem reported is a real one.
  if (axis != nullptr && problems.empty()) {
    start.preset.parameters = judged_along(all, *axis, overrides(options, true));
    return start;
  }
  const std::vector<ValidationIssue> issues = validate(all);
  if (problems.empty() && issues.empty()) {
    start.preset.parameters = all;
    finish(start);
    return start;
  }
  if (problems.empty() && keep_refused && !options.link.empty() && origin_valid) {
    start.preset.parameters = without_link;
    start.refused = all;
    finish(start);
    return start;
  }
  problems += refusals(issues, overrides(options, true), options.whose);
  problems.pop_back();  // the final newline
  throw InputError(problems);
}

}  // namespace

Preset resolve_inputs(const InputOptions& options) {
  return resolve(options, false).preset;
}

StartInputs resolve_start_inputs(const InputOptions& options) {
  return resolve(options, true);
}

SweepAxis read_sweep_axis(const SweepAxisText& text) {
  if (text.log && text.linear) {
    throw InputError("--log and --linear exclude each other");
  }
  SweepAxis axis{.key = text.key,
                 .steps = text.steps,
                 .logarithmic = text.log || (!text.linear && natural_log_scale(text.key))};
  const InputSpec* spec = find_input(text.key);
  const std::array<std::pair<std::string_view, const std::string*>, 2> ends{
      {{"--from", &text.from}, {"--to", &text.to}}};
  // An unknown key leaves the ends as they are, for check_axis to name the key.
  for (std::size_t i = 0; spec != nullptr && i < ends.size(); ++i) {
    const auto& [option, typed] = ends[i];
    const std::variant<double, InputRefusal> value = read_quantity(*spec, *typed);
    if (const InputRefusal* refusal = std::get_if<InputRefusal>(&value)) {
      throw InputError(std::string(option) + " " + refusal_sentence(*refusal));
    }
    (i == 0 ? axis.from : axis.to) = std::get<double>(value);
  }
  if (const std::optional<std::string> problem = check_axis(axis)) {
    for (const auto& [option, typed] : ends) {
      SweepAxis alone = axis;
      alone.from = alone.to = option == ends[0].first ? axis.from : axis.to;
      const std::optional<std::string> hint =
          spec == nullptr ? std::nullopt : bare_number_hint(*spec, *typed);
      if (hint && check_axis(alone)) {
        throw InputError(*problem + " (" + *hint + ")");
      }
    }
    throw InputError(*problem);
  }
  return axis;
}

StartInputs resolve_inputs_in_full(const InputOptions& options, const SweepAxis* axis) {
  return resolve(options, false, axis);
}

Preset resolve_named_inputs(const InputOptions& options) {
  StartInputs start = resolve(options, false);
  start.preset.name = edited_name(start.preset, start.loaded);
  return start.preset;
}

void check_output_extension(std::string_view option, const std::string& path,
                            std::string_view extension, std::string_view format) {
  check_output_extension(option, path, {extension}, format);
}

void check_output_extension(std::string_view option, const std::string& path,
                            std::initializer_list<std::string_view> extensions,
                            std::string_view format) {
  const auto lower = [](std::string_view text) {
    std::string out(text);
    for (char& c : out) {
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
  };
  std::string listed;
  for (const std::string_view extension : extensions) {
    if (path.empty() || lower(path).ends_with(lower(extension))) {
      return;
    }
    listed += (listed.empty() ? "" : " or ") + std::string(extension);
  }
  throw InputError(std::string(option) + " " + detail::cut(path) + " must end in " + listed +
                   " (in any case): what is written there is " + std::string(format));
}

int guarded(const std::function<int()>& body) {
  // Every command may write a file: one stopped while it writes leaves no temporary behind.
  remove_temporaries_when_interrupted();
  // Messages quote paths, values and names as given: printed through escaped_lines().
  const auto say = [](const char* prefix, const char* what) {
    std::cerr << prefix << detail::escaped_lines(what) << "\n";
  };
  try {
    return body();
  } catch (const InputError& e) {
    say("foldlab: invalid input:\n", e.what());
    return kExitInvalidInput;
  } catch (const PresetError& e) {
    say("foldlab: invalid input:\n", e.what());
    return kExitInvalidInput;
  } catch (const EnvironmentError& e) {
    say("foldlab: ", e.what());
    return kExitInternal;
  } catch (const WriteError& e) {
    say("foldlab: ", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    say("foldlab: internal error: ", e.what());
    return kExitInternal;
  }
}

namespace {

// Whether two outputs name one file, as far as can be told: an existing pair by identity (links
// included), otherwise by the canonical form of the part that exists.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (std::filesystem::equivalent(a, b, error) && !error) {
    return true;
  }
  const std::filesystem::path canonical_a =
      std::filesystem::weakly_canonical(std::filesystem::absolute(a), error);
  if (error) {
    return false;
  }
  const std::filesystem::path canonical_b =
      std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
  return !error && canonical_a == canonical_b;
}

// Whether writing `output` would replace the file `input` opens: one device and inode once links
// are followed. A file that does not exist is not yet anyone's input.
bool writes_over(const std::string& output, const std::string& input) {
  struct stat written {};
  struct stat read {};
  return ::stat(output.c_str(), &written) == 0 && ::stat(input.c_str(), &read) == 0 &&
         written.st_dev == read.st_dev && written.st_ino == read.st_ino;
}

// Paths are shown whole up to this: a folder's name is at their end, and one a refusal names must
// be seen.
constexpr std::size_t kPathShownBytes = 300;

// "--preset myfab (presets/myfab.json)": the option as typed and, when it differs, the file.
std::string shown(const NamedPath& named) {
  std::string text = std::string(named.option) + " " + detail::cut(named.path, kPathShownBytes);
  if (!named.file.empty() && named.file != named.path) {
    text += " (" + detail::cut(named.file, kPathShownBytes) + ")";
  }
  return text;
}

// The folder a write of `output` creates its temporary in: the one holding the file a chain of
// links ends at, as write_file_atomically follows them.
std::filesystem::path folder_written(const std::string& output) {
  std::error_code error;
  std::filesystem::path target = output;
  if (std::filesystem::is_symlink(target, error)) {
    const std::filesystem::path resolved =
        std::filesystem::weakly_canonical(std::filesystem::absolute(target), error);
    if (!error) {
      target = resolved;
    }
  }
  return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// Throws InputError unless `output`'s folder exists, is a folder and can be written to.
void check_output_folder(const NamedPath& output) {
  const std::filesystem::path folder = folder_written(output.path);
  const std::string whose =
      shown(output) + ": the folder " + detail::cut(folder.string(), kPathShownBytes);
  struct stat info {};
  if (::stat(folder.c_str(), &info) != 0) {
    const int error = errno;
    throw InputError(whose +
                     (error == ENOENT
                          ? std::string(" does not exist")
                          : " cannot be opened (" + std::string(std::strerror(error)) + ")") +
                     "; create it first, or name a file in another folder");
  }
  if (!S_ISDIR(info.st_mode)) {
    throw InputError(whose + " is not a folder; name a file in a folder");
  }
  if (::faccessat(AT_FDCWD, folder.c_str(), W_OK | X_OK, AT_EACCESS) != 0) {
    throw InputError(whose + " cannot be written to (" + std::string(std::strerror(errno)) +
                     "); name a file in a folder of yours");
  }
  const std::string name = std::filesystem::path(output.path).filename().string();
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  if (name_max > 0 && name.size() > static_cast<std::size_t>(name_max)) {
    throw InputError(shown(output) + ": the file's name is " + std::to_string(name.size()) +
                     " bytes long; this folder takes names of at most " + std::to_string(name_max) +
                     " bytes");
  }
  // Some folders pass every check above and still take no file (/proc, a read-only mount seen
  // by root): a file made and removed there says so before the work, not after it.
  std::string probe = (folder / ".foldlab-probe.XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) {
    throw InputError(whose + " takes no new file (" + std::string(std::strerror(errno)) +
                     "); name a file in a folder of yours");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

NamedPath preset_input(std::string_view option, const std::string& given) {
  return {option, given, preset_file(given)};
}

void check_outputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].path.empty()) {
      continue;
    }
    check_output_folder(outputs[i]);
    for (std::size_t j = i + 1; j < outputs.size(); ++j) {
      if (!outputs[j].path.empty() && same_file(outputs[i].path, outputs[j].path)) {
        throw InputError(shown(outputs[i]) + " and " + shown(outputs[j]) +
                         " name the same file; give each output its own path");
      }
    }
    for (const NamedPath& input : inputs) {
      const std::string& opened = input.file.empty() ? input.path : input.file;
      if (!opened.empty() && writes_over(outputs[i].path, opened)) {
        throw InputError(shown(outputs[i]) + " and " + shown(input) +
                         " name the same file: writing the output would destroy the input");
      }
    }
  }
}

}  // namespace foldlab::app
