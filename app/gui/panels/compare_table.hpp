// The A/B part of the Results panel: "Pin as B", "Swap A and B" and "Clear B", and while B is
// pinned a table of n, Q and z_max for A and B with their prediction intervals and A − B, the
// change since B was pinned.
#pragma once

#include <string>

#include "app/gui/document.hpp"
#include "core/io/report.hpp"
#include "core/model/solver.hpp"

namespace foldlab::gui {

// One of n, Q and z_max as Results shows it: the value, the prediction interval when the
// calibration gives one, the unit ("12.34 (9.8–15.1) mm").
struct QuantityText {
  std::string value;  // "12.34"
  std::string range;  // " (9.8–15.1)"; empty without an interval
  std::string unit;   // " mm"; empty for n and Q
  std::string joined() const { return value + range + unit; }
};
struct QuantityTexts {
  QuantityText n;
  QuantityText Q;
  QuantityText z_max;
};
QuantityTexts quantity_texts(const Solution& s, const ModelStanding& standing);

// "n = 7 (4–10)     Q = 1.2955 (…)     z_max = 48.96 (30.5–78.6) mm": the large read-out over a
// presented panel.
std::string headline(const QuantityTexts& texts);

// A − B, the change since B was pinned, with units: "+2", "-0.0123", "+1.23 mm" (no range).
QuantityTexts difference_texts(const Solution& a, const Solution& b);

// The buttons, and the table while B is pinned. `standing_a` is A's form of eq. 7 and range.
void draw_compare_section(Document& document, UiStatus& status, const ModelStanding& standing_a);
// "A: name" and "B: name" in their curves' colours, wrapped; B must be pinned.
void draw_compare_names(Document& document);
// The same three actions as the menu bar's Compare menu.
void compare_menu(Document& document, UiStatus& status);

}  // namespace foldlab::gui
