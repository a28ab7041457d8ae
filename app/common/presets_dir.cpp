#include "app/common/presets_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <string>
#include <string_view>
#include <system_error>

#include "core/io/preset.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::app {
namespace {

// "h900" before "h1400": runs of digits compare by their value.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) &&
        std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t i_end = i;
      std::size_t j_end = j;
      while (i_end < a.size() && std::isdigit(static_cast<unsigned char>(a[i_end])))
        ++i_end;
      while (j_end < b.size() && std::isdigit(static_cast<unsigned char>(b[j_end])))
        ++j_end;
      const std::string_view da(a.data() + i, i_end - i);
      const std::string_view db(b.data() + j, j_end - j);
      if (da.size() != db.size()) {
        return da.size() < db.size();
      }
      if (da != db) {
        return da < db;
      }
      i = i_end;
      j = j_end;
    } else {
      if (a[i] != b[j]) {
        return a[i] < b[j];
      }
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

// Whether the executable lies inside the build folder it was built in: only then does the source
// tree, compiled in, stand in for an installed presets folder. A copied or installed program never
// reads the source tree.
bool built_here(const std::filesystem::path& exe) {
  std::error_code error;
  const std::filesystem::path build = std::filesystem::canonical(FOLDLAB_BUILD_DIR, error);
  if (error) {
    return false;
  }
  const std::filesystem::path dir = std::filesystem::weakly_canonical(exe.parent_path(), error);
  if (error) {
    return false;
  }
  return std::mismatch(build.begin(), build.end(), dir.begin(), dir.end()).first == build.end();
}

}  // namespace

std::filesystem::path find_presets_dir() {
  std::error_code error;
  if (const char* env = std::getenv("FOLDLAB_PRESETS_DIR"); env && *env) {
    if (std::filesystem::is_directory(env, error)) {
      return env;
    }
    // Said once per run, however often the folder is looked up: a mistyped variable would
    // otherwise hide the user's presets without a word.
    static std::once_flag said;
    std::call_once(said, [&] {
      std::cerr << "foldlab: FOLDLAB_PRESETS_DIR " << detail::escaped(env)
                << " does not exist or is no folder; using the next presets folder\n";
    });
  }
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) {
    return {};
  }
  const std::filesystem::path installed =
      exe.parent_path().parent_path() / "share" / "foldlab" / "presets";
  if (std::filesystem::is_directory(installed, error)) {
    return installed;
  }
  if (built_here(exe) && std::filesystem::is_directory(FOLDLAB_SOURCE_PRESETS_DIR, error)) {
    return FOLDLAB_SOURCE_PRESETS_DIR;
  }
  return {};
}

std::vector<std::filesystem::path> preset_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
    if (entry.is_regular_file(error) && entry.path().extension() == ".json") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

FolderPresets readable_presets(const std::filesystem::path& dir) {
  FolderPresets out;
  for (const std::filesystem::path& file : preset_files(dir)) {
    try {
      out.presets.push_back(load_preset(file));
      out.files.push_back(file);
    } catch (const PresetError& e) {
      // The reason names the file itself, mostly: named once.
      std::string_view why = e.what();
      if (const std::string named = file.string() + ": "; why.starts_with(named)) {
        why.remove_prefix(named.size());
      }
      out.skipped.push_back("skipped " + file.string() + ": " + std::string(why));
    }
  }
  return out;
}

std::string preset_slug(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!out.empty() && out.back() != '-') {
      out += '-';
    }
  }
  while (!out.empty() && out.back() == '-') {
    out.pop_back();
  }
  return out;
}

std::filesystem::path config_dir() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    return std::filesystem::path(xdg) / "foldlab";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "foldlab";
  }
  return std::filesystem::current_path() / ".foldlab";
}

std::filesystem::path user_presets_dir() {
  return config_dir() / "presets";
}

namespace {

std::string lower(std::string text) {
  for (char& c : text) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return text;
}

// Each preset file where the user and the program keep them, the user's first, with its name and
// its folder's place in that order; a file that cannot be read is passed over.
template <class Visit>
void for_each_preset(Visit visit) {
  int rank = 0;
  for (const std::filesystem::path& dir : {user_presets_dir(), find_presets_dir()}) {
    ++rank;
    if (dir.empty()) {
      continue;
    }
    for (const std::filesystem::path& file : preset_files(dir)) {
      try {
        if (visit(NamedPreset{file, load_preset(file.string()).name}, rank)) {
          return;
        }
      } catch (const PresetError&) {
        continue;
      }
    }
  }
}

}  // namespace

std::vector<NamedPreset> presets_named(const std::string& name) {
  const std::string wanted = lower(name);
  const std::string wanted_slug = preset_slug(name);
  // A name written exactly so comes before a file named so: "fab-a" is the preset of that name,
  // not "Fab A" saved as fab-a.json.
  std::optional<NamedPreset> exact_name;
  std::optional<NamedPreset> exact_file;
  std::vector<NamedPreset> loose;
  int loose_rank = 0;
  for_each_preset([&](const NamedPreset& preset, int rank) {
    if (preset.name == name) {
      exact_name = preset;
      return true;
    }
    const std::string stem = preset.file.stem().string();
    if (!exact_file && (stem == name || preset.file.filename() == name)) {
      exact_file = preset;
    }
    const std::string stem_lower = lower(stem);
    const bool reads_as = (!wanted_slug.empty() && preset_slug(preset.name) == wanted_slug) ||
                          stem_lower == wanted || stem_lower + ".json" == wanted;
    if (reads_as && (loose.empty() || rank == loose_rank)) {
      loose_rank = rank;
      loose.push_back(preset);
    }
    return false;
  });
  if (exact_name) {
    return {*exact_name};
  }
  if (exact_file) {
    return {*exact_file};
  }
  return loose;
}

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for_each_preset([&](const NamedPreset& preset, int) {
    names.push_back(preset.name);
    return false;
  });
  return names;
}

}  // namespace foldlab::app
