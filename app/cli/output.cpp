#include "app/cli/output.hpp"

namespace foldlab::cli {

void write_json(const nlohmann::json& document, std::ostream& out) {
  out << document.dump(2) << "\n";
}

void write_notes(const std::vector<std::string>& notes, std::ostream& err) {
  for (const std::string& note : notes) {
    err << "foldlab: " << detail::escaped_lines(note) << "\n";
  }
}

std::string value_with_error(double value, const std::optional<double>& error, const char* format) {
  std::string out = detail::printf_string(format, value);
  if (error) {
    out += " (" + detail::printf_string("%+.1f", 100.0 * *error) + "%)";
  }
  return out;
}

}  // namespace foldlab::cli
