#include "app/gui/clipped_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include <imgui_internal.h>  // the window a draw list belongs to, for its wrapping edge

#include "app/gui/drawn_glyphs.hpp"

namespace foldlab::gui {
namespace {

// A glyph that sticks out of its clip rectangle by less than this is whole: a bearing or the
// rounding of a glyph's quad.
constexpr float kEdgeTolerancePx = 0.75f;

struct DrawnGlyph {
  unsigned codepoint = 0;
  float pen_x = 0.0f;    // where the glyph's advance starts
  float line_y = 0.0f;   // the top of its line
  float right = 0.0f;    // the quad's right edge
  float advance = 0.0f;  // scaled
  float line_height = 0.0f;
  bool cut = false;
  ImVec4 clip;
};

struct DrawnLine {
  std::string text;
  std::vector<DrawnGlyph> glyphs;
  bool cut = false;
  bool one_word = true;
};

bool quad_at(const ImDrawList& list, const ImDrawCmd& cmd, unsigned first, const ImDrawVert*& a,
             const ImDrawVert*& c) {
  const ImDrawIdx* idx = list.IdxBuffer.Data + first;
  if (idx[1] != idx[0] + 1 || idx[2] != idx[0] + 2 || idx[3] != idx[0] || idx[4] != idx[0] + 2 ||
      idx[5] != idx[0] + 3) {
    return false;
  }
  const unsigned base = cmd.VtxOffset + idx[0];
  if (base + 3 >= static_cast<unsigned>(list.VtxBuffer.Size)) {
    return false;
  }
  const ImDrawVert* v = list.VtxBuffer.Data + base;
  // Axis-aligned, with texture coordinates that run the same way: a glyph's quad.
  if (v[1].pos.y != v[0].pos.y || v[3].pos.x != v[0].pos.x || v[2].pos.x != v[1].pos.x ||
      v[2].pos.y != v[3].pos.y || !(v[2].pos.x > v[0].pos.x) || !(v[2].pos.y > v[0].pos.y)) {
    return false;
  }
  a = &v[0];
  c = &v[2];
  return true;
}

// Every glyph a draw list shows, in drawing order.
std::vector<DrawnGlyph> glyphs_of(const ImDrawList& list, const GlyphsByUv& glyphs,
                                  const ImFont& font) {
  std::vector<DrawnGlyph> out;
  for (const ImDrawCmd& cmd : list.CmdBuffer) {
    if (cmd.UserCallback != nullptr) {
      continue;
    }
    const unsigned end = cmd.IdxOffset + cmd.ElemCount;
    for (unsigned i = cmd.IdxOffset; i + 6 <= end;) {
      const ImDrawVert* a = nullptr;
      const ImDrawVert* c = nullptr;
      const ImFontGlyph* glyph = nullptr;
      if (quad_at(list, cmd, i, a, c)) {
        glyph = glyphs.find(a->uv);
      }
      if (glyph == nullptr || glyph->X1 <= glyph->X0 || glyph->Y1 <= glyph->Y0) {
        i += 3;
        continue;
      }
      const bool right_trimmed = c->uv.x < glyph->U1 - 1e-6f;
      const bool bottom_trimmed = c->uv.y < glyph->V1 - 1e-6f;
      // The size it was drawn at, from a side ImGui's fine clipping left whole.
      float scale = 1.0f;
      if (!bottom_trimmed) {
        scale = (c->pos.y - a->pos.y) / (glyph->Y1 - glyph->Y0);
      } else if (!right_trimmed) {
        scale = (c->pos.x - a->pos.x) / (glyph->X1 - glyph->X0);
      }
      DrawnGlyph g;
      g.codepoint = glyph->Codepoint;
      g.pen_x = a->pos.x - glyph->X0 * scale;
      g.line_y = a->pos.y - glyph->Y0 * scale;
      g.right = c->pos.x;
      g.advance = glyph->AdvanceX * scale;
      g.line_height = font.FontSize * scale;
      g.clip = cmd.ClipRect;
      g.cut = right_trimmed || a->pos.x < cmd.ClipRect.x - kEdgeTolerancePx ||
              c->pos.x > cmd.ClipRect.z + kEdgeTolerancePx;
      // Wholly above or below its clip rectangle: scrolled out of sight, not cut.
      if (c->pos.y <= cmd.ClipRect.y || a->pos.y >= cmd.ClipRect.w) {
        g.cut = false;
      }
      out.push_back(g);
      i += 6;
    }
  }
  return out;
}

bool same_clip(const ImVec4& a, const ImVec4& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
}

// The glyphs in lines: one line while the baseline stays and the pen moves right.
std::vector<DrawnLine> lines_of(const std::vector<DrawnGlyph>& glyphs, const ImFont& font,
                                float space_advance) {
  std::vector<DrawnLine> lines;
  for (const DrawnGlyph& g : glyphs) {
    bool starts_line = lines.empty();
    if (!starts_line) {
      const DrawnGlyph& last = lines.back().glyphs.back();
      starts_line = std::abs(g.line_y - last.line_y) > 1.0f || g.pen_x < last.pen_x - 1.0f ||
                    !same_clip(g.clip, last.clip);
    }
    if (starts_line) {
      lines.emplace_back();
    } else {
      const DrawnGlyph& last = lines.back().glyphs.back();
      // A space draws nothing: a gap wider than half of one, at the size drawn, is one.
      const float scale = g.line_height / std::max(font.FontSize, 1e-3f);
      if (g.pen_x - (last.pen_x + last.advance) > 0.5f * space_advance * scale) {
        lines.back().text += ' ';
        lines.back().one_word = false;
      }
    }
    DrawnLine& line = lines.back();
    append_utf8(line.text, g.codepoint);
    line.glyphs.push_back(g);
    line.cut = line.cut || g.cut;
  }
  return lines;
}

bool is_digit(unsigned c) {
  return c >= '0' && c <= '9';
}

// The panel a draw list belongs to: the key after "###" in its window's name ("parameters"),
// "menu_bar" for the main menu bar, else ImGui's name for it ("##Menu_00").
std::string panel_of(std::string_view owner) {
  if (owner == "##MainMenuBar") {
    return "menu_bar";
  }
  const std::size_t id = owner.find("###");
  if (id != std::string_view::npos) {
    const std::string_view key = owner.substr(id + 3);
    return std::string(key.substr(0, key.find('/')));
  }
  return std::string(owner.substr(0, owner.find('/')));
}

}  // namespace

std::vector<ClippedText> clipped_text(const ImDrawData& data, const ImFont& font) {
  std::vector<ClippedText> found;
  const auto add = [&found](ClippedText item) {
    if (std::none_of(found.begin(), found.end(), [&](const ClippedText& seen) {
          return seen.panel == item.panel && seen.text == item.text && seen.how == item.how;
        })) {
      found.push_back(std::move(item));
    }
  };
  if (!data.Valid) {
    return found;
  }
  const GlyphsByUv glyphs(font);
  const ImFontGlyph* space = font.FindGlyphNoFallback(' ');
  const float space_advance = space != nullptr ? space->AdvanceX : 0.25f * font.FontSize;
  for (int l = 0; l < data.CmdListsCount; ++l) {
    const ImDrawList& list = *data.CmdLists[l];
    const std::string_view owner = list._OwnerName != nullptr ? list._OwnerName : "";
    const std::string panel = panel_of(owner);
    const ImGuiWindow* window =
        owner.empty() ? nullptr : ImGui::FindWindowByName(std::string(owner).c_str());
    // Where ImGui wraps text in this window by default (a wrap position of 0).
    const float wrap_edge = window != nullptr ? window->ContentRegionRect.Max.x
                                              : std::numeric_limits<float>::infinity();
    const std::vector<DrawnLine> lines =
        lines_of(glyphs_of(list, glyphs, font), font, space_advance);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const DrawnLine& line = lines[i];
      if (line.cut) {
        add({panel, line.text, "cut"});
      }
      if (i + 1 == lines.size()) {
        continue;
      }
      // The next line of the same text: one line height lower, from the same left edge (the
      // lines of two items stand an item spacing apart).
      const DrawnLine& next = lines[i + 1];
      const DrawnGlyph& end = line.glyphs.back();
      const DrawnGlyph& start = next.glyphs.front();
      const bool wrapped_on = std::abs(start.line_y - (end.line_y + end.line_height)) <= 1.0f &&
                              std::abs(start.pen_x - line.glyphs.front().pen_x) <= 1.0f;
      if (!wrapped_on) {
        continue;
      }
      const bool number_broken = line.glyphs.size() >= 2 && is_digit(start.codepoint) &&
                                 (end.codepoint == '.' || end.codepoint == ',') &&
                                 is_digit(line.glyphs[line.glyphs.size() - 2].codepoint);
      const bool word_broken =
          line.one_word && end.pen_x + end.advance + start.advance > wrap_edge - 1.0f;
      if (number_broken || word_broken) {
        add({panel, line.text + "\n" + next.text, "wrapped inside a word"});
      }
    }
  }
  return found;
}

}  // namespace foldlab::gui
