#include "app/gui/key_latency.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/geometry/scene.hpp"

namespace foldlab::gui {
namespace {

double ms_between(KeyLatency::Clock::time_point from, KeyLatency::Clock::time_point to) {
  return std::max(0.0, std::chrono::duration<double, std::milli>(to - from).count());
}

double mesh_total_ms(const Scene& scene) {
  return scene.stats(Stage::fold_lines).total_ms + scene.stats(Stage::grid).total_ms +
         scene.stats(Stage::normals).total_ms;
}

// The value at fraction `q` of the sorted values (nearest rank).
double quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

// Keeps a report's figures to a microsecond.
double rounded(double ms) {
  return std::round(ms * 1000.0) / 1000.0;
}

}  // namespace

void KeyLatency::frame_started(Clock::time_point now) {
  frame_start_ = now;
}

void KeyLatency::input_read(Clock::time_point now, std::span<const Clock::time_point> keys_taken,
                            const Scene& scene, double cloth_render_ms_total) {
  input_read_ = now;
  solve_total_ms_ = scene.stats(Stage::solution).total_ms;
  mesh_total_ms_ = mesh_total_ms(scene);
  cloth_total_ms_ = cloth_render_ms_total;
  // A key still waiting from an earlier frame waited through that frame and the gap after it.
  for (Pending& pending : pending_) {
    pending.record.parts_ms[wait] += ms_between(last_finished_, frame_start_);
  }
  for (const Clock::time_point key : keys_taken) {
    Pending pending;
    pending.key = key;
    pending.solution_version = scene.version(Stage::solution);
    // A key read by this frame's own poll came after the frame started: its wait is nothing and
    // its input part starts with it.
    pending.record.parts_ms[wait] = ms_between(key, frame_start_);
    pending_.push_back(pending);
  }
}

void KeyLatency::built(Clock::time_point now, const Scene& scene, double cloth_render_ms_total) {
  built_ = now;
  solve_ms_ = std::max(0.0, scene.stats(Stage::solution).total_ms - solve_total_ms_);
  mesh_ms_ = std::max(0.0, mesh_total_ms(scene) - mesh_total_ms_);
  cloth_ms_ = std::max(0.0, cloth_render_ms_total - cloth_total_ms_);
}

void KeyLatency::drawn(Clock::time_point now) {
  drawn_ = now;
}

void KeyLatency::finished(Clock::time_point now, const Scene& scene) {
  last_finished_ = now;
  const double build_ms = ms_between(input_read_, built_);
  const double counted_ms = solve_ms_ + mesh_ms_ + cloth_ms_;
  for (Pending& pending : pending_) {
    std::array<double, kPartCount>& parts = pending.record.parts_ms;
    parts[input] += ms_between(std::max(pending.key, frame_start_), input_read_);
    // The stage and render times are measured inside the build; the build's own clock is the
    // whole of it, so that the parts never add up to more than the key's time.
    const double scale = counted_ms > build_ms && counted_ms > 0.0 ? build_ms / counted_ms : 1.0;
    parts[solve] += scale * solve_ms_;
    parts[mesh] += scale * mesh_ms_;
    parts[cloth] += scale * cloth_ms_;
    parts[ui] += std::max(0.0, build_ms - scale * counted_ms);
    parts[draw] += ms_between(built_, drawn_);
    parts[swap] += ms_between(drawn_, now);
    ++pending.frames;
    pending.record.cloth_redrawn |= cloth_ms_ > 0.0;
  }
  const std::uint64_t version = scene.version(Stage::solution);
  std::erase_if(pending_, [&](Pending& pending) {
    if (pending.solution_version != version) {
      pending.record.key_to_frame_ms = ms_between(pending.key, now);
      records_.push_back(pending.record);
      return true;
    }
    return pending.frames >= kFramesToShow;
  });
}

nlohmann::json KeyLatency::report() const {
  if (records_.empty()) {
    return nullptr;
  }
  const auto summary = [this](auto value_of) {
    std::vector<double> values;
    for (const Record& record : records_) {
      values.push_back(value_of(record));
    }
    return nlohmann::json{{"median", rounded(quantile(values, 0.5))},
                          {"p90", rounded(quantile(values, 0.9))},
                          {"max", rounded(quantile(values, 1.0))}};
  };
  nlohmann::json parts = nlohmann::json::object();
  for (int part = 0; part < kPartCount; ++part) {
    parts[kPartNames[static_cast<std::size_t>(part)]] = summary(
        [part](const Record& record) { return record.parts_ms[static_cast<std::size_t>(part)]; });
  }
  const Record& last = records_.back();
  nlohmann::json last_json = {{"key_to_frame_ms", rounded(last.key_to_frame_ms)},
                              {"cloth_redrawn", last.cloth_redrawn}};
  for (int part = 0; part < kPartCount; ++part) {
    last_json[kPartNames[static_cast<std::size_t>(part)]] =
        rounded(last.parts_ms[static_cast<std::size_t>(part)]);
  }
  return {{"keys", records_.size()},
          {"key_to_frame_ms", summary([](const Record& record) { return record.key_to_frame_ms; })},
          {"parts", parts},
          {"last", last_json}};
}

}  // namespace foldlab::gui
