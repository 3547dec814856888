#pragma once
// Short fingerprints that identify a text or a file in records (a resolved scene, a plugin file):
// 64-bit FNV-1a as 16 hex digits. Not a secret, not a defence against tampering.
#include <filesystem>
#include <string>
#include <string_view>

namespace frictionlab {

std::string fnv1a_hex(std::string_view bytes);

/// fnv1a_hex of the file's bytes, or "unreadable".
std::string file_fingerprint(const std::filesystem::path& file);

}  // namespace frictionlab
