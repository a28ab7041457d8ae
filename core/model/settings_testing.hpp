// For tests only: a row added to the input table at run time, to show that a new input needs no
// edit outside its row. Call it before anything reads the table: some readers keep the keys they
// found (the sweepable keys, the measurement columns).
#pragma once

#include "core/model/settings.hpp"

namespace foldlab {

// Appends `spec` as the table's last row; throws std::logic_error for a key already there.
void add_input_row_for_testing(const InputSpec& spec);

}  // namespace foldlab
