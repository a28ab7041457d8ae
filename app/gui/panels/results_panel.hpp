// The Results panel: the regime, the solution's numbers with their symbols, n, Q and z_max with
// the range their calibration allows ("n = 7 (6–8)"), and the fold amplitudes a_i. Every frame
// reads the scene's (cached) solution; the range is recomputed only when the solution or the
// preset's calibration changes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/gui/document.hpp"
#include "app/gui/panel.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"

namespace foldlab::gui {

class ResultsPanel : public Panel {
 public:
  const char* name() const override { return "Results"; }
  const char* introduction() const override {
    return "the regime (wrinkled, no slack, stiff, ...), n, Q, z_max and each fold's "
           "depth.";
  }
  const char* key() const override { return "results"; }
  void draw(PanelContext& context) override;
  // n, Q and z_max with their ranges as the table shows them, one line for A and, while B is
  // pinned, one for B, each with the colour it is drawn in: the read-out over a presented view.
  // `drawn`: the solution A's cloth is drawn with when it is not the closed form's (the presented
  // 3D view with the field's folds), given without ranges and followed by `drawn_words`.
  std::vector<std::pair<std::string, ImVec4>> headlines(Document& document,
                                                        const Solution* drawn = nullptr,
                                                        std::string_view drawn_words = {});
  // "results": {"field_column": {"shown", "state", "words", "rows": [[name, closed form, field],
  // ...]}}, the closed form beside the tension field as the panel showed them at its last frame.
  void report(nlohmann::json& state, PanelContext& context) const override;

 private:
  // One row of the table: the value with its unit, and the range the calibration allows (empty
  // without one), which goes under the value when the panel is too narrow for both.
  struct Row {
    std::string name;
    std::string symbol;
    std::string value;
    std::string range;
    std::string one_line() const;
  };
  // A beginner's rows are n, Q and z_max; an expert's add how the solver got there.
  std::vector<Row> rows(Document& document, bool expert);
  // The panel's parts, top to bottom: the reason for a refusal, the regime (and for experts the
  // solver's message and the model), the note on the ranges, the table and the a_i.
  void draw_refusal(const Document& document) const;
  void draw_regime(Document& document, const ModelStanding& model, bool expert) const;
  void draw_range_note(const ModelStanding& model) const;
  void draw_table(const std::vector<Row>& rows) const;
  void draw_amplitudes(const Solution& s, bool expert) const;
  const ModelStanding& standing(Document& document);
  // The closed form's n, Q, z_max and a_i beside the field's while the field is solved for a
  // view, or the offer to solve it.
  void draw_field_column(PanelContext& context);

  // What draw_field_column showed: [name, closed form, field] rows, the field's state and words.
  bool field_column_shown_ = false;
  std::string field_state_;
  std::string field_words_;
  std::vector<std::array<std::string, 3>> field_rows_;

  std::uint64_t standing_version_ = ~std::uint64_t{0};
  std::optional<CalibrationRecord> standing_record_;
  ModelStanding standing_;
};

}  // namespace foldlab::gui
