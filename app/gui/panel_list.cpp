#include "app/gui/panel_list.hpp"

#include <algorithm>
#include <tuple>
#include <type_traits>

#include "app/gui/panels/analysis_panel.hpp"
#include "app/gui/panels/calibration_panel.hpp"
#include "app/gui/panels/cloth_view_panel.hpp"
#include "app/gui/panels/field_panel.hpp"
#include "app/gui/panels/fold_plot_panel.hpp"
#include "app/gui/panels/intro_window.hpp"
#include "app/gui/panels/parameters_panel.hpp"
#include "app/gui/panels/photo_overlay.hpp"
#include "app/gui/panels/presets_panel.hpp"
#include "app/gui/panels/results_panel.hpp"

namespace foldlab::gui {
namespace {

// The list, in drawing order: a new panel is one type here (and, when its constructor takes
// arguments, one `make` below).
template <class... P>
using Types = std::tuple<std::type_identity<P>...>;
using PanelTypes = Types<ParametersPanel, PresetsPanel, FoldPlotPanel, ClothViewPanel, ResultsPanel,
                         AnalysisPanel, FieldPanel, CalibrationPanel, PhotoOverlay, IntroWindow>;

template <class P>
std::unique_ptr<Panel> make(const PanelListOptions& /*options*/) {
  return std::make_unique<P>();
}
template <>
std::unique_ptr<Panel> make<PresetsPanel>(const PanelListOptions& options) {
  return std::make_unique<PresetsPanel>(options.presets_dir, options.user_presets_dir);
}
template <>
std::unique_ptr<Panel> make<AnalysisPanel>(const PanelListOptions& options) {
  return std::make_unique<AnalysisPanel>(options.presets_dir, options.analysis_tab);
}
template <>
std::unique_ptr<Panel> make<PhotoOverlay>(const PanelListOptions& options) {
  return std::make_unique<PhotoOverlay>(PhotoPaths{options.measurements_file,
                                                   options.user_presets_dir,
                                                   shipped_measurements_file(options.presets_dir)});
}

// A panel type's pictures, known without building it.
template <class P>
void add_offers(std::vector<PictureOffer>& offers) {
  if constexpr (requires { P::kPictures; }) {
    // One at a time: GCC 12 at -O3 warns falsely (array-bounds) on a range insert here.
    for (const PictureOffer& offer : P::kPictures) {
      offers.push_back(offer);
    }
  }
}

}  // namespace

std::vector<std::unique_ptr<Panel>> make_panels(const PanelListOptions& options) {
  std::vector<std::unique_ptr<Panel>> panels;
  std::apply(
      [&](auto... type) { (panels.push_back(make<typename decltype(type)::type>(options)), ...); },
      PanelTypes{});
  return panels;
}

std::span<const PictureOffer> picture_offers() {
  static const std::vector<PictureOffer> offers = [] {
    std::vector<PictureOffer> all;
    std::apply([&](auto... type) { (add_offers<typename decltype(type)::type>(all), ...); },
               PanelTypes{});
    return all;
  }();
  return offers;
}

const PictureOffer* picture_offer(PictureView view) {
  const std::span<const PictureOffer> offers = picture_offers();
  const auto found = std::find_if(offers.begin(), offers.end(),
                                  [view](const PictureOffer& o) { return o.view == view; });
  return found == offers.end() ? nullptr : &*found;
}

const PictureOffer* picture_offer(std::string_view name) {
  const std::span<const PictureOffer> offers = picture_offers();
  const auto found = std::find_if(offers.begin(), offers.end(),
                                  [name](const PictureOffer& o) { return name == o.name; });
  return found == offers.end() ? nullptr : &*found;
}

std::string picture_view_names() {
  std::string names;
  for (const PictureOffer& offer : picture_offers()) {
    names += (names.empty() ? "" : ", ") + std::string(offer.name);
  }
  return names;
}

}  // namespace foldlab::gui
