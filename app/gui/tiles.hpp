// The automatic layout of the explorer's tiled panels: one tree, written once here, of
// edges that split the display below the menu bar in two, side by side or one over the other,
// down to the panels, named by their keys. The display is tiled edge to edge with no gap; an
// edge the user dragged is kept as a fraction of what it divides. Pure geometry: no ImGui state.
#pragma once

#include <algorithm>
#include <array>
#include <iterator>
#include <optional>
#include <string_view>

#include <imgui.h>

namespace foldlab::gui {

// A panel's place on the display, in whole pixels (ImGui floors what it is given).
struct PanelRect {
  ImVec2 pos{0, 0};
  ImVec2 size{0, 0};
};

// A window's first place (one that opens and closes, as the tension field), over the tiles of a
// `display` whose menu bar is `top_px` high.
inline PanelRect first_window_place(ImVec2 display, float top_px) {
  return {ImVec2(0.2f * display.x, std::max(0.15f * display.y, top_px)),
          ImVec2(0.6f * display.x, 0.7f * display.y)};
}

// Where an edge goes when the user has not dragged it, from the span it divides and the font
// size (tiles.cpp), so that the layout follows the UI scale.
namespace tile_sizes {
float parameters_column_px(float width, float font_px);
float parameters_height_px(float height, float font_px);
float views_height_px(float height, float font_px);
float half(float span, float font_px);
}  // namespace tile_sizes

// An edge of the tree.
struct TileSplit {
  const char* key;    // in the session
  bool side_by_side;  // a vertical edge; otherwise the first part is above the second
  float (*automatic_px)(float span_px, float font_px);
  // Each side: a panel's key (its tile) or another edge's key.
  std::string_view first, second;
};

// The panels that have a tile, by their keys.
inline constexpr std::string_view kTiles[] = {"parameters", "presets", "fold_plot",
                                              "cloth",      "results", "analysis"};
// The tree, root first: the parameters over the presets in a column on the left; right of it the
// 2D plot beside the 3D view, over the results beside the analysis. tiles.cpp checks at compile
// time that it is one tree over every tile.
inline constexpr TileSplit kSplits[] = {
    {"layout_left_column", true, tile_sizes::parameters_column_px, "layout_parameters",
     "layout_views"},
    {"layout_parameters", false, tile_sizes::parameters_height_px, "parameters", "presets"},
    {"layout_views", false, tile_sizes::views_height_px, "layout_fold_plot", "layout_results"},
    {"layout_fold_plot", true, tile_sizes::half, "fold_plot", "cloth"},
    {"layout_results", true, tile_sizes::half, "results", "analysis"},
};
inline constexpr int kTileCount = static_cast<int>(std::size(kTiles));
inline constexpr int kSplitCount = static_cast<int>(std::size(kSplits));

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
// split), and where each edge lies across that area (x for a vertical edge, y otherwise).
struct TiledLayout {
  std::array<PanelRect, kTileCount> tiles;
  std::array<PanelRect, kSplitCount> splits;
  std::array<float, kSplitCount> edge_px{};
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
// The edge `split` moved to `to_px` (screen coordinates), as a fraction of what it divides; the
// layout keeps each side's least size.
void move_split(int split, float to_px, const TiledLayout& layout, LayoutSplits& splits);

// A finger's grip on the edge `split`: `across_px` wide across the edge, centred on it, and up to
// `along_px` long, centred on the longest stretch of the edge that no other edge meets (so that
// where three tiles meet no two grips overlap).
PanelRect tile_handle(int split, const TiledLayout& layout, float across_px, float along_px);

}  // namespace foldlab::gui
