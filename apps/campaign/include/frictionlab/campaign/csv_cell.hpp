#pragma once
// Text cells of the campaign tables (study.csv, sweep.csv, events.csv).
#include <string>

namespace frictionlab {

/// A CSV cell: quoted when it holds a comma, a quote or a line break (RFC 4180).
inline std::string csv_cell(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

}  // namespace frictionlab
