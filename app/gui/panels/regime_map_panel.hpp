// The Regime map tab: n or z_max over two inputs, computed row by row on every core in the
// background and shown as an image as the rows arrive; a click moves the sliders there.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/gui/document.hpp"
#include "app/gui/renderer.hpp"
#include "core/analysis/sweep.hpp"

namespace foldlab::gui {

class RegimeMapPanel {
 public:
  RegimeMapPanel();
  ~RegimeMapPanel();
  RegimeMapPanel(const RegimeMapPanel&) = delete;
  RegimeMapPanel& operator=(const RegimeMapPanel&) = delete;

  void draw(Document& document, Renderer& renderer);

  const std::string& x_key() const { return x_key_; }
  const std::string& y_key() const { return y_key_; }
  // For tests and the docs' figure: the last completed map's size and time.
  double last_map_ms() const { return last_map_ms_; }
  // True from a (re)start until every row has been computed.
  bool computing() const;

 private:
  struct Job;
  void restart(const Parameters& base);
  void stop();
  void update_image(Renderer& renderer);

  std::string x_key_ = "h";
  std::string y_key_ = "w";
  double x_from_ = 300.0, x_to_ = 3000.0;
  double y_from_ = 3e-7, y_to_ = 1e-5;
  int resolution_ = 256;
  bool show_z_ = false;

  std::shared_ptr<Job> job_;
  std::vector<std::thread> workers_;
  Parameters job_base_;
  bool job_started_ = false;
  int image_ = -1;  // the renderer's image of the map
  int image_size_ = 0;
  std::vector<std::uint32_t> pixels_;
  int rows_shown_ = -1;
  double last_map_ms_ = 0.0;
};

}  // namespace foldlab::gui
