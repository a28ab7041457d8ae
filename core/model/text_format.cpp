#include "core/model/text_format.hpp"

#include <cstdarg>

namespace foldlab::detail {

std::string vprintf_string(const char* format, std::va_list args) {
  std::va_list again;
  va_copy(again, args);
  const int size = std::vsnprintf(nullptr, 0, format, args);
  std::string out(static_cast<std::size_t>(std::max(0, size)), '\0');
  std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

std::string printf_string(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::string out = vprintf_string(format, args);
  va_end(args);
  return out;
}

}  // namespace foldlab::detail
