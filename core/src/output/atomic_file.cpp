#include "frictionlab/output/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/os_error.hpp"

namespace frictionlab {

namespace {

[[noreturn]] void fail(const std::filesystem::path& file, int error) {
    throw RunError(fmt::format("cannot write '{}': {}", file.string(), os_error(error)));
}

/// 0, or the errno of the first failed write.
int write_all(int fd, std::string_view text) {
    while (!text.empty()) {
        const ssize_t n = ::write(fd, text.data(), text.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO;
        text.remove_prefix(static_cast<std::size_t>(n));
    }
    return 0;
}

std::filesystem::path temporary_for(const std::filesystem::path& file) {
    return std::filesystem::path(file).concat(".tmp");
}

/// fsync of a file or folder opened with `flags`; 0 or the errno.
int sync_path(const std::filesystem::path& path, int flags) {
    const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
    if (fd < 0) return errno;
    const int error = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    return error;
}

std::filesystem::path folder_of(const std::filesystem::path& file) {
    return file.parent_path().empty() ? "." : file.parent_path();
}

/// Removes the temporary file of a failed write and throws, naming `file`.
[[noreturn]] void abandon(const std::filesystem::path& tmp, const std::filesystem::path& file, int error) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    fail(file, error);
}

void rename_over(const std::filesystem::path& tmp, const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) abandon(tmp, file, ec.value());
}

}  // namespace

void write_file_atomically(const std::filesystem::path& file, std::string_view text, Durability durability) {
    replace_file_atomically(
        file,
        [&](const std::filesystem::path& tmp) {
            const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
            if (fd < 0) fail(file, errno);
            int error = write_all(fd, text);
            if (::close(fd) != 0 && error == 0) error = errno;
            if (error != 0) fail(file, error);  // the temporary file is removed below
            return true;
        },
        durability);
}

void replace_file_atomically(const std::filesystem::path& file,
                             const std::function<bool(const std::filesystem::path& tmp)>& write,
                             Durability durability) {
    const WholeWrite whole;
    const auto tmp = temporary_for(file);
    bool written = false;
    errno = 0;
    try {
        written = write(tmp);
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw;
    }
    if (!written) {
        // The writer gives no reason. A failed write leaves it in errno, but other calls may have
        // left theirs there too: trust only a reason a write gives; else ask the file system.
        if (const int error = errno; error == ENOSPC || error == EFBIG || error == EDQUOT || error == EIO)
            abandon(tmp, file, error);
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        const auto space = std::filesystem::space(folder_of(file), ec);
        if (!ec && space.available == 0) fail(file, ENOSPC);
        throw RunError(fmt::format("cannot write '{}'", file.string()));
    }
    if (durability == Durability::durable)
        if (const int error = sync_path(tmp, O_RDONLY); error != 0) abandon(tmp, file, error);
    rename_over(tmp, file);
    if (durability == Durability::durable) sync_folder_of(file);
}

void sync_folder_of(const std::filesystem::path& file) {
    if (const int error = sync_path(folder_of(file), O_RDONLY | O_DIRECTORY); error != 0) fail(file, error);
}

void overwrite_in_place(const std::filesystem::path& file, std::string_view text) {
    const WholeWrite whole;
    const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(file, errno);
    int error = write_all(fd, text);
    if (error == 0 && ::ftruncate(fd, static_cast<off_t>(text.size())) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) fail(file, error);
}

void reserve_space(const std::filesystem::path& file, long bytes) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return;
    const int ignored = ::fallocate(fd, FALLOC_FL_KEEP_SIZE, 0, bytes);
    (void)ignored;
    ::close(fd);
}

}  // namespace frictionlab
