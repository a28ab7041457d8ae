// The browser build has no EGL: the page's canvas is its only surface.
#include "app/gui/surface.hpp"

namespace foldlab::gui {

std::unique_ptr<Surface> make_headless_surface(const SurfaceOptions&) {
  throw SurfaceError("headless rendering needs the desktop program (`foldlab render`)");
}

}  // namespace foldlab::gui
