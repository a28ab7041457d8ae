// The explorer's panels, in one list: built here and nowhere else, in drawing order (the tiled
// ones in the layout's order, then the floating windows). The Explorer, the play driver, `--view`,
// `gui --report`, the Export menu and `foldlab picture` loop over what the list's panels offer.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/gui/panel.hpp"

namespace foldlab::gui {

// What the panels are built with.
struct PanelListOptions {
  std::filesystem::path presets_dir;        // shipped presets (may be empty)
  std::filesystem::path user_presets_dir;   // "Save as..." writes here
  std::string analysis_tab;                 // the Analysis tab selected at start
  std::filesystem::path measurements_file;  // the photo's "Add to measurements" appends here
};

std::vector<std::unique_ptr<Panel>> make_panels(const PanelListOptions& options);

// Every picture the list's panels give, in the list's order (before any panel is built: the
// command line's `foldlab picture VIEW` reads them).
std::span<const PictureOffer> picture_offers();
// The offer of `view`, or of the view named `name` ("fold_plot"); null for none.
const PictureOffer* picture_offer(PictureView view);
const PictureOffer* picture_offer(std::string_view name);
// "cloth, compare, fold_plot, sweep": the names `foldlab picture` takes.
std::string picture_view_names();

}  // namespace foldlab::gui
