// The fabric the explorer's panels share, one copy of each: the preset as loaded, the parameters
// being edited (possibly invalid) with their validation, the scene that always holds the last
// valid parameters, its appearance, the fabric pinned as B, the undo history and the question asked
// before unsaved edits are replaced. What the explorer says and remembers about itself (status
// line, dialogs, session flag, expert mode) is the UiStatus beside it, which the document reports
// to. The parameters change only through apply(Edit) (and the preset loads, undo and redo built on
// it), so that a slider, a map click, a preset load and a scripted run all take the same path to
// the scene: one validation, one commit, one piece of undo bookkeeping.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/gui/compare.hpp"
#include "app/gui/ui_status.hpp"
#include "core/geometry/scene.hpp"
#include "core/io/preset.hpp"
#include "core/model/parameters.hpp"
#include "core/model/settings.hpp"

namespace foldlab::gui {

// One change to the parameters, as a value: what Document::apply takes.
struct Edit {
  enum class Kind {
    assign,   // inputs through the input table, in order
    replace,  // the whole Parameters (a preset loaded, a restored session or undo step)
  };
  Kind kind = Kind::assign;
  std::vector<Assignment> assignments;  // for assign
  Parameters parameters;                // for replace
  // True: the edit is an undo step of its own (a script, a map click, a button). False: it stays
  // open and later edits join it until Document::end_step (a slider being dragged).
  bool closes_step = true;
  // True: the values come from a slider moved by the mouse or a key (their last digits are where
  // the hand stopped), so links and saved presets write them with the digits the slider shows.
  // False: typed, loaded or computed values, written exactly.
  bool dragged = false;

  static Edit input(std::string key, double value);
  // Several inputs at once, one undo step (a regime-map click sets x and y).
  static Edit inputs(std::vector<std::pair<std::string, double>> values);
  static Edit choose(std::string key, std::string text);
  // Numbers and choices at once, one undo step (a law with its constants), in the order given: K
  // after nu, as --set applies them.
  static Edit assign(std::vector<Assignment> assignments);
  static Edit replace(Parameters parameters);
  // The same edit, left open for the widget that is still being dragged or typed into.
  Edit open() && {
    closes_step = false;
    return std::move(*this);
  }
  Edit by_slider() && {
    dragged = true;
    return std::move(*this);
  }
};

class Document {
 public:
  // `status` hears of loads, undo and redo and of every change the session keeps; it must
  // outlive the document.
  Document(const Preset& initial, std::string initial_path, UiStatus& status);

  const Preset& loaded() const { return loaded_; }
  const std::string& loaded_path() const { return loaded_path_; }
  // What the widgets show: the last edit, possibly refused. Changed only by apply().
  const Parameters& edited() const { return edited_; }
  const std::vector<ValidationIssue>& issues() const { return issues_; }
  // The inputs whose value a slider set last (Edit::dragged): a link or a saved preset writes
  // them with the digits the slider shows.
  const std::vector<std::string>& dragged_keys() const { return dragged_keys_; }
  // edited() as the user can read it back: every dragged input at the slider's digits.
  Parameters edited_as_shown() const;
  // How the fabric looks (its colour in the 3D view): no input of the model, yet saved with the
  // preset, compared by the unsaved marker and restored by undo like the parameters.
  const foldlab::Appearance& appearance() const { return appearance_; }
  // An undo step of its own unless `closes_step` is false (a colour still being dragged in the
  // picker), which end_step closes as an open edit is.
  void set_appearance(const foldlab::Appearance& appearance, bool closes_step = true);
  // The model of the last valid edit. Mutable because it computes its grid and lines lazily; its
  // parameters change only through apply(), its grid resolution only through set_grid_resolution.
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  // Vertices per side of the 3D cloth mesh, a view setting remembered in the session (no re-solve).
  void set_grid_resolution(int per_side) {
    if (per_side != scene_.grid_nx()) {
      status_.mark_session_dirty();
    }
    scene_.set_grid_resolution(per_side, per_side);
  }

  // The one write path for the parameters. The edit replaces edited() and is validated once; the
  // model (the scene) sees it only when it validates, otherwise the scene keeps the last valid
  // state and the widgets show the user's value with the reason it was refused (issues()). Then
  // the undo step is closed unless the edit is open(). Returns the reason when a key or a value
  // cannot be applied at all (an unknown key, a fraction for a whole number, an unknown name);
  // then nothing changes. Range problems are issues(), never a return value.
  std::optional<std::string> apply(const Edit& edit);
  void reset_to_loaded();
  // Loads a preset file in place of the edits; on failure keeps everything and says why.
  void load_preset_file(const std::filesystem::path& path);
  // Replaces the preset as loaded (a restored session, or the file just saved).
  void adopt(const Preset& loaded, std::string path);
  // Another fabric becomes the one edited, as one undo step: `origin` (from `path`) as loaded,
  // `parameters` over it (a swap with B). Nothing changes, and the reason is returned, when the
  // parameters cannot be applied.
  std::optional<std::string> take_fabric(const Preset& origin, std::string path,
                                         const Parameters& parameters,
                                         const foldlab::Appearance& appearance);
  // True when the valid parameters or the appearance differ from the preset as loaded, or an
  // input is refused.
  bool unsaved() const;
  // Counts preset loads, so that views can reframe for a new cloth.
  std::uint64_t loads() const { return loads_; }

  // What playback reports: the refusal shown at the foot of the sliders (null when all are
  // accepted).
  std::optional<std::string> refusal() const;

  // Undo history. A continuous edit (a slider being dragged, a value being typed) changes
  // edited() frame after frame; end_step() closes it as one step, called by the frame when no
  // widget is active, so one drag is one step. Closing edits and preset loads close their own.
  void end_step();
  bool undo();
  bool redo();
  std::size_t undo_depth() const { return undo_.size(); }
  std::size_t redo_depth() const { return redo_.size(); }
  // The current state becomes the base of a new history (a restored session).
  void forget_history();

  // Runs `replace` (which replaces the edits, e.g. loads another preset) now when nothing would be
  // lost, else asks first: the explorer shows UiStatus::kUnsavedModal until save_and_replace,
  // discard_and_replace or cancel_replace answers it. `what` is the question's sentence on what
  // would happen to the edits ("Loading X replaces them.").
  void replace_edits(std::string what, std::function<void(Document&)> replace);
  const std::string& pending_replacement() const { return pending_what_; }
  void discard_and_replace();
  void cancel_replace();
  // After the edits were saved: runs the pending replacement, if any.
  void continue_replace();

  // The fabric pinned as B beside this one (A). Pinning, swapping and clearing are undo steps
  // like an edit of A (app/gui/compare.hpp), so that an undone swap brings back both fabrics.
  Comparison& compare() { return compare_; }
  const Comparison& compare() const { return compare_; }

 private:
  // What an undo step restores: the preset as loaded, the edits over it and the fabric pinned
  // as B.
  struct Snapshot {
    Preset loaded;
    std::string loaded_path;
    Parameters edited;
    foldlab::Appearance appearance;
    std::optional<PinnedFabric> compare_b;
  };
  // Validates edited_ and hands it to the scene when valid.
  void commit();
  Snapshot snapshot() const;
  static bool same(const Snapshot& a, const Snapshot& b);
  void restore(const Snapshot& s);
  // `origin` from `path` becomes the preset as loaded; another preset counts as a load.
  void set_loaded(const Preset& origin, std::string path);
  bool step_through_history(std::vector<Snapshot>& from, std::vector<Snapshot>& to,
                            const char* message);

  Preset loaded_;
  std::string loaded_path_;
  Parameters edited_;
  std::vector<std::string> dragged_keys_;
  foldlab::Appearance appearance_;
  std::vector<ValidationIssue> issues_;
  Scene scene_;
  std::uint64_t loads_ = 0;
  Comparison compare_;
  UiStatus& status_;

  Snapshot step_base_;  // the state when the open step began
  std::vector<Snapshot> undo_;
  std::vector<Snapshot> redo_;

  std::string pending_what_;
  std::function<void(Document&)> pending_replace_;
};

}  // namespace foldlab::gui
