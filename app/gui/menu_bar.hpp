// The explorer's menu bar: View (text size, theme, presenting, the introduction, the layout),
// Compare, Export (the files, the panels' pictures and the link), and while a view is presented
// the way back to the tiles and the strip of inputs shown or hidden.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "app/gui/layout.hpp"
#include "app/gui/page_link.hpp"
#include "app/gui/panel.hpp"
#include "app/gui/panels/export_panel.hpp"

namespace foldlab::gui {

class Appearance;

class MenuBar {
 public:
  // The items that show or hide the strip of inputs, and the one back to the tiles (short when
  // the bar is narrow).
  static constexpr const char* kShowInputsLabel = "Show inputs";
  static constexpr const char* kHideInputsLabel = "Hide inputs";
  static constexpr const char* kBackToTilesLabel = "Back to the tiles (Esc)";
  // While the tiles are too small for the text size (Layout::cramped).
  static constexpr const char* kCrampedNotice = "The tiles are too small for this text size:";
  static constexpr const char* kCrampedShortNotice = "Tiles too small:";
  static constexpr const char* kCrampedTooltip =
      "At this text size the six tiles cut their sliders and labels. Present one view to fill "
      "the window with it (with the inputs under its read-out), or choose a smaller text size in "
      "View.";
  static constexpr const char* kPresentOneViewLabel = "Present one view";
  static constexpr const char* kBackToTilesShortLabel = "Tiles (Esc)";

  // `copy_link`: what Export > Copy link does; `link_choices`: what its items beside it set.
  MenuBar(Layout& layout, Appearance& appearance, LinkChoices& link_choices,
          std::function<void()> copy_link)
      : layout_(layout),
        appearance_(appearance),
        link_choices_(link_choices),
        copy_link_(std::move(copy_link)) {}
  // The bar; returns its height, where the tiled panels start.
  float draw(PanelContext& context);
  // After the panels: the dialogs the Export menu opened and the pipeline's stats.
  void draw_after_panels(PanelContext& context);
  // A picture the Export menu asked for (export_panel.hpp).
  ExportPanel& export_menu() { return export_; }
  // Where the bar's own items (not its menus) were drawn in the last frame, by label: what a
  // finger taps (`gui --report`'s layout.menu_bar_items).
  const std::map<std::string, PanelRect>& item_rects() const { return item_rects_; }

 private:
  void view_menu(PanelContext& context);
  // The files, every panel's pictures, and the link.
  void export_items(PanelContext& context);
  // While presenting: the way back to the tiles and the strip's item.
  void presenting_items(PanelContext& context);
  // The notice that the tiles cannot hold the text size, and a menu presenting one view.
  void cramped_notice(PanelContext& context);
  // ImGui::MenuItem on the bar, its place kept in item_rects_.
  bool bar_item(const char* label);

  Layout& layout_;
  Appearance& appearance_;
  LinkChoices& link_choices_;
  std::function<void()> copy_link_;
  std::map<std::string, PanelRect> item_rects_;
  ExportPanel export_;
  bool show_stats_ = false;
};

}  // namespace foldlab::gui
