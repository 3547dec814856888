#include "doc_writer.hpp"

#include "frictionlab/output/json.hpp"

#include <fmt/format.h>

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
    std::string out = fmt::format("{}/{}  ({})\n  {}\n", to_string(t.kind), t.type, library_of(t), t.summary);
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
    std::string out = fmt::format("### `{}` ({})\n\n{}\n\nProvided by `{}`.\n\n", t.type, to_string(t.kind),
                                  t.summary, library_of(t));
    if (t.params.empty()) return out + "No parameters.\n\n";
    out += "| key | type | unit | default | constraints | meaning |\n|---|---|---|---|---|---|\n";
    for (const auto& p : t.params)
        out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", p.key, to_string(p.type),
                           p.unit.empty() ? "" : p.unit, default_of(p), bounds_of(p), p.doc);
    return out + "\n";
}

std::string json_value(const ParamValue& v) {
    if (std::holds_alternative<std::string>(v)) return json_quote(std::get<std::string>(v));
    if (auto* l = std::get_if<std::vector<std::string>>(&v)) {
        std::vector<std::string> items;
        for (const auto& s : *l) items.push_back(json_quote(s));
        return fmt::format("[{}]", fmt::join(items, ", "));
    }
    if (auto* d = std::get_if<double>(&v)) return fmt::format("{}", *d);
    return to_string(v);
}

std::string json(const TypeInfo& t) {
    std::vector<std::string> params;
    for (const auto& p : t.params) {
        std::string o = fmt::format(R"({{"key": {}, "type": {}, "unit": {}, "default": {}, "required": {}, "doc": {})",
                                    json_quote(p.key), json_quote(to_string(p.type)), json_quote(p.unit),
                                    json_value(p.default_value), p.required, json_quote(p.doc));
        if (p.greater_than) o += fmt::format(", \"greater_than\": {}", *p.greater_than);
        if (p.at_least) o += fmt::format(", \"at_least\": {}", *p.at_least);
        if (p.less_than) o += fmt::format(", \"less_than\": {}", *p.less_than);
        if (p.at_most) o += fmt::format(", \"at_most\": {}", *p.at_most);
        if (!p.choices.empty()) o += ", \"choices\": " + json_value(p.choices);
        params.push_back(o + "}");
    }
    return fmt::format(R"({{"kind": {}, "type": {}, "library": {}, "summary": {}, "params": [{}]}})",
                       json_quote(std::string(to_string(t.kind))), json_quote(t.type),
                       json_quote(library_of(t)), json_quote(t.summary), fmt::join(params, ", "));
}

}  // namespace

std::string render_doc(const std::vector<const TypeInfo*>& types, DocFormat format) {
    std::vector<std::string> parts;
    for (const TypeInfo* t : types)
        parts.push_back(format == DocFormat::text ? text(*t) : format == DocFormat::markdown ? markdown(*t) : json(*t));
    if (format == DocFormat::json) return fmt::format("[{}]\n", fmt::join(parts, ",\n "));
    return fmt::format("{}", fmt::join(parts, "\n"));
}

}  // namespace frictionlab::cli
