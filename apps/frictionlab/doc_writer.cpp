#include "doc_writer.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace frictionlab::cli {

namespace {

std::string bounds_of(const ParamInfo& p) {
    std::vector<std::string> parts;
    if (p.greater_than) parts.push_back(fmt::format("> {:g}", *p.greater_than));
    if (p.at_least) parts.push_back(fmt::format(">= {:g}", *p.at_least));
    if (p.less_than) parts.push_back(fmt::format("< {:g}", *p.less_than));
    if (p.at_most) parts.push_back(fmt::format("<= {:g}", *p.at_most));
    if (!p.choices.empty()) parts.push_back("one of " + fmt::format("{}", fmt::join(p.choices, ", ")));
    return fmt::format("{}", fmt::join(parts, ", "));
}

std::string default_of(const ParamInfo& p) { return p.required ? "(required)" : to_string(p.default_value); }

std::string library_of(const TypeInfo& t) {
    return t.library.empty() ? "built in" : std::filesystem::path(t.library).filename().string();
}

std::string text(const TypeInfo& t) {
    std::string out = fmt::format("{}/{}  ({})\n  {}\n  dimensions: {}\n", to_string(t.kind), t.type, library_of(t),
                                  t.summary, t.dimensions_text());
    std::size_t width = 4;
    for (const auto& p : t.params) width = std::max(width, p.key.size());
    for (const auto& p : t.params) {
        out += fmt::format("  {:<{}}  {} [{}], default {}", p.key, width, to_string(p.type),
                           p.unit.empty() ? "-" : p.unit, default_of(p));
        if (auto b = bounds_of(p); !b.empty()) out += ", " + b;
        out += fmt::format("\n  {:<{}}  {}\n", "", width, p.doc);
    }
    return out;
}

std::string markdown(const TypeInfo& t) {
    std::string out = fmt::format("### `{}` ({})\n\n{}\n\nProvided by `{}`. Dimensions: {}.\n\n", t.type,
                                  to_string(t.kind), t.summary, library_of(t), t.dimensions_text());
    if (t.params.empty()) return out + "No parameters.\n\n";
    out += "| key | type | unit | default | constraints | meaning |\n|---|---|---|---|---|---|\n";
    for (const auto& p : t.params)
        out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", p.key, to_string(p.type),
                           p.unit.empty() ? "" : p.unit, default_of(p), bounds_of(p), p.doc);
    return out + "\n";
}

nlohmann::ordered_json json(const TypeInfo& t) {
    auto params = nlohmann::ordered_json::array();
    for (const auto& p : t.params) {
        nlohmann::ordered_json o{{"key", p.key}, {"type", to_string(p.type)}, {"unit", p.unit}};
        o["default"] = std::visit([](const auto& v) { return nlohmann::ordered_json(v); }, p.default_value);
        o["required"] = p.required;
        o["doc"] = p.doc;
        if (p.greater_than) o["greater_than"] = *p.greater_than;
        if (p.at_least) o["at_least"] = *p.at_least;
        if (p.less_than) o["less_than"] = *p.less_than;
        if (p.at_most) o["at_most"] = *p.at_most;
        if (!p.choices.empty()) o["choices"] = p.choices;
        params.push_back(std::move(o));
    }
    return {{"kind", to_string(t.kind)},  {"type", t.type},
            {"library", library_of(t)},   {"summary", t.summary},
            {"dimensions", t.dimensions}, {"dimension_limit", t.dimension_limit},
            {"params", std::move(params)}};
}

}  // namespace

std::string render_doc(const std::vector<const TypeInfo*>& types, DocFormat format) {
    if (format == DocFormat::json) {
        auto all = nlohmann::ordered_json::array();
        for (const TypeInfo* t : types) all.push_back(json(*t));
        // Invalid UTF-8 (a plugin's doc string) is replaced rather than refused.
        return all.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
    }
    std::vector<std::string> parts;
    for (const TypeInfo* t : types) parts.push_back(format == DocFormat::text ? text(*t) : markdown(*t));
    return fmt::format("{}", fmt::join(parts, "\n"));
}

}  // namespace frictionlab::cli
