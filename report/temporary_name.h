// Names of the temporaries report/ makes beside a user's outputs (staged files and folders,
// probe files and folders): one counter for all of them, so that no two temporaries of one
// process, on any thread, share a name, and the process id tells processes apart.
#pragma once

#include <string>

namespace foresight {

// "PID.N" with N new on every call (thread-safe).
std::string UniqueSuffix();

}  // namespace foresight
