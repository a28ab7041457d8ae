// The desktop's files and config folder: the file dialog reads and writes the disk itself, and
// the config folder is on disk; the base classes, which do nothing.
#include "app/gui/config_store.hpp"
#include "app/gui/file_transfer.hpp"

namespace foldlab::gui {

std::unique_ptr<FileTransfer> make_file_transfer() {
  return std::make_unique<FileTransfer>();
}

std::unique_ptr<ConfigStore> make_config_store() {
  return std::make_unique<ConfigStore>();
}

}  // namespace foldlab::gui
