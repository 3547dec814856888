#include "scene/overrides.hpp"

#include <cctype>
#include <charconv>
#include <optional>

#include <fmt/format.h>

namespace frictionlab::detail {

namespace {

// One step of a key path: a key of a mapping or an index into a list.
struct Step {
    std::string key;
    std::optional<std::size_t> index;
    std::size_t offset = 0;  // in the override text
};

bool is_key_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class Override {
public:
    Override(const SceneOverride& o, SourceMap& sources, Diagnostics& diagnostics)
        : text_(o.text), origin_(o.origin), sources_(&sources), diagnostics_(&diagnostics) {}

    void apply(YAML::Node& root) {
        const std::size_t equals = text_.find('=');
        if (equals == std::string::npos) return fail(text_.size(), "", "expected key.path=value");
        if (equals + 1 == text_.size()) return fail(equals + 1, "", "no value after '='");
        if (!parse_path(equals)) return;
        value_offset_ = equals + 1;
        if (!parse_value()) return;
        // A null value (`~` or null, unquoted) removes what the path names: a list item (the later
        // ones move up) or a key of a mapping (it takes its default again).
        remove_ = value_.IsNull();
        graft(root);
    }

private:
    SourceLocation at_column(std::size_t offset) const {
        return {origin_.file, origin_.line, origin_.column + static_cast<int>(offset)};
    }

    void fail(std::size_t offset, const std::string& path, const std::string& message) {
        diagnostics_->error(at_column(offset), path, "in --set " + quote(text_) + ": " + message);
    }

    bool parse_path(std::size_t end) {
        std::size_t i = 0;
        while (true) {
            const std::size_t start = i;
            while (i < end && is_key_char(text_[i])) ++i;
            if (i == start) return fail(i, "", "expected a key name"), false;
            steps_.push_back({text_.substr(start, i - start), std::nullopt, start});
            while (i < end && text_[i] == '[') {
                const std::size_t open = i++;
                const std::size_t digits = i;
                while (i < end && std::isdigit(static_cast<unsigned char>(text_[i]))) ++i;
                if (i == digits || i == end || text_[i] != ']')
                    return fail(i, "", "expected a list index such as [0]"), false;
                std::size_t index = 0;
                const auto [end_of_number, error] = std::from_chars(text_.data() + digits, text_.data() + i, index);
                if (error != std::errc() || end_of_number != text_.data() + i)
                    return fail(digits, "",
                                fmt::format("list index {} is out of range", text_.substr(digits, i - digits))),
                           false;
                steps_.push_back({"", index, open});
                ++i;
            }
            if (i == end) return true;
            if (text_[i] != '.')
                return fail(i, "", fmt::format("unexpected character '{}' in the key path", text_[i])), false;
            ++i;
        }
    }

    // The value is YAML of its own; its marks count from the '='.
    bool parse_value() {
        Diagnostics found;
        auto value = read_yaml(text_.substr(value_offset_), origin_.file, found);
        for (const auto& d : found.list())
            diagnostics_->error(at_column(value_offset_ + std::max(d.where.column - 1, 0)), d.key_path,
                                "in --set " + quote(text_) + ": " + d.message);
        if (!value) return false;
        value_ = *value;
        return true;
    }

    SourceLocation where(const YAML::Node& node) const {
        const int pos = node.Mark().pos;
        return at_column(value_offset_ + static_cast<std::size_t>(std::max(pos, 0)));
    }

    // Records the value's nodes down to the depth a scene can hold; bounded since aliases can loop.
    void record(const YAML::Node& node, int depth) {
        sources_->add(node, where(node));
        if (depth == 0) return;
        if (node.IsMap())
            for (auto it = node.begin(); it != node.end(); ++it)
                record(it->first, depth - 1), record(it->second, depth - 1);
        if (node.IsSequence())
            for (const auto& item : node) record(item, depth - 1);
    }

    void graft(YAML::Node& root) {
        YAML::Node at;
        at.reset(root);
        std::string path;
        for (std::size_t k = 0; k < steps_.size(); ++k) {
            const Step& step = steps_[k];
            const bool last = k + 1 == steps_.size();
            if (step.index ? !enter_item(at, path, step, last) : !enter_key(at, path, step, last)) return;
        }
    }

    bool enter_item(YAML::Node& at, std::string& path, const Step& step, bool last) {
        const std::size_t i = *step.index;
        if (!at.IsSequence()) return fail(step.offset, path, "not a list, but " + describe(at)), false;
        if (i >= at.size())
            return fail(step.offset, index_path(path, i),
                        fmt::format("no such item: {} has {} item{}", path, at.size(), at.size() == 1 ? "" : "s")),
                   false;
        path = index_path(path, i);
        if (last && remove_) {
            at.remove(i);
        } else if (last) {
            at[i] = value_;
            record(value_, max_depth);
        } else {
            YAML::Node next = at[i];
            at.reset(next);
        }
        return true;
    }

    bool enter_key(YAML::Node& at, std::string& path, const Step& step, bool last) {
        if (!at.IsMap() && !at.IsNull()) {
            const std::string name = path.empty() ? "the scene" : path;
            const std::string why = at.IsSequence() ? fmt::format("a list; address its items as {}[N]", name)
                                                    : describe(at) + ", not a mapping";
            return fail(step.offset, path, "cannot set " + quote(step.key) + " in " + name + ": it is " + why), false;
        }
        if (remove_) return remove_key(at, path, step, last);
        // Non-const lookups of yaml-cpp add the key (undefined until assigned) and turn a null into a map.
        const bool absent = !at[step.key].IsDefined();
        path = join_path(path, step.key);
        if (last) {
            at[step.key] = value_;
            record(value_, max_depth);
        } else if (absent || at[step.key].IsNull()) {
            at[step.key] = YAML::Node(YAML::NodeType::Map);
            sources_->add(at[step.key], at_column(step.offset));
        }
        if (absent) record_key(at, step);
        if (!last) {
            YAML::Node next = at[step.key];
            at.reset(next);
        }
        return true;
    }

    // On the way to what is removed nothing is added: a key that is not there is reported.
    bool remove_key(YAML::Node& at, std::string& path, const Step& step, bool last) {
        const YAML::Node& lookup = at;  // a const lookup adds no key
        const bool present = at.IsMap() && lookup[step.key].IsDefined();
        const std::string parent = path.empty() ? "the scene" : path;
        path = join_path(path, step.key);
        if (!present)
            return fail(step.offset, path, fmt::format("nothing to remove: {} has no key {}", parent, quote(step.key))),
                   false;
        if (last) {
            at.remove(step.key);
        } else {
            YAML::Node next = at[step.key];
            at.reset(next);
        }
        return true;
    }

    // A key the override added has no mark; point unknown-key errors at the override.
    void record_key(const YAML::Node& map, const Step& step) {
        for (auto it = map.begin(); it != map.end(); ++it)
            if (it->first.IsScalar() && it->first.Scalar() == step.key)
                return sources_->add(it->first, at_column(step.offset));
    }

    static constexpr int max_depth = 4;
    std::string text_;
    SourceLocation origin_;
    SourceMap* sources_;
    Diagnostics* diagnostics_;
    std::vector<Step> steps_;
    std::size_t value_offset_ = 0;
    YAML::Node value_;
    bool remove_ = false;
};

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<SceneOverride>& overrides, SourceMap& sources,
                     Diagnostics& diagnostics) {
    for (const auto& o : overrides) Override(o, sources, diagnostics).apply(root);
}

}  // namespace frictionlab::detail
