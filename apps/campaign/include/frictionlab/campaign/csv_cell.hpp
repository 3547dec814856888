#pragma once
// Text cells of the campaign tables (study.csv, sweep.csv, events.csv).
#include <string>

namespace frictionlab {

/// A CSV cell that every reader takes as one cell without quoting rules (numpy.genfromtxt has none):
/// a comma becomes a semicolon, a double quote a single one, a line break a space. The text in full
/// stays where it came from (a failed case's reason: its run.yaml and log).
inline std::string csv_cell(std::string text) {
    for (char& c : text) c = c == ',' ? ';' : c == '"' ? '\'' : c == '\n' || c == '\r' ? ' ' : c;
    return text;
}

}  // namespace frictionlab
