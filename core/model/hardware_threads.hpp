// How many threads parallel work may use. In the lowest layer, so that every layer asks the same.
#pragma once

#include <algorithm>
#include <thread>

namespace foldlab {

// The hardware's threads, at least 1; exactly 1 in a build without threads (the browser build,
// where starting a std::thread fails), so that parallel work runs on the calling thread there.
inline int hardware_threads() {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
  return 1;
#else
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
#endif
}

}  // namespace foldlab
