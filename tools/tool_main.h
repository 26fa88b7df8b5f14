// The main of a developer tool, in the foresight command's format: `run` does the work; bad
// input it throws (InputError) becomes one line "TOOL: error: message" on standard error and
// exit status 2, running out of memory the same with the command's out-of-memory message, and
// anything else "TOOL: internal error: message" and exit status 3. The message is printed in
// its one-line form (common/one_line.h: a newline or an ESC from a settings file's key is
// escaped), with nothing written (the tools write through report/output_set.h, so an error
// before the commit leaves every output as it was). No output may replace a file the tool read
// (common/input_log.h).
#pragma once

#include <exception>
#include <iostream>
#include <new>

#include "common/error.h"
#include "common/input_log.h"
#include "common/one_line.h"

namespace foresight {

template <class Run>
int ToolMain(const char* tool, Run run) {
  try {
    const InputLog read;  // no output may replace a file the tool read
    return run();
  } catch (const InputError& e) {
    std::cerr << tool << ": error: " << OneLine(e.what()) << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << tool << ": error: out of memory (a memory limit such as ulimit -v? a smaller "
                         "run may fit)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << tool << ": internal error: " << OneLine(e.what()) << "\n";
    return 3;
  }
}

}  // namespace foresight
