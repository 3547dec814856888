#pragma once
// The options of the commands that run scenes (run, study, sweep): where outputs go, and what a run
// may replace and risk.
#include <string>

#include <CLI/CLI.hpp>
#include <spdlog/logger.h>

#include "frictionlab/campaign/runner.hpp"

namespace frictionlab::cli {

/// `-o,--output DIR`. An empty name is refused: it would mean the working directory.
struct OutputOption {
    std::string directory;
    CLI::Option* option = nullptr;

    void add(CLI::App& cmd, const std::string& description);
    /// True, after an error, if `-o` was given an empty name.
    bool refuse_empty(spdlog::logger& log) const;
};

/// --overwrite and --allow-unstable-step; `--force` once meant both and is refused, with why.
struct RunFlags {
    bool overwrite = false;
    bool allow_unstable_step = false;
    bool removed_force = false;
    int threads = 0;  // --threads; 0: the command's default

    void add(CLI::App& cmd);
    /// True, after an error, if --force was given.
    bool refuse_removed_force(spdlog::logger& log) const;
    /// A campaign's options with these flags, `jobs` runs at once, stopped by the command's
    /// InterruptSignals.
    CampaignOptions campaign_options(int jobs) const;
};

}  // namespace frictionlab::cli
