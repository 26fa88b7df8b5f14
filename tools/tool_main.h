// The main of a developer tool: `run` does the work, and any error it throws becomes one line
// "TOOL: message" on standard error and exit status 2, with nothing written (the tools write
// through report/output_set.h, so an error before the commit leaves every output as it was).
// No output may replace a file the tool read (common/input_log.h).
#pragma once

#include <exception>
#include <iostream>

#include "common/input_log.h"

namespace foresight {

template <class Run>
int ToolMain(const char* tool, Run run) {
  try {
    const InputLog read;  // no output may replace a file the tool read
    return run();
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return 2;
  }
}

}  // namespace foresight
