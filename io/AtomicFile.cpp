#include "io/AtomicFile.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace mcpp::io {
namespace {

// A name no other writer of this process or another uses at the same time.
std::string temporaryNameBeside(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const std::filesystem::path target(path);
    return (target.parent_path() / ("." + target.filename().string() + ".partial-" +
                                    std::to_string(getpid()) + "-" + std::to_string(counter++)))
        .string();
}

std::string reason() {
    return std::strerror(errno);
}

// Every byte written, or false with errno set; a short write is retried, so a full disk ends in ENOSPC.
bool writeAll(int descriptor, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(descriptor, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR)
            continue;
        if (written <= 0) {
            if (written == 0)
                errno = EIO;
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

} // namespace

Status writeFileAtomically(const std::string& path, std::string_view bytes, Sync sync) {
    const std::string temporary = temporaryNameBeside(path);
    // 0666 less the umask, as any new file of the user's.
    const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (descriptor < 0)
        return Status::failure(path + ": cannot write: " + reason());
    const bool written = writeAll(descriptor, bytes) && (sync == Sync::BySystem || ::fsync(descriptor) == 0);
    const std::string writeError = written ? std::string() : reason();
    const bool closed = ::close(descriptor) == 0;
    if (!written || !closed) {
        const std::string error = written ? reason() : writeError;
        ::unlink(temporary.c_str());
        return Status::failure(path + ": write failed, the previous file is kept: " + error);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string error = reason();
        ::unlink(temporary.c_str());
        return Status::failure(path + ": cannot move the finished file into place: " + error);
    }
    return {};
}

} // namespace mcpp::io
