#include "app/gui/panels/file_dialog.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include <imgui.h>

#include "app/gui/panels/widgets.hpp"

namespace foldlab::gui {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

fs::path expand_home(std::string_view typed) {
  const char* home = std::getenv("HOME");
  if (home == nullptr || *home == '\0' || typed.empty() || typed.front() != '~' ||
      (typed.size() > 1 && typed[1] != '/')) {
    return fs::path(typed);
  }
  typed.remove_prefix(std::min<std::size_t>(typed.size(), 2));
  return typed.empty() ? fs::path(home) : fs::path(home) / fs::path(typed);
}

const std::string& FileDialog::title() const {
  static const std::string none;
  return request_ ? request_->title : none;
}

void FileDialog::open(Request request, UiStatus& status) {
  request_ = std::move(request);
  std::snprintf(name_, sizeof name_, "%s", request_->file_name.c_str());
  replace_.reset();
  problem_.clear();
  focus_name_ = true;
  std::error_code error;
  if (!fs::is_directory(folder_, error)) {
    folder_ = fs::current_path(error);
  }
  list();
  status.set_modal(request_->title);
}

bool FileDialog::listed(const fs::path& file) const {
  if (request_->extensions.empty()) {
    return true;
  }
  const std::string extension = lower(file.extension().string());
  return std::find(request_->extensions.begin(), request_->extensions.end(), extension) !=
         request_->extensions.end();
}

void FileDialog::list() {
  entries_.clear();
  std::vector<Entry> folders;
  std::vector<Entry> files;
  std::error_code error;
  for (fs::directory_iterator it(folder_, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.front() == '.') {
      continue;  // hidden, as file managers do
    }
    std::error_code type_error;
    if (it->is_directory(type_error)) {
      folders.push_back({name, true});
    } else if (listed(it->path())) {
      files.push_back({name, false});
    }
  }
  if (error) {
    problem_ = "Cannot list " + folder_.string() + ": " + error.message();
  }
  const auto by_name = [](const Entry& a, const Entry& b) { return lower(a.name) < lower(b.name); };
  std::sort(folders.begin(), folders.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);
  if (folder_.has_parent_path() && folder_.parent_path() != folder_) {
    entries_.push_back({"..", true});
  }
  entries_.insert(entries_.end(), folders.begin(), folders.end());
  entries_.insert(entries_.end(), files.begin(), files.end());
}

void FileDialog::enter(const fs::path& folder) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(folder, error);
  folder_ = error ? folder : canonical;
  problem_.clear();
  replace_.reset();
  list();
}

void FileDialog::close(UiStatus& status) {
  request_.reset();
  replace_.reset();
  entries_.clear();
  if (!status.modal_title().empty()) {
    status.set_modal("");
  }
}

void FileDialog::submit(std::string_view typed, UiStatus& status) {
  if (!request_) {
    return;
  }
  std::string text(typed);
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  if (text.empty()) {
    problem_ = request_->mode == Mode::save ? "Type a file name." : "Choose a file.";
    return;
  }
  fs::path path = expand_home(text);
  if (path.is_relative()) {
    path = folder_ / path;
  }
  std::error_code error;
  if (fs::is_directory(path, error)) {
    enter(path);
    name_[0] = '\0';
    return;
  }
  if (request_->mode == Mode::open) {
    if (!fs::exists(path, error)) {
      problem_ = "There is no file " + path.string() + ".";
      return;
    }
    choose(path, status);
    return;
  }
  if (!request_->extensions.empty() && path.extension().empty()) {
    path += request_->extensions.front();
  }
  if (!fs::is_directory(path.parent_path(), error)) {
    problem_ = "There is no folder " + path.parent_path().string() + ".";
    return;
  }
  if (fs::exists(path, error) && replace_ != path) {
    replace_ = path;  // asked first; the same name again (or "Replace") writes
    problem_.clear();
    return;
  }
  choose(path, status);
}

void FileDialog::choose(const fs::path& path, UiStatus& status) {
  replace_.reset();
  const std::optional<std::string> problem = request_->chosen(path);
  if (problem) {
    problem_ = *problem;
    return;
  }
  std::error_code error;
  folder_ = fs::weakly_canonical(path, error).parent_path();
  if (error || folder_.empty()) {
    folder_ = path.parent_path();
  }
  close(status);
}

void FileDialog::draw(UiStatus& status) {
  if (!request_) {
    return;
  }
  const char* title = request_->title.c_str();
  if (status.modal_title() != request_->title) {
    close(status);  // another dialog took over
    return;
  }
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(
      ImVec2(std::min(ems(34.0f), 0.95f * display.x), std::min(ems(26.0f), 0.9f * display.y)),
      ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  const int escape_key = ImGui::GetKeyIndex(ImGuiKey_Escape);
  const bool escape = escape_key >= 0 && ImGui::IsKeyPressed(escape_key, false);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    return;
  }
  ImGui::TextColored(kDimText, "%s", folder_.string().c_str());
  const float footer = 3.0f * ImGui::GetFrameHeightWithSpacing() +
                       (problem_.empty() ? 0.0f : 2.0f * ImGui::GetTextLineHeightWithSpacing());
  std::optional<fs::path> go_to;
  std::optional<std::string> picked;
  if (ImGui::BeginChild("##entries", ImVec2(0.0f, -footer), true)) {
    for (const Entry& entry : entries_) {
      const std::string label = entry.folder ? entry.name + "/" : entry.name;
      const bool selected = !entry.folder && entry.name == name_;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (entry.folder) {
          go_to = entry.name == ".." ? folder_.parent_path() : folder_ / entry.name;
        } else {
          std::snprintf(name_, sizeof name_, "%s", entry.name.c_str());
          replace_.reset();
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            picked = entry.name;
          }
        }
      }
    }
  }
  ImGui::EndChild();
  const bool saving = request_->mode == Mode::save;
  ImGui::TextUnformatted(saving ? "file name" : "file");
  ImGui::SameLine();
  if (focus_name_) {
    ImGui::SetKeyboardFocusHere();
    focus_name_ = false;
  }
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputTextWithHint(
          "##file name", "a name, or a path (~/ is your home folder)", name_, sizeof name_,
          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    picked = name_;
    focus_name_ = true;
  }
  if (replace_) {
    ImGui::TextColored(kNoteText, "%s is there already: write over it?",
                       replace_->filename().string().c_str());
    if (ImGui::Button("Replace")) {
      picked = replace_->string();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) {
      replace_.reset();
    }
  } else {
    if (ImGui::Button(saving ? "Save" : "Load")) {
      picked = name_;
    }
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel") || escape;
  if (!problem_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    wrapped_text("%s", problem_.c_str());
    ImGui::PopStyleColor();
  }
  if (cancel) {
    ImGui::CloseCurrentPopup();
    close(status);
  } else if (go_to) {
    enter(*go_to);
  } else if (picked) {
    submit(*picked, status);
    if (!request_) {
      ImGui::CloseCurrentPopup();
    }
  }
  ImGui::EndPopup();
}

}  // namespace foldlab::gui
