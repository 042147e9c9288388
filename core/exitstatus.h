// core/exitstatus.h: the exit statuses of both programs (README: Running), and the one mapping
// from how a command went (outcome.h) to a status, which the mains alone call.
#pragma once

#include <functional>

#include "core/outcome.h"

namespace jello {

// Exit statuses of the README (Running), chosen by the mains alone (outcome.h).
constexpr int kExitOk = 0;
constexpr int kExitDiverged = 1;
constexpr int kExitBadInput = 2;

// The exit status of `outcome`, its message (when it has one) printed on stderr as one line.
// Called by the mains alone: only they print a verdict and choose the status.
int exitStatusOf(const Outcome& outcome);

// A program's main around its command: the command's outcome, its line printed; every exception
// it lets out one line and status 2 (std::bad_alloc as `outOfMemory`); and a result the user
// cannot receive (standard output closed or full) a failure too, never a success.
int runMain(const char* outOfMemory, const std::function<Outcome()>& command);

}  // namespace jello
