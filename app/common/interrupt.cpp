#include "app/common/interrupt.hpp"

#include <signal.h>

#include "core/io/io.hpp"

namespace foldlab::app {
namespace {

void remove_temporaries_and_stop(int number) {
  remove_pending_temporaries();
  // The default action put back here, not by SA_RESETHAND, which a handler restored with
  // std::signal (calibrate's) would not carry. Delivered once this handler returns, it stops the
  // program with the signal's own status, which a parent or shell expects.
  ::signal(number, SIG_DFL);
  ::raise(number);
}

}  // namespace

void remove_temporaries_when_interrupted() {
  for (const int number : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    if (::sigaction(number, nullptr, &previous) != 0 || previous.sa_handler == SIG_IGN) {
      continue;
    }
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_stop;
    ::sigemptyset(&action.sa_mask);
    ::sigaction(number, &action, nullptr);
  }
}

}  // namespace foldlab::app
