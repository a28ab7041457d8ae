// The automatic layout of the explorer's tiled panels: one tree, written once in tiles.cpp, of
// edges that split the display below the menu bar in two, side by side or one over the other,
// down to the panels, named by their keys. The display is tiled edge to edge with no gap; an
// edge the user dragged is kept as a fraction of what it divides. Pure geometry: no ImGui state.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include <imgui.h>

namespace foldlab::gui {

// A panel's place on the display, in whole pixels (ImGui floors what it is given).
struct PanelRect {
  ImVec2 pos{0, 0};
  ImVec2 size{0, 0};
};

// How many panels and edges the tree has (checked against the tree in tiles.cpp).
inline constexpr int kTileCount = 6;
inline constexpr int kSplitCount = 5;

// Whether the panel with this key has a tile, and its tile's index (in the tree's order).
std::optional<int> tile_index(std::string_view panel_key);
// Each edge's key in the session ("layout_views"), in the tree's order.
const char* split_key(int split);

// Where the user dragged each edge, as a fraction of what it divides; a negative fraction leaves
// that edge where the automatic layout puts it.
struct LayoutSplits {
  static constexpr std::array<float, kSplitCount> all_automatic() {
    std::array<float, kSplitCount> fractions{};
    fractions.fill(-1.0f);
    return fractions;
  }
  std::array<float, kSplitCount> fraction = all_automatic();
  bool any() const {
    for (float f : fraction) {
      if (f >= 0.0f) {
        return true;
      }
    }
    return false;
  }
};

// Every tile's rectangle (by tile_index) and every edge's rectangle, the area it divides (by
// split).
struct TiledLayout {
  std::array<PanelRect, kTileCount> tiles;
  std::array<PanelRect, kSplitCount> splits;
  const PanelRect* find(std::string_view panel_key) const {
    const std::optional<int> i = tile_index(panel_key);
    return i ? &tiles[static_cast<std::size_t>(*i)] : nullptr;
  }
};

// The display below `top_px` (the menu bar) tiled. Each edge's automatic place is a function of
// the span it divides and the font size, so that the layout follows the UI scale; `splits` moves
// the edges the user dragged. Every panel keeps at least a few font sizes either way.
TiledLayout tiled_layout(ImVec2 display, float top_px, float font_px,
                         const LayoutSplits& splits = {});

// A tile's edge that a user dragged to `to_px` (screen coordinates): the split it moves, as a
// fraction of what it divides. False when that edge is the window's border, which stays.
enum class Edge { left, right, top, bottom };
bool drag_split(int tile, Edge edge, float to_px, const TiledLayout& layout, LayoutSplits& splits);

}  // namespace foldlab::gui
