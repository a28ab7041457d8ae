// What a command stopped by a signal does before it goes.
#pragma once

namespace foldlab::app {

// Installs SIGINT and SIGTERM handlers that remove the temporaries of files being written
// (core's remove_pending_temporaries) and then stop the program as the signal would have: an
// export interrupted while it writes leaves neither its file nor a temporary as large. A signal
// the program was started ignoring (nohup) stays ignored. A command with handlers of its own
// (calibrate's Ctrl+C, the explorer's close) installs them after this one.
void remove_temporaries_when_interrupted();

}  // namespace foldlab::app
