// The Results panel: the regime, the solution's numbers with their symbols, n, Q and z_max with
// the range their calibration allows ("n = 7 (6–8)"), and the fold amplitudes a_i. Every frame
// reads the scene's (cached) solution; the range is recomputed only when the solution or the
// preset's calibration changes.
#pragma once

#include <cstdint>
#include <optional>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"

namespace foldlab::gui {

class ResultsPanel : public Panel {
 public:
  const char* name() const override { return "Results"; }
  const char* key() const override { return "results"; }
  std::optional<Tile> tile() const override { return Tile::results; }
  void draw(PanelContext& context) override;

 private:
  const ModelStanding& standing(Document& document);

  std::uint64_t standing_version_ = ~std::uint64_t{0};
  std::optional<CalibrationRecord> standing_record_;
  ModelStanding standing_;
};

}  // namespace foldlab::gui
