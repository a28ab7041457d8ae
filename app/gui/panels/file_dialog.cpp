#include "app/gui/panels/file_dialog.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <system_error>
#include <utility>

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

bool escape_pressed() {
  const int escape_key = ImGui::GetKeyIndex(ImGuiKey_Escape);
  return escape_key >= 0 && ImGui::IsKeyPressed(escape_key, false);
}

void problem_text(const std::string& problem) {
  if (!problem.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    wrapped_text("%s", problem.c_str());
    ImGui::PopStyleColor();
  }
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
  status.set_modal(request_->title);
  if (!transfer_->browses_folders()) {
    entries_.clear();
    if (request_->mode == Mode::open) {
      transfer_->pick(request_->extensions);
    }
    return;
  }
  std::error_code error;
  if (!fs::is_directory(folder_, error)) {
    folder_ = fs::current_path(error);
  }
  list();
}

void FileDialog::pick_again() {
  if (request_ && request_->mode == Mode::open && !transfer_->browses_folders()) {
    problem_.clear();
    transfer_->pick(request_->extensions);
  }
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
  // What the chosen file led to may have opened a dialog of its own (unsaved edits to keep or
  // drop before a preset loads): only the file dialog's own closes.
  if (request_ && status.modal_title() == request_->title) {
    status.set_modal("");
  }
  request_.reset();
  replace_.reset();
  entries_.clear();
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
  if (!transfer_->browses_folders()) {
    if (request_->mode == Mode::save) {
      download(text, status);
    }
    return;  // a file to open comes from the picker, not from a typed path
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

void FileDialog::download(const std::string& typed, UiStatus& status) {
  // A name alone: the browser decides where its downloads go.
  fs::path name = fs::path(typed).filename();
  if (name.empty() || name == "." || name == "..") {
    problem_ = "Type a file name.";
    return;
  }
  if (!request_->extensions.empty() && name.extension().empty()) {
    name += request_->extensions.front();
  }
  const fs::path path = transfer_->outbox() / name;
  std::error_code error;
  fs::create_directories(path.parent_path(), error);
  fs::remove(path, error);  // an earlier download's copy: what is delivered is written anew
  const std::optional<std::string> problem = request_->chosen(path);
  if (problem) {
    problem_ = *problem;
    return;
  }
  close(status);
  to_deliver_ = path;
  deliver_when_written(status);
}

void FileDialog::deliver_when_written(UiStatus& status) {
  std::error_code error;
  if (!to_deliver_ || !fs::is_regular_file(*to_deliver_, error)) {
    return;
  }
  const fs::path path = *std::exchange(to_deliver_, std::nullopt);
  const std::uintmax_t bytes = fs::file_size(path, error);
  const std::string name = path.filename().string();
  if (transfer_->deliver(path)) {
    status.notify("Downloaded " + name + " (" + std::to_string(error ? 0 : bytes) +
                      " bytes): the browser keeps it with its downloads.",
                  MessageKind::success);
  } else {
    status.notify("Not downloaded: the browser did not take " + name + ".", MessageKind::error);
  }
  fs::remove(path, error);  // the browser holds its own copy
}

void FileDialog::draw_without_folders(const std::optional<fs::path>& picked, UiStatus& status) {
  const std::string title_text = request_->title;  // a picked file may close the request
  const char* title = title_text.c_str();
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  const bool escape = escape_pressed();
  if (!ImGui::BeginPopupModal(
          title, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    return;
  }
  if (picked && request_->mode == Mode::open) {
    choose(*picked, status);
    if (!request_) {
      ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
      return;
    }
  }
  const float width = std::min(ems(26.0f), 0.9f * display.x);
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
  bool act = false;
  if (request_->mode == Mode::save) {
    ImGui::TextUnformatted(
        "Name the file: the browser downloads it, into its downloads folder (or it asks where).");
    if (focus_name_) {
      ImGui::SetKeyboardFocusHere();
      focus_name_ = false;
    }
    ImGui::SetNextItemWidth(width);
    if (ImGui::InputTextWithHint(
            "##file name", "a file name", name_, sizeof name_,
            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
      act = true;
    }
    act = ImGui::Button("Download") || act;
  } else {
    std::string kinds;
    for (const std::string& extension : request_->extensions) {
      kinds += (kinds.empty() ? "" : ", ") + extension;
    }
    ImGui::Text("Choose the file (%s) in the browser's file picker; FoldLab reads a copy of it.",
                kinds.empty() ? "any" : kinds.c_str());
    if (ImGui::Button("Choose a file...")) {
      pick_again();
    }
  }
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel") || escape;
  if (!problem_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
    ImGui::TextUnformatted(problem_.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopTextWrapPos();
  if (cancel) {
    close(status);
  } else if (act) {
    submit(name_, status);
    focus_name_ = request_.has_value();
  }
  if (!request_) {
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void FileDialog::draw(UiStatus& status) {
  deliver_when_written(status);
  // A file picked after its dialog was cancelled is not wanted any more.
  const std::optional<fs::path> picked_file = transfer_->take_picked();
  if (!request_) {
    return;
  }
  if (status.modal_title() != request_->title) {
    close(status);  // another dialog took over
    return;
  }
  if (!transfer_->browses_folders()) {
    draw_without_folders(picked_file, status);
    return;
  }
  const bool escape = escape_pressed();
  if (!begin_browsing_popup()) {
    return;
  }
  Asked asked;
  draw_folder(asked);
  draw_name_field(asked);
  draw_answer_buttons(asked, escape);
  problem_text(problem_);
  act_on(asked, status);
  ImGui::EndPopup();
}

bool FileDialog::begin_browsing_popup() {
  const char* title = request_->title.c_str();
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
  }
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(
      ImVec2(std::min(ems(34.0f), 0.95f * display.x), std::min(ems(26.0f), 0.9f * display.y)),
      ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  return ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings);
}

void FileDialog::draw_folder(Asked& asked) {
  ImGui::TextColored(kDimText, "%s", folder_.string().c_str());
  const float footer_px = 3.0f * ImGui::GetFrameHeightWithSpacing() +
                          (problem_.empty() ? 0.0f : 2.0f * ImGui::GetTextLineHeightWithSpacing());
  if (ImGui::BeginChild("##entries", ImVec2(0.0f, -footer_px), true)) {
    begin_touch_rows();
    for (const Entry& entry : entries_) {
      const std::string label = entry.folder ? entry.name + "/" : entry.name;
      const bool selected = !entry.folder && entry.name == name_;
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        if (entry.folder) {
          asked.go_to = entry.name == ".." ? folder_.parent_path() : folder_ / entry.name;
        } else {
          std::snprintf(name_, sizeof name_, "%s", entry.name.c_str());
          replace_.reset();
          if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
            asked.picked = entry.name;
          }
        }
      }
    }
    end_touch_rows();
  }
  ImGui::EndChild();
}

void FileDialog::draw_name_field(Asked& asked) {
  ImGui::TextUnformatted(request_->mode == Mode::save ? "file name" : "file");
  ImGui::SameLine();
  if (focus_name_) {
    ImGui::SetKeyboardFocusHere();
    focus_name_ = false;
  }
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputTextWithHint(
          "##file name", "a name, or a path (~/ is your home folder)", name_, sizeof name_,
          ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
    asked.picked = name_;
    focus_name_ = true;
  } else if (ImGui::IsItemEdited()) {
    // A name typed after "write over it?" is a new answer: the question was of the old name,
    // and its Replace must never write that file under the name now shown.
    replace_.reset();
  }
}

void FileDialog::draw_answer_buttons(Asked& asked, bool escape) {
  if (replace_) {
    // Wrapped: a long file name would push "write over it?" past the dialog's edge.
    ImGui::PushStyleColor(ImGuiCol_Text, kNoteText);
    ImGui::TextWrapped("%s is there already: write over it?",
                       replace_->filename().string().c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Replace")) {
      asked.picked = replace_->string();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) {
      replace_.reset();
    }
  } else {
    if (ImGui::Button(request_->mode == Mode::save ? "Save" : "Load")) {
      asked.picked = name_;
    }
  }
  ImGui::SameLine();
  asked.cancel = ImGui::Button("Cancel") || escape;
}

void FileDialog::act_on(const Asked& asked, UiStatus& status) {
  if (asked.cancel) {
    ImGui::CloseCurrentPopup();
    close(status);
  } else if (asked.go_to) {
    enter(*asked.go_to);
  } else if (asked.picked) {
    submit(*asked.picked, status);
    if (!request_) {
      ImGui::CloseCurrentPopup();
    }
  }
}

}  // namespace foldlab::gui
