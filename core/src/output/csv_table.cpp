#include "frictionlab/output/csv_table.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

#include <fmt/format.h>

#include "frictionlab/output/atomic_file.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/os_error.hpp"
#include "frictionlab/output/provenance.hpp"

namespace frictionlab {

CsvTable::CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, const ColumnTypes& types,
                   const RunInfo& info)
    : TableWriter(file), columns_(columns.size()) {
    fd_ = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd_ < 0 && errno == EEXIST)
        throw InputError(
            fmt::format("'{}' is written by another observer of this run already; give each observer "
                        "its own file",
                        file.string()));
    if (fd_ < 0) throw RunError(fmt::format("cannot create '{}': {}", file.string(), os_error(errno)));
    write_file_atomically(table_sidecar_path(file), table_sidecar_yaml(Provenance::of(info), columns, types));
    append(fmt::format("{}\n", fmt::join(columns, ",")));
}

CsvTable::CsvTable(const std::filesystem::path& file, const std::vector<std::string>& columns, Resume)
    : TableWriter(file), columns_(columns.size()) {
    fd_ = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) throw RunError(fmt::format("cannot reopen '{}' to resume: {}", file.string(), os_error(errno)));
    committed_ = static_cast<long long>(::lseek(fd_, 0, SEEK_END));
}

CsvTable::~CsvTable() {
    if (fd_ >= 0) ::close(fd_);
}

void CsvTable::row(const std::vector<double>& values) {
    if (values.size() != columns_)
        throw RunError(fmt::format("{}: row of {} values for {} columns", file_.string(), values.size(), columns_));
    line_.clear();
    for (std::size_t i = 0; i < values.size(); ++i)
        fmt::format_to(std::back_inserter(line_), "{}{:.10g}", i ? "," : "", values[i]);
    line_ += '\n';
    append(line_);
}

void CsvTable::append(const std::string& text) {
    const WholeWrite whole;
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            // Part of the line may have reached the file: cut it back to the last whole line.
            if (done > 0 && ::ftruncate(fd_, committed_) == 0) ::lseek(fd_, committed_, SEEK_SET);
            throw RunError(fmt::format("cannot write '{}': {}", file_.string(), os_error(error)));
        }
        done += static_cast<std::size_t>(n);
    }
    committed_ += static_cast<long long>(text.size());
}

}  // namespace frictionlab
