#include "frictionlab/base/diagnostics.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include <fmt/format.h>

namespace frictionlab {

std::string Diagnostic::format(const std::string& severity) const {
    std::string out = where.file.empty() ? "<scene>" : where.file;
    if (where.line > 0) out += fmt::format(":{}:{}", where.line, where.column);
    out += ": " + severity + ": ";
    if (!key_path.empty()) out += key_path + ": ";
    return out + message;
}

void Diagnostics::error(SourceLocation where, std::string key_path, std::string message) {
    list_.push_back({std::move(where), std::move(key_path), std::move(message)});
}

std::string Diagnostics::format() const {
    std::vector<const Diagnostic*> sorted;
    for (const auto& d : list_) sorted.push_back(&d);
    std::stable_sort(sorted.begin(), sorted.end(), [](const Diagnostic* a, const Diagnostic* b) {
        return std::tie(a->where.file, a->where.line, a->where.column) <
               std::tie(b->where.file, b->where.line, b->where.column);
    });
    std::string out;
    for (const auto* d : sorted) out += d->format() + "\n";
    return out;
}

namespace {
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), 0);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}
}  // namespace

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) best_distance = d, best = c;
    }
    return best;
}

}  // namespace frictionlab
