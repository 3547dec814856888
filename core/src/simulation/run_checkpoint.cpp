#include "run_checkpoint.hpp"

#include <sstream>

#include <fmt/format.h>

#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/state_archive.hpp"
#include "frictionlab/plugins/plugin.hpp"

namespace frictionlab {

RunCheckpoint RunCheckpoint::identity_of(const RunInfo& info) {
    RunCheckpoint c;
    c.framework_version = info.framework_version;
    c.framework_abi = framework_abi_version;
    c.scene_hash = info.scene_hash;
    for (const auto& p : info.plugins) c.plugins.emplace_back(p.name, p.fingerprint);
    return c;
}

std::string RunCheckpoint::payload() const {
    std::ostringstream bytes;
    {
        StateOut out(bytes);
        out(*this);
    }
    return std::move(bytes).str();
}

RunCheckpoint RunCheckpoint::from_payload(const std::string& payload) {
    std::istringstream bytes(payload);
    RunCheckpoint c;
    try {
        StateIn in(bytes);
        in(c);
    } catch (const cereal::Exception& e) {
        throw RunError(fmt::format("the checkpoint does not read back: {}", e.what()));
    }
    return c;
}

void RunCheckpoint::check_same_run(const RunCheckpoint& now) const {
    const auto refuse = [](const std::string& why) {
        throw RunError(fmt::format("the checkpoint is of another run: {}; start the run afresh (--overwrite)", why));
    };
    if (framework_version != now.framework_version)
        refuse(fmt::format("it was written by FrictionLab {}, this is {}", framework_version, now.framework_version));
    if (framework_abi != now.framework_abi)
        refuse(fmt::format("its plugin ABI is {}, this FrictionLab's is {}", framework_abi, now.framework_abi));
    if (scene_hash != now.scene_hash)
        refuse(fmt::format("the scene changed since (scene hash {} then, {} now)", scene_hash, now.scene_hash));
    if (plugins != now.plugins) {
        std::vector<std::string> then, today;
        for (const auto& [name, fingerprint] : plugins) then.push_back(name + " " + fingerprint);
        for (const auto& [name, fingerprint] : now.plugins) today.push_back(name + " " + fingerprint);
        refuse(fmt::format("its plugins were [{}], now they are [{}]", fmt::join(then, ", "), fmt::join(today, ", ")));
    }
}

std::string archived(const std::function<void(StateOut&)>& save) {
    std::ostringstream bytes;
    {
        StateOut out(bytes);
        save(out);
    }
    return std::move(bytes).str();
}

std::string archived_state(const Component& component) {
    return archived([&](StateOut& out) { component.save_state(out); });
}

void restore_archived_state(Component& component, const std::string& state, const std::string& who) {
    restore_archived(state, who, [&](StateIn& in) { component.restore_state(in); });
}

void restore_archived(const std::string& state, const std::string& who, const std::function<void(StateIn&)>& restore) {
    std::istringstream bytes(state);
    try {
        StateIn in(bytes);
        restore(in);
    } catch (const cereal::Exception& e) {
        throw RunError(fmt::format("the checkpoint's state of {} does not read back: {}", who, e.what()));
    }
    if (bytes.peek() != std::char_traits<char>::eof())
        throw RunError(fmt::format("the checkpoint's state of {} is longer than it reads back", who));
}

}  // namespace frictionlab
