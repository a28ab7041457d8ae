#include "app/gui/session.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/common/version.hpp"
#include "core/io/io.hpp"
#include "core/io/json_input.hpp"
#include "core/model/text_format.hpp"

namespace foldlab::gui {

std::optional<std::string> oversized_file(const std::filesystem::path& path, std::uintmax_t limit) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec || bytes <= limit) {
    return std::nullopt;  // absent or unreadable: the reader says so
  }
  return detail::printf_string("%s is %ju bytes, above the %ju a valid one can have; not read",
                               path.string().c_str(), bytes, limit);
}

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) {
    return "a folder";
  }
  if (S_ISFIFO(mode)) {
    return "a FIFO";
  }
  if (S_ISCHR(mode) || S_ISBLK(mode)) {
    return "a device";
  }
  if (S_ISSOCK(mode)) {
    return "a socket";
  }
  return "not a regular file";
}

}  // namespace

ConfigFile read_config_file(const std::filesystem::path& path, std::uintmax_t limit) {
  ConfigFile file;
  const std::string name = path.string();
  auto refuse = [&](std::string problem) {
    file.problem = std::move(problem);
    file.may_save = false;
    return file;
  };
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) {
    if (errno == ENOENT) {
      return file;  // a first start: nothing to read, a new file to write
    }
    return refuse(name + " cannot be opened (" + std::strerror(errno) + ")");
  }
  // A link is read (and later saved) through when it leads to a file the explorer can read as
  // its own; a dangling one or a loop would be created or replaced somewhere unasked.
  if (S_ISLNK(info.st_mode) && ::stat(path.c_str(), &info) != 0) {
    return refuse(name + " cannot be opened (a symbolic link: " + std::strerror(errno) + ")");
  }
  if (!S_ISREG(info.st_mode)) {
    return refuse(name + " is " + kind_of(info.st_mode) + ", not a regular file; not read");
  }
  if (info.st_uid != ::geteuid()) {
    return refuse(name + " belongs to another user; not read");
  }
  if (std::optional<std::string> too_large = oversized_file(path, limit)) {
    return refuse(*too_large);  // said in the words of the listing, before the reader's check
  }
  try {
    file.text = read_text_file(path, limit);
  } catch (const ReadError& e) {
    return refuse(name + " cannot be opened (" + e.what() + ")");
  }
  return file;
}

SessionSettings SessionSettings::from_json(const nlohmann::json& view,
                                           std::vector<std::string>& dropped) {
  SessionSettings out;
  if (!view.is_object()) {
    throw std::runtime_error("view must be an object");
  }
  for (const auto& [key, value] : view.items()) {
    const bool text_key = std::find(std::begin(kTextViewKeys), std::end(kTextViewKeys), key) !=
                          std::end(kTextViewKeys);
    if (text_key ? value.is_string() : value.is_boolean() || value.is_number()) {
      out.values_[key] = value;
    } else if (text_key) {
      dropped.push_back("view." + detail::cut(key) + " must be text, not " +
                        std::string(value.type_name()));
    } else {
      dropped.push_back("view." + detail::cut(key) + " must be true, false or a number, not " +
                        std::string(value.type_name()));
    }
  }
  return out;
}

std::optional<Session> load_session(const std::filesystem::path& path, std::string& error,
                                    bool& may_save) {
  error.clear();
  ConfigFile file = read_config_file(path, kMaxSessionBytes);
  may_save = file.may_save;
  if (!file.problem.empty()) {
    error = "the saved session " + file.problem + "; starting from the default preset";
    return std::nullopt;
  }
  if (!file.text) {
    return std::nullopt;  // a first start: nothing to say
  }
  std::optional<Session> session = session_from_text(*file.text, path.string(), error);
  if (!session) {
    may_save = false;  // another program's JSON, text, a file this format cannot parse
  } else if (!session->complete) {
    // What could not be read is kept beside it before the next save replaces the file.
    std::filesystem::path kept = path;
    kept += ".unread";
    try {
      write_file_atomically(kept, *file.text);
      session->notices.push_back("The session file as it was is kept as " + kept.string() + ".");
    } catch (const WriteError& e) {
      may_save = false;
      session->notices.push_back(std::string("The session file could not be kept aside (") +
                                 e.what() + "), so it is not saved over.");
    }
  }
  return session;
}

std::optional<Session> session_from_text(const std::string& text, const std::string& origin,
                                         std::string& error) {
  nlohmann::json j;
  try {
    j = parse_json(text, origin);
    if (!j.is_object() || !j.contains("foldlab_session")) {
      throw std::runtime_error("not a FoldLab session");
    }
  } catch (const std::exception& e) {
    error = "the saved session " + origin + " could not be read (" + e.what() +
            "); starting from the default preset";
    return std::nullopt;
  }
  // Each part is read on its own, so that one bad value (a d of 1e308) drops its part alone and
  // the rest (the other fabric, B, the view's switches) is still the user's.
  Session s;
  const auto dropped = [&](const std::string& what, const std::exception& e) {
    s.notices.push_back("The saved session's " + what + " was not restored: " + e.what());
    s.complete = false;
  };
  std::optional<Preset> current;
  std::optional<Preset> loaded;
  try {
    current = preset_from_json(j.at("current"), origin + " (current)");
  } catch (const std::exception& e) {
    dropped("fabric being edited", e);
  }
  try {
    loaded = preset_from_json(j.at("loaded"), origin + " (loaded)");
    s.loaded_preset_path = j.value("loaded_preset_path", "");
  } catch (const std::exception& e) {
    dropped("preset it came from", e);
  }
  if (current || loaded) {
    s.current = current ? *current : *loaded;
    s.loaded = loaded ? *loaded : *current;
  } else {
    s.fabric_restored = false;
  }
  try {
    const nlohmann::json& view = j.at("view");
    // Each setting on its own: one that is not a number or a switch is left at its default.
    std::vector<std::string> bad;
    s.view = SessionSettings::from_json(view, bad);
    for (const std::string& problem : bad) {
      s.notices.push_back("The saved session's " + problem + "; that setting is at its default.");
      s.complete = false;
    }
    // Read as a double: a huge stored number must be clamped, not converted to int first.
    const nlohmann::json& resolution = s.view.json().value("grid_resolution", nlohmann::json());
    const double stored_resolution =
        resolution.is_number() ? resolution.get<double>() : static_cast<double>(s.grid_resolution);
    const double clamped = std::clamp(stored_resolution, static_cast<double>(kMinGridResolution),
                                      static_cast<double>(kMaxGridResolution));
    s.grid_resolution = static_cast<int>(clamped);  // NaN cannot come from JSON
    if (clamped != stored_resolution) {
      s.notices.push_back(detail::printf_string(
          "The saved grid resolution %s is outside the slider's %d to %d; using %d.",
          detail::shortest_number(stored_resolution).c_str(), kMinGridResolution,
          kMaxGridResolution, s.grid_resolution));
    }
  } catch (const std::exception& e) {
    dropped("view settings", e);
  }
  if (j.contains("compare")) {
    try {
      s.compare = preset_from_json(j.at("compare"), origin + " (compare)");
      if (j.contains("compare_origin")) {
        s.compare_origin = preset_from_json(j.at("compare_origin"), origin + " (compare_origin)");
        s.compare_origin_path = j.value("compare_origin_path", "");
      }
    } catch (const std::exception& e) {
      s.compare.reset();
      s.compare_origin.reset();
      dropped("fabric pinned as B", e);
    }
  }
  return s;
}

void save_session(const std::filesystem::path& path, const Session& session) {
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error) {
    throw WriteError(path.string() + ": cannot create the folder " + path.parent_path().string() +
                     " (" + error.message() + ")");
  }
  nlohmann::json view = session.view.json();
  view["grid_resolution"] = session.grid_resolution;
  nlohmann::json j = {
      {"foldlab_session", 1},
      {"written_by", app::version_line()},
      {"current", preset_to_json(session.current)},
      {"loaded", preset_to_json(session.loaded)},
      {"loaded_preset_path", session.loaded_preset_path},
      {"view", view},
  };
  if (session.compare) {
    j["compare"] = preset_to_json(*session.compare);
    if (session.compare_origin) {
      j["compare_origin"] = preset_to_json(*session.compare_origin);
      j["compare_origin_path"] = session.compare_origin_path;
    }
  }
  write_file_atomically(path, j.dump(2) + "\n");
}

}  // namespace foldlab::gui
