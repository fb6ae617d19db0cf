// SPDX-License-Identifier: Apache-2.0
// The temporary files and directories a run writes before it renames them into place:
// removed when a signal (SIGINT, SIGTERM, SIGHUP) ends the run, and, for a run that was
// killed outright (SIGKILL), by the next run that writes the same target.
#pragma once

#include <string>

namespace dda::cli {

// Installs the handlers (once; later calls do nothing).
void install_signal_cleanup();
// A path to remove if a signal ends the run (files, and directories once empty), until
// it is released (renamed into place or removed by the run itself). Removed on a signal
// in the reverse order of registration, so a directory's files go before it.
void register_temp(const std::string& path);
void release_temp(const std::string& path);

// "TARGET.tmp.PID" and "TARGET.old.PID" (the names this tool gives its temporary files)
// beside `target`, for a PID that is no longer running: left by a killed run, removed.
void remove_stale_temps(const std::string& target);

}  // namespace dda::cli
