// Writing a file so that a crash or a full disk never leaves it half written: the text goes
// to a temporary file beside it, is flushed to disk, and then renamed over the final name
// (rename is atomic within one file system). Used for saved scenes and session recordings.
#pragma once

#include <string>

namespace weft::app {

// Refuses to replace an existing file unless `overwrite`. On failure sets `error` to
// "PATH: what" and leaves no temporary file behind.
bool write_file_atomically(const std::string& path, const std::string& text, bool overwrite,
                           std::string& error);

}  // namespace weft::app
