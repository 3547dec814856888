#include "frictionlab/scene/yaml.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

namespace frictionlab::detail {

void SourceMap::add(const YAML::Node& node, SourceLocation where) { grafted_.emplace_back(node, std::move(where)); }

SourceLocation SourceMap::at(const YAML::Node& node) const {
    // An absent node (const lookup of a missing key) has no mark, and yaml-cpp throws if asked.
    if (!node.IsDefined()) return {file_, 0, 0};
    for (const auto& [grafted, where] : grafted_)
        if (grafted.is(node)) return where;
    return location(file_, node.Mark());
}

void Reporter::error(const YAML::Node& at, const std::string& path, std::string message) const {
    diagnostics_->error(sources_->at(at), path, std::move(message));
}

void Reporter::error(SourceLocation where, const std::string& path, std::string message) const {
    diagnostics_->error(std::move(where), path, std::move(message));
}

SourceLocation location(const std::string& file, const YAML::Mark& mark) {
    if (mark.line < 0) return {file, 0, 0};
    return {file, mark.line + 1, mark.column + 1};
}

std::string join_path(const std::string& parent, const std::string& key) {
    return parent.empty() ? escaped(key) : parent + "." + escaped(key);
}

std::string index_path(const std::string& parent, std::size_t index) { return fmt::format("{}[{}]", parent, index); }

std::string escaped(const std::string& text) {
    constexpr std::size_t longest = 60;
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (i == longest) return out.append("...");
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7f)
            out += fmt::format("\\x{:02x}", c);
        else
            out += text[i];
    }
    return out;
}

std::string quote(const std::string& text) {
    // Appending, not operator+ chains: GCC 12 gives a false -Wrestrict on "'" + s + "'".
    std::string out(1, '\'');
    out += escaped(text);
    out += '\'';
    return out;
}

std::string quote_list(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : ", ") + quote(item);
    return out;
}

bool is_quoted(const YAML::Node& node) { return node.IsScalar() && node.Tag() != "?"; }

std::string describe(const YAML::Node& node) {
    if (!node.IsDefined()) return "nothing";
    switch (node.Type()) {
        case YAML::NodeType::Null:
            return "an empty value";
        case YAML::NodeType::Sequence:
            return "a list";
        case YAML::NodeType::Map:
            return "a mapping";
        case YAML::NodeType::Scalar:
            return is_quoted(node) ? "the quoted string " + quote(node.Scalar()) : quote(node.Scalar());
        default:
            return "nothing";
    }
}

namespace {

// Replays the parser's events to see every key with its mark, which the node tree hides: a mapping
// node keeps duplicate entries, but lookups silently return the first.
class KeyEventChecker final : public YAML::EventHandler {
public:
    KeyEventChecker(std::string file, Diagnostics& found) : file_(std::move(file)), found_(&found) {}
    int documents() const { return documents_; }

    void OnDocumentStart(const YAML::Mark& mark) override {
        if (++documents_ == 2)
            found_->error(location(file_, mark), "",
                          "a scene file holds one YAML document; remove this second one (after '---')");
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override { leaf(); }
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override { leaf(); }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
        if (reading_key()) check_key(mark, value);
        node_done();
    }
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        open(false);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        open(true);
    }
    void OnMapEnd() override { close(); }

private:
    struct Frame {
        bool is_map = false;
        std::string path;
        bool expecting_key = true;
        std::string key;  // of the value being read; "" after a key that is not a scalar
        std::size_t index = 0;
        std::map<std::string, YAML::Mark> seen;
    };

    bool active() const { return documents_ == 1; }
    bool reading_key() const {
        return active() && !stack_.empty() && stack_.back().is_map && stack_.back().expecting_key;
    }

    void check_key(const YAML::Mark& mark, const std::string& key) {
        Frame& f = stack_.back();
        f.key = key;
        const auto [it, first] = f.seen.emplace(key, mark);
        if (!first)
            found_->error(location(file_, mark), join_path(f.path, key),
                          fmt::format("duplicate key {}, first given at line {}{}", quote(key), it->second.line + 1,
                                      it->second.line == mark.line ? fmt::format(", column {}", it->second.column + 1)
                                                                   : std::string()));
    }
    void leaf() {
        if (reading_key()) stack_.back().key.clear();
        node_done();
    }
    void open(bool is_map) {
        if (!active()) return;
        std::string path;
        if (!stack_.empty()) {
            Frame& parent = stack_.back();
            if (parent.is_map && parent.expecting_key) parent.key.clear();
            path = parent.is_map ? join_path(parent.path, parent.key) : index_path(parent.path, parent.index);
        }
        Frame frame;
        frame.is_map = is_map;
        frame.path = std::move(path);
        stack_.push_back(std::move(frame));
    }
    void close() {
        if (!active()) return;
        stack_.pop_back();
        node_done();
    }
    void node_done() {
        if (!active() || stack_.empty()) return;
        Frame& f = stack_.back();
        if (f.is_map)
            f.expecting_key = !f.expecting_key;
        else
            ++f.index;
    }

    std::string file_;
    Diagnostics* found_;
    int documents_ = 0;
    std::vector<Frame> stack_;
};

/// Offset of the first byte that does not belong to a well-formed UTF-8 sequence (RFC 3629: no
/// overlong forms, no surrogates, nothing above U+10FFFF), if any.
std::optional<std::size_t> first_invalid_utf8(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
        const unsigned char c = byte(i);
        std::size_t length = 0;
        unsigned char low = 0x80, high = 0xbf;  // allowed range of the second byte
        if (c < 0x80)
            length = 1;
        else if (c >= 0xc2 && c <= 0xdf)
            length = 2;
        else if (c >= 0xe0 && c <= 0xef)
            length = 3, low = c == 0xe0 ? 0xa0 : 0x80, high = c == 0xed ? 0x9f : 0xbf;
        else if (c >= 0xf0 && c <= 0xf4)
            length = 4, low = c == 0xf0 ? 0x90 : 0x80, high = c == 0xf4 ? 0x8f : 0xbf;
        else
            return i;
        if (i + length > text.size()) return i;
        for (std::size_t k = 1; k < length; ++k) {
            const unsigned char lo = k == 1 ? low : 0x80, hi = k == 1 ? high : 0xbf;
            if (byte(i + k) < lo || byte(i + k) > hi) return i;
        }
        i += length;
    }
    return std::nullopt;
}

SourceLocation location_of_offset(const std::string& file, std::string_view text, std::size_t offset) {
    const auto before = text.substr(0, offset);
    const auto newline = before.rfind('\n');
    const int line = 1 + static_cast<int>(std::count(before.begin(), before.end(), '\n'));
    const int column = 1 + static_cast<int>(newline == std::string_view::npos ? offset : offset - newline - 1);
    return {file, line, column};
}

void merge(const Diagnostics& from, Diagnostics& into) {
    for (const auto& d : from.list()) into.error(d.where, d.key_path, d.message);
}

}  // namespace

std::optional<YAML::Node> read_yaml(const std::string& text, const std::string& name, Diagnostics& diagnostics) {
    // Key errors are held back until the whole text has parsed: malformed YAML is one error only.
    Diagnostics key_errors;
    // yaml-cpp passes bytes through: invalid UTF-8 would reach run.yaml and make it unreadable.
    if (const auto bad = first_invalid_utf8(text)) {
        diagnostics.error(location_of_offset(name, text, *bad), "",
                          fmt::format("invalid UTF-8 (byte 0x{:02x}): a scene is UTF-8 text",
                                      static_cast<unsigned char>(text[*bad])));
        return std::nullopt;
    }
    try {
        std::istringstream in(text);
        YAML::Parser parser(in);
        KeyEventChecker checker(name, key_errors);
        while (checker.documents() < 2 && parser.HandleNextDocument(checker)) {}
        YAML::Node root = YAML::Load(text);
        merge(key_errors, diagnostics);
        return root;
    } catch (const YAML::DeepRecursion& e) {
        diagnostics.error(location(name, e.mark), "", "malformed YAML: nested too deeply");
    } catch (const YAML::Exception& e) {
        diagnostics.error(location(name, e.mark), "", "malformed YAML: " + e.msg);
    }
    return std::nullopt;
}

}  // namespace frictionlab::detail
