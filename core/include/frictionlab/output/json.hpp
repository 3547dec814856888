#pragma once
#include <string>
#include <string_view>

namespace frictionlab {

/// `s` as a JSON string literal, quotes included (RFC 8259 escapes).
std::string json_quote(std::string_view s);

}  // namespace frictionlab
