// A/B comparison: a fabric pinned as "B" beside the one being edited ("A"). B is a value of its
// own, not an edit of A: it holds the parameters A had when it was pinned (the last valid ones,
// with the law and method settings), the calibration record its intervals come from, and a label.
// Undo and redo restore B with A. B has a lazy Scene of its own, so a view that does not show B
// computes nothing for it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/scene.hpp"
#include "core/io/preset.hpp"
#include "core/io/report.hpp"

namespace foldlab::gui {

class Document;
class UiStatus;

// A fabric pinned as B: its label and last valid parameters (`fabric`), and the preset it came
// from with that preset's file (`origin`, `origin_path`, empty for the built-in default) — what
// "Reset to preset", "Save as" and the "(edited)" marker compare against once a swap makes it A.
// `dragged_keys` are the inputs a slider set last when B was pinned: a link writes them with the
// digits the slider showed, as it does A's (a session or a preset file does not keep them).
struct PinnedFabric {
  Preset fabric;
  Preset origin;
  std::string origin_path;
  std::vector<std::string> dragged_keys = {};
};

class Comparison {
 public:
  bool pinned() const { return b_.has_value(); }
  // B as a preset: its name is the label shown, its parameters are valid, its calibration is the
  // one its intervals come from. Precondition: pinned().
  const Preset& b() const { return b_->fabric; }
  // B's scene, at `grid_nx` vertices a side (A's, so that the two cloths are drawn alike).
  // Precondition: pinned().
  Scene& scene(int grid_nx);
  // B's solution, a shortcut for the views that show numbers only.
  const Solution& solution() { return scene_.solution(); }
  // The form of eq. 7 and the prediction intervals for B, as Results shows them for A.
  const ModelStanding& standing();
  // Counts pins and clears, so that views know when B is another fabric.
  std::uint64_t changes() const { return changes_; }

  // The preset B came from and its file. Precondition: pinned().
  const Preset& b_origin() const { return b_->origin; }
  const std::string& b_origin_path() const { return b_->origin_path; }
  // B with its identity, as undo and the session keep it. Precondition: pinned().
  const PinnedFabric& pinned_fabric() const { return *b_; }

  // Precondition: validate(b.fabric.parameters) is empty.
  void pin(PinnedFabric b);
  void clear();

 private:
  std::optional<PinnedFabric> b_;
  Scene scene_;
  std::optional<ModelStanding> standing_;
  std::uint64_t changes_ = 0;
};

// The label of the fabric being edited: the loaded preset's name, "(edited)" after it once its
// parameters differ from it.
std::string fabric_label(const Document& document);
// A's last valid state as a preset to pin: the loaded preset with the scene's parameters, named
// by fabric_label.
Preset current_fabric(const Document& document);

// What the buttons and the Compare menu do, each one undo step (B is part of what undo restores).
// Pinning replaces an earlier B. Swapping gives A the parameters and the preset of B, and pins A's
// former state with its preset as B: each fabric keeps its own identity. Each says what it did in
// the status line.
void pin_as_b(Document& document, UiStatus& status);
void swap_a_and_b(Document& document, UiStatus& status);
void clear_b(Document& document, UiStatus& status);

}  // namespace foldlab::gui
