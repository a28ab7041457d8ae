// Where the explorer's panels go: the automatic tiles (tiled_layout), the edges the user dragged,
// the user's own arrangement once a panel is moved by its title, and presentation (one tiled
// panel filling the window below a read-out). The Explorer draws the panels; the Layout places
// the tiled ones before each draw and watches what the user did to them after it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/gui/panel.hpp"
#include "app/gui/tiles.hpp"
#include "app/gui/view_settings.hpp"

namespace foldlab::gui {

class Layout {
 public:
  // `panels`: the explorer's list, which outlives the layout; a panel whose key is in the tiles'
  // tree (tiles.cpp) is tiled, the others float.
  explicit Layout(const std::vector<std::unique_ptr<Panel>>& panels) : panels_(panels) {}

  // At the frame's start, after the menu bar (`menu_height_px` high): a requested presentation
  // takes effect, and the tiles are laid out, following an edge the user dragged in the last
  // frame.
  void begin_frame(float menu_height_px);
  // While a panel is presented: the read-out above it ends at `top_px`.
  void set_presented_top(float top_px);
  // Whether the panel has a tile.
  static bool tiled(const Panel& panel) { return tile_index(panel.key()).has_value(); }
  // Whether View > Present offers it: a tiled panel, or a window that says it may fill the
  // window (the tension field).
  static bool presentable(const Panel& panel) { return tiled(panel) || panel.presentable(); }
  // Whether the panel is drawn this frame (a tiled one behind the presented one is not).
  bool shows(const Panel& panel) const;
  // Before a presentable panel's draw: a tiled one's place in the automatic layout (every frame
  // until the user moves a panel), or the whole window below the read-out while it is presented;
  // a window put back where it was after it was presented.
  void place(const Panel& panel);
  // After a presentable panel's draw: the button in its title bar (and a double-click on the
  // title) that presents it, or returns to the tiles.
  void present_button(const Panel& panel);

  // Presentation: one presentable panel fills the window (opened, if it is a window that opens),
  // the other presentable ones hidden; null returns to the tiles. Not remembered: a start shows
  // the tiles.
  void present(const Panel* panel);
  // From a menu or a button, taking effect at the next frame's start.
  void request_present(const Panel* panel) { present_request_ = panel; }
  const Panel* presented() const { return presented_; }
  // When the view presented now was presented (ImGui's clock, s).
  double presented_since_s() const { return presented_since_s_; }
  // Whether a presented view has the strip of the cloth's inputs under its read-out (remembered).
  bool presents_inputs() const { return presents_inputs_; }
  void set_presents_inputs(bool shown) { presents_inputs_ = shown; }
  // On a coarse pointer, after the tiled panels' draw: a grip a finger wide (`target_px`) on each
  // edge between two tiles, drawn over both, that drags the edge as ImGui's few-pixel window
  // border does for a mouse. None for a mouse, while a panel is presented, or once the user
  // arranged the panels.
  void tile_handles(bool coarse_pointer, float target_px);
  // Where each grip was drawn in the last frame (its whole target), by its edge's key.
  const std::vector<std::pair<std::string, PanelRect>>& handle_rects() const {
    return handle_rects_;
  }
  // "View > Reset layout": the automatic layout again, from the next frame.
  void reset();
  // True while the panels follow the window (until the user moves or resizes one).
  bool automatic() const { return automatic_; }
  const LayoutSplits& splits() const { return splits_; }
  // Where each tiled panel was drawn in the last frame (ImGui's windows, after the user's moves),
  // by Panel::key().
  std::vector<std::pair<std::string, PanelRect>> panel_rects() const;
  // Where the tiled `panel` was placed last (zero when it was not).
  PanelRect rect_of(const Panel& panel) const;
  // True when the tiled panels cover the display below the menu bar exactly: no gap, no overlap,
  // nothing outside it.
  bool fills_window() const;
  // True when the automatic tiles, as last laid out, leave a panel too small for the text size
  // (a projector's 1280 x 800 at 200 %: a slider or two in sight, labels cut at the panel's
  // edge): the menu bar then says so and offers to present one view. Never while one is
  // presented or the user arranged the panels.
  bool cramped() const;
  // The least a tile must be, in font sizes, to hold a panel's rows.
  static constexpr float kLeastTileWidthEms = 16.0f;
  static constexpr float kLeastTileHeightEms = 9.0f;

  // The user's arrangement: automatic or not, the dragged edges, and the presented inputs' strip.
  // The dragged edges, the automatic layout and the strip (remembered); `present` (scripted).
  void view_settings(ViewSettings& settings);
  // The presentable panel with this key, or null.
  Panel* presentable_panel(std::string_view key) const;

 private:
  // A resize of a tiled panel since the last frame moves the split it shares with its
  // neighbours; a move of one leaves the tiles for the user's own arrangement. True when a split
  // moved.
  bool follow_user_edits();
  void forget_places();

  const std::vector<std::unique_ptr<Panel>>& panels_;
  bool automatic_ = true;
  double presented_since_s_ = 0.0;
  float menu_height_px_ = 0.0f;
  TiledLayout tiles_;
  PanelRect placed_[kTileCount];  // what place() set last, to see the user's moves
  bool placed_valid_[kTileCount] = {};
  LayoutSplits splits_;
  const Panel* presented_ = nullptr;
  bool presents_inputs_ = true;
  PanelRect presented_rect_;  // where the presented panel goes this frame
  std::optional<const Panel*> present_request_;
  // In the user's own arrangement, where a presented panel was, to put it back.
  std::optional<PanelRect> restore_[kTileCount];
  std::vector<std::pair<std::string, PanelRect>> handle_rects_;
  // While a grip is held: how far from its edge the finger took it, along the drag.
  float handle_grab_px_ = 0.0f;
  // Where a presented window was, to put it back.
  std::optional<PanelRect> window_restore_;
  const Panel* window_to_restore_ = nullptr;
};

}  // namespace foldlab::gui
