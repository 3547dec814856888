#include "frictionlab/plugins/library.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <gelf.h>
#include <libelf.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/fingerprint.hpp"

namespace frictionlab {

namespace {
/// The fields of a fingerprint, named, in order: the first that differs is what we report.
std::array<std::pair<const char*, std::uint32_t>, 8> named_fields(const AbiFingerprint& a) {
    return {{{"framework_abi", a.framework_abi},
             {"compiler", a.compiler},
             {"compiler_major", a.compiler_major},
             {"stdlib", a.stdlib},
             {"cxx11_abi", a.cxx11_abi},
             {"cxx_standard", a.cxx_standard},
             {"eigen_version", a.eigen_version},
             {"eigen_max_align", a.eigen_max_align}}};
}

std::string first_difference(const AbiFingerprint& plugin, const AbiFingerprint& host) {
    const auto p = named_fields(plugin), h = named_fields(host);
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i].second != h[i].second)
            return fmt::format("ABI mismatch in field '{}': plugin has {}, this frictionlab has {}", p[i].first,
                               p[i].second, h[i].second);
    return {};
}

/// dlerror() repeats the file name ("<file>: cannot open shared object file: ..."); our message
/// already starts with it.
std::string dl_reason(const std::string& file) {
    const char* e = dlerror();
    std::string reason = e ? e : "dlopen failed";
    if (const std::string prefix = file + ": "; reason.starts_with(prefix)) reason.erase(0, prefix.size());
    return reason;
}

/// The stamp section's bytes as a PluginStamp, or why they cannot be one. A stamp of another header
/// version is reported by its first two fields, which never move.
std::string read_stamp(Elf* elf, std::uint64_t file_size, PluginStamp& stamp) {
    std::size_t names = 0;
    if (elf_getshdrstrndx(elf, &names) != 0) return "its section names cannot be read";
    for (Elf_Scn* section = elf_nextscn(elf, nullptr); section; section = elf_nextscn(elf, section)) {
        GElf_Shdr header{};
        if (!gelf_getshdr(section, &header)) return "its section headers cannot be read";
        const char* name = elf_strptr(elf, names, header.sh_name);
        if (!name || std::strcmp(name, FRICTIONLAB_PLUGIN_SECTION) != 0) continue;
        if (header.sh_type != SHT_PROGBITS || header.sh_offset + header.sh_size > file_size)
            return "its section " FRICTIONLAB_PLUGIN_SECTION " is damaged or truncated";
        const Elf_Data* data = elf_getdata(section, nullptr);
        constexpr std::size_t fixed = 2 * sizeof(std::uint32_t);  // header_version, header_size
        if (!data || !data->d_buf || data->d_size < fixed)
            return fmt::format("its section " FRICTIONLAB_PLUGIN_SECTION " has {} bytes, too few for a plugin stamp",
                               data ? data->d_size : 0);
        std::memcpy(&stamp, data->d_buf, std::min(data->d_size, sizeof stamp));
        if (stamp.header_version != plugin_header_version || stamp.header_size != sizeof(PluginStamp) ||
            data->d_size < sizeof stamp)
            return fmt::format("plugin header version {} (size {}), this frictionlab reads version {} (size {})",
                               stamp.header_version, stamp.header_size, plugin_header_version, sizeof(PluginStamp));
        return {};
    }
    return "it has no section " FRICTIONLAB_PLUGIN_SECTION
           " (define its entry point with FRICTIONLAB_PLUGIN; a plugin built against an older frictionlab "
           "has none: rebuild it)";
}

/// Why the file cannot be a plugin for this frictionlab, or "": read with libelf before dlopen,
/// which maps the file's segments (and would die of SIGBUS on one cut short: a truncated copy, a
/// download that stopped) and runs the library's static constructors. Fills in `stamp`.
std::string elf_problem(const std::filesystem::path& file, PluginStamp& stamp) {
    if (elf_version(EV_CURRENT) == EV_NONE) return "libelf cannot read ELF files here";
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::strerror(errno);
    struct stat st {};
    if (::fstat(fd, &st) != 0) return ::close(fd), std::string(std::strerror(errno));
    const auto size = static_cast<std::uint64_t>(st.st_size);
    Elf* elf = elf_begin(fd, ELF_C_READ, nullptr);
    std::string problem;
    GElf_Ehdr header{};
    std::size_t segments = 0;
#if defined(__x86_64__)
    constexpr int machine = EM_X86_64;
#elif defined(__aarch64__)
    constexpr int machine = EM_AARCH64;
#else
    constexpr int machine = EM_NONE;  // not checked
#endif
    if (!elf || elf_kind(elf) != ELF_K_ELF || !gelf_getehdr(elf, &header))
        problem = "it is not an ELF file";
    else if (header.e_type != ET_DYN)
        problem = "it is an ELF file but not a shared library";
    else if (machine != EM_NONE && header.e_machine != machine)
        problem =
            fmt::format("it is built for another machine (ELF machine {}, this one is {})", header.e_machine, machine);
    else if (header.e_shoff + std::uint64_t{header.e_shnum} * header.e_shentsize > size)
        problem = fmt::format("it is truncated: its section table ends at byte {}, the file has {}",
                              header.e_shoff + std::uint64_t{header.e_shnum} * header.e_shentsize, size);
    else if (elf_getphdrnum(elf, &segments) != 0)
        problem = "its program headers cannot be read";
    for (std::size_t i = 0; problem.empty() && i < segments; ++i) {
        GElf_Phdr segment{};
        if (!gelf_getphdr(elf, static_cast<int>(i), &segment))
            problem = "its program headers cannot be read";
        else if (segment.p_offset + segment.p_filesz > size)
            problem = fmt::format("it is truncated: segment {} ends at byte {}, the file has {}", i,
                                  segment.p_offset + segment.p_filesz, size);
    }
    if (problem.empty()) problem = read_stamp(elf, size, stamp);
    if (elf) elf_end(elf);
    ::close(fd);
    return problem;
}

/// Why a stamp of the right version is not one this frictionlab can load, or "".
std::string stamp_problem(const PluginStamp& stamp) {
    if (auto diff = first_difference(stamp.abi, current_abi()); !diff.empty()) return diff;
    const auto terminated = [](const auto& text) { return std::memchr(text, '\0', sizeof text) != nullptr; };
    if (!terminated(stamp.name) || !terminated(stamp.version) || !stamp.name[0] || !stamp.version[0])
        return "its stamp has no name or version";
    return {};
}

/// Absolute, so that dlopen opens this very file: a name without a slash would instead be searched
/// for in LD_LIBRARY_PATH and the system library directories. Also what run metadata records.
std::filesystem::path absolute_path(const std::filesystem::path& file) {
    std::error_code ec;
    auto p = std::filesystem::absolute(file, ec);
    return ec ? file : p.lexically_normal();
}
}  // namespace

PluginLibrary::PluginLibrary(const std::filesystem::path& file) : file_(absolute_path(file)) {
    const auto fail = [&](const std::string& why) {
        if (handle_) dlclose(handle_);
        handle_ = nullptr;
        throw InputError(fmt::format("{}: cannot use this plugin: {}", file_.string(), why));
    };
    if (std::error_code ec; !std::filesystem::exists(file_, ec)) fail("no such file");
    // Nothing of the file runs until its stamp has passed: dlopen runs its static constructors.
    PluginStamp stamp{};
    if (const std::string problem = elf_problem(file_, stamp); !problem.empty()) fail(problem);
    if (const std::string problem = stamp_problem(stamp); !problem.empty()) fail(problem);
    // Once, as loaded: a copy earlier in the search path wins over the shipped plugin of the same
    // name, and every run's record must show which file ran.
    fingerprint_ = file_fingerprint(file_);
    dlerror();
    handle_ = dlopen(file_.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) fail(dl_reason(file_.string()));
    void* symbol = dlsym(handle_, FRICTIONLAB_PLUGIN_ENTRY_SYMBOL);
    if (!symbol)
        fail("it does not export the entry symbol '" FRICTIONLAB_PLUGIN_ENTRY_SYMBOL
             "' (define it with FRICTIONLAB_PLUGIN)");
    using Entry = const PluginHeader* (*)();
    Entry entry = nullptr;
    std::memcpy(&entry, &symbol, sizeof entry);  // object pointer -> function pointer, as POSIX allows
    header_ = entry();
    if (!header_) fail("its entry point returned no header");
    // The stamp passed; the entry point's header is checked again, as it may be written by hand.
    // Only the first two fields are read before they have been checked: their place never moves.
    if (header_->header_version != plugin_header_version || header_->header_size != sizeof(PluginHeader))
        fail(fmt::format("plugin header version {} (size {}), this frictionlab reads version {} (size {})",
                         header_->header_version, header_->header_size, plugin_header_version, sizeof(PluginHeader)));
    if (auto diff = first_difference(header_->abi, current_abi()); !diff.empty()) fail(diff);
    if (!header_->register_types) fail("its header has no register function");
    if (!header_->name || !header_->version) fail("its header has no name or version");
}

PluginLibrary::~PluginLibrary() {
    if (handle_) dlclose(handle_);
}

PluginRecord PluginLibrary::record() const { return {header_->name, header_->version, file_, fingerprint_}; }

}  // namespace frictionlab
