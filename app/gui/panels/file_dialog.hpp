// The explorer's one file dialog, for saving (exports) and opening (a swatch, a photo): the
// current folder's folders and files (filtered by extension), a typed file name or path ("~/"
// is the home folder), and a question before a file is replaced. One instance serves every
// panel, so that the folder last used is where the next dialog opens, for the whole session.
// Where the platform's FileTransfer browses no folders (the page), saving asks for a name and
// the file is downloaded, and opening hands over to the browser's file picker.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/gui/file_transfer.hpp"
#include "app/gui/ui_status.hpp"

namespace foldlab::gui {

// The pictures the explorer reads (a swatch, a photo), as the open dialog lists them.
inline const std::vector<std::string> kImageExtensions = {".png", ".jpg", ".jpeg"};

// A typed path with "~" or "~/..." read as the home folder ($HOME); any other path as typed.
std::filesystem::path expand_home(std::string_view typed);

class FileDialog {
 public:
  enum class Mode { open, save };
  // Called with the path chosen; a returned sentence (the file cannot be read or written) keeps
  // the dialog open with it, so that another file can be chosen.
  using Chosen = std::function<std::optional<std::string>(const std::filesystem::path&)>;
  struct Request {
    Mode mode = Mode::open;
    std::string title;                    // the dialog's title, which says what it is for
    std::string file_name;                // save: the name offered
    std::vector<std::string> extensions;  // ".png", lower case: the files listed (all if empty);
                                          // save: the first is added to a name without one
    Chosen chosen;
  };
  struct Entry {
    std::string name;
    bool folder = false;
  };

  explicit FileDialog(std::filesystem::path folder) : folder_(std::move(folder)) {}

  // How files reach the user (file_transfer.hpp); the desktop's until set. Must outlive the
  // dialog.
  void set_transfer(FileTransfer& transfer) { transfer_ = &transfer; }

  // Opens the dialog (as the status's modal) in the folder last used.
  void open(Request request, UiStatus& status);
  // Once per frame, after the panels: the dialog while it is open.
  void draw(UiStatus& status);
  bool is_open() const { return request_.has_value(); }
  const std::string& title() const;
  const std::filesystem::path& folder() const { return folder_; }
  // What the folder holds as listed: "..", then folders, then the files the request lists.
  const std::vector<Entry>& entries() const { return entries_; }
  // Why the last file chosen was not taken (shown in the dialog); empty when none.
  const std::string& problem() const { return problem_; }

  // What the buttons and the name field do, for the draw and for tests: a typed name or path
  // (relative to the folder; a folder is entered), an entry clicked, the answer to "replace?".
  void submit(std::string_view typed, UiStatus& status);
  void enter(const std::filesystem::path& folder);
  // Without folders: asks the browser's picker again (the first ask may have been refused).
  void pick_again();

 private:
  // The dialog where the platform browses no folders: a name and "Download", or the picker.
  // `picked`: a file the picker has copied in, taken as chosen.
  void draw_without_folders(const std::optional<std::filesystem::path>& picked, UiStatus& status);
  // What one frame of the dialog with folders was asked: acted on after its last widget, since
  // entering a folder or choosing a file changes what the widgets read.
  struct Asked {
    std::optional<std::filesystem::path> go_to;  // a folder clicked
    std::optional<std::string> picked;           // a name or path to submit
    bool cancel = false;
  };
  // The dialog with folders, top to bottom: its popup (false while it is not shown), the folder
  // and its entries, the name field, then "Save"/"Load" (or the question before replacing a
  // file) and "Cancel".
  bool begin_browsing_popup();
  void draw_folder(Asked& asked);
  void draw_name_field(Asked& asked);
  void draw_answer_buttons(Asked& asked, bool escape);
  void act_on(const Asked& asked, UiStatus& status);
  void download(const std::string& name, UiStatus& status);
  // A file written for a download is delivered once it is there (a picture is written by the
  // frame loop after the dialog closed).
  void deliver_when_written(UiStatus& status);
  void list();
  void choose(const std::filesystem::path& path, UiStatus& status);
  void close(UiStatus& status);
  bool listed(const std::filesystem::path& file) const;

  std::filesystem::path folder_;
  std::optional<Request> request_;
  std::vector<Entry> entries_;
  char name_[1024] = {};
  std::optional<std::filesystem::path> replace_;  // asked whether to replace this file
  std::string problem_;
  bool focus_name_ = false;
  FileTransfer desktop_transfer_;
  FileTransfer* transfer_ = &desktop_transfer_;
  std::optional<std::filesystem::path> to_deliver_;
};

}  // namespace foldlab::gui
