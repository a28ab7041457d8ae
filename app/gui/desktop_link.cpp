// The desktop's link: the clipboard alone (the base class); no address follows it.
#include "app/gui/page_link.hpp"

namespace foldlab::gui {

std::unique_ptr<PageLink> make_page_link() {
  return std::make_unique<PageLink>();
}

}  // namespace foldlab::gui
