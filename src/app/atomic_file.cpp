#include "app/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace weft::app {

bool write_file_atomically(const std::string& path, const std::string& text, bool overwrite,
                           std::string& error) {
    namespace fs = std::filesystem;
    std::error_code exists_error;
    if (!overwrite && fs::exists(path, exists_error)) {
        error = path + ": exists; confirm to replace it";
        return false;
    }
    // A unique temporary file in the same folder (rename is atomic only within one file
    // system), written and flushed to disk before it takes the final name.
    const fs::path folder = fs::path(path).parent_path();
    std::string temporary =
        (folder.empty() ? fs::path(".") : folder).string() + "/.weft-save-XXXXXX";
    const int fd = ::mkstemp(temporary.data());
    if (fd < 0) {
        error = path + ": cannot create a temporary file beside it: " + std::strerror(errno);
        return false;
    }
    int failure = 0;  // errno of the first thing that went wrong
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            failure = n < 0 ? errno : EIO;
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    if (!failure && ::fsync(fd) != 0) failure = errno;
    ::fchmod(fd, 0644);  // mkstemp makes it private; the file is an ordinary document
    if (::close(fd) != 0 && !failure) failure = errno;
    if (!failure && ::rename(temporary.c_str(), path.c_str()) != 0) failure = errno;
    if (failure) {
        error = path + ": cannot write: " + std::strerror(failure);
        ::unlink(temporary.c_str());
        return false;
    }
    return true;
}

}  // namespace weft::app
