// The words a frame drew, read back from the glyph quads of ImGui's draw data: what a person
// sees, whichever widget drew it. The play driver finds a label by them and the layout's check
// finds text cut at an edge by them.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

#include <imgui.h>

namespace foldlab::gui {

// The font's glyphs by the texture coordinates of their top-left corner: a glyph's quad in the
// draw data is recognised by them.
class GlyphsByUv {
 public:
  explicit GlyphsByUv(const ImFont& font) {
    for (const ImFontGlyph& g : font.Glyphs) {
      if (g.Visible) {
        by_uv_.emplace(key(g.U0, g.V0), &g);
      }
    }
  }

  const ImFontGlyph* find(const ImVec2& uv) const {
    const auto found = by_uv_.find(key(uv.x, uv.y));
    return found == by_uv_.end() ? nullptr : found->second;
  }

 private:
  static std::uint64_t key(float u, float v) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u * 1e6f)) << 32) |
           static_cast<std::uint32_t>(v * 1e6f);
  }

  std::unordered_map<std::uint64_t, const ImFontGlyph*> by_uv_;
};

inline void append_utf8(std::string& text, unsigned c) {
  if (c < 0x80) {
    text += static_cast<char>(c);
  } else if (c < 0x800) {
    text += static_cast<char>(0xC0 | (c >> 6));
    text += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    text += static_cast<char>(0xE0 | (c >> 12));
    text += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    text += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace foldlab::gui
