#include "app/gui/tiles.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace foldlab::gui {

namespace tile_sizes {

// 25 font sizes hold a slider's label, the slider and its unit; 40 keep the sliders short enough
// that a pixel of drag stays a small step on a wide screen. At a large UI scale the sliders
// shorten (to 6 font sizes, 20 with the longest label) and the views keep the rest: the column
// takes at most 36 % of the width, or up to 40 % for those 20 font sizes.
float parameters_column_px(float width, float font_px) {
  const float bound = std::max(0.36f * width, std::min(20.0f * font_px, 0.40f * width));
  return std::min(std::clamp(0.30f * width, 25.0f * font_px, 40.0f * font_px), bound);
}
// The parameters take most of the column; the presets list scrolls.
float parameters_height_px(float height, float /*font_px*/) {
  return 0.62f * height;
}
// The views' toolbars are lines of text, so their row grows with the font: 56 % of the height at
// 100 % on a laptop, up to 70 % at a large UI scale, which keeps the plots' share.
float views_height_px(float height, float font_px) {
  return std::min(std::max(0.56f * height, 0.42f * height + 6.0f * font_px), 0.70f * height);
}
float half(float span, float /*font_px*/) {
  return span / 2.0f;
}

}  // namespace tile_sizes

namespace {

// One side of an edge, by its index: a panel's tile or another edge.
struct Part {
  bool tile;
  int index;
};

// The part a name in kSplits means; index -1 for a name that is neither.
constexpr Part part_named(std::string_view name) {
  for (int i = 0; i < kTileCount; ++i) {
    if (kTiles[i] == name) {
      return {true, i};
    }
  }
  for (int i = 0; i < kSplitCount; ++i) {
    if (kSplits[i].key == name) {
      return {false, i};
    }
  }
  return {false, -1};
}

// Every tile and every edge but the root is a side of exactly one edge, which comes before it
// (so that the tree has no loop), and every side names one of them.
constexpr bool is_a_tree() {
  int tiles_used[kTileCount] = {};
  int splits_used[kSplitCount] = {};
  for (int i = 0; i < kSplitCount; ++i) {
    for (const std::string_view side : {kSplits[i].first, kSplits[i].second}) {
      const Part part = part_named(side);
      if (part.index < 0 || (!part.tile && part.index <= i)) {
        return false;
      }
      if (part.tile) {
        ++tiles_used[part.index];
      } else {
        ++splits_used[part.index];
      }
    }
  }
  for (int used : tiles_used) {
    if (used != 1) {
      return false;
    }
  }
  for (int i = 1; i < kSplitCount; ++i) {
    if (splits_used[i] != 1) {
      return false;
    }
  }
  return splits_used[0] == 0;
}
static_assert(is_a_tree());

// The least a panel keeps either way of a dragged edge: its title and a few lines (a quarter of
// the window at most, so that the bounds never cross).
struct Least {
  float width_px;
  float height_px;
};

// The least extent of a part along x (or y): a tile's least, the sum over an edge across that
// axis, the larger side along it.
float least_extent(Part part, bool along_x, const Least& least) {
  if (part.tile) {
    return along_x ? least.width_px : least.height_px;
  }
  const TileSplit& s = kSplits[part.index];
  const float a = least_extent(part_named(s.first), along_x, least);
  const float b = least_extent(part_named(s.second), along_x, least);
  return s.side_by_side == along_x ? a + b : std::max(a, b);
}

void lay_out(Part part, const PanelRect& rect, float font_px, const Least& least,
             const LayoutSplits& splits, TiledLayout& out) {
  if (part.tile) {
    out.tiles[static_cast<std::size_t>(part.index)] = rect;
    return;
  }
  out.splits[static_cast<std::size_t>(part.index)] = rect;
  const TileSplit& s = kSplits[part.index];
  const float span = s.side_by_side ? rect.size.x : rect.size.y;
  const float dragged = splits.fraction[static_cast<std::size_t>(part.index)];
  // A dragged edge comes back to the whole pixel it was dragged to, whatever the fraction's
  // rounding.
  const float chosen = dragged >= 0.0f ? std::round(dragged * span) : s.automatic_px(span, font_px);
  const float high = span - least_extent(part_named(s.second), s.side_by_side, least);
  const float low = std::min(least_extent(part_named(s.first), s.side_by_side, least), high);
  const float first = std::floor(std::clamp(chosen, low, high));
  out.edge_px[static_cast<std::size_t>(part.index)] =
      (s.side_by_side ? rect.pos.x : rect.pos.y) + first;
  PanelRect a = rect;
  PanelRect b = rect;
  if (s.side_by_side) {
    a.size.x = first;
    b.pos.x = rect.pos.x + first;
    b.size.x = rect.size.x - first;
  } else {
    a.size.y = first;
    b.pos.y = rect.pos.y + first;
    b.size.y = rect.size.y - first;
  }
  lay_out(part_named(s.first), a, font_px, least, splits, out);
  lay_out(part_named(s.second), b, font_px, least, splits, out);
}

// The edge that holds `part` as its first or second side.
std::optional<std::pair<int, bool>> parent_of(Part part) {
  for (int i = 0; i < kSplitCount; ++i) {
    const Part first = part_named(kSplits[i].first);
    const Part second = part_named(kSplits[i].second);
    if (first.tile == part.tile && first.index == part.index) {
      return std::pair{i, true};
    }
    if (second.tile == part.tile && second.index == part.index) {
      return std::pair{i, false};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<int> tile_index(std::string_view panel_key) {
  for (int i = 0; i < kTileCount; ++i) {
    if (kTiles[i] == panel_key) {
      return i;
    }
  }
  return std::nullopt;
}

const char* split_key(int split) {
  return kSplits[split].key;
}

TiledLayout tiled_layout(ImVec2 display, float top_px, float font_px, const LayoutSplits& splits) {
  const float width = std::max(std::floor(display.x), 1.0f);
  const float height = std::max(std::floor(display.y - top_px), 1.0f);
  const Least least{std::min(8.0f * font_px, 0.25f * width),
                    std::min(4.0f * font_px, 0.25f * height)};
  TiledLayout out;
  lay_out(Part{false, 0}, PanelRect{ImVec2(0.0f, std::floor(top_px)), ImVec2(width, height)},
          font_px, least, splits, out);
  return out;
}

bool drag_split(int tile, Edge edge, float to_px, const TiledLayout& layout, LayoutSplits& splits) {
  // The nearest edge above the tile in the tree that lies on the dragged side.
  const bool vertical = edge == Edge::left || edge == Edge::right;
  const bool tile_is_first = edge == Edge::right || edge == Edge::bottom;
  Part part{true, tile};
  while (const std::optional<std::pair<int, bool>> parent = parent_of(part)) {
    const auto [split, first] = *parent;
    if (kSplits[split].side_by_side == vertical && first == tile_is_first) {
      const PanelRect& area = layout.splits[static_cast<std::size_t>(split)];
      if ((vertical ? area.size.x : area.size.y) <= 0.0f) {
        return false;
      }
      move_split(split, to_px, layout, splits);
      return true;
    }
    part = Part{false, split};
  }
  return false;
}

void move_split(int split, float to_px, const TiledLayout& layout, LayoutSplits& splits) {
  const PanelRect& area = layout.splits[static_cast<std::size_t>(split)];
  const bool vertical = kSplits[split].side_by_side;
  const float origin = vertical ? area.pos.x : area.pos.y;
  const float span = vertical ? area.size.x : area.size.y;
  if (span > 0.0f) {
    splits.fraction[static_cast<std::size_t>(split)] =
        std::clamp((to_px - origin) / span, 0.0f, 1.0f);
  }
}

PanelRect tile_handle(int split, const TiledLayout& layout, float across_px, float along_px) {
  const bool vertical = kSplits[split].side_by_side;
  const PanelRect& area = layout.splits[static_cast<std::size_t>(split)];
  const float edge = layout.edge_px[static_cast<std::size_t>(split)];
  const float start = vertical ? area.pos.y : area.pos.x;
  const float end = start + (vertical ? area.size.y : area.size.x);
  // Where the edges across this one end on it, from either side.
  std::vector<float> cuts{start, end};
  for (int other = 0; other < kSplitCount; ++other) {
    if (kSplits[other].side_by_side == vertical) {
      continue;
    }
    const PanelRect& across = layout.splits[static_cast<std::size_t>(other)];
    const float low = vertical ? across.pos.x : across.pos.y;
    const float high = low + (vertical ? across.size.x : across.size.y);
    const float at = layout.edge_px[static_cast<std::size_t>(other)];
    if ((low == edge || high == edge) && at > start && at < end) {
      cuts.push_back(at);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  float from = start;
  float to = start;
  for (std::size_t i = 1; i < cuts.size(); ++i) {
    if (cuts[i] - cuts[i - 1] > to - from) {
      from = cuts[i - 1];
      to = cuts[i];
    }
  }
  const float length = std::min(along_px, to - from);
  const float along_pos = std::floor(0.5f * (from + to - length));
  const float across_pos = std::floor(edge - 0.5f * across_px);
  return vertical ? PanelRect{ImVec2(across_pos, along_pos), ImVec2(across_px, length)}
                  : PanelRect{ImVec2(along_pos, across_pos), ImVec2(length, across_px)};
}

}  // namespace foldlab::gui
