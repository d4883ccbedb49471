#pragma once

// Private to vantage::io: the files a signal handler removes (remove_partial_files_on_signal(),
// text_file.h). AtomicTextFile registers its temporary and WriteLock its lock file while they
// exist, so that an interrupted command leaves neither behind.

#include <string>

namespace vantage::io::internal {

/// Registers `path` for removal on SIGINT, SIGTERM or SIGHUP (when the handler is installed).
/// Returns the slot to unregister, or -1 when every slot is taken or the path is too long (the
/// file is then removed by its owner only). Safe to call from several threads.
int register_removal(const std::string& path);

/// Unregisters a slot that register_removal() returned (-1: nothing).
void unregister_removal(int slot);

}  // namespace vantage::io::internal
