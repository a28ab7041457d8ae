// A tension field that follows its inputs while they change, a slice of time at a time: a view
// asks for the field of the inputs it shows every frame and gives the solve what is left of the
// frame; the last converged field stays on show, marked as older, until the new one has
// converged. Each new solve starts from the latest iterate (on the same mesh) or from the latest
// field carried onto the new mesh, so that a drag costs a few Newton steps a frame; inputs that
// change while a solve is under way wait for it, so that the field on show is at most a solve
// behind. No thread: a page without threads runs it alike.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/field/field_case.hpp"
#include "core/field/mesh.hpp"
#include "core/field/outline.hpp"
#include "core/field/solver.hpp"

namespace foldlab::field {

// What a field is solved for.
struct FieldInputs {
  Outline outline;
  Material material;
  MeshResolution resolution;

  bool operator==(const FieldInputs&) const = default;
};

// A converged field as it is drawn: its inputs, mesh and report.
struct SolvedField {
  FieldInputs inputs;
  Mesh mesh;
  FieldReport report;
};

class LiveField {
 public:
  LiveField();
  ~LiveField();
  LiveField(LiveField&&) noexcept;
  LiveField& operator=(LiveField&&) noexcept;

  // The field wanted now; nothing happens when it is the one already asked for. An outline that
  // cannot be meshed leaves the last field and sets refusal() to why.
  void request(const FieldInputs& inputs);
  // Newton steps on the wanted field for about `budget_ms` (0: until it converges or gives up).
  // The first field of all, solved cold with nothing to show meanwhile, may take up to
  // `first_budget_ms` at once. True when shown() changed.
  bool step(double budget_ms, double first_budget_ms = kFirstColdMs);
  // True while the wanted field is neither shown nor given up.
  bool working() const;
  // The last converged field, or null before the first.
  const SolvedField* shown() const { return shown_.get(); }
  // Counts the fields shown so far: a view that derives something from shown() knows when to
  // derive it again.
  std::uint64_t shown_count() const { return shown_count_; }
  // Whether shown() is of the inputs last asked for.
  bool current() const;
  // Why the wanted field is not shown: the outline refused, or the solve gave up (its residual
  // said); empty otherwise.
  const std::string& refusal() const { return refusal_; }
  // The relative residual of the solve in progress (or of the last one).
  double residual() const { return residual_; }
  // Newton steps spent on the wanted field so far.
  int iterations() const { return iterations_; }

  // A solve is given up after this many Newton steps, the default solve's own limit.
  static constexpr int kMaxIterations = 1000;
  // Newer inputs wait for a solve under way while it has taken fewer Newton steps than this: a
  // warm re-solve takes 6-25.
  static constexpr int kFinishBeforeNewer = 60;
  // A view opening shows its field in its first frame (a cold solve of the live mesh takes
  // 30-250 ms); only a cloth whose cold solve takes longer, a very stiff one, is sliced.
  static constexpr double kFirstColdMs = 1000.0;

 private:
  void start(const FieldInputs& inputs);

  struct Work;
  std::unique_ptr<Work> work_;  // the wanted field's solver and latest iterate
  std::shared_ptr<const SolvedField> shown_;
  std::optional<FieldInputs> wanted_;  // the inputs being solved for
  std::optional<FieldInputs> latest_;  // the inputs last asked for: solved next when not wanted_
  std::string refusal_;
  double residual_ = 0.0;
  int iterations_ = 0;
  std::uint64_t shown_count_ = 0;
};

// The field of `inputs` solved to the end at once (a picture, a command).
std::optional<SolvedField> solve_field(const FieldInputs& inputs, std::string& refusal);

}  // namespace foldlab::field
